#!/usr/bin/env bash
# Runs the three benchmark programs in adair, CPython 3, Lua 5.4 and GNAT and
# prints the wall-clock time of each and adair's ratio to the others.
# Needs: python3, lua5.4 and gnat (apt-get install -y lua5.4 gnat).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
secs() { local s e; s=$(date +%s.%N); "$@" >/dev/null; e=$(date +%s.%N); echo "$e - $s" | bc; }
printf '%-8s %9s %9s %9s %9s %12s %12s\n' program adair python3 lua5.4 gnat 'adair/py' 'adair/lua'
for p in fib matrix list; do
  cp "bench/programs/$p.adb" "$work/"
  (cd "$work" && gnatmake -q -O2 "$p.adb" >/dev/null)
  a=$(secs ./target/release/adair run "bench/programs/$p.adb")
  py=$(secs python3 "bench/programs/$p.py")
  lu=$(secs lua5.4 "bench/programs/$p.lua")
  g=$(secs "$work/$p")
  printf '%-8s %9.3f %9.3f %9.3f %9.3f %12.2f %12.2f\n' "$p" "$a" "$py" "$lu" "$g" "$(echo "$a / $py" | bc -l)" "$(echo "$a / $lu" | bc -l)"
done

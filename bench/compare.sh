#!/usr/bin/env bash
# Runs the programs of bench/programs in adair, Lua 5.4, CPython and GNAT
# (-O2), each workload in ONE hyperfine run, and prints the medians and
# adair's ratios; then the peak RSS of the two list programs in each, and the
# check time of the checker's two pathological inputs.
# Usage: bench/compare.sh   (RUNS=n for more runs per command)
# Needs: hyperfine, lua5.4, python3, gnatmake, jq, /usr/bin/time.
# CPython runs as `python3 -S` through its real executable: a version
# manager's shim (pyenv) adds tens of milliseconds that are not Python's.
set -euo pipefail
cd "$(dirname "$0")/.."
# ADAIR=path/to/adair compares another build (a baseline) instead.
if [ -z "${ADAIR:-}" ]; then
  cargo build --release --quiet
fi
adair=${ADAIR:-$PWD/target/release/adair}
python=$(command -v pyenv >/dev/null && pyenv which python3 2>/dev/null || readlink -f "$(command -v python3)")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
runs=${RUNS:-10}

median() { jq -r ".results[$1].median" "$2"; }

printf '%-8s %10s %10s %10s %10s %9s %9s %9s\n' \
  workload 'adair ms' 'lua ms' 'python ms' 'gnat ms' adair/lua adair/py adair/gnat
for p in hello fib matrix list records strings; do
  cp "bench/programs/$p.adb" "$work/"
  (cd "$work" && gnatmake -q -O2 "$p.adb" >/dev/null 2>&1)
  hyperfine -N --warmup 2 --runs "$runs" --style none --export-json "$work/$p.json" \
    -n adair "$adair run bench/programs/$p.adb" \
    -n lua "lua5.4 bench/programs/$p.lua" \
    -n python "$python -S bench/programs/$p.py" \
    -n gnat "$work/$p" >/dev/null
  j="$work/$p.json"
  a=$(median 0 "$j"); l=$(median 1 "$j"); y=$(median 2 "$j"); g=$(median 3 "$j")
  awk -v p="$p" -v a="$a" -v l="$l" -v y="$y" -v g="$g" 'BEGIN {
    printf "%-8s %10.1f %10.1f %10.1f %10.1f %9.2f %9.2f %9.2f\n",
      p, a*1000, l*1000, y*1000, g*1000, a/l, a/y, a/g }'
done

rss() { /usr/bin/time -f '%M' "$@" 2>&1 >/dev/null | tail -1; }
for p in list records; do
  ra=$(rss "$adair" run "bench/programs/$p.adb")
  rl=$(rss lua5.4 "bench/programs/$p.lua")
  ry=$(rss "$python" -S "bench/programs/$p.py")
  rg=$(rss "$work/$p")
  awk -v p="$p" -v a="$ra" -v l="$rl" -v y="$ry" -v g="$rg" 'BEGIN {
    printf "%-8s %10.1f %10.1f %10.1f %10.1f %9.2f %9.2f %9.2f   (peak RSS, MiB)\n",
      p, a/1024, l/1024, y/1024, g/1024, a/l, a/y, a/g }'
done

# The checker on its two pathological inputs (adair only).
python3 bench/pathological.py "$work"
for f in minus star; do
  hyperfine -N --runs 3 --style none --export-json "$work/c$f.json" \
    -n "$f" "$adair check $work/$f.adb" >/dev/null
  awk -v n="$f" -v a="$(median 0 "$work/c$f.json")" \
    'BEGIN { printf "check %-6s %8.1f ms\n", n, a*1000 }'
done

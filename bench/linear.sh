#!/usr/bin/env bash
# The costs that must grow linearly with the input (issue 35), each at 1x,
# 2x and 4x: the time and the growth ratio (2.0 is linear, 4.0 quadratic).
# Shapes: an unfinished program (loops never closed, statements broken), a
# dotted name, piped REPL declarations, a device file's events, allocated
# tasks. The parser's and checker's work counts are checked exactly by
# tests/linear.rs; this measures times.
# Usage: bench/linear.sh   (ADAIR=path/to/adair to time another build)
# Needs: python3, /usr/bin/time.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ -z "${ADAIR:-}" ]; then
  cargo build --release --quiet
fi
adair=${ADAIR:-$PWD/target/release/adair}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 -S - "$work" <<'PY'
import sys
w = sys.argv[1]
head = "procedure P is\n   X : Integer := 0;\nbegin\n"
for k, n in (("1x", 1), ("2x", 2), ("4x", 4)):
    open(f"{w}/unfinished-{k}.air", "w").write(
        head + "for I in 1 .. 3 loop\n  X := X + I;\n  if X > 0 then\n" * (1000 * n))
    open(f"{w}/broken-{k}.air", "w").write(
        head + "X < 10 loop X := X + 1 ; exit when X = 5 ; loop ;\n" * (5000 * n) + "when")
    open(f"{w}/assign-{k}.air", "w").write(
        "procedure P is\n" + "".join(f"   V{i} : Integer := 0;\n" for i in range(3000 * n))
        + "begin\n" + "".join(f"   V{i} := {i};\n" for i in range(3000 * n)) + "end P;\n")
    open(f"{w}/dotted-{k}.air", "w").write(
        head + "X := A" + ".A" * (20000 * n) + ";\nend P;\n")
    open(f"{w}/repl-{k}.txt", "w").write(
        "".join(f"X{i} : Integer := {i};\n" for i in range(1000 * n)))
    dev = ('[[device]]\nname = "parallel"\nkind = "parallel"\ninterrupt = 0o340\n'
           'input = 0o342\noutput = 0o344\ncontrol = 0o346\n')
    dev += "".join(f'[[event]]\nat = {i * 0.001:.3f}\ndevice = "parallel"\ninput = {i % 65536}\n'
                   for i in range(10000 * n))
    open(f"{w}/devices-{k}.toml", "w").write(dev)
    open(f"{w}/tasks-{k}.air", "w").write(
        "procedure T is\n   task type W;\n   type W_Ptr is access W;\n"
        "   task body W is\n   begin\n      null;\n   end W;\n   P : W_Ptr;\n"
        f"begin\n   for I in 1 .. {25000 * n} loop\n      P := new W;\n   end loop;\n"
        "   P := P;\nend T;\n")
open(f"{w}/delay.air", "w").write("procedure D is\nbegin\n   delay 45.0;\nend D;\n")
PY

secs() { { /usr/bin/time -f %e "$@" 2>&1 >/dev/null || true; } | tail -1; }
row() {
  local name=$1; shift
  local a b c
  a=$("$@" 1x); b=$("$@" 2x); c=$("$@" 4x)
  printf '%-34s %8s %8s %8s %6.2f %6.2f\n' "$name" "$a" "$b" "$c" \
    "$(echo "$b / ($a + 0.001)" | bc -l)" "$(echo "$c / ($b + 0.001)" | bc -l)"
}
check() { secs "$adair" check "$work/$1-$2.air"; }
repl() { secs sh -c "'$adair' repl < '$work/repl-$1.txt'"; }
devices() { secs "$adair" run --devices "$work/devices-$1.toml" "$work/delay.air"; }
tasks() { secs "$adair" run "$work/tasks-$1.air"; }

printf '%-34s %8s %8s %8s %6s %6s\n' shape '1x s' '2x s' '4x s' '2x/1x' '4x/2x'
row "unclosed loops/ifs (1000 at 1x)" check unfinished
row "broken statements (5000 at 1x)" check broken
row "variables assigned (3000 at 1x)" check assign
row "dotted name (20000 parts at 1x)" check dotted
row "piped REPL (1000 decls at 1x)" repl
row "device events (10000 at 1x)" devices
row "allocated tasks (25000 at 1x)" tasks

#!/bin/sh
# The framework's cost per step, by instruction count (callgrind): test1
# (50 balls) and test9 (one ball) headless against bench_overhead_bare, a
# bare ODE loop of the very scene (it prints the same state_hash, which is
# checked). Two run lengths, SHORT and LONG simulated seconds; the difference
# cancels start-up and the final report, so
#   per step  = (I(LONG) - I(SHORT)) / (steps(LONG) - steps(SHORT))
#   overhead  = program's per step / bare loop's per step - 1
#   start-up  = I(a run of one step): loading, parsing, building, reporting
#
#   sh checks/bench_overhead.sh [SHORT LONG]     (default 9 18; build/ built first)
#
# Environment: BUILD_DIR (default: build). Needs valgrind.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
build=${BUILD_DIR:-$here/../build}
short=${1:-9} long=${2:-18}
command -v valgrind >/dev/null || { echo "bench_overhead: valgrind not found (apt-get install valgrind)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# instructions NAME COMMAND...: runs COMMAND under callgrind, prints its total
# instruction count; its standard output is kept in $work/NAME.out.
instructions() {
  name=$1
  shift
  valgrind --tool=callgrind --callgrind-out-file="$work/$name.cg" "$@" >"$work/$name.out" 2>"$work/$name.err"
  sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$work/$name.err"
}
value() { sed -n "s/^ *$2 = \([0-9.e+-]*\).*/\1/p" "$work/$1.out"; }

printf '%-6s %10s %16s %16s %10s %14s %14s\n' scene steps program_per_step bare_per_step overhead \
  program_startup bare_startup
for scene in test1 test9; do
  for s in "$short" "$long"; do
    (cd "$work" && instructions "${scene}_program_$s" "$build/tests/$scene" --headless --seconds "$s") >"$work/p$s"
    (cd "$work" && instructions "${scene}_bare_$s" "$build/checks/bench_overhead_bare" "$scene" "$s") >"$work/b$s"
    program_hash=$(value "${scene}_program_$s" state_hash) bare_hash=$(value "${scene}_bare_$s" state_hash)
    if [ "$program_hash" != "$bare_hash" ]; then
      echo "bench_overhead: $scene ${s} s: the bare loop's state_hash $bare_hash is not the program's $program_hash" >&2
      exit 1
    fi
  done
  start_program=$(cd "$work" && instructions "${scene}_program_start" "$build/tests/$scene" --headless --seconds 0.001)
  start_bare=$(cd "$work" && instructions "${scene}_bare_start" "$build/checks/bench_overhead_bare" "$scene" 0.001)
  python3 - "$scene" "$(cat "$work/p$short")" "$(cat "$work/p$long")" "$(cat "$work/b$short")" "$(cat "$work/b$long")" \
    "$(value "${scene}_bare_$short" steps)" "$(value "${scene}_bare_$long" steps)" "$start_program" "$start_bare" <<'PY'
import sys
scene, p1, p2, b1, b2, n1, n2, s1, s2 = sys.argv[1], *map(int, sys.argv[2:])
program, bare = (p2 - p1) / (n2 - n1), (b2 - b1) / (n2 - n1)
print(f"{scene:6} {n2 - n1:10d} {program:16.1f} {bare:16.1f} {100 * (program / bare - 1):9.2f}% "
      f"{s1 / 1e6:12.2f} M {s2 / 1e6:12.2f} M")
PY
done

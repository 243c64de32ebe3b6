#!/usr/bin/env bash
# Where Node.js is missing, Havok, Jolt, Rapier and PhysX are named as missing,
# never fatal to anything else, and the lab's peers section says they were
# skipped:
#  - `test9 --list-engines` marks the four not available, saying to install
#    Node.js, while ode, bullet and mujoco are listed as before;
#  - `test9 --engine jolt` is refused with status 2 before anything runs,
#    naming the engine and Node.js, and leaves nothing in its folder;
#  - `odelab-report --quick --only peers` ends with status 0, writes peers.csv
#    with no havok, jolt, rapier or physx row, and RESULTS.md names the four skipped.
# Node is hidden by ODELAB_NODE naming a program that does not exist, which
# is where the adapters look first (peers/engines/NodeEngine.cpp).
# Usage: without_node.sh SOURCE_DIR BUILD_TESTS_DIR WORK_DIR
set -uo pipefail
source_dir=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
work=$3
rm -rf "$work" && mkdir -p "$work/run"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
export ODELAB_NODE=/nonexistent/node

listing=$("$build/test9" --list-engines)
for engine in havok jolt rapier physx; do
  grep -q "^$engine: not available" <<<"$listing" || fail "--list-engines does not mark $engine not available"
done
grep -q "Node.js" <<<"$listing" || fail "--list-engines does not say Node.js is what is missing"
grep -q "^ode: available" <<<"$listing" || fail "--list-engines lost ode"

(cd "$work/run" && "$build/test9" --headless --engine jolt >"$work/out.txt" 2>"$work/err.txt")
status=$?
[ $status -eq 2 ] || fail "--engine jolt without node ended with status $status, not 2"
grep -q "jolt" "$work/err.txt" && grep -q "Node.js" "$work/err.txt" ||
  fail "--engine jolt without node did not name the engine and Node.js: $(cat "$work/err.txt")"
[ -z "$(ls -A "$work/run")" ] || fail "--engine jolt without node left files: $(ls -A "$work/run")"

"$source_dir/lab/odelab-report" --quick --only peers --build-dir "$build" --out "$work/report" >"$work/lab.log" 2>&1
status=$?
if [ $status -ne 0 ]; then
  fail "the lab without node ended with status $status: $(tail -n 5 "$work/lab.log")"
else
  engines=$(grep -v '^#' "$work/report/peers.csv" | tail -n +2 | cut -d, -f2 | sort -u | tr '\n' ' ')
  case " $engines" in
    *" havok "* | *" jolt "* | *" rapier "* | *" physx "*) fail "peers.csv has rows of an engine that needs node: $engines" ;;
  esac
  grep -qi "skipped.*havok.*jolt.*rapier.*physx" "$work/report/RESULTS.md" ||
    fail "RESULTS.md does not say that havok, jolt, rapier and physx were skipped"
fi

if [ $failures -eq 0 ]; then
  echo "without node: havok, jolt, rapier and physx named as missing, refused with status 2, skipped and said by the lab"
  rm -rf "$work"
fi
exit $((failures > 0))

#!/usr/bin/env bash
# Where Node.js is missing the project still configures, the peers in C++
# still run, and the lab's peers section says that Havok, Jolt and Rapier
# were skipped instead of failing or leaving them out unsaid:
#  - CMake configures a build told there is no node (ODELAB_NODE not found)
#    and generates no web-peer check;
#  - `odelab-report --quick --only peers` on programs whose peers/ folder has
#    only bullet_lab and mujoco_lab (what a build without node has) ends with
#    status 0, writes peers.csv with ode, bullet and mujoco rows and no web
#    peer's, and RESULTS.md names the three skipped engines.
# Usage: without_node.sh SOURCE_DIR BUILD_TESTS_DIR WORK_DIR
set -uo pipefail
source_dir=$(cd "$1" && pwd)
build=$(cd "$2" && pwd)
work=$3
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# 1. Configure without node. The checks are on so that the web peers' checks
# would be generated if node were taken to be there.
if cmake -S "$source_dir" -B "$work/configure" -DODELAB_BUILD_CHECKS=ON -DODELAB_NODE=ODELAB_NODE-NOTFOUND \
    >"$work/configure.log" 2>&1; then
  grep -q "Web peers (Havok, Jolt, Rapier) skipped: node not found" "$work/configure.log" \
    || fail "configure without node did not say the web peers are skipped"
  web_checks=$(cd "$work/configure" && ctest -N | grep -c "peers_\(havok\|jolt\|rapier\)_") || true
  [ "$web_checks" -eq 0 ] || fail "configure without node generated $web_checks web-peer checks"
else
  fail "configure without node failed: $(tail -n 5 "$work/configure.log")"
fi

# 2. The lab with the C++ peers only: the programs as file links in a folder
# of their own, since the lab looks for peers/ beside the programs' folder.
mkdir -p "$work/build/tests" "$work/build/peers"
for program in "$build"/*; do
  [ -f "$program" ] && [ -x "$program" ] && ln -s "$program" "$work/build/tests/"
done
for peer in bullet_lab mujoco_lab; do
  ln -s "$build/../peers/$peer" "$work/build/peers/$peer"
done
"$source_dir/lab/odelab-report" --quick --only peers --build-dir "$work/build/tests" --out "$work/report" \
  >"$work/lab.log" 2>&1
status=$?
if [ $status -ne 0 ]; then
  fail "the lab without the web peers ended with status $status: $(tail -n 5 "$work/lab.log")"
else
  engines=$(grep -v '^#' "$work/report/peers.csv" | tail -n +2 | cut -d, -f2 | sort -u | tr '\n' ' ')
  [ "$engines" = "bullet mujoco ode " ] || fail "peers.csv has the engines '$engines', not 'bullet mujoco ode '"
  grep -q "\*\*Skipped: havok, jolt, rapier\*\*" "$work/report/RESULTS.md" \
    || fail "RESULTS.md does not say that havok, jolt and rapier were skipped"
fi

if [ $failures -eq 0 ]; then
  echo "without node: configures with no web-peer check; the lab reports ode, bullet, mujoco and names the skipped"
  rm -rf "$work"
fi
exit $((failures > 0))

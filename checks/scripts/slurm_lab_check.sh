#!/usr/bin/env bash
# The lab on a real single-node Slurm cluster (issue 16), started and stopped
# by slurm_single_node.sh (munged, slurmctld, slurmd on loopback):
#  1. a quick report of limit-test4 (a search), limit-test9 (a grid) and
#     energy-test2 (an output file) as srun steps inside an allocation gives
#     the same non-timing CSV columns as a local run;
#  2. SIGINT to the lab inside an allocation: status 130, nothing written, no
#     step and no program of it left;
#  3. the allocation cancelled under the lab (scancel): status 1, a message
#     naming the allocation, nothing written.
# Usage: slurm_lab_check.sh BUILD_TESTS_DIR WORK_DIR
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if [ "${1:-}" != --inside ]; then
  # slurmd starts every step as its user: it runs as root (CTest: skipped otherwise).
  [ "$(id -u)" -eq 0 ] || { echo "SKIPPED: slurmd needs root"; exit 77; }
  build=$(cd "$1" && pwd)
  for tool in munged slurmctld slurmd salloc; do
    command -v $tool >/dev/null || { echo "FAIL: no $tool: install Debian's munge slurmctld slurmd slurm-client (scripts/odelab.sh does)"; exit 1; }
  done
  mkdir -p "$2"
  exec "$here/slurm_single_node.sh" "$2/slurm" "$0" --inside "$build" "$(cd "$2" && pwd)"
fi
build=$2
work=$3
lab=$here/../../lab/odelab-report
fail() { echo "FAIL: $*"; exit 1; }
experiments=limit-test4,limit-test9,energy-test2
rm -rf "$work/local" "$work/srun" "$work/interrupted" "$work/cancelled"

"$lab" --quick --only $experiments --build-dir "$build" --out "$work/local" >"$work/local.log" 2>&1 \
  || fail "local report failed: $(tail -n 5 "$work/local.log")"
salloc -N1 -n1 -c2 "$lab" --quick --only $experiments --build-dir "$build" --out "$work/srun" --executor srun \
  >"$work/srun.log" 2>&1 || fail "srun report failed: $(tail -n 5 "$work/srun.log")"
/usr/bin/python3 "$here/compare_reports.py" "$work/local" "$work/srun" || fail "srun and local reports differ"

# The lab in the background of a shell inside an allocation, then SIGINT or scancel.
# (set -m: the lab must not start with SIGINT ignored, as `&` in a script would.)
interrupt_inside() {  # $1: interrupted (SIGINT) or cancelled (scancel)
  salloc -N1 -n1 -c2 bash -c '
    set -m
    "$0" --quick --only limit-test4 --build-dir "$1" --out "$2" --executor srun >"$2.log" 2>&1 &
    lab=$!
    for _ in $(seq 200); do pgrep -f "$1/test4" >/dev/null && break; sleep 0.05; done
    sleep 1
    if [ "$3" = interrupted ]; then kill -INT $lab; else scancel "$SLURM_JOB_ID"; fi
    status=0; wait $lab || status=$?
    echo $status >"$2.status"
    # A step ended by SIGTERM is "completing" for a moment after srun returns.
    for _ in $(seq 50); do
      squeue -h -s -j "$SLURM_JOB_ID" 2>/dev/null | grep -q odelab || break
      sleep 0.2
    done
    squeue -h -s -j "$SLURM_JOB_ID" >"$2.steps" 2>/dev/null || true
  ' "$lab" "$build" "$work/$1" "$1" >"$work/$1.salloc.log" 2>&1 || true
}

interrupt_inside interrupted
[ "$(cat "$work/interrupted.status")" = 130 ] || fail "SIGINT: status $(cat "$work/interrupted.status"), not 130"
[ ! -e "$work/interrupted" ] || fail "SIGINT: a report was written"
grep -q "interrupted; the outstanding runs" "$work/interrupted.log" || fail "SIGINT: no message"
! grep -q "test4\|odelab" "$work/interrupted.steps" || fail "SIGINT: steps left: $(cat "$work/interrupted.steps")"
sleep 0.5
! pgrep -f "$build/test4" >/dev/null || fail "SIGINT: test4 still running"
echo "SIGINT inside an allocation: status 130, no step left (within 10 s)"

interrupt_inside cancelled
[ "$(cat "$work/cancelled.status")" = 1 ] || fail "scancel: status $(cat "$work/cancelled.status"), not 1"
[ ! -e "$work/cancelled" ] || fail "scancel: a report was written"
grep -q "Slurm allocation [0-9]*.*cancelled" "$work/cancelled.log" || fail "scancel: no message naming the allocation"
! grep -q "Traceback" "$work/cancelled.log" || fail "scancel: a traceback"
# The failed report keeps its runs for a post-mortem; this one needs none.
kept=$(sed -n 's/.*the runs are kept in \(\/tmp\/odelab-report-runs-[A-Za-z0-9_]*\)$/\1/p' "$work/cancelled.log")
[ -z "$kept" ] || rm -rf "$kept"
echo "allocation cancelled: status 1, $(grep -m1 "srun could not run" "$work/cancelled.log")"
echo PASS

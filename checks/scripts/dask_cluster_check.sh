#!/usr/bin/env bash
# The lab on a real Dask cluster on loopback (issue 16): a scheduler and two
# workers on 127.0.0.1, started here and stopped by their process ids (a
# trap, so a failure stops them too).
#  1. A local quick report of limit-test4 (a search: one run at a time),
#     limit-test9 (a grid: all at once, results from stdout) and energy-test2
#     (an output file), and the same through Dask while one worker process is
#     killed: the report must succeed (the scheduler reschedules the lost
#     run) and every non-timing CSV column must equal the local run's.
#  2. SIGINT to the lab during a Dask report: status 130, the previous report
#     untouched, no staging folder left, and no program of it still running.
#  3. The scheduler killed during a report: status 1, a message naming it,
#     the previous report untouched.
# Usage: dask_cluster_check.sh BUILD_TESTS_DIR WORK_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
work=$2
here=$(cd "$(dirname "$0")" && pwd)
lab=$here/../../lab/odelab-report
py=/usr/bin/python3
rm -rf "$work" && mkdir -p "$work"

source "$here/daemons.sh"
trap stop_daemons EXIT
fail() { echo "FAIL: $*"; exit 1; }

command -v dask >/dev/null || fail "no dask command: install Debian's python3-distributed (scripts/odelab.sh does)"
port=$(free_port)
address=tcp://127.0.0.1:$port
dask scheduler --host 127.0.0.1 --port "$port" --no-dashboard >"$work/scheduler.log" 2>&1 &
daemon_pids+=($!)
for i in 1 2; do
  dask worker "$address" --host 127.0.0.1 --nthreads 1 --no-dashboard \
    --local-directory "$work/worker$i" >"$work/worker$i.log" 2>&1 &
  daemon_pids+=($!)
done
$py -c "import distributed, sys
c = distributed.Client('$address', timeout=30); c.wait_for_workers(2, timeout=60); c.close()" \
  || fail "the Dask cluster at $address did not start (logs in $work)"
echo "Dask scheduler $address, nannies ${daemon_pids[*]:1}"

experiments=limit-test4,limit-test9,energy-test2
"$lab" --quick --only $experiments --build-dir "$build" --out "$work/local" >"$work/local.log" 2>&1 \
  || fail "local report failed: $(tail -n 5 "$work/local.log")"

"$lab" --quick --only $experiments --build-dir "$build" --out "$work/dask" --executor "dask:$address" \
  >"$work/dask.log" 2>&1 &
lab_pid=$!
# Kill worker 1's worker process (its nanny starts a new one) while a run is on it.
victim=
for _ in $(seq 100); do
  victim=$(pgrep -P "${daemon_pids[1]}" -f spawn_main || true)
  [ -n "$victim" ] && pgrep -P "$victim" -f "$build/test" >/dev/null && break
  sleep 0.1
done
[ -n "$victim" ] && kill -9 $victim && echo "killed worker process $victim during a run"
wait $lab_pid || fail "Dask report failed: $(tail -n 5 "$work/dask.log")"
grep -q "Remove worker" "$work/scheduler.log" || fail "no worker was lost; the retry was not exercised"
grep -q "hosts.*every timed run\|hosts.*no timed runs" "$work/dask/RESULTS.md" || fail "RESULTS.md names no hosts"
$py "$here/compare_reports.py" "$work/local" "$work/dask" || fail "Dask and local reports differ"

# 2. Interrupt: the previous report (work/dask) must stay as it was. Job
# control on: the lab must not start with SIGINT ignored, as `&` in a script would.
set -m
before=$(cd "$work/dask" && find . -type f -exec md5sum {} + | sort)
"$lab" --quick --only limit-test4 --build-dir "$build" --out "$work/dask" --executor "dask:$address" \
  >"$work/interrupt.log" 2>&1 &
lab_pid=$!
for _ in $(seq 200); do pgrep -f "$build/test4" >/dev/null && break; sleep 0.05; done
sleep 1
kill -INT $lab_pid
status=0; wait $lab_pid || status=$?
[ $status -eq 130 ] || fail "interrupted report: status $status, not 130: $(tail -n 5 "$work/interrupt.log")"
! grep -q "Traceback\|FATAL" "$work/interrupt.log" || fail "interrupted report printed a traceback"
[ "$before" = "$(cd "$work/dask" && find . -type f -exec md5sum {} + | sort)" ] || fail "previous report changed"
! ls -a "$work" | grep -q '^\.dask\.' || fail "a staging folder was left in $work"
sleep 0.5
! pgrep -f "$build/test4" >/dev/null || fail "test4 still runs on a worker after the interrupt"
echo "interrupt: status 130, previous report unchanged, no run left on the workers"

# 3. The scheduler lost in the middle of a report: status 1, a message naming
# it, the previous report untouched. (Last: the cluster is gone after it.)
"$lab" --quick --only limit-test4 --build-dir "$build" --out "$work/dask" --executor "dask:$address" \
  >"$work/lost.log" 2>&1 &
lab_pid=$!
for _ in $(seq 200); do pgrep -f "$build/test4" >/dev/null && break; sleep 0.05; done
kill -9 "${daemon_pids[0]}"
status=0; wait $lab_pid || status=$?
[ $status -eq 1 ] || fail "lost scheduler: status $status, not 1: $(tail -n 5 "$work/lost.log")"
grep -q "lost the Dask scheduler at $address" "$work/lost.log" || fail "lost scheduler: no message naming it"
! grep -q "Traceback" "$work/lost.log" || fail "lost scheduler: a traceback"
[ "$before" = "$(cd "$work/dask" && find . -type f -exec md5sum {} + | sort)" ] || fail "previous report changed"
# The failed report keeps its runs for a post-mortem; this one needs none.
kept=$(sed -n 's/.*the runs are kept in \(\/tmp\/odelab-report-runs-[A-Za-z0-9_]*\)$/\1/p' "$work/lost.log")
[ -z "$kept" ] || rm -rf "$kept"
echo "scheduler lost: status 1, $(grep -m1 "lost the Dask scheduler" "$work/lost.log" | cut -c1-100)..."
echo "PASS"

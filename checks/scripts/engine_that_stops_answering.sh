#!/bin/sh
# engine_that_stops_answering.sh TEST2
#
# An engine that stops answering never holds the program (doc/hardening.md,
# "Fourth round"; doc/engine-protocol.md, "Deadlines"):
#   - test2 --engine jolt whose Node.js child is stopped (SIGSTOP) mid-run
#     ends by itself once the step's deadline (about 10 s) has passed: status
#     7, Test2_output.txt's last line "# incomplete: ... engine jolt failed:
#     ... no answer within ...", the child ended and gone;
#   - the same with SIGTERM sent to the program while it waits: it ends
#     within 3 s with status 143 and "stopped by SIGTERM", the child gone;
#   - an engine that never answers its build (a child that only sleeps),
#     SIGTERM after 2 s: status 143 within 3 s, the child gone, no output
#     file written.
program=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_engine_hang.XXXXXX") || exit 2
pids=
trap 'for p in $pids; do kill -CONT "$p" 2>/dev/null; kill -KILL "$p" 2>/dev/null; done; rm -rf "$root"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok:   $*"; }

# child_of PID: the program's engine child (its one child process)
child_of() { pgrep -P "$1" | head -n 1; }
# ends_within PID SECONDS: waits for PID to end; false when it is still there
ends_within() {
  n=0
  while kill -0 "$1" 2>/dev/null; do
    # A zombie has ended: its parent (this shell) reaps it in wait.
    [ "$(ps -o stat= -p "$1" 2>/dev/null | cut -c1)" = Z ] && return 0
    [ "$n" -ge $(($2 * 10)) ] && return 1
    sleep 0.1
    n=$((n + 1))
  done
}
wait_rows() {
  n=0
  while [ "$(cat Test2_output.txt 2>/dev/null | wc -l)" -lt 50 ]; do
    [ "$n" -ge 1200 ] && return 1
    sleep 0.1
    n=$((n + 1))
  done
}
gone() {
  if [ -n "$2" ] && kill -0 "$2" 2>/dev/null; then
    fail "$1: the engine's child $2 is still there ($(ps -o stat=,args= -p "$2"))"
    kill -CONT "$2"; kill -KILL "$2"
  else
    ok "$1: the engine's child has ended"
  fi
}

# 1. The child stopped mid-run: the step's deadline ends it.
mkdir "$root/deadline" && cd "$root/deadline" || exit 2
"$program" --headless --seconds 100000 --engine jolt --metrics-json m.json >/dev/null 2>err.txt &
pid=$!
pids=$pid
wait_rows || fail "deadline: no 50 lines within 120 s: $(cat err.txt)"
child=$(child_of "$pid")
pids="$pid $child"
kill -STOP "$child"
if ends_within "$pid" 40; then
  wait "$pid"
  status=$?
  [ "$status" = 7 ] && ok "deadline: status 7" || fail "deadline: status $status, expected 7 (the engine failed)"
  last=$(tail -n 1 Test2_output.txt)
  case $last in
    "# incomplete: "*"engine jolt failed"*"no answer within"*) ok "deadline: last line '$last'" ;;
    *) fail "deadline: last line '$last', expected '# incomplete: ... engine jolt failed: ... no answer within ...'" ;;
  esac
else
  fail "deadline: still waiting for the stopped engine 40 s later"
  kill -KILL "$pid" 2>/dev/null
fi
gone deadline "$child"

# 2. The child stopped, then SIGTERM: acted on while waiting.
mkdir "$root/sigterm" && cd "$root/sigterm" || exit 2
"$program" --headless --seconds 100000 --engine jolt --metrics-json m.json >/dev/null 2>err.txt &
pid=$!
pids=$pid
wait_rows || fail "SIGTERM: no 50 lines within 120 s: $(cat err.txt)"
child=$(child_of "$pid")
pids="$pid $child"
kill -STOP "$child"
sleep 1
kill -TERM "$pid"
if ends_within "$pid" 3; then
  wait "$pid"
  status=$?
  [ "$status" = 143 ] && ok "SIGTERM: status 143" || fail "SIGTERM: status $status, expected 143"
  tail -n 1 Test2_output.txt | grep -q '^# incomplete: .*stopped by SIGTERM' && ok "SIGTERM: marked" ||
    fail "SIGTERM: last line '$(tail -n 1 Test2_output.txt)'"
  [ -e m.json ] && fail "SIGTERM: a metrics JSON was written"
else
  fail "SIGTERM: still running 3 s after SIGTERM while the engine was stopped"
  kill -KILL "$pid" 2>/dev/null
fi
gone SIGTERM "$child"

# 3. An engine that never answers its build.
mkdir "$root/build" && cd "$root/build" || exit 2
printf '#!/bin/sh\nexec sleep 1000\n' > silent-node && chmod +x silent-node
ODELAB_NODE=$PWD/silent-node "$program" --headless --seconds 1 --engine jolt >/dev/null 2>err.txt &
pid=$!
pids=$pid
sleep 2
child=$(child_of "$pid")
pids="$pid $child"
kill -TERM "$pid"
if ends_within "$pid" 3; then
  wait "$pid"
  status=$?
  [ "$status" = 143 ] && ok "build: status 143" || fail "build: status $status, expected 143: $(cat err.txt)"
else
  fail "build: still waiting for the build's answer 3 s after SIGTERM"
  kill -KILL "$pid" 2>/dev/null
fi
gone build "$child"
[ -e Test2_output.txt ] && fail "build: Test2_output.txt written by a run that never started"
pids=
[ "$failures" = 0 ]

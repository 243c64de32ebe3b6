#!/usr/bin/env bash
# The lab's inputs and every way it can end (doc/hardening.md, third round):
#  - a CMakeCache.txt beside --build-dir that is a FIFO, a 3 GB sparse file,
#    a binary or a text file naming no compiler: status 2 at once, a message
#    naming the file and what is wrong, no traceback, nothing left behind;
#  - a program that hangs while the run header is collected, then SIGTERM:
#    status 130 within 10 s and the program ended;
#  - SIGHUP to the lab (in a session of its own) while its runs go on:
#    status 130, no staging folder, no runs' folder, no run left going;
#  - standard error closed early: the report is still written (status 0);
#  - a run that leaves a FIFO as its metrics, or 3 GB of standard output:
#    status 1 naming the file, no traceback, no hang;
#  - a run that ends with status 0 and metrics saying it took no step:
#    status 1, not a result.
# The "programs" are a wrapper around test2 (FAKE_MODE picks what it does).
# Usage: lab_inputs_and_endings_check.sh BUILD_TESTS_DIR WORK_DIR [LAB_LAUNCHER]
set -uo pipefail
build=$(cd "$1" && pwd)
work=$2
here=$(cd "$(dirname "$0")" && pwd)
lab=${3:-$here/../../lab/odelab-report}
rm -rf "$work" && mkdir -p "$work/fake/tests" "$work/tmp"
work=$(cd "$work" && pwd)
export TMPDIR=$work/tmp FAKE_PIDS=$work/pids
failures=0
pid=
# Whatever stops this check (a failure, CTest's timeout), no lab and no fake
# program outlives it.
trap 'for p in ${pid:-} $(cat "$FAKE_PIDS" 2>/dev/null); do kill -KILL "$p" 2>/dev/null; done' EXIT
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok:   $*"; }
no_trace() { ! grep -q "Traceback\|FATAL" "$1" || fail "$2: a traceback: $(grep -m1 "Traceback\|FATAL" "$1")"; }
# Running, and not a zombie waiting for its parent.
alive() { local state; state=$(ps -o stat= -p "$1" 2>/dev/null); [ -n "$state" ] && [ "${state#Z}" = "$state" ]; }
# No staging folder beside --out, no runs' folder, no run still going.
nothing_left() {
  local left
  left=$(cd "$work" && ls -A | grep "^\.$1\.\(new\|old\)-" || true)
  [ -z "$left" ] || fail "$2: left $left beside --out"
  [ ! -e "$work/$1" ] || fail "$2: wrote $work/$1"
  left=$(ls -A "$work/tmp")
  [ -z "$left" ] || fail "$2: left $left in TMPDIR"
  rm -rf "${work:?}/tmp/"*
  if [ -s "$FAKE_PIDS" ]; then
    for p in $(cat "$FAKE_PIDS"); do
      if alive "$p"; then fail "$2: its program $p still runs"; kill -KILL "$p"; fi
    done
  fi
  : >"$FAKE_PIDS"
}
# Waits (at most $1 s) for the fake program to have started once.
wait_started() {
  local n=0
  while [ ! -s "$FAKE_PIDS" ]; do
    [ $n -ge $(($1 * 10)) ] && return 1
    sleep 0.1
    n=$((n + 1))
  done
}

cat >"$work/fake/tests/test2" <<EOF
#!/bin/sh
# The lab's runs carry --metrics-json; the header's run of test2 does not.
case " \$* " in *" --metrics-json "*) run=yes ;; *) run=no ;; esac
case "\${FAKE_MODE:-}:\$run" in
  hang-header:no | hang-runs:yes) echo \$\$ >>"\$FAKE_PIDS"; exec sleep 300 ;;
  fifo-metrics:yes) mkfifo metrics.json; exit 0 ;;
  huge-stdout:yes) truncate -s 3G /proc/self/fd/1; exit 0 ;;
  no-step:yes) echo '{"steps": 0, "sim_seconds": 0, "non_finite": 0}' >metrics.json; exit 0 ;;
esac
exec "$build/test2" "\$@"
EOF
chmod +x "$work/fake/tests/test2"
: >"$FAKE_PIDS"
lab_args=(--quick --only speed-test2 --jobs 1 --build-dir "$work/fake/tests")
cache=$work/fake/CMakeCache.txt

# ---- the build's CMake cache --------------------------------------------------
try_cache() {  # NAME NEEDLE: runs the lab on the cache as it is now
  (ulimit -v 2500000; timeout -k 5 60 "$lab" "${lab_args[@]}" --out "$work/$1" >"$work/$1.log" 2>&1)
  local status=$?
  if [ $status -eq 2 ] && grep -q "CMakeCache.txt.*$2" "$work/$1.log"; then
    ok "$1: status 2: $(grep -m1 error "$work/$1.log")"
  else
    fail "$1: status $status (124: a hang), message: $(grep -m1 . "$work/$1.log")"
  fi
  no_trace "$work/$1.log" "$1"
  nothing_left "$1" "$1"
}
mkfifo "$cache"
try_cache fifo-cache "is a FIFO"
rm -f "$cache" && truncate -s 3G "$cache"
try_cache huge-cache "3221225472 bytes"
rm -f "$cache" && head -c 4096 /bin/sh >"$cache"
try_cache binary-cache "not a text file"
echo "CMAKE_BUILD_TYPE:STRING=Release" >"$cache"
try_cache cache-without-compiler "no C++ compiler"
cp "$build/../CMakeCache.txt" "$cache"

# ---- signals while the lab waits on a program ------------------------------------
# SIGTERM while the run header's test2 hangs (the lab waited for it 60 s).
FAKE_MODE=hang-header setsid "$lab" "${lab_args[@]}" --out "$work/term" >"$work/term.log" 2>&1 &
pid=$!
if wait_started 60; then
  kill -TERM "$pid"
  start=$(date +%s)
  n=0
  while alive "$pid" && [ $n -lt 100 ]; do sleep 0.1; n=$((n + 1)); done
  if alive "$pid"; then fail "SIGTERM during the header: still running after 10 s"; kill -KILL "$pid"; fi
  wait "$pid"; status=$?; pid=
  [ $status -eq 130 ] && ok "SIGTERM during the header: status 130 after $(($(date +%s) - start)) s" \
    || fail "SIGTERM during the header: status $status"
else
  fail "the header's test2 never started"; kill -KILL "$pid"
fi
no_trace "$work/term.log" "SIGTERM during the header"
nothing_left term "SIGTERM during the header"

# SIGHUP while the runs go on: the lab alone gets it (its own session), as
# when the terminal it was started from goes away under setsid or nohup-less ssh.
FAKE_MODE=hang-runs setsid "$lab" "${lab_args[@]}" --out "$work/hup" >"$work/hup.log" 2>&1 &
pid=$!
if wait_started 120; then
  staging=$(cd "$work" && ls -A | grep '^\.hup\.new-' || true)
  [ -n "$staging" ] || fail "SIGHUP: no staging folder while the runs went on (the check itself is wrong)"
  kill -HUP "$pid"
  n=0
  while alive "$pid" && [ $n -lt 150 ]; do sleep 0.1; n=$((n + 1)); done
  if alive "$pid"; then fail "SIGHUP during the runs: still running after 15 s"; kill -KILL "$pid"; fi
  wait "$pid"; status=$?; pid=
  [ $status -eq 130 ] && ok "SIGHUP during the runs: status 130" || fail "SIGHUP during the runs: status $status"
else
  fail "no run started within 120 s: $(tail -n 3 "$work/hup.log")"; kill -KILL "$pid"
fi
no_trace "$work/hup.log" "SIGHUP during the runs"
nothing_left hup "SIGHUP during the runs"

# Standard error closed after the first line (a pipe to head, a terminal that
# went away): the messages are lost, the report is not.
"$lab" "${lab_args[@]}" --out "$work/closed-stderr" 2>&1 | head -n 1 >/dev/null
status=${PIPESTATUS[0]}
if [ "$status" -eq 0 ] && [ -f "$work/closed-stderr/RESULTS.md" ]; then
  ok "standard error closed: status 0, the report written"
else
  fail "standard error closed: status $status (the report failed on its progress lines)"
fi
rm -rf "${work:?}/closed-stderr"
nothing_left closed-stderr "standard error closed"

# ---- what a run leaves ------------------------------------------------------------
try_run() {  # MODE NEEDLE
  (ulimit -v 2500000; FAKE_MODE=$1 timeout -k 5 120 "$lab" "${lab_args[@]}" --out "$work/$1" >"$work/$1.log" 2>&1)
  local status=$?
  if [ $status -eq 1 ] && grep -q "$2" "$work/$1.log"; then
    ok "$1: status 1: $(grep -m1 "$2" "$work/$1.log")"
  else
    fail "$1: status $status (124: a hang), message: $(grep -m1 "error\|FAIL" "$work/$1.log")"
  fi
  no_trace "$work/$1.log" "$1"
  # A failed report keeps its runs (and names them); remove them here.
  rm -rf "${work:?}/tmp/"*
  nothing_left "$1" "$1"
}
try_run fifo-metrics "metrics.json is a FIFO"
try_run huge-stdout "stdout.txt is 3221225472 bytes"
try_run no-step "ended with status 0 but took no step"

[ $failures -eq 0 ] && echo PASS || { echo "$failures failures"; exit 1; }

#!/usr/bin/env bash
# The lab trusts no run blindly (doc/lab.md, "Safety"; doc/hardening.md):
#  - energy-test2's run blows up (status 3) with plausible energies, writes a
#    NaN metric, or a NaN in Test2_output.txt: status 1, a message naming the
#    run and what was wrong, no traceback, no "holds", nothing written;
#  - --executor dask:127.0.0.1:99999 (no such port) and srun in an allocation
#    of zero CPUs: status 2 at once (within 10 s; Python starts in about 3), naming the reason, no run;
#  - SIGTERM while a run is a wrapper that does not exec (its child keeps
#    going under it): status 130 and the child ended too.
# The "program" is a wrapper around test2 (FAKE_MODE picks what it does).
# Usage: lab_trusts_check.sh BUILD_TESTS_DIR WORK_DIR [LAB_LAUNCHER]
set -uo pipefail
build=$(cd "$1" && pwd)
work=$2
here=$(cd "$(dirname "$0")" && pwd)
lab=${3:-$here/../../lab/odelab-report}
rm -rf "$work" && mkdir -p "$work/fake/tests" "$work/tmp"
work=$(cd "$work" && pwd)
export TMPDIR=$work/tmp FAKE_CHILD=$work/child.pid
failures=0
pid=
# Whatever stops this check, no lab and no fake program outlives it.
trap 'for p in ${pid:-} $(cat "$FAKE_CHILD" 2>/dev/null); do kill -KILL "$p" 2>/dev/null; done' EXIT
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok:   $*"; }
alive() { local state; state=$(ps -o stat= -p "$1" 2>/dev/null); [ -n "$state" ] && [ "${state#Z}" = "$state" ]; }

cat >"$work/fake/tests/test2" <<EOF
#!/bin/sh
# The lab's runs carry --metrics-json; the run header's test2 does not.
case " \$* " in *" --metrics-json "*) run=yes ;; *) run=no ;; esac
[ \$run = yes ] || exec "$build/test2" "\$@"
case "\${FAKE_MODE:-}" in
  blow-up) "$build/test2" "\$@"; exit 3 ;;  # the energies stay flat: only the status says it blew up
  nan-metric) "$build/test2" "\$@" || exit; sed -i 's/"energy_max_J": [^,]*/"energy_max_J": NaN/' metrics.json ;;
  # the total energy at t = 10 s becomes NaN: a data row, not a comment
  nan-output) "$build/test2" "\$@" || exit; sed -i 's/^\(10\t.*\t\)[^\t]*\$/\1nan/' Test2_output.txt ;;
  wrapper) sleep 300 & echo \$! >"\$FAKE_CHILD"; wait ;;  # no exec: the child is the lab's grandchild
  *) exec "$build/test2" "\$@" ;;
esac
EOF
chmod +x "$work/fake/tests/test2"
cp "$build/../CMakeCache.txt" "$work/fake/CMakeCache.txt"
lab_args=(--quick --only energy-test2 --jobs 1 --build-dir "$work/fake/tests")

# ---- a run that cannot give a figure ------------------------------------------------
untrusted() {  # MODE NEEDLE
  FAKE_MODE=$1 timeout -k 5 120 "$lab" "${lab_args[@]}" --out "$work/$1" >"$work/$1.log" 2>&1
  local status=$?
  if [ $status -eq 1 ] && grep -q "test2 --erp 0.4 .*$2" "$work/$1.log"; then
    ok "$1: status 1: $(grep -m1 -o "$2.*" "$work/$1.log" | cut -c1-110)"
  else
    fail "$1: status $status, message: $(grep -m1 -A1 "failed\|error" "$work/$1.log")"
  fi
  ! grep -q "Traceback" "$work/$1.log" || fail "$1: a traceback: $(grep -m1 "Traceback" "$work/$1.log")"
  [ ! -e "$work/$1" ] || fail "$1: wrote $work/$1 ($(grep -o "the energy holds" -m1 "$work/$1/RESULTS.md"))"
  rm -rf "${work:?}/tmp/"*  # a failed report keeps its runs
}
untrusted blow-up "blew up (status 3: a non-finite state); this experiment does not measure blow-ups"
untrusted nan-metric "its metrics are not finite: energy_max_J = nan"
untrusted nan-output "Test2_output.txt line [0-9]* holds a non-finite number"

# The control: the same wrapper passing test2 through writes the report.
timeout -k 5 120 "$lab" "${lab_args[@]}" --out "$work/plain" >"$work/plain.log" 2>&1
status=$?
[ $status -eq 0 ] && grep -q "the energy holds" "$work/plain/RESULTS.md" \
  && ok "the same run unchanged: status 0, the rule holds" \
  || fail "the same run unchanged: status $status: $(tail -n 2 "$work/plain.log")"

# ---- executor values that can only fail or hang ----------------------------------------
refused() {  # NAME NEEDLE ENV... -- LAB ARGS...
  local name=$1 needle=$2 start status
  shift 2
  start=$(date +%s%N)
  env "$@" >"$work/$name.log" 2>&1
  status=$?
  local took_ms=$((($(date +%s%N) - start) / 1000000))
  if [ $status -eq 2 ] && grep -q "$needle" "$work/$name.log" && [ $took_ms -lt 10000 ]; then
    ok "$name: status 2 in $took_ms ms: $(grep -m1 error "$work/$name.log" | cut -c1-120)"
  else
    fail "$name: status $status after $took_ms ms (2 at once wanted): $(grep -m1 . "$work/$name.log")"
  fi
  [ -z "$(ls -A "$work/tmp")" ] || fail "$name: left $(ls -A "$work/tmp") in TMPDIR"
  [ ! -e "$work/$name" ] || fail "$name: wrote $work/$name"
}
refused dask-port "the port of '127.0.0.1:99999' is 99999" \
  timeout -k 5 60 "$lab" "${lab_args[@]}" --out "$work/dask-port" --executor dask:127.0.0.1:99999
refused srun-no-cpu "the Slurm allocation offers no CPU" SLURM_JOB_ID=1 SLURM_JOB_CPUS_PER_NODE=0 \
  SLURM_JOB_NODELIST=localhost timeout -k 5 60 "$lab" "${lab_args[@]}" --out "$work/srun-no-cpu" --executor srun

# ---- SIGTERM reaches what a run started -------------------------------------------------
: >"$FAKE_CHILD"
FAKE_MODE=wrapper setsid "$lab" "${lab_args[@]}" --out "$work/term" >"$work/term.log" 2>&1 &
pid=$!
n=0
while [ ! -s "$FAKE_CHILD" ] && [ $n -lt 600 ]; do sleep 0.1; n=$((n + 1)); done
if [ -s "$FAKE_CHILD" ]; then
  child=$(cat "$FAKE_CHILD")
  kill -TERM "$pid"
  n=0
  while alive "$pid" && [ $n -lt 150 ]; do sleep 0.1; n=$((n + 1)); done
  if alive "$pid"; then fail "SIGTERM: the lab still runs after 15 s"; kill -KILL "$pid"; fi
  wait "$pid"; status=$?; pid=
  n=0
  while alive "$child" && [ $n -lt 50 ]; do sleep 0.1; n=$((n + 1)); done
  if alive "$child"; then
    fail "SIGTERM: status $status, and the wrapper's child $child still runs"; kill -KILL "$child"
  elif [ $status -eq 130 ]; then
    ok "SIGTERM: status 130, the wrapper's child ended with it"
  else
    fail "SIGTERM: status $status, not 130"
  fi
else
  fail "the wrapper never started: $(tail -n 3 "$work/term.log")"; kill -KILL "$pid"; pid=
fi
[ -z "$(ls -A "$work/tmp")" ] || fail "SIGTERM: left $(ls -A "$work/tmp") in TMPDIR"

[ $failures -eq 0 ] && echo PASS || { echo "$failures failures"; exit 1; }

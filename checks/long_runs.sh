#!/bin/sh
# Long runs (issue 7), too long for CI: resident memory stays flat after
# warm-up and object counts stay bounded.
#
#   sh checks/long_runs.sh [test0|test5]...     (default: both)
#
#   test0  an object spawned every 0.1 s for 30 simulated minutes
#          (--spawn-interval 0.1 --seconds 1800): 18000 objects; the 30 s
#          lifetime and the boundary (|x|, |z| > 50, y < -20) must keep at
#          most 301 alive (300 younger than 30 s, plus one spawned the same
#          step), and spawned = removed + alive.
#   test5  300 plates, one every 0.3 s (--plates 300 --spawn-interval 0.3
#          --seconds 240): the stack grows for 90 s, then 150 s more pass;
#          all 300 plates exist (test5 removes none) and the state stays
#          finite. Whether the column still stands is physics, not checked
#          here: it is printed.
#
# While a run goes, its VmRSS (/proc/PID/status) is sampled every second.
# Warm-up is the first quarter of test0's run (its population is steady
# after the first 30 of 1800 simulated seconds) and the first half of
# test5's (the stack, and with it the memory, grows until 90 s, about a
# quarter of the wall time, since each step costs more as plates are
# added). Memory is flat when the highest sample after warm-up exceeds the
# sample at the end of warm-up by less than 2 MiB or 2 %, whichever is larger. Figures go to standard
# output; the samples and metrics to $BUILD_DIR/long_runs/. Status 0 when
# every check held. Uses the Release build in $BUILD_DIR (default: build/).
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
out=$build/long_runs
mkdir -p "$out"
failures=0

metric() {  # metric FILE NAME: a value from a metrics JSON
  sed -n "s/^ *\"$2\": *\([^,]*\),*$/\1/p" "$1"
}

# long_run NAME PROGRAM WARMUP ARGS...: runs build/tests/PROGRAM ARGS headless,
# sampling RSS; WARMUP is the fraction of the samples that is warm-up.
long_run() {
  name=$1 program=$2 warmup=$3
  shift 3
  exe=$build/tests/$program
  [ -x "$exe" ] || { echo "$name: $exe not built"; failures=$((failures + 1)); return; }
  samples=$out/$name.rss
  : >"$samples"
  echo "== $name: $program $*"
  t0=$(date +%s)
  "$exe" --headless --metrics-json "$out/$name.json" "$@" >"$out/$name.stdout" 2>"$out/$name.stderr" &
  pid=$!
  sleep 1  # past the program's start-up
  while kill -0 "$pid" 2>/dev/null; do
    rss=$(sed -n 's/^VmRSS:[[:space:]]*\([0-9]*\) kB/\1/p' "/proc/$pid/status" 2>/dev/null)
    [ -n "$rss" ] && echo "$(($(date +%s) - t0)) $rss" >>"$samples"
    sleep 1
  done
  wait "$pid"
  status=$?
  wall=$(($(date +%s) - t0))
  echo "   status $status after $wall s wall; $(wc -l <"$samples") RSS samples in $samples"
  [ "$status" = 0 ] || { echo "   FAIL: status $status"; sed 's/^/   stderr: /' "$out/$name.stderr" | tail -3; failures=$((failures + 1)); }
  # RSS: at the end of warm-up (first quarter), then min / max / last after it.
  awk -v warmup="$warmup" '
    { t[NR] = $1; r[NR] = $2 }
    END {
      if (NR < 4) { print "   FAIL: too few samples"; exit 1 }
      w = int(NR * warmup); if (w < 1) w = 1
      base = r[w]; lo = base; hi = base
      for (i = w; i <= NR; i++) { if (r[i] < lo) lo = r[i]; if (r[i] > hi) hi = r[i] }
      printf "   RSS (MiB): first %.2f; end of warm-up (t=%d s) %.2f; after warm-up min %.2f, max %.2f, last %.2f\n",
             r[1] / 1024, t[w], base / 1024, lo / 1024, hi / 1024, r[NR] / 1024
      printf "   RSS over the run (t s: MiB):"
      for (k = 0; k <= 8; k++) { i = 1 + int((NR - 1) * k / 8); printf " %d: %.2f;", t[i], r[i] / 1024 }
      printf "\n"
      allowed = base * 0.02; if (allowed < 2048) allowed = 2048
      growth = hi - base
      if (growth < allowed) printf "   ok:   memory flat after warm-up (growth %.2f MiB, allowed %.2f)\n", growth / 1024, allowed / 1024
      else { printf "   FAIL: memory grows after warm-up by %.2f MiB (allowed %.2f)\n", growth / 1024, allowed / 1024; exit 1 }
    }' "$samples" || failures=$((failures + 1))
}

check() {  # check DESCRIPTION CONDITION...
  text=$1
  shift
  if "$@"; then echo "   ok:   $text"; else echo "   FAIL: $text"; failures=$((failures + 1)); fi
}

run_test0() {
  long_run test0_30_minutes test0 0.25 --spawn-interval 0.1 --seconds 1800
  j=$out/test0_30_minutes.json
  [ -s "$j" ] || { echo "   FAIL: no metrics"; failures=$((failures + 1)); return; }
  spawned=$(metric "$j" spawned) removed=$(metric "$j" removed_bodies) bodies=$(metric "$j" bodies)
  most=$(metric "$j" max_bodies)
  echo "   sim $(metric "$j" sim_seconds) s in $(metric "$j" wall_seconds) s; spawned $spawned, removed $removed, alive at the end $bodies (disabled $(metric "$j" disabled_bodies)); most alive at once: $most"
  check "18000 objects spawned" [ "$spawned" = 18000 ]
  check "at most 301 alive at the end" [ "$bodies" -le 301 ]
  check "at most 301 alive at any time" [ "$most" -le 301 ]
  check "spawned = removed + alive" [ "$spawned" = "$((removed + bodies))" ]
  check "state finite" [ "$(metric "$j" non_finite)" = 0 ]
}

run_test5() {
  long_run test5_300_plates test5 0.5 --plates 300 --spawn-interval 0.3 --seconds 240
  j=$out/test5_300_plates.json
  [ -s "$j" ] || { echo "   FAIL: no metrics"; failures=$((failures + 1)); return; }
  echo "   sim $(metric "$j" sim_seconds) s in $(metric "$j" wall_seconds) s; plates $(metric "$j" plates), landed $(metric "$j" landed_plates), bodies $(metric "$j" bodies), stack height $(metric "$j" stack_height) m, contacts $(metric "$j" contacts), $(metric "$j" ms_per_step) ms per step; farthest plate $(metric "$j" max_axis_offset) m off the axis, most twisted $(metric "$j" max_twist_degrees) degrees"
  check "300 plates, all of them bodies" [ "$(metric "$j" plates)" = 300 -a "$(metric "$j" bodies)" = 300 ]
  check "state finite" [ "$(metric "$j" non_finite)" = 0 ]
}

[ $# -gt 0 ] || set -- test0 test5
for which; do
  case $which in
    test0) run_test0 ;;
    test5) run_test5 ;;
    *) echo "usage: sh checks/long_runs.sh [test0|test5]..."; exit 2 ;;
  esac
done
echo "long runs: $failures failed"
[ "$failures" = 0 ]

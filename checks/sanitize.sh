#!/bin/sh
# Sanitizer check (issue 7): builds ODE Lab with AddressSanitizer and
# UndefinedBehaviorSanitizer (the CMake preset "sanitize": ODELAB_SANITIZE=ON,
# Debug, in build-sanitize/), then runs the unit tests and a short
# headless run of every test program under them, and two window runs under
# Xvfb (an ODE error's recovery, fuzzed input). Clean means: every run ends
# with status 0 and no sanitizer reports anything. Leaks are detected
# (detect_leaks=1); only those inside libode are suppressed (checks/lsan.supp:
# ODE's own allocations are left to ODE).
#
#   sh checks/sanitize.sh              configure, build, run; status 0 when clean
#
# Environment: JOBS (build jobs, default: number of cores). Each run's output
# is kept in build-sanitize/sanitize-logs/.
set -u
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-sanitize
logs=$build/sanitize-logs
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}

say() { printf 'sanitize: %s\n' "$*"; }
now() { date +%s; }

start=$(now)
cd "$root" || exit 2
cmake --preset sanitize >/dev/null || { say "error: configuring $build failed"; exit 1; }
# Everything (the programs, the unit tests and the small check tools): one
# make run builds them side by side, where naming targets would build them
# one after another.
cmake --build "$build" -j "$jobs" || { say "error: building in $build failed"; exit 1; }
built=$(now)
say "configured and built in $((built - start)) s"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$root/checks/lsan.supp:print_suppressions=0
rm -rf "$logs"
mkdir -p "$logs"
failures=0

# run NAME STATUS COMMAND...: the expected status and no sanitizer report, or a failure.
run() {
  name=$1 expected=$2
  shift 2
  t0=$(now)
  (cd "$logs" && "$@") >"$logs/$name.log" 2>&1
  status=$?
  reports=$(grep -c -E 'ERROR: (AddressSanitizer|LeakSanitizer)|runtime error:|SUMMARY: (Address|Undefined|Leak)' "$logs/$name.log")
  if [ "$status" = "$expected" ] && [ "$reports" = 0 ]; then
    printf 'ok      %-22s %3d s\n' "$name" "$(($(now) - t0))"
  else
    printf 'FAILED  %-22s %3d s  status %s, %s sanitizer report lines (%s)\n' "$name" "$(($(now) - t0))" \
      "$status" "$reports" "$logs/$name.log"
    grep -m 8 -E 'ERROR:|runtime error:|SUMMARY:|#[0-9] ' "$logs/$name.log" | sed 's/^/        /'
    failures=$((failures + 1))
  fi
}

run unit_tests 0 "$build/checks/odelab_unit_tests"
programs=$("$build/tests/odelab" --list | cut -f1)  # the registry: every program
# A short headless run of every program; where a scene ignores --seconds or
# needs something to happen first, a scene-appropriate run instead.
for p in $programs; do
  exe=$build/tests/$p
  [ -x "$exe" ] || continue
  case $p in
    test0) run "$p" 0 "$exe" --headless --seconds 32 --spawn-interval 0.5 ;;  # spawns, and removes at the 30 s lifetime
    test5) run "$p" 0 "$exe" --headless --seconds 3 --spawn-interval 0.1 ;;
    test7) run "$p" 0 "$exe" --headless --throws 2 --throw-interval 0.5 ;;
    test10) run "$p" 0 "$exe" --headless --launches 2 --random-orientation --phase-jitter ;;
    *) run "$p" 0 "$exe" --headless --seconds 1 ;;
  esac
done
# Three more paths: test10's continuous collision; an ODE error, which
# leaves through std::exit (status 4: dWorldStep with CFM 0 under a box
# with infinite friction fails ODE's own check in its first step); a
# refused option (status 2).
if [ -x "$build/tests/test10" ]; then
  run test10_ccd 0 "$build/tests/test10" --headless --launches 2 --velocity 2000 --ccd
fi
if [ -x "$build/tests/test6" ]; then
  run test6_ode_error 4 "$build/tests/test6" --headless --seconds 1 --solver step --cfm 0
  run test6_refused_option 2 "$build/tests/test6" --headless --step nan
fi
# Two window runs under Xvfb, where they can run: an ODE error in a window,
# which resets the scene and goes on (its script says how), and 3000
# fuzzed input events into test5. Leak detection is off for them:
# LeakSanitizer itself fails (signal 11 in its tracer) once Mesa's software
# renderer has started its threads.
if command -v xvfb-run >/dev/null 2>&1; then
  window() { ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 xvfb-run -a -s "-screen 0 1280x800x24" "$@"; }
  if [ -x "$build/tests/test4" ]; then
    run test4_window_ode_error 0 window "$build/tests/test4" --solver step --cfm 0 \
      --events "$root/checks/scripts/ode_error_recovery.events" --out-dir "$logs"
  fi
  if [ -x "$build/tests/test5" ] && [ -x "$build/checks/fuzz_events" ]; then
    "$build/checks/fuzz_events" --seed 7005 --events 3000 --out "$logs/fuzz.events" &&
      run test5_window_fuzz 0 window "$build/tests/test5" --events "$logs/fuzz.events" --out-dir "$logs" \
        --width 960 --height 600
  fi
else
  say "xvfb-run not found: the window runs are left out"
fi
end=$(now)
say "ran in $((end - built)) s; total $((end - start)) s; $failures failed"
[ "$failures" = 0 ]

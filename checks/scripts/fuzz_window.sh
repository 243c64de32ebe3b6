#!/bin/sh
# One window fuzz run (issue 7):
#
#   fuzz_window.sh XVFB_RUN FUZZ_EVENTS EXPECT_METRICS PROGRAM OUT_DIR SEED [EVENTS]
#
# Writes a random script of EVENTS (default 10000) input events from SEED
# (checks/fuzz_events.cpp), plays it into PROGRAM's window under Xvfb and
# checks that the program took it all: it reached the script's last mark
# (mark_fuzz_end_steps in its metrics) and exited with status 0 on the
# final Esc, within 300 s. ODELAB_FUZZ_SEED in the environment replaces
# SEED ("random" draws one). The seed and the command that replays the run
# are printed first, so a hang or crash can be replayed; a run that passes
# leaves nothing behind, a failing one keeps its script and output in OUT_DIR.
set -u
xvfb=$1 generator=$2 expect=$3 program=$4 out=$5 seed=${ODELAB_FUZZ_SEED:-$6} events=${7:-10000}
[ "$seed" = random ] && seed=$(od -An -N4 -tu4 /dev/urandom | tr -d ' ')
width=960 height=600
rm -rf "$out" && mkdir -p "$out" || exit 1
script="$out/fuzz_seed_$seed.events"
"$generator" --seed "$seed" --events "$events" --width "$width" --height "$height" --out "$script" || exit 1
echo "fuzz seed $seed: $events events into $(basename "$program")"
echo "replay: xvfb-run -a $program --events $script --width $width --height $height"
timeout -k 10 300 "$xvfb" -a -s "-screen 0 1280x800x24" "$expect" mark_fuzz_end_steps'>='0 -- \
  "$program" --events "$script" --out-dir "$out" --width "$width" --height "$height" >"$out/output.txt" 2>&1
status=$?
grep -E '^(window|mark fuzz_end)|mark_fuzz_end_steps|^error' "$out/output.txt" | head -20
count() { grep -c -E "$1" "$out/output.txt"; }
echo "seen: $(count '^t=[^:]*: scene reset') resets by R, $(count 'ODE error: .*scene reset') after an ODE error," \
  "$(count 'blew up.*scene reset') after a blow-up; $(count '^t=[^:]*: rewound') rewinds; $(count '^screenshot:') screenshots"
if [ "$status" -ne 0 ]; then
  tail -n 30 "$out/output.txt"
  case $status in
    124 | 137) why="no exit within 300 s" ;;
    *) why="the check failed (status $status; the lines above say why)" ;;
  esac
  echo "FAIL: fuzz seed $seed: $why; the script and output are in $out"
  echo "replay: ODELAB_FUZZ_SEED=$seed ctest -R fuzz_window_$(basename "$program")"
  exit 1
fi
rm -rf "$out"

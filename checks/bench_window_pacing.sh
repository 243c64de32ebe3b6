#!/bin/sh
# Benchmark, not a test: does a window keep real time, and does a paused
# window leave the processor alone? Under Xvfb with Mesa's software OpenGL:
#
# 1. Each program at its defaults runs FRAMES frames in a 1280x720 window
#    and prints its window metrics: window_fps, real_time_factor (simulated
#    seconds per wall second over the run; the goal is 0.9 or more),
#    longest_frame_ms and dropped_steps (steps the 50 ms stepping budget left
#    out: the physics could not keep up).
# 2. test0 runs in a window for SECONDS, then again paused (P), and prints
#    the share of one core the process used in each: the goal is under 10%
#    paused.
#
#   checks/bench_window_pacing.sh [--frames N] [--seconds S] [PROGRAM...]
#
# PROGRAM defaults to every program (odelab --list, in build/tests); N = 240, S = 5.
# Figures depend on the machine and its load: compare runs made side by side.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
bin=${BUILD_DIR:-$here/../build}/tests
frames=240
seconds=5
while [ $# -gt 0 ]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    -h | --help) sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "bench_window_pacing: unknown option $1" >&2; exit 2 ;;
    *) break ;;
  esac
done
programs=${*:-$("$bin/odelab" --list | cut -f1)}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf '%-8s %10s %17s %17s %14s\n' program window_fps real_time_factor longest_frame_ms dropped_steps
for program in $programs; do
  xvfb-run -a -s "-screen 0 1280x720x24" "$bin/$program" --screenshot "$work/s.png" --frames "$frames" \
    --metrics-json "$work/$program.json" --out-dir "$work" >/dev/null 2>&1 || { echo "$program: failed"; continue; }
  python3 - "$work/$program.json" "$program" <<'PY'
import json, sys
m = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]:<8} {m['window_fps']:10.1f} {m['real_time_factor']:17.3f} {m['longest_frame_ms']:17.1f} "
      f"{int(m['dropped_steps']):14d}")
PY
done

# The share of a core test0 uses over SECONDS, running and then paused (P
# at its second frame), in two runs side by side.
cpu_share() {  # EVENTS_FILE
  xvfb-run -a -s "-screen 0 1280x720x24" "$bin/test0" --events "$1" --out-dir "$work" >/dev/null 2>&1 &
  wrapper=$!
  pid=
  for _ in $(seq 50); do
    pid=$(pgrep -n -x -f "$bin/test0 --events $1 --out-dir $work" || true)
    [ -n "$pid" ] && break
    sleep 0.2
  done
  [ -n "$pid" ] || { echo "test0 did not start" >&2; return 1; }
  sleep 2  # past start-up
  a=$(awk '{print $14 + $15}' "/proc/$pid/stat")
  sleep "$seconds"
  b=$(awk '{print $14 + $15}' "/proc/$pid/stat")
  kill "$pid" 2>/dev/null || true
  wait "$wrapper" 2>/dev/null || true
  awk -v a="$a" -v b="$b" -v hz="$(getconf CLK_TCK)" -v s="$seconds" 'BEGIN { printf "%.1f", 100 * (b - a) / hz / s }'
}
printf '1 mark start\n' > "$work/run.events"
printf '2 key P\n' > "$work/pause.events"
running=$(cpu_share "$work/run.events")
paused=$(cpu_share "$work/pause.events")
echo "test0 in a window: running ${running}% of a core, paused ${paused}% of a core (over ${seconds} s each)"

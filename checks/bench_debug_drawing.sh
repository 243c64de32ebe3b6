#!/bin/sh
# Benchmark, not a test: does the debug drawing and the live plot cost more
# than 10% of the frame rate? test5 with 100 plates runs under Xvfb with
# scripted input: the plates drop at 8x time scale, the run goes back to 1x
# and settles, then alternates phases of N frames with the debug drawing off
# and on (contacts C, joints J, bounding boxes X, live plot L), marking each
# phase's start; the window prints its frame totals at every mark. Phases
# alternate within one run so that the load of a shared machine, which drifts,
# falls on both alike.
#
#   checks/bench_debug_drawing.sh [TEST5] [--frames N] [--pairs P] [--runs R] [--keys "C J X L"]
#
# TEST5 defaults to build/tests/test5; N = 30 frames per phase, P = 3 off/on
# pairs per run, R = 1 run. Prints, for debug drawing off and on, the frame
# rate, the wall time per frame spent drawing and stepping, and the process's
# CPU time per frame (all threads; Mesa's llvmpipe draws on several), then the
# ratio of the frame rates, on / off: 0.9 or more meets the goal. --keys
# measures other toggles (one of them alone, say). Also reachable as
# `cmake --build build --target bench_debug_drawing`.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
program=$here/../build/tests/test5
frames=30
pairs=3
runs=1
keys="C J X L"
while [ $# -gt 0 ]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --pairs) pairs=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --keys) keys=$2; shift 2 ;;
    -h|--help) sed -n '2,21p' "$0"; exit 0 ;;
    *) program=$1; shift ;;
  esac
done
[ -x "$program" ] || { echo "error: $program is not a program (build test5 first)" >&2; exit 2; }
command -v xvfb-run >/dev/null || { echo "error: xvfb-run not found (install xvfb and xauth)" >&2; exit 2; }

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
first=100
{
  echo "1 key = *3      # 8x while the plates fall"
  echo "80 key - *3     # back to 1x; settle until frame $first"
  phase=0
  while [ $phase -le $((2 * pairs)) ]; do
    frame=$((first + phase * frames))
    # Odd phases have the debug drawing on: the toggles come before the mark.
    if [ $phase -gt 0 ]; then for key in $keys; do echo "$frame key $key"; done; fi
    echo "$frame mark p$phase"
    phase=$((phase + 1))
  done
  echo "$((first + 2 * pairs * frames + 1)) quit"
} >"$work/bench.events"

echo "test5, 100 plates, 1280x720 under Xvfb: $runs run(s) of $pairs off/on pairs of $frames frames; on: $keys"
: >"$work/phases"
run=1
while [ $run -le "$runs" ]; do
  xvfb-run -a -s "-screen 0 1280x800x24" "$program" --plates 100 --spawn-interval 0.05 \
    --events "$work/bench.events" --out-dir "$work" >"$work/out" 2>"$work/err" ||
    { echo "error: test5 failed:" >&2; cat "$work/err" >&2; exit 1; }
  # "mark p1: 129 frames in 30.1 s (4.3 fps; 230.5 ms per frame drawing and stepping; longest frame 310.2 ms; CPU 61.2 s)"
  # Each phase: its frames, wall seconds, busy seconds and CPU seconds.
  awk -v run=$run '
    /^mark p[0-9]+:/ {
      k = substr($2, 2, length($2) - 2) + 0
      n[k] = $3; s[k] = $6; b[k] = $10 * $3 / 1000; c[k] = $(NF - 1); last = k
    }
    END { for (k = 0; k < last; ++k)
            printf "%d %s %d %.6f %.6f %.6f\n", run, (k % 2) ? "on" : "off", n[k+1] - n[k], s[k+1] - s[k], b[k+1] - b[k], c[k+1] - c[k] }' \
    "$work/out" >>"$work/phases"
  run=$((run + 1))
done

awk '
  { f[$2] += $3; s[$2] += $4; b[$2] += $5; c[$2] += $6
    printf "  run %d, debug drawing %-3s: %3d frames, %6.2f fps, %8.2f ms drawing and stepping, %8.2f ms CPU per frame\n", $1, $2, $3, $3 / $4, 1000 * $5 / $3, 1000 * $6 / $3 }
  END {
    for (m = 0; m < 2; ++m) {
      mode = m ? "on" : "off"
      fps[mode] = f[mode] / s[mode]
      printf "debug drawing %-3s: %6.2f fps, %8.2f ms drawing and stepping, %8.2f ms CPU per frame\n", mode, fps[mode], 1000 * b[mode] / f[mode], 1000 * c[mode] / f[mode]
    }
    r = fps["on"] / fps["off"]
    printf "frame rate on / off: %.3f (goal: 0.900 or more, within 10%%): %s\n", r, (r >= 0.9) ? "met" : "NOT met"
    printf "CPU per frame on / off: %.3f\n", (c["on"] / f["on"]) / (c["off"] / f["off"])
  }' "$work/phases"

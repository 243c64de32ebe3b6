#!/usr/bin/env bash
# Benchmark, not a test: each program's frame rate in a window under Xvfb,
# uncapped (--no-vsync --max-fps 0), at 1280x720 and 640x360, as a user
# opens it (panel and compact HUD on). One run per program, size, repeat
# and build: frames 1 to W warm up, then the window's own totals between
# two scripted marks give the rate of the next F frames. Builds given
# together are run in turn within each repeat, so the load of a shared
# machine falls on all of them alike; compare them by their ratio.
#
#   checks/bench_drawing.sh [--repeats R] [--frames F] [--warmup W] [--csv FILE] [BUILD_DIR...]
#
# Defaults: R = 3, F = 60, W = 20, BUILD_DIR = build. Prints, and writes to
# FILE as CSV, one row per build, program and size: the median frame rate
# and the lowest and highest of the R runs, and the renderer OpenGL named
# (the first build's).
# Needs xvfb-run (Debian's xvfb).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repeats=3 frames=60 warmup=20 csv=
builds=()
while [ $# -gt 0 ]; do
  case $1 in
    --repeats) repeats=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --warmup) warmup=$2; shift 2 ;;
    --csv) csv=$2; shift 2 ;;
    -*) echo "usage: $0 [--repeats R] [--frames F] [--warmup W] [--csv FILE] [BUILD_DIR...]" >&2; exit 2 ;;
    *) builds+=("$(cd "$1" && pwd)"); shift ;;
  esac
done
[ ${#builds[@]} -eq 0 ] && builds=("$(cd "$here/../build" && pwd)")
for value in "$repeats" "$frames" "$warmup"; do
  [[ "$value" =~ ^[1-9][0-9]*$ ]] || { echo "bench_drawing: '$value' is not a whole number above 0" >&2; exit 2; }
done

# One X server for every run.
if [ -z "${ODELAB_BENCH_INNER:-}" ]; then
  command -v xvfb-run >/dev/null || { echo "bench_drawing: xvfb-run not found (apt-get install xvfb xauth)" >&2; exit 1; }
  args=(--repeats "$repeats" --frames "$frames" --warmup "$warmup")
  [ -n "$csv" ] && args+=(--csv "$(cd "$(dirname "$csv")" && pwd)/$(basename "$csv")")
  ODELAB_BENCH_INNER=1 exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" "${args[@]}" "${builds[@]}"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
printf '%s mark a\n%s mark b\n%s quit\n' "$((warmup + 1))" "$((warmup + frames + 1))" "$((warmup + frames + 2))" \
  >"$work/bench.events"
renderer=

# The frame rate between the marks a and b of one run's output.
rate() {
  awk '/^mark a:/ { fa = $3; sa = $6 } /^mark b:/ { fb = $3; sb = $6 }
       END { if (sb > sa) printf "%.2f\n", (fb - fa) / (sb - sa); else print "nan" }' "$1"
}

mapfile -t programs < <("${builds[0]}/tests/odelab" --list | cut -f1)  # the registry
sizes=(1280x720 640x360)
declare -A runs
for program in "${programs[@]}"; do
  for size in "${sizes[@]}"; do
    for ((r = 1; r <= repeats; r++)); do
      for b in "${!builds[@]}"; do
        binary=${builds[$b]}/tests/$program
        "$binary" --width "${size%x*}" --height "${size#*x}" --no-vsync --max-fps 0 --events "$work/bench.events" \
          --out-dir "$work" >"$work/out.txt" 2>/dev/null || { echo "bench_drawing: $binary failed" >&2; exit 1; }
        runs[$b,$program,$size]+="$(rate "$work/out.txt") "
        [ -n "$renderer" ] || renderer=$(sed -n 's/^renderer: \([^(]*\).*/\1/p' "$work/out.txt" | sed 's/ *$//')
      done
    done
  done
done

header="build,program,size,fps_median,fps_min,fps_max,repeats,frames,renderer"
echo "$header"
[ -n "$csv" ] && echo "$header" >"$csv"
for b in "${!builds[@]}"; do
  for program in "${programs[@]}"; do
    for size in "${sizes[@]}"; do
      read -r -a values <<<"${runs[$b,$program,$size]}"
      sorted=$(printf '%s\n' "${values[@]}" | sort -g)
      median=$(printf '%s\n' "$sorted" | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else printf "%.2f\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }')
      row="$(basename "$(dirname "${builds[$b]}")")/$(basename "${builds[$b]}"),$program,$size,$median,$(printf '%s\n' "$sorted" | head -n 1),$(printf '%s\n' "$sorted" | tail -n 1),$repeats,$frames,\"$renderer\""
      echo "$row"
      [ -n "$csv" ] && echo "$row" >>"$csv"
    done
  done
done

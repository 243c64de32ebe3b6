#!/usr/bin/env bash
# Screenshots of every program in a window under Xvfb, for looking at: is
# the subject in view and uncovered, is any text clipped, is the panel
# readable? Each program at 1280x720 and 1024x768, three ways: the compact
# HUD (the default), the full HUD (F1) and the help open (H), after 60
# frames at its defaults. Files: OUT_DIR/<program>_<size>_<compact|full|help>.png,
# reduced to 256 colours with pngquant where it is installed (doc/screenshots
# holds such a set).
#
#   scripts/screenshots.sh [OUT_DIR] [PROGRAM...]   (default: screenshots/, every program: odelab --list)
#
# Environment: BUILD_DIR (default: build). Needs xvfb-run (Debian's xvfb).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build}
out=${1:-screenshots}
[ $# -gt 0 ] && shift
programs=("$@")
[ ${#programs[@]} -eq 0 ] && mapfile -t programs < <("$build_dir/tests/odelab" --list | cut -f1)
mkdir -p "$out"
out=$(cd "$out" && pwd)
for program in "${programs[@]}"; do
  [ -x "$build_dir/tests/$program" ] || { echo "screenshots: no $build_dir/tests/$program (build first)" >&2; exit 1; }
done

# One X server for every shot, rather than one per shot.
if [ -z "${ODELAB_SCREENSHOTS_INNER:-}" ]; then
  command -v xvfb-run >/dev/null || { echo "screenshots: xvfb-run not found (apt-get install xvfb xauth)" >&2; exit 1; }
  ODELAB_SCREENSHOTS_INNER=1 BUILD_DIR=$build_dir exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" "$out" "${programs[@]}"
fi

help_events=$(mktemp)
trap 'rm -f "$help_events"' EXIT
echo "1 key H" >"$help_events"
runs=$(mktemp -d)
trap 'rm -rf "$help_events" "$runs"' EXIT
for program in "${programs[@]}"; do
  for size in 1280x720 1024x768; do
    width=${size%x*} height=${size#*x}
    for mode in compact full help; do
      file=$out/${program}_${size}_${mode}.png
      extra=()
      case $mode in
        full) extra=(--hud full) ;;
        help) extra=(--events "$help_events") ;;
      esac
      "$build_dir/tests/$program" --width "$width" --height "$height" --screenshot "$file" --frames 60 \
        --out-dir "$runs" "${extra[@]}" >/dev/null 2>&1 || { echo "screenshots: $program $size $mode failed" >&2; exit 1; }
      if command -v pngquant >/dev/null; then pngquant --force --quality 60-90 --speed 3 --output "$file" "$file" || true; fi
      echo "$file"
    done
  done
done

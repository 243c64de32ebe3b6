#!/usr/bin/env bash
# Screenshots of every program in a window under Xvfb, at 1280x720 and
# 1024x768, after 120 frames at its defaults, for looking at: is the subject
# in view, is any text clipped, is the panel readable?
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
command -v xvfb-run >/dev/null || { echo "screenshots: xvfb-run not found (apt-get install xvfb xauth)" >&2; exit 1; }
mkdir -p "$out"
for program in "${programs[@]}"; do
  binary=$build_dir/tests/$program
  [ -x "$binary" ] || { echo "screenshots: no $binary (build first)" >&2; exit 1; }
  for size in 1280x720 1024x768; do
    width=${size%x*} height=${size#*x}
    file=$out/${program}_${size}.png
    xvfb-run -a -s "-screen 0 ${size}x24" "$binary" --width "$width" --height "$height" \
      --screenshot "$file" --frames 120 --metrics-json "$out/${program}_${size}.json" --out-dir "$out" >/dev/null
    echo "$file"
  done
done

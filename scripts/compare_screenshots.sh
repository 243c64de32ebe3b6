#!/usr/bin/env bash
# The compare window's pictures in doc/screenshots: test5 (plates dropped
# onto a stack) and test10 (cubes launched at a thin wall) on ODE and three
# other engines, at 1280x720 and 1024x768, and test5 merged (M: the others
# as outlines over ODE's stack) at 1280x720. Each is the run's last frame
# (--screenshot with --seconds). Files: OUT_DIR/compare_<program>_<size>.png
# and compare_test5_1280x720_merged.png; test2 (the pendulum) on every
# engine, one view each and merged, running and paused, at both sizes with
# the compact HUD and the panel open: compare_test2_<size>_{views,merged}_
# {running,paused}.png, each frame 20 (--frames), and its help (H) over it,
# compare_test2_<size>_help.png; and a world file on every engine, one view
# each, its bodies edged in each engine's colour:
# compare_world_tumbling_brick_1280x720.png; and an atlas case with its
# analytic ghost (doc/world-format.md, "ghost") on every engine, the ball
# risen from its first bounce, at both sizes:
# compare_world_bounce-v5-e0p5_ghost_<size>.png. Reduced to 256 colours with
# pngquant where it is installed.
#
#   scripts/compare_screenshots.sh [OUT_DIR]   (default: doc/screenshots)
#
# Environment: BUILD_DIR (default: build), ENGINES (default: bullet,havok,jolt;
# Havok's thesis comparison beside two others), ALL_ENGINES (test2's and the
# world's: default every engine the build names, from test2 --list-engines), PICTURES (all, or test2 for
# test2's alone). Needs xvfb-run and the
# engines named (testN --list-engines).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir=${BUILD_DIR:-$root/build}
engines=${ENGINES:-bullet,havok,jolt}
# Every engine but ODE (which leads every compare run), in --list-engines' order.
all_engines=${ALL_ENGINES:-$("$build_dir/tests/test2" --list-engines | awk -F: '/^[a-z]/ && $1 != "ode" {print $1}' | paste -sd, -)}
pictures=${PICTURES:-all}
out=${1:-$root/doc/screenshots}
mkdir -p "$out"
out=$(cd "$out" && pwd)

if [ -z "${ODELAB_SCREENSHOTS_INNER:-}" ]; then
  command -v xvfb-run >/dev/null || { echo "compare_screenshots: xvfb-run not found (apt-get install xvfb xauth)" >&2; exit 1; }
  ODELAB_SCREENSHOTS_INNER=1 BUILD_DIR=$build_dir ENGINES=$engines ALL_ENGINES=$all_engines PICTURES=$pictures exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" "$out"
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "1 key M" >"$work/merge.events"

# shot NAME SIZE PROGRAM ARGS...: the program's compare window, its last frame saved as NAME.
shot() {
  local name=$1 size=$2 program=$3
  shift 3
  local file=$out/$name.png
  "$build_dir/tests/$program" "$@" --compare "$engines" --width "${size%x*}" --height "${size#*x}" --screenshot "$file" \
    --out-dir "$work" >"$work/$name.log" 2>&1 || { echo "compare_screenshots: $name failed:" >&2; cat "$work/$name.log" >&2; exit 1; }
  if command -v pngquant >/dev/null; then pngquant --force --quality 60-90 --speed 3 --output "$file" "$file" || true; fi
  echo "$file"
}

# test5: 40 plates, one every 0.25 s, and a second for the last to settle.
plates=(--spawn-interval 0.25 --plates 40 --seconds 11)
# test10: its first cube, launched at once at 600 m/s, half a second after.
# (A second one launched with B a frame later would start inside the first
# on a fast machine, and the two would knock each other off course.)
launch=(--velocity 600 --seconds 0.5)
if [ "$pictures" = all ]; then
  for size in 1280x720 1024x768; do
    shot "compare_test5_$size" "$size" test5 "${plates[@]}"
    shot "compare_test10_$size" "$size" test10 "${launch[@]}"
  done
  shot compare_test5_1280x720_merged 1280x720 test5 "${plates[@]}" --events "$work/merge.events"
fi

# test2 on every engine: one view each or merged (M), running or paused (P
# five frames before the picture), at frame 20.
printf '1 key M\n' >"$work/merged_running.events"
printf '15 key P\n' >"$work/views_paused.events"
printf '1 key M\n15 key P\n' >"$work/merged_paused.events"
: >"$work/views_running.events"
for size in 1280x720 1024x768; do
  for layout in views merged; do
    for state in running paused; do
      engines=$all_engines shot "compare_test2_${size}_${layout}_${state}" "$size" test2 --frames 20 \
        --events "$work/${layout}_${state}.events"
    done
  done
  # The help (H, a key tap) over the paused views and the open panel.
  printf '15 key P\n16 key H\n' >"$work/help.events"
  engines=$all_engines shot "compare_test2_${size}_help" "$size" test2 --frames 20 --events "$work/help.events"
done

# A world file on every engine (odelab --world): its brick in each view,
# edged in the view's engine colour, paused mid-flip (frame 20).
# (doc/worlds/projectile.json's ball is out of the window's start view at
# these sizes, so its views would show the ground alone.)
engines=$all_engines shot compare_world_tumbling_brick_1280x720 1280x720 odelab --world "$root/doc/worlds/tumbling_brick.json" \
  --frames 20 --events "$work/views_paused.events"

# An atlas case with its ghost on every engine: bounce-v5-e0p5 at 0.7 s, the
# ball 0.19 s after its first impact (t = v/g = 0.51 s) on its way to the
# apex e^2 h (t = 0.76 s), where the engines' bounces have parted from the
# analytic one the dark grey ghost draws. The panel hidden for room; at
# 1024x768 the text a size smaller, so that six of the seven views' labels
# fit at their tops, clear of the ball.
for size in 1280x720 1024x768; do
  text=()
  if [ "$size" = 1024x768 ]; then text=(--text-size 13); fi
  engines=$all_engines shot "compare_world_bounce-v5-e0p5_ghost_$size" "$size" odelab \
    --world "$root/doc/atlas/bounce-v5-e0p5.json" --seconds 0.7 --no-panel "${text[@]}"
done

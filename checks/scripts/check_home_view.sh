#!/bin/sh
# Home restores the start view:
#   check_home_view.sh XVFB_RUN PROGRAM PNG_COMPARE EVENTS DIR [PROGRAM ARGS...]
# With home_view.events the paused scene is recorded before the camera
# moves (frame 2), after the wheel and W (frame 4) and after Home (frame 6).
# The move must change most of the view, and Home must bring back the start
# view pixel for pixel (no channel off by more than 24 of 255 anywhere).
set -u
xvfb=$1 program=$2 compare=$3 events=$4 dir=$5
shift 5
rm -rf "$dir" && mkdir -p "$dir" || exit 1
"$xvfb" -a -s "-screen 0 1280x800x24" "$program" --events "$events" --record "$dir" --out-dir "$dir" --hud off "$@" ||
  { echo "FAIL: exit status $?"; exit 1; }
name=$(basename "$program")
start=$dir/${name}_frame_000002.png moved=$dir/${name}_frame_000004.png home=$dir/${name}_frame_000006.png
"$compare" "$start" "$moved" --region 0,0,0.7,1 --min-changed 0.2 || { echo "FAIL: the wheel and W did not move the view"; exit 1; }
"$compare" "$start" "$home" --max-changed 0 || { echo "FAIL: Home did not restore the start view"; exit 1; }

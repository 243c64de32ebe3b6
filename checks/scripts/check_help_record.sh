#!/bin/sh
# Help overlay and --record check:
#   check_help_record.sh XVFB_RUN PROGRAM PNG_COMPARE EVENTS DIR [PROGRAM ARGS...]
# With help_record.events the run records frames 1 to 5 as
# <program>_frame_000001.png ... and no more; the scene is paused, so frames 1
# and 2 match in the middle of the window, and the help panel (H at frame 3)
# changes most of it in frame 3.
set -u
xvfb=$1 program=$2 compare=$3 events=$4 dir=$5
shift 5
rm -rf "$dir" && mkdir -p "$dir" || exit 1
"$xvfb" -a -s "-screen 0 1280x800x24" "$program" --events "$events" --record "$dir" --out-dir "$dir" "$@" || { echo "FAIL: exit status $?"; exit 1; }
name=$(basename "$program")
for n in 1 2 3 4 5; do
  [ -f "$dir/${name}_frame_00000$n.png" ] || { echo "FAIL: $dir/${name}_frame_00000$n.png missing"; exit 1; }
done
[ ! -e "$dir/${name}_frame_000006.png" ] || { echo "FAIL: a sixth frame was recorded after quit"; exit 1; }
echo "ok: frames ${name}_frame_000001.png to 000005.png recorded"
middle=0.3,0.45,0.7,0.8
"$compare" "$dir/${name}_frame_000001.png" "$dir/${name}_frame_000002.png" --region $middle --max-changed 0.01 &&
  "$compare" "$dir/${name}_frame_000002.png" "$dir/${name}_frame_000003.png" --region $middle --min-changed 0.5

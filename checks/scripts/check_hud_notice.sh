#!/bin/sh
# A notice joining the HUD moves nothing else:
#   check_hud_notice.sh XVFB_RUN PROGRAM PNG_COMPARE EVENTS DIR WIDTH HEIGHT REGIONS [PROGRAM ARGS...]
# With hud_notice.events the paused scene is recorded before a notice comes
# (frame 11) and with it (frame 13). Each of REGIONS (space-separated
# x0,y0,x1,y1 fractions of the window) must stay the same pixel for pixel:
# the view below the HUD's strip (the strip keeps a row for notices, so it
# does not grow and push the view down), and with the full HUD in columns
# the top of the later columns (the notice joins the last column's end; no
# line moves between columns).
# Frames are recorded (--record), so the HUD's rate line reads the same in both.
set -u
xvfb=$1 program=$2 compare=$3 events=$4 dir=$5 width=$6 height=$7 regions=$8
shift 8
rm -rf "$dir" && mkdir -p "$dir" || exit 1
"$xvfb" -a -s "-screen 0 1280x800x24" "$program" --events "$events" --record "$dir" --out-dir "$dir" \
  --width "$width" --height "$height" --no-panel "$@" 2>"$dir/stderr.txt" ||
  { cat "$dir/stderr.txt"; echo "FAIL: exit status $?"; exit 1; }
grep -q "no later snapshot" "$dir/stderr.txt" || { echo "FAIL: no notice came"; exit 1; }
name=$(basename "$program")
before=$dir/${name}_frame_000011.png after=$dir/${name}_frame_000013.png
for region in $regions; do
  "$compare" "$before" "$after" --region "$region" --max-changed 0 ||
    { echo "FAIL: region $region changed when the HUD gained the notice"; exit 1; }
done
echo "ok: nothing moved but the notice"

#!/bin/sh
# Panel check: check_panel_cfm_zero.sh XVFB_RUN TEST2 EXPECT_METRICS EVENTS OUT_DIR
# A CFM of 0 typed into the control panel reaches the world (world_cfm
# reads dWorldGetCFM back) as --cfm 0 would, and the panel refuses nothing
# on the way (no "panel: ..." line on standard error).
set -u
xvfb=$1 program=$2 expect=$3 events=$4 out=$5
rm -rf "$out" && mkdir -p "$out" || exit 1
"$xvfb" -a -s "-screen 0 1280x800x24" "$expect" world_cfm==0 -- "$program" --cfm 0.01 --events "$events" \
  --out-dir "$out" 2>"$out/err.txt"
status=$?
cat "$out/err.txt"
test $status -eq 0 || { echo "FAIL: the window run or its metrics"; exit 1; }
if grep -q '^panel: ' "$out/err.txt"; then echo "FAIL: the panel refused a value"; exit 1; fi
echo "ok"

#!/bin/sh
# Panel check: check_panel_cfm.sh XVFB_RUN TEST2 EXPECT_METRICS EVENTS OUT_DIR
# A CFM typed into the control panel must reach the world (the world_cfm
# metric reads dWorldGetCFM back), the output file (a "# t=... s: CFM
# 1e-06 -> 0.01" line in Test2_output.txt) and the run log, once Enter is
# pressed in the field.
set -u
xvfb=$1 program=$2 expect=$3 events=$4 out=$5
rm -rf "$out" && mkdir -p "$out" || exit 1
"$xvfb" -a -s "-screen 0 1280x800x24" "$expect" world_cfm==0.01 -- "$program" --events "$events" --out-dir "$out" \
  || { echo "FAIL: the window run or its metrics"; exit 1; }
grep -E '^# t=[0-9.e+-]+ s: CFM 0 -> 0.01$' "$out/Test2_output.txt" \
  || { echo "FAIL: no CFM change line in Test2_output.txt"; exit 1; }
grep -E 'CFM 0 -> 0.01$' "$out/test2_run_log.txt" || { echo "FAIL: no CFM change in the run log"; exit 1; }

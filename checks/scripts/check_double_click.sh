#!/bin/sh
# Double-click check: check_double_click.sh XVFB_RUN TEST2 EVENTS OUT_DIR
# Runs the script, then the same script without its presses and releases;
# both must reach the same state hash at mark a, and the first run's log
# must name no drag.
set -u
xvfb=$1 program=$2 events=$3 out=$4
rm -rf "$out" && mkdir -p "$out/clicks" "$out/none" || exit 1
grep -v -E '^[0-9]+ (down|up) ' "$events" >"$out/none.events" || exit 1
for run in clicks none; do
  script=$events
  [ $run = none ] && script=$out/none.events
  "$xvfb" -a -s "-screen 0 1280x800x24" "$program" --no-panel --hud off --events "$script" --out-dir "$out/$run" \
    --metrics-json "$out/$run/metrics.json" || { echo "FAIL: the $run run"; exit 1; }
done
hash() { grep -o '"mark_a_hash": *[0-9.e+-]*' "$1" | sed 's/.*: *//'; }
a=$(hash "$out/clicks/metrics.json") b=$(hash "$out/none/metrics.json")
echo "mark_a_hash with the double click: $a; without: $b"
test -n "$a" && test "$a" = "$b" || { echo "FAIL: the double click changed the run"; exit 1; }
if grep -n 'drag' "$out/clicks/test2_run_log.txt"; then echo "FAIL: the double click was logged as a drag"; exit 1; fi
echo "ok"

#!/bin/sh
# Esc check: check_escape.sh XVFB_RUN PROGRAM EVENTS OUT_DIR FIRST_MARK [NOTICE]
# The program's window plays EVENTS, which press Esc twice and set mark
# FIRST_MARK between the two presses and mark after_quit long after the
# second: the run must end by itself with status 0 (the second Esc quit),
# with FIRST_MARK recorded (the first did not) and after_quit not. With
# NOTICE, standard error must carry that text (what the first Esc said).
set -u
xvfb=$1 program=$2 events=$3 out=$4 first=$5 notice=${6:-}
rm -rf "$out" && mkdir -p "$out" || exit 1
timeout 150 "$xvfb" -a -s "-screen 0 1280x800x24" "$program" --events "$events" --out-dir "$out" \
  --metrics-json "$out/metrics.json" 2>"$out/err.txt"
status=$?
cat "$out/err.txt"
test $status -eq 0 || { echo "FAIL: status $status (124: the second Esc did not quit)"; exit 1; }
grep -q "\"mark_${first}_steps\"" "$out/metrics.json" || { echo "FAIL: the first Esc quit (no mark $first)"; exit 1; }
if grep -q '"mark_after_quit_steps"' "$out/metrics.json"; then echo "FAIL: the second Esc did not quit"; exit 1; fi
if [ -n "$notice" ]; then
  grep -qF "$notice" "$out/err.txt" || { echo "FAIL: the first Esc did not say '$notice'"; exit 1; }
fi
echo "ok"

#!/bin/sh
# F12 check: check_f12.sh XVFB_RUN PROGRAM SCREENSHOT_CHECK EVENTS OUT_DIR [PROGRAM ARGS...]
# The scripted F12 must save exactly one <program>_t<seconds, 3 decimals>.png
# in --out-dir, print its path, and the PNG must be a real frame
# (screenshot_check: 1280x720, not blank, lit and shadowed surfaces).
set -u
xvfb=$1 program=$2 check=$3 events=$4 out=$5
shift 5
rm -rf "$out" && mkdir -p "$out" || exit 1
"$xvfb" -a -s "-screen 0 1280x800x24" "$program" --events "$events" --out-dir "$out" "$@" >"$out/stdout.txt"
status=$?
cat "$out/stdout.txt"
[ "$status" -eq 0 ] || { echo "FAIL: exit status $status"; exit 1; }
name=$(basename "$program")
file=$(ls "$out" | grep -E "^${name}_t[0-9]+\.[0-9]{3}\.png\$")
[ "$(printf '%s\n' "$file" | grep -c .)" -eq 1 ] || { echo "FAIL: expected one ${name}_t<seconds>.png in $out; found: $(ls "$out" | tr '\n' ' ')"; exit 1; }
grep -qx "screenshot: $out/$file" "$out/stdout.txt" || { echo "FAIL: the screenshot's path was not printed"; exit 1; }
"$check" "$out/$file"

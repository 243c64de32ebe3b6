#!/bin/sh
# The --help and doc/manual.md say the same:
#   help_agrees_with_manual.sh PROGRAM MANUAL
# the name of --metrics-json's temporary file (utils/SafeFile.cpp: a hidden
# ".FILE." prefix and mkstemp's six characters) and what --text-size sizes
# (the HUD, the help and the panel all take their text height from it), and
# what exit status 7 means.
set -u
program=$1 manual=$2
help=$("$program" --help) || { echo "FAIL: --help exited with status $?"; exit 1; }
for phrase in '.FILE.XXXXXX' 'text height of the HUD, the help and the panel' \
              '7: the engine failed, not its physics'; do
  printf '%s\n' "$help" | tr -s ' \n' ' ' | grep -qF "$phrase" || { echo "FAIL: --help does not say '$phrase'"; exit 1; }
  tr -s ' \n' ' ' < "$manual" | grep -qF "$phrase" || { echo "FAIL: $manual does not say '$phrase'"; exit 1; }
done
printf '%s\n' "$help" | grep -n 'FILE\.tmp' && { echo "FAIL: --help names FILE.tmp"; exit 1; }
echo "ok: --help and the manual agree"

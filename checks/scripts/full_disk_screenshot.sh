#!/bin/sh
# full_disk_screenshot.sh PROGRAM
#
# A PNG that cannot be written whole is not reported as written: with every
# file limited to 4 KiB (ulimit -f 4, SIGXFSZ ignored, as a full disk
# refuses a write), --screenshot and --record must end with status 1 and a
# message, and leave no PNG, whole or truncated, and no temporary file.
program=$1
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_full_disk.XXXXXX") || exit 2
trap 'rm -rf "$root"' EXIT
failures=0
for how in screenshot record; do
  run="$root/$how"
  mkdir -p "$run/frames"
  if [ "$how" = screenshot ]; then set -- --screenshot shot.png --frames 2; else set -- --record frames --seconds 0.05; fi
  (cd "$run" && timeout 120 xvfb-run -a -s "-screen 0 1280x800x24" sh -c \
    'ulimit -f 4; trap "" XFSZ; "$@" >/dev/null 2>err.txt; echo $? > status' sh "$program" "$@")
  status=$(cat "$run/status" 2>/dev/null)
  left=$(cd "$run" && find . -type f ! -name err.txt ! -name status | sort | tr '\n' ' ')
  if [ "$status" = 1 ] && grep -q "error:.*cannot write" "$run/err.txt" && [ -z "$left" ]; then
    echo "ok:   --$how on a full disk -> status 1: $(grep -m1 error "$run/err.txt")"
  else
    echo "FAIL: --$how on a full disk -> status '$status', left: '$left'"
    sed 's/^/      stderr: /' "$run/err.txt" | head -3
    failures=$((failures + 1))
  fi
done
[ "$failures" = 0 ]

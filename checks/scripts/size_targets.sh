#!/bin/sh
# The scene base stays a short class that composes its parts, and each test
# program reads as its thesis chapter: utils/AbstractWindow.h at most 160
# lines, every tests/scenes/*.cpp at most 320 (wc -l, comments included).
# Usage: size_targets.sh SOURCE_DIR
cd "$1" || exit 2
status=0
check() {
  lines=$(wc -l < "$1")
  if [ "$lines" -gt "$2" ]; then
    echo "FAIL: $1 has $lines lines, over $2"
    status=1
  else
    echo "ok: $1 $lines lines (at most $2)"
  fi
}
check utils/AbstractWindow.h 160
for program in tests/scenes/*.cpp; do check "$program" 320; done
exit $status

#!/bin/sh
# A program without its window module (odelab_window.so, Linux): a headless
# run does not need it and gives the same state_hash as the program beside
# its module; a window run is refused with status 5 (MISSING_RESOURCE) and a
# message that names the module and every path tried. Needs no display: the
# module is looked for before any window is opened.
#   check_window_module.sh PROGRAM
set -u
program=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cp "$program" "$work/alone" || fail "cannot copy $program"
(cd "$work" && "$program" --headless --seconds 0.5 >beside.out 2>&1) || fail "the program beside its module failed headless"
(cd "$work" && ./alone --headless --seconds 0.5 >alone.out 2>alone.err) ||
  fail "headless without the module: status $? ($(cat "$work/alone.err"))"
beside=$(grep '^state_hash = ' "$work/beside.out") alone=$(grep '^state_hash = ' "$work/alone.out")
[ -n "$beside" ] && [ "$beside" = "$alone" ] || fail "headless without the module: '$alone', beside it: '$beside'"

(cd "$work" && ./alone --seconds 0.5 >window.out 2>window.err)
status=$?
[ "$status" = 5 ] || fail "a window run without the module: status $status, expected 5"
grep -q "odelab_window.so" "$work/window.err" || fail "the message does not name odelab_window.so: $(cat "$work/window.err")"
grep -q "$work/odelab_window.so" "$work/window.err" || fail "the message does not name the path tried beside the program"
[ ! -s "$work/window.out" ] || fail "a refused window run printed on standard output: $(cat "$work/window.out")"
echo "ok: headless without the module ($alone); a window run refused with status 5 naming the module"

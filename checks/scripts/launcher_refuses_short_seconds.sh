#!/bin/sh
# launcher_refuses_short_seconds.sh ODELAB
#
# odelab's window can switch to any scene, so its options must hold for
# every one: --seconds 0.003 is three steps of test2 but less than one step
# of test3 (0.005 s). The window run is refused at start: status 2, a
# message naming --seconds and test3, and nothing written to its folder.
program=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_short_seconds.XXXXXX") || exit 2
trap 'rm -rf "$root"' EXIT
mkdir "$root/run" && cd "$root/run" || exit 2
timeout 60 xvfb-run -a -s "-screen 0 1280x800x24" sh -c '"$@" 2>"$0/err.txt"; echo $? > "$0/status"' "$root" \
  "$program" --scene test2 --seconds 0.003 --metrics-json m.json >/dev/null
status=$(cat "$root/status" 2>/dev/null)
failures=0
[ "$status" = 2 ] || { echo "FAIL: status '$status', expected 2"; failures=1; }
grep -q -- '^error: --seconds: .*test3' "$root/err.txt" || { echo "FAIL: no message naming --seconds and test3"; failures=1; }
left=$(ls -A)
[ -z "$left" ] || { echo "FAIL: files left behind: $left"; failures=1; }
cat "$root/err.txt"
[ "$failures" = 0 ] && echo "ok:   refused with status 2"

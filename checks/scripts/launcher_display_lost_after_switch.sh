#!/bin/sh
# launcher_display_lost_after_switch.sh ODELAB
#
# odelab's window opens on test7 and Page Down switches to test8, which
# writes Test8_output.txt. Then the X server goes away (Xlib calls exit()
# itself): the exit hook must mark the scene on screen, not the one the
# window opened on, so Test8_output.txt ends "# incomplete: ...; the program
# exited inside the run ..." and the status is 1, with no metrics JSON
# (doc/hardening.md, "What you can rely on").
program=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") file=Test8_output.txt
check_name=launcher_display_lost
. "$(dirname "$0")/output_check_common.sh"
cd "$root" || exit 2
printf '2 key PageDown\n' > switch.events
# A server of our own, on the first free display (it writes the number).
Xvfb -displayfd 3 -screen 0 1280x800x24 3>display.txt >/dev/null 2>&1 &
server=$!
pids="$server"
n=0
while [ ! -s display.txt ] && [ $n -lt 300 ]; do sleep 0.1; n=$((n + 1)); done
DISPLAY=:$(cat display.txt) "$program" --scene test7 --events switch.events --no-vsync --width 320 --height 240 \
  --metrics-json m.json >/dev/null 2>err.txt &
pid=$!
pids="$server $pid"
wait_lines . 50 || fail "no 50 lines of $file within 60 s"
kill -TERM "$server"
wait "$pid"
status=$?
wait "$server"
pids=
last=$(tail -n 1 "$file" 2>/dev/null)
[ "$status" = 1 ] || fail "status $status, expected 1"
case $last in
  "# incomplete: "*"exited inside the run"*) ok "status $status, last line '$last'" ;;
  *) fail "last line of $file '$last', expected '# incomplete: ...exited inside the run...'" ;;
esac
[ -e m.json ] && fail "metrics JSON written for a run that did not finish"
[ "$failures" = 0 ]

#!/bin/sh
# every_ending_marked.sh PROGRAM FILE [window]
#
# However a run of PROGRAM ends, its output FILE (Test2_output.txt, ...) says
# whether it finished: the last line is "# complete: ..." or "# incomplete:
# ...; <why>" (doc/hardening.md, "What you can rely on"). The endings tried:
#   - SIGHUP to a headless run (the terminal went away): status 129,
#     "stopped by SIGHUP", no metrics JSON; SIGINT likewise, status 130
#     (SIGTERM: output_files.sh);
#   - with "window" (needs Xvfb): --record on a full disk (ulimit -f 4, as
#     full_disk_screenshot.sh): status 1, the write failure as the reason;
#   - with "window": the X server goes away mid-run (Xlib then calls exit()
#     itself): status 1, the exit named as the reason.
program=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") file=$2 window=${3:-}
check_name=every_ending
. "$(dirname "$0")/output_check_common.sh"
# marked NAME STATUS EXPECTED-STATUS PATTERN: FILE's last line in the current folder
marked() {
  last=$(tail -n 1 "$file" 2>/dev/null)
  [ "$2" = "$3" ] || fail "$1: status $2, expected $3"
  case $last in
    "# incomplete: "*$4*) ok "$1: status $2, last line '$last'" ;;
    *) fail "$1: last line '$last', expected '# incomplete: ...$4...'" ;;
  esac
  [ -e m.json ] && fail "$1: metrics JSON written for a run that did not finish"
}

for signal_status in HUP:129 INT:130; do
  signal=${signal_status%:*}
  mkdir "$root/$signal" && cd "$root/$signal" || exit 2
  "$program" --headless --seconds 100000 --metrics-json m.json >/dev/null 2>err.txt &
  pid=$!
  pids=$pid
  wait_lines . 50 || fail "SIG$signal: no 50 lines within 60 s"
  kill -"$signal" "$pid"
  wait "$pid"
  status=$?
  pids=
  marked "SIG$signal, headless" $status "${signal_status#*:}" "stopped by SIG$signal"
done

if [ "$window" = window ]; then
  mkdir -p "$root/record/frames" && cd "$root/record" || exit 2
  timeout 120 xvfb-run -a -s "-screen 0 1280x800x24" sh -c \
    'ulimit -f 4; trap "" XFSZ; "$@" >/dev/null 2>err.txt; echo $? > status' sh "$program" --record frames \
    --seconds 0.05 --metrics-json m.json
  marked "--record on a full disk" "$(cat status 2>/dev/null)" 1 "cannot write"

  mkdir "$root/display" && cd "$root/display" || exit 2
  # A server of our own, on the first free display (it writes the number).
  Xvfb -displayfd 3 -screen 0 1280x800x24 3>display.txt >/dev/null 2>&1 &
  server=$!
  pids="$server"
  n=0
  while [ ! -s display.txt ] && [ $n -lt 300 ]; do sleep 0.1; n=$((n + 1)); done
  DISPLAY=:$(cat display.txt) "$program" --seconds 100000 --no-vsync --metrics-json m.json >/dev/null 2>err.txt &
  pid=$!
  pids="$server $pid"
  wait_lines . 50 || fail "display lost: no 50 lines within 60 s"
  kill -TERM "$server"
  wait "$pid"
  status=$?
  wait "$server"
  pids=
  marked "the display went away" $status 1 "exited inside the run"
fi
[ "$failures" = 0 ]

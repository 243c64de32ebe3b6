#!/bin/sh
# output_files.sh PROGRAM FILE [window]
#
# What a run promises about its files (doc/hardening.md, "What you can rely
# on"), checked on PROGRAM and its output FILE (Test2_output.txt, ...):
#   - a whole run ends FILE with "# complete: ..." and records the run length
#     asked for ("# run_seconds_asked: ...");
#   - a planted symbolic link at FILE is refused before the run (status 2,
#     target kept);
#   - a second run into the same folder while the first runs is refused
#     (status 1, "another run"), and the first run's file stays whole;
#   - SIGTERM ends a headless run with status 143, "# incomplete: ... stopped
#     by SIGTERM" as FILE's last line, and no metrics JSON;
#   - with "window" (under xvfb-run), SIGTERM ends a window run the same way.
program=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") file=$2 window=${3:-}
check_name=output_files
. "$(dirname "$0")/output_check_common.sh"

# A whole run.
mkdir "$root/whole" && cd "$root/whole" || exit 2
"$program" --headless --seconds 0.5 --metrics-json m.json >/dev/null 2>err.txt
status=$?
[ "$status" = 0 ] || fail "whole run: status $status"
last=$(tail -n 1 "$file")
case $last in "# complete: t=0.5 s, "*) ok "whole run ends with '$last'" ;; *) fail "whole run: last line '$last'" ;; esac
grep -q '^# run_seconds_asked: 0.5$' "$file" && ok "header records the run length asked for" ||
  fail "no '# run_seconds_asked: 0.5' in the header"

# A planted link.
mkdir "$root/link" && cd "$root/link" || exit 2
echo "precious" > "$root/target"
ln -s "$root/target" "$file"
"$program" --headless --seconds 0.1 >/dev/null 2>err.txt
status=$?
[ "$status" = 2 ] || fail "planted link: status $status, expected 2 (refused before the run)"
grep -q "error: cannot write '$file': is a symbolic link" err.txt && ok "planted link refused: $(head -1 err.txt)" ||
  fail "planted link: message '$(head -1 err.txt)'"
[ "$(cat "$root/target")" = precious ] || fail "planted link: its target was overwritten"

# Two runs into one folder, then SIGTERM to the first.
mkdir "$root/two" && cd "$root/two" || exit 2
"$program" --headless --seconds 100000 --metrics-json m.json >/dev/null 2>first.txt &
first=$!
pids="$first"
wait_lines . 100 || fail "the first run wrote no 100 lines within 60 s"
"$program" --headless --seconds 1 --metrics-json second.json >/dev/null 2>second.txt
status=$?
[ "$status" = 1 ] || fail "second run into one folder: status $status, expected 1"
grep -q "another run is writing it" second.txt && ok "second run refused: $(head -1 second.txt)" ||
  fail "second run: message '$(head -1 second.txt)'"
[ -e second.json ] && fail "the refused second run wrote metrics"
kill -TERM "$first"
wait "$first"
status=$?
pids=
[ "$status" = 143 ] && ok "SIGTERM: status 143" || fail "SIGTERM: status $status, expected 143"
last=$(tail -n 1 "$file")
case $last in "# incomplete: "*"stopped by SIGTERM") ok "SIGTERM: last line '$last'" ;; *) fail "SIGTERM: last line '$last'" ;; esac
header=$(grep -v '^#' "$file" | head -n 1)
[ "$(grep -cxF "$header" "$file")" = 1 ] || fail "a second column-name line in $file: two runs' rows were mixed"
[ -e m.json ] && fail "SIGTERM: metrics JSON written"
grep -q "stopped by SIGTERM" first.txt || fail "SIGTERM: no message on standard error"

# A window run ended by SIGTERM.
if [ "$window" = window ]; then
  mkdir "$root/window" && cd "$root/window" || exit 2
  timeout 120 xvfb-run -a -s "-screen 0 1280x800x24" sh -c '
    "$1" --metrics-json m.json --no-vsync --max-fps 0 >/dev/null 2>err.txt &
    echo $! > pid
    wait $!
    echo $? > status' sh "$program" &
  pids=$!
  wait_lines . 50 || fail "the window run wrote no 50 lines within 60 s"
  kill -TERM "$(cat pid)"
  wait "$pids"
  pids=
  status=$(cat status 2>/dev/null)
  [ "$status" = 143 ] && ok "window SIGTERM: status 143" || fail "window SIGTERM: status '$status', expected 143"
  last=$(tail -n 1 "$file")
  case $last in "# incomplete: "*"stopped by SIGTERM") ok "window SIGTERM: last line '$last'" ;;
    *) fail "window SIGTERM: last line '$last'" ;; esac
  [ -e m.json ] && fail "window SIGTERM: metrics JSON written"
fi
[ "$failures" = 0 ]

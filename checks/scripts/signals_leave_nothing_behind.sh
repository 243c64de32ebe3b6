#!/bin/sh
# signals_leave_nothing_behind.sh TEST2 [ENGINE_SERVER_JS]
#
# However a run ends, it says so and leaves no temporary behind
# (doc/hardening.md, "Fourth round"):
#   - SIGUSR1 and SIGALRM stop a headless run as SIGTERM does: status 138
#     and 142, Test2_output.txt's last line "# incomplete: ... stopped by
#     SIGUSR1" (SIGALRM), no metrics JSON and no hidden temporary file;
#   - a file size limit (ulimit -f 4) with SIGXFSZ at its default, as a shell
#     leaves it: status 1 naming the file that could not be written, not a
#     death by SIGXFSZ (153), and no hidden temporary file;
#   - `test2 | true`: the run completes with status 0, not 141 (SIGPIPE);
#   - --export-world with TMPDIR naming no folder: the world is written,
#     status 0, and nothing is made in a TMPDIR that exists;
#   - with ENGINE_SERVER_JS: `engine_server.js --info __proto__` is refused
#     with status 2 and one line, no traceback.
program=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") server=${2:-}
file=Test2_output.txt check_name=signals
. "$(dirname "$0")/output_check_common.sh"
no_temporaries() {
  left=$(ls -A | grep '^\.' | tr '\n' ' ')
  [ -z "$left" ] && ok "$1: no hidden temporary left" || fail "$1: left $left"
}

for signal_status in USR1:138 ALRM:142; do
  signal=${signal_status%:*}
  mkdir "$root/$signal" && cd "$root/$signal" || exit 2
  "$program" --headless --seconds 100000 --metrics-json m.json >/dev/null 2>err.txt &
  pid=$!
  pids=$pid
  wait_lines . 50
  kill -"$signal" "$pid"
  wait "$pid"
  status=$?
  pids=
  [ "$status" = "${signal_status#*:}" ] && ok "SIG$signal: status $status" ||
    fail "SIG$signal: status $status, expected ${signal_status#*:}"
  case $(tail -n 1 Test2_output.txt 2>/dev/null) in
    "# incomplete: "*"stopped by SIG$signal"*) ok "SIG$signal: marked" ;;
    *) fail "SIG$signal: last line '$(tail -n 1 Test2_output.txt 2>/dev/null)'" ;;
  esac
  [ -e m.json ] && fail "SIG$signal: a metrics JSON was written"
  no_temporaries "SIG$signal"
done

mkdir "$root/xfsz" && cd "$root/xfsz" || exit 2
(ulimit -f 4; exec "$program" --headless --seconds 60 --metrics-json m.json) >/dev/null 2>err.txt
status=$?
[ "$status" = 1 ] && ok "file size limit: status 1" || fail "file size limit: status $status, expected 1 (153: killed by SIGXFSZ)"
grep -q "cannot write.*Test2_output.txt" err.txt && ok "file size limit: the file named" ||
  fail "file size limit: no 'cannot write ... Test2_output.txt': $(head -n 2 err.txt)"
no_temporaries "file size limit"

mkdir "$root/pipe" && cd "$root/pipe" || exit 2
{ "$program" --headless --seconds 0.5 2>err.txt; echo $? > status.txt; } | true
status=$(cat status.txt)
[ "$status" = 0 ] && ok "| true: status 0" || fail "| true: status $status, expected 0 (the run completed)"
tail -n 1 Test2_output.txt | grep -q '^# complete: ' && ok "| true: the output is complete" ||
  fail "| true: last line '$(tail -n 1 Test2_output.txt)'"

mkdir "$root/export" "$root/export/tmp" && cd "$root/export" || exit 2
TMPDIR=/nonexistent/folder "$program" --export-world w.json >/dev/null 2>err.txt
status=$?
[ "$status" = 0 ] && [ -s w.json ] && ok "--export-world, TMPDIR nowhere: written" ||
  fail "--export-world, TMPDIR nowhere: status $status: $(head -n 2 err.txt)"
TMPDIR=$root/export/tmp "$program" --export-world w2.json >/dev/null 2>&1 || fail "--export-world failed"
[ -z "$(ls -A tmp)" ] && ok "--export-world: nothing made in TMPDIR" || fail "--export-world left $(ls -A tmp) in TMPDIR"

if [ -n "$server" ]; then
  node "$server" --info __proto__ >out.txt 2>err.txt
  status=$?
  [ "$status" = 2 ] && [ "$(wc -l < err.txt)" = 1 ] && ok "--info __proto__: status 2, one line" ||
    fail "--info __proto__: status $status: $(head -n 3 err.txt)"
fi
[ "$failures" = 0 ]

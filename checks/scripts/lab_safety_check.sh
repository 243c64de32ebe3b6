#!/usr/bin/env bash
# The lab's --out, --only and interrupts (issue 15, items 3 and 8):
#  - --out naming a file, or a folder with files and no previous report, is
#    refused with status 2 and a message, and nothing there changes;
#  - --only "" (or ",") is refused with status 2 instead of running everything;
#  - an --out the lab cannot create ends with a message, not a traceback;
#  - SIGINT at many moments of a short report gives status 130 (or 0 when the
#    report was complete before it), never a traceback or "FATAL: exception
#    not rethrown", and leaves the previous report whole and no staging folder.
# Usage: lab_safety_check.sh BUILD_TESTS_DIR WORK_DIR [LAB_LAUNCHER]
set -uo pipefail
build=$(cd "$1" && pwd)
work=$2
here=$(cd "$(dirname "$0")" && pwd)
lab=${3:-$here/../../lab/odelab-report}
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
snapshot() { (cd "$1" && find . -type f -exec md5sum {} + | sort); }
no_trace() { ! grep -q "Traceback\|FATAL" "$1" || fail "$2 printed a traceback: $(grep -m1 "Traceback\|FATAL" "$1")"; }
quick=(--quick --only limit-test9 --build-dir "$build")

# --out naming a file
echo "precious" >"$work/file.txt"
"$lab" "${quick[@]}" --out "$work/file.txt" >"$work/out-file.log" 2>&1; status=$?
[ $status -eq 2 ] || fail "--out FILE: status $status, not 2"
[ "$(cat "$work/file.txt")" = precious ] && [ -z "$(ls -a "$work" | grep '^\.file')" ] \
  || fail "--out FILE touched the file or left a folder beside it"
grep -q "not a folder" "$work/out-file.log" || fail "--out FILE: no clear message"
no_trace "$work/out-file.log" "--out FILE"

# --out naming a folder that holds something else (a source folder, say)
mkdir -p "$work/sources/sub" && echo "int main() {}" >"$work/sources/main.cpp" && touch "$work/sources/sub/x"
before=$(snapshot "$work/sources")
"$lab" "${quick[@]}" --out "$work/sources" >"$work/out-folder.log" 2>&1; status=$?
[ $status -eq 2 ] || fail "--out FOLDER-WITH-FILES: status $status, not 2"
[ "$before" = "$(snapshot "$work/sources")" ] || fail "--out FOLDER-WITH-FILES changed the folder"
grep -q "no previous report" "$work/out-folder.log" || fail "--out FOLDER-WITH-FILES: no clear message"
no_trace "$work/out-folder.log" "--out FOLDER-WITH-FILES"

# --only "" and --only ","
for only in "" ","; do
  # (a lab that takes it for "everything" is stopped after 30 s)
  timeout 30 "$lab" --quick --only "$only" --build-dir "$build" --out "$work/only" >"$work/only.log" 2>&1; status=$?
  [ $status -eq 2 ] || fail "--only '$only': status $status, not 2"
  [ ! -e "$work/only" ] || fail "--only '$only' wrote a report"
  no_trace "$work/only.log" "--only '$only'"
done

# an --out whose parent is a file: a message, not a traceback
"$lab" "${quick[@]}" --out "$work/file.txt/report" >"$work/out-under-file.log" 2>&1; status=$?
[ $status -ne 0 ] || fail "--out under a file: status 0"
no_trace "$work/out-under-file.log" "--out under a file"

# an empty folder is accepted, and a previous report is replaced
mkdir -p "$work/report"
"$lab" "${quick[@]}" --out "$work/report" >"$work/report.log" 2>&1 || fail "--out EMPTY: $(tail -n 3 "$work/report.log")"
"$lab" "${quick[@]}" --out "$work/report" >"$work/report2.log" 2>&1 || fail "--out PREVIOUS-REPORT refused"

# SIGINT at many moments of a report into the previous report's folder; with
# job control on, so that the lab does not start with SIGINT ignored (as `&`
# in a script would) and has a process group of its own: the odd moments send
# SIGINT to that group, as Ctrl-C on a terminal does (the programs get it too).
set -m
before=$(snapshot "$work/report")
turn=0
for delay in 0 0.05 0.15 0.3 0.5 0.8 1.2 1.8 2.5 3.5; do
  "$lab" "${quick[@]}" --out "$work/report" >"$work/sigint-$delay.log" 2>&1 &
  pid=$!
  sleep "$delay"
  turn=$((turn + 1)); target=$pid; [ $((turn % 2)) -eq 0 ] || target=-$pid
  sent=yes; kill -INT -- $target 2>/dev/null || sent=no
  wait $pid; status=$?
  no_trace "$work/sigint-$delay.log" "SIGINT after $delay s"
  if [ $status -eq 130 ]; then
    after=$(snapshot "$work/report")
    # 130 with a new report in place: the signal came after it was complete
    # (during the final rename or the exit), and the report is whole.
    [ "$before" = "$after" ] || { grep -q "report was complete\|odelab-report: wrote" "$work/sigint-$delay.log" \
      && [ -f "$work/report/.odelab-report" ] && [ -f "$work/report/RESULTS.md" ]; } \
      || fail "SIGINT after $delay s: status 130 but the report folder changed"
  elif [ $status -eq 0 ] && { [ $sent = no ] || { grep -q "odelab-report: wrote" "$work/sigint-$delay.log" \
      && [ -f "$work/report/.odelab-report" ] && [ -f "$work/report/RESULTS.md" ]; }; }; then
    :  # finished before the signal, or it came while the lab was exiting with the report whole
  else
    fail "SIGINT after $delay s: status $status (signal sent: $sent)"
  fi
  before=$(snapshot "$work/report")
  leftovers=$(ls -a "$work" | grep '^\.report\.' || true)
  [ -z "$leftovers" ] || fail "SIGINT after $delay s left $leftovers"
  echo "SIGINT after $delay s: status $status"
done
[ -f "$work/report/RESULTS.md" ] || fail "the previous report is gone"

[ $failures -eq 0 ] && echo PASS || { echo "$failures failures"; exit 1; }

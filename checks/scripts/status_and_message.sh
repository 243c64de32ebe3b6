#!/bin/sh
# One run's ending, to the letter: its exit status and the words of its
# message on standard error.
#   status_and_message.sh STATUS PHRASE... -- PROGRAM ARGS...
# Each PHRASE must appear (fixed text) in what PROGRAM writes to stderr.
set -u
usage() { echo "usage: status_and_message.sh STATUS PHRASE... -- PROGRAM ARGS..."; exit 2; }
[ $# -ge 3 ] || usage
expected=$1; shift
phrases=""
while [ $# -gt 0 ] && [ "$1" != "--" ]; do phrases="$phrases$1
"; shift; done
[ $# -ge 2 ] || usage
shift
err=$(mktemp)
trap 'rm -f "$err"' EXIT
"$@" > /dev/null 2> "$err"
status=$?
echo "stderr: $(head -c 400 "$err")"
failures=0
if [ "$status" = "$expected" ]; then echo "ok:   status $status"
else echo "FAIL: status $status, expected $expected"; failures=$((failures + 1)); fi
while IFS= read -r phrase; do
  [ -n "$phrase" ] || continue
  if grep -qF -- "$phrase" "$err"; then echo "ok:   stderr says '$phrase'"
  else echo "FAIL: stderr does not say '$phrase'"; failures=$((failures + 1)); fi
done <<PHRASES
$phrases
PHRASES
[ "$failures" = 0 ]

#!/bin/sh
# interrupted_output.sh HOW PROGRAM CHECKER FILE COLUMNS INTERVAL ARGS...
#
# An output file must survive a run that does not end normally: it parses
# (CHECKER: check_output_file) up to its last complete row, and no metrics
# JSON, whole or partial, exists. HOW:
#   kill        the run (--seconds 100000, far beyond its end) is killed with
#               SIGKILL once FILE holds 200 lines;
#   file-limit  the run (--seconds 60) may write 2 KiB per file (ulimit -f 4,
#               SIGXFSZ ignored): it must stop with status 1 and a message
#               naming FILE.
# Either way FILE must not end with "# complete: ..." (a whole run's marker).
how=$1 program=$2 checker=$3 file=$4 columns=$5 interval=$6
shift 6
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_interrupted.XXXXXX") || exit 2
pid=
trap '[ -n "$pid" ] && kill -KILL "$pid" 2>/dev/null; rm -rf "$root"' EXIT
cd "$root" || exit 2
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
case $how in
  kill)
    "$program" --headless --seconds 100000 --metrics-json metrics.json "$@" >/dev/null 2>err.txt &
    pid=$!
    waited=0
    while [ "$(cat "$file" 2>/dev/null | wc -l)" -lt 200 ]; do
      kill -0 "$pid" 2>/dev/null || { fail "the run ended before it was killed"; cat err.txt; exit 1; }
      [ "$waited" -ge 600 ] && { fail "$file did not reach 200 lines within 60 s"; exit 1; }
      sleep 0.1
      waited=$((waited + 1))
    done
    kill -KILL "$pid"
    wait "$pid" 2>/dev/null
    status=$?
    pid=
    [ "$status" = 137 ] || fail "status $status after SIGKILL, expected 137"
    ;;
  file-limit)
    (ulimit -f 4; trap '' XFSZ; exec "$program" --headless --seconds 60 --metrics-json metrics.json "$@") >/dev/null 2>err.txt
    status=$?
    [ "$status" = 1 ] || fail "status $status, expected 1 (an output file could not be written)"
    grep -q "error: cannot write.*$file" err.txt || fail "no 'error: cannot write ... $file' message"
    sed 's/^/      stderr: /' err.txt | head -3
    ;;
  *) echo "usage: interrupted_output.sh kill|file-limit PROGRAM CHECKER FILE COLUMNS INTERVAL ARGS..."; exit 2 ;;
esac
[ -e metrics.json ] && fail "a metrics JSON exists after the interrupted run"
# The metrics' temporary file is .metrics.json.XXXXXX (utils/SafeFile.cpp).
for partial in .metrics.json.*; do
  [ -e "$partial" ] && fail "a partial metrics JSON ($partial) exists"
done
[ -s "$file" ] || { fail "$file is missing or empty"; exit 1; }
# A run cut short never claims to be whole.
grep -q '^# complete: ' "$file" && fail "$file says '# complete' after a run that was cut short"
# The complete part: everything up to the last newline.
bytes=$(wc -c < "$file")
complete=$(tr -cd '\n' < "$file" | wc -c)
head -n "$complete" "$file" > complete.txt
tail_bytes=$((bytes - $(wc -c < complete.txt)))
# Every line that is not a comment is a row, but the first: the column names.
rows=$(($(grep -vc '^#' complete.txt) - 1))
echo "$file: $bytes bytes, $complete complete lines ($rows rows), $tail_bytes bytes of an unfinished line after them"
"$checker" complete.txt --columns "$columns" --interval "$interval" --rows "$rows" || failures=$((failures + 1))
[ "$failures" = 0 ]

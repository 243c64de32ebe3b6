#!/bin/sh
# windows_files.sh EXE: what doc/hardening.md promises about files, held on
# Windows: EXE is test2.exe, run under Wine (WINEPREFIX set by the caller).
#
# 1. A long run writes Test2_output.txt; a second run into the same
#    --out-dir, started while the first writes, is refused with status 1
#    ("another run is writing it now") and leaves the first run's rows.
#    On Windows the file is held by a handle that shares reading only.
# 2. The first run ends with status 0, its file ends "# complete: ...", and
#    its metrics JSON exists.
# 3. A third run with the same --metrics-json replaces that file (on Windows
#    a rename fails when the target exists: MoveFileEx replaces it), and no
#    temporary file is left beside it.
exe=$1
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_windows_files.XXXXXX") || exit 2
trap 'rm -rf "$root"' EXIT
cd "$root" || exit 2
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# Several seconds of wall time at test2's speed under Wine; rows once a second.
wine "$exe" --headless --seconds 8000 --sample-interval 1 --metrics-json metrics.json >first.out 2>first.err &
first=$!
i=0
while [ ! -s Test2_output.txt ] || [ "$(grep -c '^[0-9]' Test2_output.txt)" -lt 2 ]; do
  i=$((i + 1))
  [ $i -gt 600 ] && { fail "the first run wrote no rows within 60 s"; cat first.err; exit 1; }
  sleep 0.1
done
before=$(grep -c '^[0-9]' Test2_output.txt)
status=0
wine "$exe" --headless --seconds 1 >second.out 2>second.err || status=$?
after=$(grep -c '^[0-9]' Test2_output.txt)
if ! kill -0 "$first" 2>/dev/null; then
  fail "the first run ended before the second was tried; make it longer"
elif [ "$status" = 1 ] && grep -q "another run is writing it now" second.err; then
  echo "ok:   a second writer was refused (status 1): $(head -c 150 second.err)"
else
  fail "the second run ended with status $status: $(head -c 300 second.err)"
fi
[ "$after" -ge "$before" ] && echo "ok:   the first run's rows kept ($before, then $after)" ||
  fail "the first run's rows shrank from $before to $after"

status=0
wait "$first" || status=$?
last=$(tail -n 1 Test2_output.txt)
if [ "$status" = 0 ] && [ -f metrics.json ]; then echo "ok:   the first run ended with status 0 and its metrics"
else fail "the first run ended with status $status (metrics: $(ls metrics.json 2>&1))"; cat first.err; fi
case $last in
  "# complete:"*) echo "ok:   Test2_output.txt ends '$last'" ;;
  *) fail "Test2_output.txt ends '$last', not '# complete: ...'" ;;
esac

old=$(grep -c . metrics.json)
status=0
mkdir third
wine "$exe" --headless --seconds 2 --out-dir third --metrics-json metrics.json >third.out 2>third.err || status=$?
if [ "$status" = 0 ] && grep -q '"sim_seconds": 2,' metrics.json; then
  echo "ok:   an existing metrics.json was replaced ($old lines before, $(grep -c . metrics.json) after)"
else
  fail "the third run (status $status) did not replace metrics.json: $(head -c 300 third.err)"
fi
leftovers=$(ls -A | grep '^\.metrics\.json\.' || true)
[ -z "$leftovers" ] && echo "ok:   no temporary file left" || fail "temporary files left: $leftovers"
[ "$failures" = 0 ]

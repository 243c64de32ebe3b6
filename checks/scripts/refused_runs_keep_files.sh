#!/bin/sh
# refused_runs_keep_files.sh TESTS_DIR [node]
#
# A run that is refused, or whose engine fails before its first step, leaves
# every file of the run before it as it was (doc/hardening.md, "Fourth
# round"), and no run writes a file it reads:
#   - with "node" (Jolt installed): test2 --engine jolt and test8 --compare
#     jolt with an engine process that dies at once (ODELAB_NODE=/bin/false)
#     end with status 7 (the engine failed), and the previous run's
#     Test2_output.txt / Test8_output.txt are byte for byte as they were; the
#     compare run leaves no jolt/ folder;
#   - odelab --world w.json with --metrics-json or --export-world naming
#     w.json (the same path, another spelling of it, or the same file by a
#     link), and test2 with --events or --font naming a file --metrics-json or
#     --screenshot names: status 2, before anything runs, the input intact;
#   - --compare jolt,rapier with a file named rapier in the way: status 2,
#     no jolt/ folder left.
tests=$(cd "$1" && pwd) node=${2:-}
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_refused_runs.XXXXXX") || exit 2
trap 'rm -rf "$root"' EXIT
cd "$root" || exit 2
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
ok() { echo "ok:   $*"; }

# same NAME FILE COPY: FILE is byte for byte COPY
same() {
  if cmp -s "$2" "$3"; then ok "$1: $2 kept"; else fail "$1: $2 changed ($(tail -n 1 "$2" 2>/dev/null))"; fi
}

# expect NAME STATUS EXPECTED: the status and, for 2, an error on stderr
expect() {
  if [ "$2" = "$3" ]; then ok "$1: status $2"; else fail "$1: status $2, expected $3: $(head -n 2 err.txt)"; fi
}

# A complete run's files, kept to compare with.
"$tests/test2" --headless --seconds 0.2 >/dev/null 2>&1 || fail "the first test2 run failed"
"$tests/test8" --headless --seconds 0.2 >/dev/null 2>&1 || fail "the first test8 run failed"
cp Test2_output.txt before2.txt && cp Test8_output.txt before8.txt

if [ "$node" = node ]; then
  ODELAB_NODE=/bin/false "$tests/test2" --headless --seconds 1 --engine jolt >/dev/null 2>err.txt
  expect "test2 --engine jolt, the engine dead at once" $? 7
  grep -q "jolt" err.txt || fail "test2 --engine jolt: the error does not name the engine: $(cat err.txt)"
  same "test2 --engine jolt, the engine dead at once" Test2_output.txt before2.txt

  ODELAB_NODE=/bin/false "$tests/test8" --headless --seconds 1 --compare jolt >/dev/null 2>err.txt
  expect "test8 --compare jolt, the engine dead at once" $? 7
  same "test8 --compare jolt, the engine dead at once" Test8_output.txt before8.txt
  [ -e jolt ] && fail "test8 --compare jolt left a jolt/ folder: $(ls -A jolt)"

  touch rapier
  "$tests/test8" --headless --seconds 1 --compare jolt,rapier >/dev/null 2>err.txt
  expect "--compare jolt,rapier with a file named rapier" $? 2
  [ -e jolt ] && fail "--compare jolt,rapier refused left a jolt/ folder"
  rm -f rapier
fi

# A world file, and every way of naming it as a run's output.
"$tests/test2" --export-world w.json >/dev/null 2>&1 || fail "test2 --export-world failed"
cp w.json world-before.json
mkdir sub
ln -s "$root/w.json" link.json
for output in "--metrics-json w.json" "--metrics-json sub/../w.json" "--metrics-json $root/w.json" \
              "--export-world w.json" "--export-world ./w.json"; do
  cp world-before.json w.json
  # shellcheck disable=SC2086
  "$tests/odelab" --world w.json --headless --seconds 0.1 $output >/dev/null 2>err.txt
  expect "odelab --world w.json $output" $? 2
  grep -q "reads" err.txt || fail "odelab --world w.json $output: the error does not say the run reads it: $(cat err.txt)"
  same "odelab --world w.json $output" w.json world-before.json
done
# The world read through a link, the output named by its real path.
cp world-before.json w.json
"$tests/odelab" --world link.json --headless --seconds 0.1 --metrics-json w.json >/dev/null 2>err.txt
expect "odelab --world link.json --metrics-json w.json (one file)" $? 2
same "odelab --world link.json --metrics-json w.json" w.json world-before.json
# The world named as the scene's own output file in --out-dir.
cp world-before.json world_run_log.txt && cp world-before.json log-before.txt
"$tests/odelab" --world world_run_log.txt --headless --seconds 0.1 >/dev/null 2>err.txt
expect "odelab --world world_run_log.txt (its own run log)" $? 2
same "odelab --world world_run_log.txt" world_run_log.txt log-before.txt

# A window run's inputs, refused at the command line (no display needed).
printf '# no input\n' > script.events && cp script.events script-before.events
"$tests/test2" --events script.events --metrics-json script.events >/dev/null 2>err.txt
expect "test2 --events script.events --metrics-json script.events" $? 2
grep -q "reads" err.txt || fail "test2 --events: the error does not say the run reads it: $(cat err.txt)"
same "test2 --events script.events --metrics-json script.events" script.events script-before.events
printf 'font' > f.ttf && cp f.ttf f-before.ttf
"$tests/test2" --font f.ttf --screenshot f.ttf >/dev/null 2>err.txt
expect "test2 --font f.ttf --screenshot f.ttf" $? 2
grep -q "reads" err.txt || fail "test2 --font: the error does not say the run reads it: $(cat err.txt)"
same "test2 --font f.ttf --screenshot f.ttf" f.ttf f-before.ttf
[ "$failures" = 0 ]

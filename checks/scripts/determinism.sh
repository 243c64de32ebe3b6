#!/bin/sh
# determinism.sh PROGRAM OTHER_SEED ARGS...
#
# Runs PROGRAM --headless ARGS twice, each in a fresh folder (its --out-dir),
# and checks that both end with status 0, report the same state_hash in
# their metrics JSON and write the same set of output files, byte for byte
# (cmp). The metrics JSON itself is not compared: wall_seconds and
# real_time_factor differ from run to run by nature. With OTHER_SEED (not
# "none"), a third run with --seed OTHER_SEED must report a different hash,
# so the hash is shown to depend on the seeded choices.
program=$1 other_seed=$2
shift 2
root=$(mktemp -d "${TMPDIR:-/tmp}/odelab_determinism.XXXXXX") || exit 2
trap 'rm -rf "$root"' EXIT
hash_of() {
  sed -n 's/^ *"state_hash": *\([0-9][0-9]*\).*/\1/p' "$1/metrics.json"
}
run() {  # run NAME ARGS...
  name=$1
  shift
  mkdir "$root/$name"
  (cd "$root/$name" && timeout 300 "$program" --headless "$@" --metrics-json metrics.json >/dev/null 2>"$root/$name.err")
  status=$?
  if [ "$status" != 0 ]; then
    echo "FAIL: run $name ended with status $status"
    sed 's/^/      stderr: /' "$root/$name.err" | head -5
    exit 1
  fi
}
run a "$@"
run b "$@"
a=$(hash_of "$root/a") b=$(hash_of "$root/b")
failures=0
if [ -z "$a" ]; then
  echo "FAIL: no state_hash in the metrics"
  exit 1
fi
if [ "$a" = "$b" ]; then echo "ok:   state_hash $a in both runs"
else echo "FAIL: state_hash $a, then $b"; failures=$((failures + 1)); fi
files_a=$(cd "$root/a" && ls | grep -v '^metrics\.json$')
files_b=$(cd "$root/b" && ls | grep -v '^metrics\.json$')
if [ "$files_a" != "$files_b" ]; then
  echo "FAIL: the runs wrote different files: [$files_a] and [$files_b]"
  failures=$((failures + 1))
fi
for f in $files_a; do
  if cmp "$root/a/$f" "$root/b/$f"; then echo "ok:   $f identical ($(wc -c < "$root/a/$f") bytes)"
  else failures=$((failures + 1)); fi
done
if [ "$other_seed" != none ]; then
  run c "$@" --seed "$other_seed"
  c=$(hash_of "$root/c")
  if [ "$c" != "$a" ]; then echo "ok:   --seed $other_seed gives another state_hash ($c)"
  else echo "FAIL: --seed $other_seed gives the same state_hash"; failures=$((failures + 1)); fi
fi
[ "$failures" = 0 ]

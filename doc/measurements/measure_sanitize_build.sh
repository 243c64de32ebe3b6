#!/bin/sh
# Times checks/sanitize.sh from scratch (build-sanitize/ removed first) and
# the compile of one scene under the sanitizers at -O0 (what the preset
# uses) and at -O2, and writes what doc/hardening.md quotes as a CSV with
# its run header:
#
#   doc/measurements/measure_sanitize_build.sh [CSV]
#
# CSV defaults to doc/measurements/sanitize_build.csv: one row per figure
# (quantity, value, unit, note). The build's wall time and the runs' come
# from sanitize.sh's own lines; its CPU time is user + system of the whole
# run, children included. About 5 minutes on 2 cores. Status 1 when the
# sanitizer check itself failed (the figures are written all the same).
set -eu
USAGE_LINES=2,13p
. "$(dirname "$0")/common.sh"
csv=${1:-$root/doc/measurements/sanitize_build.csv}
scene=tests/scenes/test10_maximum_velocity.cpp  # the largest scene source
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
[ -x /usr/bin/time ] || { echo "measure_sanitize_build: needs GNU time (apt-get install time)" >&2; exit 2; }

# The check from scratch, as scripts/odelab.sh test runs it.
rm -rf "$root/build-sanitize"
/usr/bin/time -f '%U %S' -o "$work/cpu" sh "$root/checks/sanitize.sh" >"$work/sanitize.log" 2>&1 || status=1
built=$(sed -n 's/^sanitize: configured and built in \([0-9]*\) s$/\1/p' "$work/sanitize.log")
ran=$(sed -n 's/^sanitize: ran in \([0-9]*\) s;.*/\1/p' "$work/sanitize.log")
cpu=$(awk '{printf "%.0f", $1 + $2}' "$work/cpu")
[ -n "$built" ] && [ -n "$ran" ] || { echo "measure_sanitize_build: sanitize.sh printed no timings:" >&2; tail -n 20 "$work/sanitize.log" >&2; exit 1; }

# One scene's compile command from the sanitizer configuration, at -O0 and -O2.
cmake -S "$root" -B "$work/flags" -DCMAKE_BUILD_TYPE=Debug -DODELAB_SANITIZE=ON -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >/dev/null
command=$(python3 - "$work/flags/compile_commands.json" "$root/$scene" <<'PY'
import json, sys
for entry in json.load(open(sys.argv[1])):
    if entry["file"] == sys.argv[2]:
        print(entry["directory"] + "\n" + entry["command"])
        break
PY
)
[ -n "$command" ] || { echo "measure_sanitize_build: no compile command for $scene" >&2; exit 1; }
directory=$(echo "$command" | head -n 1)
compile=$(echo "$command" | tail -n 1 | sed 's/ -o [^ ]*/ -o \/dev\/null/')
seconds() {  # seconds EXTRA-FLAGS: wall time of the compile with those flags last
  start=$(date +%s.%N)
  (cd "$directory" && eval "$compile $1") >/dev/null 2>&1 || { echo "measure_sanitize_build: the compile failed" >&2; exit 1; }
  echo "$(date +%s.%N) $start" | awk '{printf "%.1f", $1 - $2}'
}
o0=$(seconds "-O0")
o2=$(seconds "-O2")
[ -n "$o0" ] && [ -n "$o2" ] || exit 1

measurement_header "doc/measurements/measure_sanitize_build.sh" >"$work/csv"
{
  echo "quantity,value,unit,note"
  echo "sanitize_build_wall,$built,s,checks/sanitize.sh: configure and build from scratch at -O0 (its own line)"
  echo "sanitize_build_and_runs_cpu,$cpu,s,user + system of the whole check"
  echo "sanitize_runs_wall,$ran,s,checks/sanitize.sh: the unit tests and every program's runs (its own line)"
  echo "scene_compile_O0,$o0,s,$scene under the sanitizers at -O0"
  echo "scene_compile_O2,$o2,s,$scene under the sanitizers at -O2"
} >>"$work/csv"
mv "$work/csv" "$csv"
echo "measure_sanitize_build: wrote $csv"
exit $status

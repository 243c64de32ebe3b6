#!/bin/sh
# Runs the window-fuzzing checks with the CI seeds, one at a time
# (ctest -j1 -R fuzz_window -V; about 3 minutes on 2 cores, under Xvfb) and
# writes what doc/hardening.md quotes of each run as a CSV with its run
# header:
#
#   doc/measurements/measure_fuzz_window.sh [CSV]
#
# CSV defaults to doc/measurements/fuzz_window.csv, one row per program:
# its seed, frames, wall seconds, mean ms a frame (drawing and stepping) and
# longest frame in ms, from the window's own last line, and the check's wall
# time from CTest. Uses the build in BUILD_DIR (default: build/).
set -eu
USAGE_LINES=2,12p
. "$(dirname "$0")/common.sh"
csv=${1:-$root/doc/measurements/fuzz_window.csv}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
log=$work/ctest.txt
status=0
ctest --test-dir "$build" -j1 -R '^fuzz_window_test[0-9]+$' -V > "$log" 2>&1 || status=1
measurement_header "doc/measurements/measure_fuzz_window.sh (ctest -j1 -R fuzz_window -V; a 960 x 600 window at the \
start, Mesa llvmpipe under Xvfb)" > "$work/csv"
python3 - "$log" >> "$work/csv" <<'PY'
import re, sys
log = sys.argv[1]
text = open(log, errors="replace").read()
# ctest -V prefixes each test's lines with its number: the seed line names the program.
programs = {n: (p, seed) for n, seed, p in re.findall(r"(\d+): fuzz seed (\d+): \d+ events into (test\d+)", text)}
window = re.compile(r"(\d+): window: (\d+) frames in ([\d.]+) s \([\d.]+ fps; ([\d.]+) ms per frame drawing and "
                    r"stepping; longest frame ([\d.]+) ms")
checks = dict(re.findall(r"Test +#\d+: fuzz_window_(test\d+) \.+ +\S+ +([\d.]+) sec", text))
rows = []
for number, frames, wall, mean, longest in window.findall(text):
    program, seed = programs.get(number, ("", ""))
    rows.append((program, seed, frames, wall, mean, longest, checks.get(program, "")))
if not rows:
    sys.exit("measure_fuzz_window: no window line in the checks' output")
print("program,seed,frames,wall_s,mean_ms_per_frame,longest_frame_ms,check_wall_s")
for row in rows:
    print(",".join(row))
PY
mv "$work/csv" "$csv"
echo "measure_fuzz_window: wrote $csv"
exit $status

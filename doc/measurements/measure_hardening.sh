#!/bin/sh
# Measures the figures doc/hardening.md quotes from checks that are quick to
# run again, and writes them as a CSV with its run header:
#
#   doc/measurements/measure_hardening.sh [CSV]
#
# CSV defaults to doc/measurements/hardening.csv, one row per figure
# (quantity, value, unit, detail): the checks labelled hardening, run as CI
# runs them (ctest -j2 -L hardening -V, one to two minutes on 2 cores):
# their count and wall time, and each check's wall time; the
# extreme-settings grid's rows alone (ctest -j2 -R ^extreme_settings_grid_
# -V): their runs, wall time, failures and slowest run; the lab's inputs
# check alone; and the simulated time at which test5's island-stepping
# thread fails (test5 --headless --threads 2 --solver step --plates 20
# --seconds 3).
# Uses the build in BUILD_DIR (default: build/), configured with its checks.
set -eu
USAGE_LINES=2,16p
. "$(dirname "$0")/common.sh"
csv=${1:-$root/doc/measurements/hardening.csv}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ctest --test-dir "$build" -j2 -L hardening -V > "$work/hardening.txt" 2>&1 || true
ctest --test-dir "$build" -j2 -R '^extreme_settings_grid_' -V > "$work/grid.txt" 2>&1 || true
"$build/tests/test5" --headless --threads 2 --solver step --plates 20 --seconds 3 --out-dir "$work" \
  > "$work/test5.txt" 2>&1 || true
ctest --test-dir "$build" -R '^lab_inputs_checked_and_every_ending_clean$' > "$work/checks.txt" 2>&1 || true
measurement_header doc/measurements/measure_hardening.sh > "$work/csv"
python3 - "$work" >> "$work/csv" <<'PY'
import re, sys
from pathlib import Path
work = Path(sys.argv[1])
rows = []
hardening = (work / "hardening.txt").read_text(errors="replace")
grid = (work / "grid.txt").read_text(errors="replace")
total = re.search(r"(\d+)% tests passed, (\d+) tests failed out of (\d+)", hardening)
real = re.search(r"Total Test time \(real\) = +([\d.]+) sec", hardening)
grid_real = re.search(r"Total Test time \(real\) = +([\d.]+) sec", grid)
if not (total and real and grid_real):
    sys.exit("measure_hardening: no CTest total in ctest -L hardening's or the grid's output")
# The grid's rows each print their table: program step ERP CFM iter solver
# sim_s wall_s result detail (ctest -V puts "N: " before every line).
table = [line.split(": ", 1)[-1].split() for line in grid.splitlines()]
runs = [cells for cells in table if len(cells) >= 9 and re.fullmatch(r"test\d+", cells[0])
        and re.fullmatch(r"[\d.]+", cells[7])]
if not runs:
    sys.exit("measure_hardening: no run of the grid in its rows' output")
rows += [("hardening_checks", total.group(3), "checks", f"{total.group(2)} failed"),
         ("hardening_wall", real.group(1), "s", "ctest -j2 -L hardening"),
         ("grid_runs", str(len(runs)), "runs", ""),
         ("grid_wall", grid_real.group(1), "s", "ctest -j2 -R ^extreme_settings_grid_, alone"),
         ("grid_failed", str(sum(cells[8] == "FAILED" for cells in runs)), "runs", "")]
slowest = max(runs, key=lambda cells: float(cells[7]))
rows.append(("grid_slowest_run_wall", slowest[7], "s", " ".join(f"{k} {v}" for k, v in zip(
    ("program", "step", "ERP", "CFM", "iterations", "solver"), slowest[:6]))))
test5 = (work / "test5.txt").read_text(errors="replace")
when = re.search(r"at t=([\d.]+) s", test5)
if not when:
    sys.exit("measure_hardening: test5's thread error named no time: " + test5[-300:])
rows.append(("test5_thread_error_time", when.group(1), "s simulated", "test5 --headless --threads 2 --solver step --plates 20 --seconds 3"))
# The grid's 231 rows are given by the grid's figures above, not one by one.
for name, seconds in re.findall(r"Test +#\d+: (\S+) \.+ +Passed +([\d.]+) sec", hardening):
    if name.startswith("extreme_settings_grid_"):
        continue
    rows.append((f"check_wall:{name}", seconds, "s", "ctest -j2 -L hardening"))
for name, seconds in re.findall(r"Test +#\d+: (\S+) \.+ +Passed +([\d.]+) sec", (work / "checks.txt").read_text()):
    rows.append((f"check_wall:{name}", seconds, "s", "alone"))
print("quantity,value,unit,detail")
for row in rows:
    print(",".join(row))
PY
mv "$work/csv" "$csv"
echo "measure_hardening: wrote $csv"

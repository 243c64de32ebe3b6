#!/bin/sh
# Runs checks/long_runs.sh (test0 for 30 simulated minutes, test5 with 300
# plates; about 5 minutes) and writes what doc/hardening.md quotes from it
# as a CSV with its run header:
#
#   doc/measurements/measure_long_runs.sh [CSV]
#
# CSV defaults to doc/measurements/long_runs.csv: one row per figure (run,
# quantity, value, unit): the runs' metrics, their wall time, and resident
# memory (VmRSS, sampled every second) at the start, at the end of warm-up,
# its highest after warm-up and at the end. Uses the Release build in
# BUILD_DIR (default: build/). Status 1 when a long run's check failed.
set -eu
USAGE_LINES=2,12p
. "$(dirname "$0")/common.sh"
csv=${1:-$root/doc/measurements/long_runs.csv}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
status=0
BUILD_DIR=$build sh "$root/checks/long_runs.sh" || status=1
measurement_header "doc/measurements/measure_long_runs.sh (checks/long_runs.sh; samples in build/long_runs/)" > "$work/csv"
python3 - "$build/long_runs" >> "$work/csv" <<'PY'
import json, sys
from pathlib import Path
folder = Path(sys.argv[1])
# The warm-up fractions of checks/long_runs.sh: a quarter of test0's samples, half of test5's.
runs = {"test0_30_minutes": 0.25, "test5_300_plates": 0.5}
metrics = {"test0_30_minutes": ["sim_seconds", "wall_seconds", "spawned", "removed_bodies", "bodies", "disabled_bodies",
                                "max_bodies", "non_finite"],
           "test5_300_plates": ["sim_seconds", "wall_seconds", "ms_per_step", "plates", "landed_plates", "bodies",
                                "stack_height", "max_axis_offset", "max_twist_degrees", "non_finite"]}
rows = []
for run, warmup in runs.items():
    m = json.loads((folder / f"{run}.json").read_text())
    rows += [(run, name, m[name], "") for name in metrics[run]]
    samples = [tuple(map(int, line.split())) for line in (folder / f"{run}.rss").read_text().splitlines() if line.strip()]
    w = max(1, int(len(samples) * warmup)) - 1
    after = samples[w:]
    mib = lambda kb: round(kb / 1024, 2)
    rows += [(run, "rss_first_MiB", mib(samples[0][1]), f"at t={samples[0][0]} s wall"),
             (run, "rss_end_of_warmup_MiB", mib(samples[w][1]), f"at t={samples[w][0]} s wall"),
             (run, "rss_max_after_warmup_MiB", mib(max(r for _, r in after)), ""),
             (run, "rss_last_MiB", mib(samples[-1][1]), f"at t={samples[-1][0]} s wall"),
             (run, "rss_growth_after_warmup_MiB", mib(max(r for _, r in after) - samples[w][1]), "")]
print("run,quantity,value,note")
for run, name, value, note in rows:
    print(f"{run},{name},{value},{note}")
PY
mv "$work/csv" "$csv"
echo "measure_long_runs: wrote $csv"
exit $status

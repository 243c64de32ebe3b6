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
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
case ${1:-} in -h | --help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;; -*) echo "measure_long_runs: unknown option $1" >&2; exit 2 ;; esac
csv=${1:-$here/long_runs.csv}
build=${BUILD_DIR:-$root/build}
load=$(cut -d' ' -f1-3 /proc/loadavg)
status=0
BUILD_DIR=$build sh "$root/checks/long_runs.sh" || status=1
python3 - "$build/long_runs" "$csv" "$load" "$(git -C "$root" rev-parse HEAD 2>/dev/null || echo unknown)" <<'PY'
import json, sys, time
from pathlib import Path
folder, csv_path, load, commit = Path(sys.argv[1]), sys.argv[2], sys.argv[3], sys.argv[4]
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
with open(csv_path, "w") as out:
    out.write("# measured by: doc/measurements/measure_long_runs.sh (checks/long_runs.sh; samples in build/long_runs/)\n")
    out.write(f"# date: {time.strftime('%Y-%m-%d %H:%M:%S +0000', time.gmtime())}\n")
    out.write(f"# commit: {commit}\n# load average at the start: {load}\n")
    out.write("run,quantity,value,note\n")
    for run, name, value, note in rows:
        out.write(f"{run},{name},{value},{note}\n")
print(f"measure_long_runs: wrote {csv_path}")
PY
exit $status

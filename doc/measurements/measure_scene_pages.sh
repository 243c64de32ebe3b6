#!/bin/sh
# Runs the headless commands whose figures the scene pages doc/tests/test1, 3,
# 4, 5, 6, 7 and 10 .md quote and that the report does not run, and writes the
# figures quoted as a CSV with its run header:
#
#   doc/measurements/measure_scene_pages.sh [CSV]
#
# CSV defaults to doc/measurements/scene_pages.csv: one row per figure
# (program, arguments, repeat, metric, value, exit status). The metrics are the
# programs' own (deterministic: one run each), except the costs of test3 and
# test5, and build/checks/bench_swept_collision's timings: those are repeated
# (three times, interleaved; the benchmark twice), and cpu_seconds
# is the run's CPU time (user + system, from the kernel's account of the
# child). Uses the Release build in BUILD_DIR (default: build/). About five
# minutes.
set -eu
USAGE_LINES=2,15p
. "$(dirname "$0")/common.sh"
csv=${1:-$root/doc/measurements/scene_pages.csv}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
measurement_header "doc/measurements/measure_scene_pages.sh" > "$work/csv"
python3 - "$build/tests" "$work" >> "$work/csv" <<'PY'
import csv, json, re, resource, subprocess, sys
from pathlib import Path

programs, work = Path(sys.argv[1]), Path(sys.argv[2])
BOUNCE = ("max_rebound_error", "worst_ball", "balls_measured", "balls_bounced")
HOLD = ("held", "seconds_held", "max_tilt_degrees", "max_penetration")
UPRIGHT = ("fell", "seconds_upright")
STOP = ("launches", "passed_through", "stopped", "max_stop_energy_ratio")
COST = ("cpu_seconds", "real_time_factor", "bodies", "disabled_bodies")
# (program, arguments, metrics kept, repeats): the commands as the pages write them.
RUNS = [("test1", f"--seconds 15 --cfm 0 {a}", BOUNCE, 1) for a in ("--erp 0.2", "--erp 0.8", "--erp 0 --bounce-velocity 2")]
RUNS += [("test3", a, COST, 3) for a in ("--seconds 20", "--seconds 20 --no-auto-disable",
                                         "--seconds 20 --no-auto-disable --iterations 20",
                                         "--seconds 9", "--seconds 9 --no-auto-disable")]
RUNS += [("test4", f"--seconds {t} --big-mass 5000 --seed {s}", HOLD, 1) for t in (20, 60) for s in range(1, 7)]
RUNS += [("test4", f"--seconds {t} --big-mass {m} --seed {s}", HOLD, 1)
         for t, m in ((60, 10000), (20, 15000), (20, 20000)) for s in range(1, 4)]
RUNS += [("test4", a, HOLD, 1) for a in ("--cfm 1e-5", "--cfm 1e-4", "--cfm 1e-3", "--erp 0.05")]
RUNS += [("test5", f"--seconds 20 --plates 50 --spawn-interval 0.3 --seed {s}",
          ("landed_plates", "max_axis_offset", "stack_height", "max_twist_degrees"), 1) for s in (2, 3)]
PLATES = "--seconds 20 --plates 50 --spawn-interval 0.3"
RUNS += [("test5", f"{PLATES} {a}".rstrip(), ("ms_per_step", "real_time_factor", "max_axis_offset"), 3)
         for a in ("", *(f"--auto-disable --auto-disable-linear {v} --auto-disable-angular {w}"
                         for v, w in (("0.01", "0.01"), ("0.3", "0.01"), ("0.01", "0.05"), ("0.05", "0.05"),
                                      ("0.3", "0.05"))))]
RUNS += [("test5", f"--plates 100 --seconds 35 --space {s}", ("cpu_seconds", "max_axis_offset"), r)
         for s, r in (("simple", 3), ("hash", 3), ("sap", 1), ("quadtree", 1))]
RUNS += [("test6", f"--seconds 20 {a}", UPRIGHT, 1) for a in ("--mu 1", "--mu 0.5", "--max-contacts 4", "--max-contacts 1")]
RUNS += [("test7", f"--max-angular-speed 10 --throws 3 --seed {s}", ("max_joint_error", "max_angular_speed"), 1)
         for s in range(1, 11)]
RUNS += [("test7", f"--max-angular-speed 0 --throws 3 --seed {s}", ("max_joint_error", "max_angular_speed"), 1)
         for s in range(1, 6)]
RUNS += [("test7", "--max-angular-speed 0 --throws 1", ("max_joint_error", "max_angular_speed"), 1)]
RUNS += [("test10", "--find-max-velocity", ("launches", "passed_through", "band_upper_velocity",
                                            "velocities_passed_in_band"), 1)]
RUNS += [("test10", f"--ccd --velocity {a}", STOP, 1) for a in ("200 --launches 5", "10000 --launches 5",
                                                                "10000 --launches 20",
                                                                "10000 --launches 100 --random-orientation")]

# test10.md's cost of the sweep: the benchmark's own lines ("what: 15.9 ns"), two runs.
BENCH = programs.parent / "checks" / "bench_swept_collision"
missing = sorted({program for program, *_ in RUNS if not (programs / program).is_file()})
missing += [] if BENCH.is_file() else [BENCH.name]
if missing:
    sys.exit(f"measure_scene_pages: no {', '.join(missing)} in {programs} (build them, or set BUILD_DIR)")
rows = []
for repeat in range(1, max(r[3] for r in RUNS) + 1):  # interleaved: every command once per round
    for program, arguments, kept, repeats in RUNS:
        if repeat > repeats:
            continue
        out = work / "metrics.json"
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        rc = subprocess.run([str(programs / program), "--headless", *arguments.split(), "--metrics-json", str(out)],
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        if not out.exists():
            sys.exit(f"measure_scene_pages: {program} {arguments} wrote no metrics (status {rc})")
        metrics = json.loads(out.read_text())
        out.unlink()
        metrics["cpu_seconds"] = round(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime, 3)
        for name in kept:
            if name not in metrics:
                sys.exit(f"measure_scene_pages: {program} {arguments} reported no {name}")
            rows.append((program, arguments, repeat, name, metrics[name], rc))
for repeat in (1, 2):
    run = subprocess.run([str(BENCH)], capture_output=True, text=True)
    timed = [re.fullmatch(r"(.+?):\s+([0-9.]+)( ns)?", line.strip()) for line in run.stdout.splitlines()]
    rows += [(BENCH.name, "", repeat, m.group(1) + (" (ns)" if m.group(3) else ""), m.group(2), run.returncode)
             for m in timed if m]
out = csv.writer(sys.stdout, lineterminator="\n")
out.writerow(("program", "arguments", "repeat", "metric", "value", "exit_status"))
out.writerows(rows)
PY
mv "$work/csv" "$csv"
echo "measure_scene_pages: wrote $csv"

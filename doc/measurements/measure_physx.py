#!/usr/bin/python3
"""Runs the scenes on PhysX (`--engine physx`) at the settings and options
that doc/peers.md ("PhysX") and checks/engine_claims_physx.cmake quote, and
writes the metrics they quote as a CSV with the run header every CSV here
starts with:

  /usr/bin/python3 doc/measurements/measure_physx.py [--csv CSV] [--build BUILD] [--jobs N]

CSV defaults to doc/measurements/physx.csv: one row per figure (scene,
setting, options, metric, value). Each run is made once: the engine is
deterministic (the same figures twice, digit for digit). Uses
build/tests/testN of BUILD (default: BUILD_DIR, else build/). About four
minutes on two shared cores with --jobs 2."""

import argparse
import concurrent.futures
import json
import os
import platform
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "lab"))

from odelab_report import files  # noqa: E402

# (scene, setting, options, metrics kept): every run the page and the claims quote.
RUNS = [
    ("test2", "default", ["--seconds", "20"], ["energy_drift", "energy_max_deviation", "period_error"]),
    ("test2", "best", ["--seconds", "20"], ["energy_drift", "energy_max_deviation", "period_error"]),
    ("test8", "default", ["--seconds", "20"], ["max_relative_elongation"]),
    ("test8", "best", ["--seconds", "20"], ["max_relative_elongation"]),
    ("test9", "default", ["--seconds", "21"], ["apex_error_20", "bounces"]),
    ("test9", "best", ["--seconds", "21"], ["apex_error_20", "bounces"]),
    ("test1", "default", [], ["max_rebound_error", "worst_ball", "balls_measured"]),
    ("test1", "best", [], ["max_rebound_error", "worst_ball", "balls_measured"]),
    ("test4", "default", [], ["held", "seconds_held", "max_penetration", "max_tilt_degrees"]),
    ("test4", "best", [], ["held", "seconds_held", "max_penetration", "max_tilt_degrees"]),
    ("test6", "default", ["--seconds", "5"], ["sink_while_upright_metres"]),
    ("test6", "best", ["--seconds", "5"], ["sink_while_upright_metres"]),
    ("test10", "default", ["--velocity", "5000"], ["stopped", "passed_through"]),
    ("test10", "best", ["--velocity", "5000"], ["stopped", "passed_through"]),
    ("test7", "default", [], ["max_joint_error", "cube_passed_pivot", "throws"]),
    ("test7", "best", [], ["max_joint_error", "cube_passed_pivot", "throws"]),
    ("test5", "default", ["--plates", "10", "--seconds", "5"],
     ["landed_plates", "stack_height", "max_axis_offset", "max_twist_degrees"]),
    ("test5", "best", ["--plates", "10", "--seconds", "5"],
     ["landed_plates", "stack_height", "max_axis_offset", "max_twist_degrees"]),
    ("test3", "default", [], ["fallen_fraction", "active_bodies"]),
    ("test3", "best", [], ["fallen_fraction", "active_bodies"]),
]
# The cost of the engine's own step calls, for every run.
COST = ["engine_cpu_seconds", "steps"]


def header(command):
    cpu = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                if line.startswith("model name")), platform.processor() or "unknown")
    commit = subprocess.run(["git", "-C", str(ROOT), "rev-parse", "HEAD"], capture_output=True, text=True)
    return [f"# measured by: {command}", f"# CPU: {cpu}, {os.cpu_count()} cores, shared with other work",
            f"# load average at the start: {' '.join(Path('/proc/loadavg').read_text().split()[:3])}",
            f"# date: {time.strftime('%Y-%m-%d %H:%M:%S +0000', time.gmtime())}",
            f"# commit: {commit.stdout.strip() if commit.returncode == 0 else 'unknown'}"]


def run(build, scene, setting, options):
    """One headless run in a folder of its own: its metrics."""
    with tempfile.TemporaryDirectory(prefix="measure_physx.") as folder:
        metrics = Path(folder) / "m.json"
        command = [str(build / "tests" / scene), "--headless", "--engine", "physx", "--engine-setting", setting,
                   "--out-dir", folder, "--metrics-json", str(metrics), *options]
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0 or not metrics.exists():
            raise RuntimeError(f"{' '.join(command)} ended with status {done.returncode}: {done.stderr[-500:]}")
        return json.loads(metrics.read_text())


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("--csv", type=Path, default=ROOT / "doc" / "measurements" / "physx.csv",
                        help="the CSV to write (default: doc/measurements/physx.csv)")
    parser.add_argument("--build", type=Path, default=Path(os.environ.get("BUILD_DIR", ROOT / "build")),
                        help="the build folder holding tests/testN (default: BUILD_DIR, else build/)")
    parser.add_argument("--jobs", type=int, default=1, help="runs at a time (default 1)")
    args = parser.parse_args(argv)
    for scene in sorted({r[0] for r in RUNS}):
        if not os.access(args.build / "tests" / scene, os.X_OK):
            parser.error(f"no program {args.build / 'tests' / scene}")
    files.check_writable(args.csv)
    lines = header("/usr/bin/python3 doc/measurements/measure_physx.py")
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        results = list(pool.map(lambda r: run(args.build, r[0], r[1], r[2]), RUNS))
    lines.append("scene,setting,options,metric,value")
    for (scene, setting, options, kept), metrics in zip(RUNS, results):
        for metric in kept + COST:
            lines.append(f"{scene},{setting},{' '.join(options)},{metric},{metrics.get(metric, '')}")
    files.write_atomically(args.csv, ("\n".join(lines) + "\n").encode())
    print(f"measure_physx: wrote {args.csv} ({len(lines) - 6} rows)", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/env python3
"""The engine adapters' cost per step: how long a step of test1 (50 balls)
and test2 (the pendulum) takes inside each engine's own collision and step
calls (the metric engine_wall_seconds), against the time outside them in the
same run loop: passing edits and states through the adapter (for Havok, Jolt
and Rapier the pipe to Node.js), writing the states into the ODE bodies, and
the scene's own measurement. Both are per step, the median and range of
--repeats interleaved runs (each engine's first run, then each one's second,
so a busy spell of the machine falls on every engine alike).

    python3 checks/bench_engine_overhead.py [--build build] [--seconds 10] [--repeats 5] [--csv FILE]

It prints figures; it judges nothing. Engines not available here are named
and left out (their --list-engines line says why)."""

import argparse
import csv
import datetime
import io
import json
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lab"))
from odelab_report import files  # noqa: E402

SCENES = ("test1", "test2")


def available_engines(program):
    """[(name, available, why)] from `program --list-engines`."""
    out = subprocess.run([program, "--list-engines"], capture_output=True, text=True, check=True).stdout
    engines = []
    for line in out.splitlines():
        if not line.startswith(" ") and ": " in line:
            name, rest = line.split(": ", 1)
            engines.append([name, rest.startswith("available"), ""])
        elif line.strip().startswith("missing:") and engines:
            engines[-1][2] = line.strip()[len("missing: "):]
    return engines


def one_run(program, engine, seconds, folder):
    metrics = Path(folder) / "m.json"
    args = [program, "--headless", "--seconds", str(seconds), "--metrics-json", str(metrics), "--out-dir", folder]
    if engine != "ode":
        args += ["--engine", engine]
    subprocess.run(args, capture_output=True, text=True, check=True)
    m = json.loads(metrics.read_text())
    steps = m["steps"]
    inside = m["engine_wall_seconds"] / steps
    outside = (m["wall_seconds"] - m["engine_wall_seconds"]) / steps
    return inside, outside


def spread(values):
    return statistics.median(values), min(values), max(values)


def write_rows(path, rows):
    """The rows (dicts of one set of keys) as a CSV file, whole or not at
    all, by the lab's one writer (lab/odelab_report/files.py)."""
    text = io.StringIO()
    writer = csv.DictWriter(text, fieldnames=list(rows[0]), lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    files.write_atomically(path, text.getvalue())


def timing_options(description, seconds):
    """The engine benchmarks' command line: --build, --seconds (simulated
    seconds per run), --repeats (at least five) and --csv; parsed and checked."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--build", default=str(Path(__file__).resolve().parents[1] / "build"))
    parser.add_argument("--seconds", type=float, default=seconds, help=f"simulated seconds per run (default {seconds:g})")
    parser.add_argument("--repeats", type=int, default=5, help="interleaved runs per cell, at least 5 (default 5)")
    parser.add_argument("--csv", help="also write the figures to this CSV file")
    options = parser.parse_args()
    if options.repeats < 5:
        parser.error("--repeats: at least 5 (a timing figure is the median and range of five runs or more)")
    if not options.seconds > 0:
        parser.error("--seconds: must be > 0")
    return parser, options


def main():
    _, options = timing_options(__doc__.split("\n\n")[0], 10.0)
    tests = Path(options.build) / "tests"
    engines = available_engines(str(tests / "test1"))
    for name, ok, why in engines:
        if not ok:
            print(f"left out: {name} ({why})")
    names = [name for name, ok, _ in engines if ok]
    cells = [(scene, engine) for scene in SCENES for engine in names]
    runs = {cell: [] for cell in cells}
    with tempfile.TemporaryDirectory() as folder:
        for _ in range(options.repeats):
            for scene, engine in cells:
                runs[(scene, engine)].append(one_run(str(tests / scene), engine, options.seconds, folder))
    rows = []
    print(f"{'scene':6} {'engine':7} {'engine step (us)':>26} {'outside it (us)':>26} {'outside / step':>15}")
    for scene, engine in cells:
        inside = spread([r[0] * 1e6 for r in runs[(scene, engine)]])
        outside = spread([r[1] * 1e6 for r in runs[(scene, engine)]])
        ratio = outside[0] / inside[0] if inside[0] else float("nan")
        print(f"{scene:6} {engine:7} {inside[0]:9.2f} [{inside[1]:7.2f}-{inside[2]:7.2f}] "
              f"{outside[0]:9.2f} [{outside[1]:7.2f}-{outside[2]:7.2f}] {ratio:15.3f}")
        rows.append(dict(scene=scene, engine=engine, seconds=options.seconds, repeats=options.repeats,
                         engine_step_us=inside[0], engine_step_us_min=inside[1], engine_step_us_max=inside[2],
                         outside_us=outside[0], outside_us_min=outside[1], outside_us_max=outside[2],
                         outside_per_engine_step=ratio, date=datetime.date.today().isoformat()))
    if options.csv:
        write_rows(options.csv, rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())

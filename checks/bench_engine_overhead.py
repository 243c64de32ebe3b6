#!/usr/bin/env python3
"""The engine adapters' cost per step: how long a step of test1 (50 balls),
test2 (the pendulum) and test5 (40 plates) takes inside each engine's own
collision and step calls (the metric engine_wall_seconds), against the time
outside them in the same run loop: passing edits and states through the
adapter (for Havok, Jolt, Rapier and PhysX the pipe to Node.js), writing the
states into the ODE bodies, and the scene's own measurement. Beside the
engine's step, its bare harness's (peers/wasm/bench/bare.js: the engine's npm
build stepping the same world in a tight loop with none of the adapter
around it) for the engines that have one, measured in the same rounds. Each
figure is per step, the median and range of --repeats interleaved runs (each
cell's first run, then each one's second, so a busy spell of the machine
falls on every engine alike), printed beside its target: the engine step at
most 1.20 times the bare harness's, the time outside at most 0.25 of the
engine step.

    python3 checks/bench_engine_overhead.py [--build build] [--seconds 10] [--repeats 5]
        [--engines ode,bullet,...] [--scenes test1,test2,test5] [--csv FILE]

It prints figures; it judges nothing. Engines not available here are named
and left out (their --list-engines line says why)."""

import argparse
import csv
import datetime
import io
import json
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from adapter_world_capture import capture_world

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "lab"))
from odelab_report import files  # noqa: E402

# Each scene's arguments and the least simulated time a run takes: test5
# drops a plate every 0.3 s, so 40 plates are all in after 12 s.
SCENES = {"test1": ([], 0.0), "test2": ([], 0.0), "test5": (["--plates", "40"], 40 * 0.3 + 0.5)}
BARE_ENGINES = ("havok", "jolt", "rapier")  # the engines peers/wasm/bench/bare.js builds
BARE_TARGET = 1.20     # adapter's engine step / bare harness's, at most
OUTSIDE_TARGET = 0.25  # time outside the engine / engine step, at most


def available_engines(program):
    """[(name, available, why)] from `program --list-engines`."""
    out = subprocess.run([program, "--list-engines"], capture_output=True, text=True, check=True).stdout
    engines = []
    for line in out.splitlines():
        if not line.startswith((" ", "(")) and ": " in line:  # "(measured: ...)" closes the list
            name, rest = line.split(": ", 1)
            engines.append([name, rest.startswith("available"), ""])
        elif line.strip().startswith("missing:") and engines:
            engines[-1][2] = line.strip()[len("missing: "):]
    return engines


def one_run(program, engine, seconds, folder, scene_args=()):
    metrics = Path(folder) / "m.json"
    args = [program, "--headless", "--seconds", str(seconds), "--metrics-json", str(metrics), "--out-dir", folder,
            *scene_args]
    if engine != "ode":
        args += ["--engine", engine]
    subprocess.run(args, capture_output=True, text=True, check=True)
    m = json.loads(metrics.read_text())
    steps = m["steps"]
    inside = m["engine_wall_seconds"] / steps
    outside = (m["wall_seconds"] - m["engine_wall_seconds"]) / steps
    return inside, outside


def bare_run(bare_js, engine, world_file, steps):
    """Seconds per step of the engine's own step call in the bare harness:
    (warm, cold): after one untimed run of the same steps (the engine's
    steady state, the floor) and in that first run (a fresh process's, as
    the adapter's run is)."""
    out = subprocess.run(["node", bare_js, engine, world_file, "--steps", str(steps), "--repeats", "1", "--warmup", "1"],
                         capture_output=True, text=True, check=True).stdout
    result = json.loads(out)
    return result["step_seconds"], result["cold_step_seconds"]


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


def timing_options(description, seconds, more=None):
    """The engine benchmarks' command line: --build, --seconds (simulated
    seconds per run), --repeats (at least five) and --csv, and what `more`
    adds to the parser; parsed and checked."""
    parser = argparse.ArgumentParser(description=description)
    if more:
        more(parser)
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
    def engines_option(parser):
        parser.add_argument("--engines", help="comma-separated engines to time (default: every one available)")
        parser.add_argument("--scenes", default=",".join(SCENES),
                            help=f"comma-separated scenes of {', '.join(SCENES)} (default: all)")
    parser, options = timing_options(__doc__.split("\n\n")[0], 10.0, engines_option)
    tests = Path(options.build) / "tests"
    bare_js = str(Path(__file__).resolve().parents[1] / "peers" / "wasm" / "bench" / "bare.js")
    engines = available_engines(str(tests / "test1"))
    if options.engines:
        asked = options.engines.split(",")
        unknown = [e for e in asked if e not in {name for name, _, _ in engines}]
        if unknown:
            parser.error(f"--engines: unknown {', '.join(unknown)} (known: {', '.join(n for n, _, _ in engines)})")
        engines = [e for e in engines if e[0] in asked]
    scenes = options.scenes.split(",")
    if any(scene not in SCENES for scene in scenes):
        parser.error(f"--scenes: each one of {', '.join(SCENES)}, got {options.scenes}")
    for name, ok, why in engines:
        if not ok:
            print(f"left out: {name} ({why})")
    names = [name for name, ok, _ in engines if ok]
    seconds = {scene: max(options.seconds, SCENES[scene][1]) for scene in scenes}
    cells = [(scene, engine) for scene in scenes for engine in names]
    runs = {cell: [] for cell in cells}
    bare = {cell: [] for cell in cells}
    with tempfile.TemporaryDirectory() as folder:
        worlds = {}
        if any(engine in BARE_ENGINES for engine in names):
            # The world each scene's adapter is given, once, for the bare harness.
            for scene in scenes:
                world, steps = capture_world(str(tests / scene), SCENES[scene][0], "rapier", seconds[scene], folder)
                path = Path(folder) / f"{scene}.world.json"
                files.write_atomically(path, json.dumps(world))
                worlds[scene] = (str(path), steps)
        for _ in range(options.repeats):
            for scene, engine in cells:
                runs[(scene, engine)].append(
                    one_run(str(tests / scene), engine, seconds[scene], folder, SCENES[scene][0]))
                if engine in BARE_ENGINES:
                    bare[(scene, engine)].append(bare_run(bare_js, engine, *worlds[scene]))
    rows = []
    print(f"{'scene':6} {'engine':7} {'engine step (us)':>26} {'bare harness (us)':>26} {'step / bare':>11} "
          f"{'target':>6} {'outside it (us)':>26} {'outside / step':>14} {'target':>6}")
    for scene, engine in cells:
        inside = spread([r[0] * 1e6 for r in runs[(scene, engine)]])
        outside = spread([r[1] * 1e6 for r in runs[(scene, engine)]])
        ratio = outside[0] / inside[0] if inside[0] else float("nan")
        floor = spread([b[0] * 1e6 for b in bare[(scene, engine)]]) if bare[(scene, engine)] else None
        cold = spread([b[1] * 1e6 for b in bare[(scene, engine)]]) if bare[(scene, engine)] else None
        over = inside[0] / floor[0] if floor and floor[0] else float("nan")
        floor_text = f"{floor[0]:9.2f} [{floor[1]:7.2f}-{floor[2]:7.2f}]" if floor else f"{'(none)':>26}"
        print(f"{scene:6} {engine:7} {inside[0]:9.2f} [{inside[1]:7.2f}-{inside[2]:7.2f}] {floor_text} "
              f"{over:11.3f} {BARE_TARGET:6.2f} {outside[0]:9.2f} [{outside[1]:7.2f}-{outside[2]:7.2f}] "
              f"{ratio:14.3f} {OUTSIDE_TARGET:6.2f}")
        rows.append(dict(scene=scene, engine=engine, seconds=seconds[scene], repeats=options.repeats,
                         engine_step_us=inside[0], engine_step_us_min=inside[1], engine_step_us_max=inside[2],
                         outside_us=outside[0], outside_us_min=outside[1], outside_us_max=outside[2],
                         outside_per_engine_step=ratio, outside_target=OUTSIDE_TARGET,
                         bare_step_us=floor[0] if floor else "", bare_step_us_min=floor[1] if floor else "",
                         bare_step_us_max=floor[2] if floor else "",
                         engine_step_per_bare=over if floor else "", bare_target=BARE_TARGET,
                         bare_cold_step_us=cold[0] if cold else "",
                         engine_step_per_bare_cold=inside[0] / cold[0] if cold and cold[0] else "",
                         load_average=" ".join(f"{x:.2f}" for x in os.getloadavg()),
                         date=datetime.date.today().isoformat()))
    print("bare harness: the engine's steady state (after one untimed run of the same steps); the CSV also has "
          "its first, cold run (bare_cold_step_us), as a fresh process such as the adapter's runs it")
    print(f"load average at the end: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    if options.csv:
        write_rows(options.csv, rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())

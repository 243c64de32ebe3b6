#!/usr/bin/env python3
"""The compare window's speed (testN --compare, doc/manual.md, "Engines side
by side"): frames per second and the real-time factor of the window at
1280x720 under Xvfb (Mesa's llvmpipe: no GPU) for test2 (the pendulum),
test5 (plates dropped every 0.25 s) and test9 (bouncing balls) with two,
four and six engines, ODE's included, and where each frame's time goes: each
engine's stepping (its steps and the scene's measurement; for another
engine also the edits and states passed to it, the pipe to Node.js for
Havok, Jolt and Rapier) with the part inside the engine's own collision and
step calls, and the drawing (the swap included). Each figure is the median
and range of --repeats interleaved runs (every configuration's first run,
then every one's second...). A share is of the window's wall time.

    python3 checks/bench_compare.py [--build build] [--seconds 3] [--repeats 5] [--csv FILE]

The engines: two = ODE and Bullet; four = with MuJoCo and Jolt; six = all.
A configuration whose engines are not all here is named and left out. It
prints figures; it judges nothing. The machine's load average is printed
at the start and the end, and written to the CSV's rows."""

import datetime
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_engine_overhead import available_engines, spread, timing_options, write_rows  # noqa: E402

SCENES = {"test2": [], "test5": ["--spawn-interval", "0.25", "--plates", "40"], "test9": []}
ENGINE_SETS = {2: ["bullet"], 4: ["bullet", "mujoco", "jolt"], 6: ["bullet", "mujoco", "havok", "jolt", "rapier"]}
COMPARE_LINE = re.compile(r"^compare: (\d+) frames in ([\d.]+) s; stepping s:(.*); drawing s: ([\d.]+)", re.M)


def one_run(program, scene_args, engines, seconds, folder):
    """(fps, real-time factor, dropped steps, {part: share of the wall time},
    {engine: share inside its own calls}) of one compare window."""
    metrics = Path(folder) / "m.json"
    done = subprocess.run([program, "--compare", ",".join(engines), *scene_args, "--seconds", str(seconds),
                           "--width", "1280", "--height", "720",
                           "--metrics-json", str(metrics), "--out-dir", folder],
                          capture_output=True, text=True, timeout=900)
    if done.returncode != 0:
        raise RuntimeError(f"{program} --compare {','.join(engines)} ended with status {done.returncode}: "
                           f"{done.stderr.strip()[-400:]}")
    found = COMPARE_LINE.search(done.stdout)
    if not found:
        raise RuntimeError(f"{program}: no compare totals line in its output")
    frames, wall = int(found.group(1)), float(found.group(2))
    stepping = dict(zip(found.group(3).split()[::2], map(float, found.group(3).split()[1::2])))
    m = json.loads(metrics.read_text())
    shares = {engine: seconds_ / wall for engine, seconds_ in stepping.items()}
    shares["drawing"] = float(found.group(4)) / wall
    inside = {engine: m[f"{engine}.engine_wall_seconds"] / wall for engine in stepping}
    return frames / wall, m["ode.real_time_factor"], m["ode.dropped_steps"], shares, inside


def main():
    parser, options = timing_options(__doc__.split("\n\n")[0], 3.0)
    if not os.environ.get("DISPLAY"):
        xvfb = shutil.which("xvfb-run")
        if not xvfb:
            parser.error("no DISPLAY and no xvfb-run (apt-get install xvfb xauth)")
        return subprocess.call([xvfb, "-a", "-s", "-screen 0 1280x800x24", sys.executable, *sys.argv])
    tests = Path(options.build) / "tests"
    here = {name for name, ok, _ in available_engines(str(tests / "test2")) if ok}
    sets = {}
    for count, engines in ENGINE_SETS.items():
        missing = [e for e in engines if e not in here]
        if missing:
            print(f"left out: {count} engines ({', '.join(missing)} not here)")
        else:
            sets[count] = engines
    configurations = [(scene, count) for scene in SCENES for count in sets]
    load = os.getloadavg()
    print(f"load average at the start: {load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    runs = {c: [] for c in configurations}
    with tempfile.TemporaryDirectory() as folder:
        for _ in range(options.repeats):
            for scene, count in configurations:
                runs[(scene, count)].append(one_run(str(tests / scene), SCENES[scene], sets[count], options.seconds,
                                                    folder))
    end = os.getloadavg()
    print(f"load average at the end: {end[0]:.2f} {end[1]:.2f} {end[2]:.2f}")
    rows = []
    for scene, count in configurations:
        got = runs[(scene, count)]
        fps, factor = spread([r[0] for r in got]), spread([r[1] for r in got])
        dropped = max(r[2] for r in got)
        print(f"{scene} with {count} engines (ode, {', '.join(sets[count])}): {fps[0]:.1f} fps [{fps[1]:.1f}-{fps[2]:.1f}], "
              f"real-time factor {factor[0]:.3f} [{factor[1]:.3f}-{factor[2]:.3f}], dropped steps up to {dropped}")
        for part in got[0][3]:
            share = spread([r[3][part] for r in got])
            inside = spread([r[4][part] for r in got]) if part in got[0][4] else (None, None, None)
            print(f"    {part:8} {100 * share[0]:5.1f}% of the wall time [{100 * share[1]:.1f}-{100 * share[2]:.1f}]"
                  + (f", inside its own calls {100 * inside[0]:.1f}%" if inside[0] is not None else ""))
            rows.append(dict(scene=scene, engine_count=count, engines=" ".join(["ode", *sets[count]]),
                             seconds=options.seconds, repeats=options.repeats, fps=fps[0], fps_min=fps[1],
                             fps_max=fps[2], real_time_factor=factor[0], real_time_factor_min=factor[1],
                             real_time_factor_max=factor[2], dropped_steps_max=dropped, part=part,
                             share=share[0], share_min=share[1], share_max=share[2], inside_share=inside[0],
                             load_start=f"{load[0]:.2f}", load_end=f"{end[0]:.2f}",
                             date=datetime.date.today().isoformat()))
    if options.csv and rows:
        write_rows(options.csv, rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())

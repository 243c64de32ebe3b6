#!/usr/bin/env python3
"""Checks that the web peers' measurement rules (JavaScript,
peers/wasm/src/measurements.js) and the C++ peers' (peers/Measurements.cpp)
give the same metrics on the same trajectory: records one from a web peer
(peers/wasm/parity/record.js), measures it with both (replay.js and
replay_lab) and compares every metric to 1e-9 relative (the metrics files
hold 10 significant digits). A rule changed on one side only fails here.

Usage: check_parity.py NODE REPLAY_LAB ENGINE SCENE SETTING STEP SECONDS [VELOCITY]
Exit 0: the same metrics; 1: a difference, a missing metric or a failed run; 2: bad usage."""

import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

TOLERANCE = 1e-9
TIMINGS = {"ms_per_step", "cpu_ms_per_step"}  # test5's cost per step: each run's own clock
PARITY = Path(__file__).resolve().parent / "wasm" / "parity"


def run(command):
    done = subprocess.run(command, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        sys.stderr.write(f"{' '.join(map(str, command))} exited with {done.returncode}:\n{done.stderr}")
        sys.exit(1)
    return done.stdout


def same(a, b):
    if a is None or b is None:
        return a is None and b is None
    return math.isclose(a, b, rel_tol=TOLERANCE, abs_tol=1e-300)


def main(argv):
    if len(argv) < 8:
        sys.stderr.write(__doc__)
        return 2
    node, replay_lab, record = argv[1], argv[2], argv[3:]
    with tempfile.TemporaryDirectory(prefix="parity-") as folder:
        trajectory = Path(folder) / "trajectory.txt"
        trajectory.write_text(run([node, str(PARITY / "record.js"), *record]))
        javascript = json.loads(run([node, str(PARITY / "replay.js"), str(trajectory)]))
        cpp = json.loads(run([replay_lab, str(trajectory)]))
    names = [n for n in dict.fromkeys([*cpp, *javascript]) if n not in TIMINGS]
    different = [n for n in names if n not in cpp or n not in javascript or not same(cpp[n], javascript[n])]
    for name in names:
        print(f"{name}: C++ {cpp.get(name, 'missing')!r}, JavaScript {javascript.get(name, 'missing')!r}"
              f"{'  DIFFERENT' if name in different else ''}")
    return 1 if different or not names else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""Sets MuJoCo 3 (npm mujoco-js, through peers/wasm/mujoco3.js) beside
Debian's MuJoCo 2.2.2 (peers/mujoco_lab) on the very same MJCF (mujoco_lab
--write-model) and the same measurement rules, and checks that METRIC agrees
between the two versions within a relative TOLERANCE (both printed).

Usage: check_mujoco3.py MUJOCO_LAB NODE SCENE SETTING SECONDS METRIC TOLERANCE
Exit 0: they agree; 1: they differ, a metric is missing or a run failed; 2: bad usage."""

import math
import subprocess
import sys
import tempfile
from pathlib import Path

from check_same_scene import metrics_of

MUJOCO3 = Path(__file__).resolve().parent / "wasm" / "mujoco3.js"


def run(command):
    done = subprocess.run([str(c) for c in command], capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        sys.stderr.write(f"{' '.join(map(str, command))} exited with {done.returncode}:\n{done.stderr}")
        sys.exit(1)


def main(argv):
    if len(argv) != 8:
        sys.stderr.write(__doc__)
        return 2
    mujoco_lab, node, scene, setting, seconds, metric, tolerance = argv[1:]
    mujoco_lab = str(Path(mujoco_lab).resolve())  # the runs start in a scratch folder
    try:
        tolerance = float(tolerance)
    except ValueError:
        sys.stderr.write(f"check_mujoco3: TOLERANCE {tolerance!r} is not a number\n")
        return 2
    with tempfile.TemporaryDirectory(prefix="mujoco3-") as folder:
        model = Path(folder) / "model.xml"
        args = ["--scene", scene, "--setting", setting]
        run([mujoco_lab, *args, "--write-model", model])
        a = metrics_of([mujoco_lab, *args, "--seconds", seconds], folder, "old").get(metric)
        b = metrics_of([node, str(MUJOCO3), str(model), "--scene", scene, "--seconds", seconds], folder, "new").get(metric)
    print(f"{scene} {setting}, {seconds} s: {metric} MuJoCo 2.2.2 {a!r}, MuJoCo 3 {b!r}")
    if a is None or b is None or not math.isclose(a, b, rel_tol=tolerance, abs_tol=0.0):
        print(f"check_mujoco3: the two versions differ by more than {tolerance:g} relative (or a figure is missing)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

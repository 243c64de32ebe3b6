#!/usr/bin/env python3
"""Checks that a peer program builds the same scene as the ODE program: runs
both briefly with --metrics-json and compares the metrics that follow from
the scene's constants alone (start energy, pendulum length, start height,
the wall's geometric limit...), as the metrics files hold them (10
significant digits), to a relative 1e-12. Both programs take the constants
from tests/shared/SceneConstants.h; this catches a peer (or an ODE program)
that builds its scene from a copy instead.

Usage: check_same_scene.py [--tolerance=T] METRIC[,METRIC...] ODE_PROGRAM PEER_PROGRAM SCENE [ARGS...]
ARGS go to both programs. --tolerance: the relative tolerance instead of
1e-12, for a peer whose engine holds its state in float32 (the web peers:
1e-6, a few roundings of float32's 6e-8). Exit 0: every metric equal; 1: a difference or a
missing metric (each printed); 2: bad usage."""

import json
import subprocess
import sys
import tempfile
from pathlib import Path

TOLERANCE = 1e-12


def metrics_of(command, folder, name):
    path = Path(folder) / f"{name}.json"
    done = subprocess.run([*command, "--metrics-json", str(path)], cwd=folder, capture_output=True, text=True,
                          timeout=300)
    if done.returncode != 0:
        sys.stderr.write(f"{' '.join(command)} exited with {done.returncode}:\n{done.stderr}")
        sys.exit(1)
    return json.loads(path.read_text())


def main(argv):
    tolerance = TOLERANCE
    if len(argv) > 1 and argv[1].startswith("--tolerance="):
        tolerance = float(argv[1].split("=", 1)[1])
        argv = argv[:1] + argv[2:]
    if len(argv) < 5:
        sys.stderr.write(__doc__)
        return 2
    names, scene, args = argv[1].split(","), argv[4], argv[5:]
    ode, peer = (str(Path(p).resolve()) for p in argv[2:4])  # the programs run in a scratch folder
    for program in (ode, peer):
        if not Path(program).is_file():
            sys.stderr.write(f"check_same_scene.py: no program {program}\n")
            return 2
    with tempfile.TemporaryDirectory(prefix="same-scene-") as folder:
        reference = metrics_of([ode, "--headless", *args], folder, "ode")
        measured = metrics_of([peer, "--scene", scene, *args], folder, "peer")
    failed = False
    for name in names:
        a, b = reference.get(name), measured.get(name)
        same = a is not None and b is not None and abs(a - b) <= tolerance * max(abs(a), abs(b), 1e-300)
        print(f"{name}: ODE {a!r}, {Path(peer).name} {b!r}: {'same' if same else 'DIFFERENT'}")
        failed = failed or not same
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""A world file's engines are handed the file, not ODE's read-back of it: a
translation note names only what the file sets. For each world and engine
given, `odelab --world W --engine E --headless --seconds <one step>` and its
notes (stderr, "translation note: ...") against the file:
- "infinite friction" only where a surface of the file has mu infinity;
- "a joint's own ERP/CFM" only where a joint of the file sets erp or cfm;
- MuJoCo's elliptic cones for friction above 1 only where a surface of the
  file has mu above 1.
On the read-back (before the link took the file's joints and surfaces)
tumbling_brick.json had "infinite friction" on Bullet, MuJoCo and the Node.js
engines, and every ball joint and hinge "a joint's own ERP/CFM".
Usage: world_notes_name_file_values.py ODELAB ENGINE[,ENGINE...] WORLD.json...
Exit 0: every note holds; 1: a note names a value the file does not set."""

import json
import math
import os
import subprocess
import sys
import tempfile


def mu_of(surface):
    mu = surface.get("mu")
    return math.inf if mu in ("infinity", "inf") else float(mu)


def forbidden(world):
    """(needle, why) pairs a note may not contain on this world."""
    mus = [mu_of(s) for s in world.get("surfaces", [])]
    rules = []
    if not any(math.isinf(m) for m in mus):
        rules.append(("infinite friction", "no surface of the file has mu infinity"))
    if not any("erp" in j or "cfm" in j for j in world.get("joints", [])):
        rules.append(("joint's own ERP/CFM", "no joint of the file sets erp or cfm"))
    if not any(m > 1 for m in mus):
        rules.append(("the cones are elliptic", "no surface of the file has mu above 1"))
    return rules


def notes(odelab, path, engine, step):
    with tempfile.TemporaryDirectory(prefix="world-notes-") as folder:
        done = subprocess.run([odelab, "--world", path, "--engine", engine, "--headless", "--seconds", str(step)],
                              cwd=folder, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True, timeout=300)
    if done.returncode != 0:
        raise SystemExit(f"{engine} on {path}: status {done.returncode}: {done.stderr.strip()[-400:]}")
    return [line.split("translation note: ", 1)[1] for line in done.stderr.splitlines() if "translation note: " in line]


def main(argv):
    if len(argv) < 4:
        raise SystemExit(__doc__)
    # Absolute: each run is made in a folder of its own.
    odelab, worlds = os.path.abspath(argv[1]), [os.path.abspath(w) for w in argv[3:]]
    engines = [e for e in argv[2].split(",") if e]
    wrong = 0
    for path in worlds:
        with open(path) as stream:
            world = json.load(stream)
        rules = forbidden(world)
        for engine in engines:
            said = notes(odelab, path, engine, world["settings"]["step"])
            for note in said:
                for needle, why in rules:
                    if needle in note:
                        print(f"WRONG {engine} on {path}: \"{note}\" although {why}")
                        wrong += 1
            print(f"{engine} on {path}: {len(said)} notes checked")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

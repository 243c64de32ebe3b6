#!/usr/bin/env python3
"""odelab --scene NAME runs the scene as its program does.

usage: launcher_same_run.py ODELAB PROGRAM ARGS...

Runs PROGRAM --headless ARGS and ODELAB --scene NAME --headless ARGS (NAME:
PROGRAM's file name), each in a fresh folder, and checks that both end with
status 0, give every metric the same value (state_hash included) but the
ones read from a clock, and write the same output files byte for byte.
"""
import json
import os
import subprocess
import sys
import tempfile

# Measured with a clock: they differ between any two runs.
CLOCK_METRICS = {"wall_seconds", "real_time_factor", "ms_per_step", "cpu_ms_per_step", "collide_step_seconds",
                 "engine_wall_seconds", "engine_cpu_seconds", "link_wall_seconds"}


def run(command, folder):
    os.mkdir(folder)
    done = subprocess.run([*command, "--metrics-json", "metrics.json"], cwd=folder, capture_output=True, text=True,
                          timeout=600)
    if done.returncode != 0:
        sys.exit(f"FAIL: {' '.join(command)} ended with status {done.returncode}: {done.stderr.strip()}")
    with open(os.path.join(folder, "metrics.json")) as f:
        metrics = json.load(f)
    files = {}
    for name in sorted(os.listdir(folder)):
        if name != "metrics.json":
            with open(os.path.join(folder, name), "rb") as f:
                files[name] = f.read()
    return metrics, files


def main():
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    odelab, program, args = sys.argv[1], sys.argv[2], sys.argv[3:]
    name = os.path.basename(program)
    with tempfile.TemporaryDirectory() as root:
        own, own_files = run([program, "--headless", *args], os.path.join(root, "program"))
        launched, launched_files = run([odelab, "--scene", name, "--headless", *args], os.path.join(root, "odelab"))
    failures = [f"{key}: {own.get(key)} by {name}, {launched.get(key)} by odelab"
                for key in sorted(set(own) | set(launched))
                if key not in CLOCK_METRICS and own.get(key) != launched.get(key)]
    if sorted(own_files) != sorted(launched_files):
        failures.append(f"files {sorted(own_files)} by {name}, {sorted(launched_files)} by odelab")
    failures += [f"{f} differs" for f in own_files if f in launched_files and own_files[f] != launched_files[f]]
    for failure in failures:
        print("FAIL", failure)
    print(f"{name}: {len(own) - len(CLOCK_METRICS & set(own))} metrics (state_hash {own.get('state_hash')}) "
          f"and {len(own_files)} output files compared, {len(failures)} differences")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

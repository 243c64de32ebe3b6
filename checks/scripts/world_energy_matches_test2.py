#!/usr/bin/env python3
"""The world file's energy measure is test2's own (checks/worlds.cmake).

  world_energy_matches_test2.py TEST2 ODELAB SECONDS

test2 exports its pendulum (`--export-world`); `"measures": [{"kind": "energy"}]`
is added to that file; then `test2 --headless` and `odelab --world` run the
same SECONDS, each in a folder of its own. The energy figures both write
(start, min, max, last, largest deviation, drift) must be equal as printed in
the metrics files (10 significant digits): the measure takes the same energy
(0.5 m v^2 + 0.5 w.Iw - m g.p) at the same steps with the same default scale,
|E at t = 0|. Exit 0 when all six are equal, 1 naming each that is not.
"""
import json
import os
import subprocess
import sys
import tempfile

FIGURES = ["energy_start_J", "energy_min_J", "energy_max_J", "energy_last_J", "energy_max_deviation", "energy_drift"]


def run(command, folder):
    os.makedirs(folder)
    done = subprocess.run(command + ["--metrics-json", "m.json"], cwd=folder, stdout=subprocess.PIPE,
                          stderr=subprocess.STDOUT, text=True, errors="replace", timeout=300)
    if done.returncode != 0:
        print(f"{' '.join(command)}: status {done.returncode}\n{done.stdout}")
        return None
    with open(os.path.join(folder, "m.json"), encoding="utf-8") as f:
        # The numbers as printed: two equal texts parse to the same double.
        return json.load(f)


def main():
    if len(sys.argv) != 4:
        print("usage: world_energy_matches_test2.py TEST2 ODELAB SECONDS", file=sys.stderr)
        return 2
    test2, odelab, seconds = sys.argv[1:]
    with tempfile.TemporaryDirectory(prefix="odelab_test2_energy.") as root:
        world = os.path.join(root, "test2.json")
        done = subprocess.run([test2, "--export-world", world], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                              text=True, errors="replace", timeout=120)
        if done.returncode != 0:
            print(f"{test2} --export-world: status {done.returncode}\n{done.stdout}")
            return 1
        with open(world, encoding="utf-8") as f:
            description = json.load(f)
        description["measures"] = [{"kind": "energy"}]
        with open(world, "w", encoding="utf-8") as f:
            json.dump(description, f, indent=1)
        program = run([test2, "--headless", "--seconds", seconds], os.path.join(root, "program"))
        from_file = run([odelab, "--world", world, "--headless", "--seconds", seconds], os.path.join(root, "file"))
        if program is None or from_file is None:
            return 1
    failures = []
    for name in FIGURES:
        a, b = program.get(name), from_file.get(name)
        if a is None or b is None or a != b:
            failures.append(f"{name}: test2 {a!r}, its world file {b!r}")
    if failures:
        print("test2's energy figures and its world file's differ:")
        for failure in failures:
            print(f"  {failure}")
        return 1
    print(f"ok: {len(FIGURES)} energy figures equal as printed after {seconds} s, e.g. energy_max_deviation "
          f"{program['energy_max_deviation']!r}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

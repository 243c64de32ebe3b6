#!/usr/bin/env python3
"""Checks that a peer program gives the same metrics twice in a row: runs it
twice with the same arguments, each with --metrics-json, and compares every
metric except the run's own timings (wall_seconds, cpu_seconds; test5's
ms_per_step and cpu_ms_per_step) exactly, as
the metrics files hold them. A peer that read a clock, a random seed or
uninitialised memory into its physics would fail here.

Usage: check_repeat.py PROGRAM ARGS...
Exit 0: the same metrics; 1: a difference, a missing metric or a failed run
(each printed); 2: bad usage."""

import sys
import tempfile
from pathlib import Path

from check_same_scene import metrics_of

TIMINGS = {"wall_seconds", "cpu_seconds", "ms_per_step", "cpu_ms_per_step"}  # test5's cost per step too


def main(argv):
    if len(argv) < 2:
        sys.stderr.write(__doc__)
        return 2
    program = str(Path(argv[1]).resolve())
    if not Path(program).is_file():
        sys.stderr.write(f"check_repeat.py: no program {program}\n")
        return 2
    with tempfile.TemporaryDirectory(prefix="repeat-") as folder:
        first = metrics_of([program, *argv[2:]], folder, "first")
        second = metrics_of([program, *argv[2:]], folder, "second")
    names = [n for n in dict.fromkeys([*first, *second]) if n not in TIMINGS]
    different = [n for n in names if first.get(n, "missing") != second.get(n, "missing")]
    for name in different:
        print(f"{name}: {first.get(name, 'missing')!r} then {second.get(name, 'missing')!r}")
    print(f"{len(names) - len(different)} of {len(names)} metrics the same in both runs")
    return 1 if different or not names else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

"""For check_report.py: every timing figure of a report folder rests on
enough timed runs, each long enough to time (timing.py's rules): a cost
row of peers.csv, speed-*.csv or remedy-test4.csv with fewer runs than
timing.repeats, or whose shortest run lasted less than timing.min_run_cpu
of CPU, is a problem (peers' scenes whose length is their figure, such as
test10's scan, excepted from the length)."""

import re

from . import timing
from .claims import read_rows

# file -> (the column of its cost, the scene column or None)
TIMED_FILES = {"peers.csv": ("cpu_s_per_sim_s", "scene"), "remedy-test4.csv": ("wall_per_sim_second", None)}
SPEED = re.compile(r"speed-test\d+\.csv")
# experiments/peers.py's FIXED_LENGTH: their timed runs repeat the figure's own run
FIXED_LENGTH = ("test3", "test5", "test10")


def quick(path):
    """Whether the report that wrote `path` ran with --quick (its header's options line)."""
    with open(path) as stream:
        for line in stream:
            if not line.startswith("#"):
                return False
            if line.startswith("# options:"):
                return "--quick" in line
    return False


def _number(cell):
    try:
        return float(cell)
    except (TypeError, ValueError):
        return None


def problems(folder):
    found = []
    for path in sorted(folder.glob("*.csv")):
        if path.name in TIMED_FILES:
            cost, scene = TIMED_FILES[path.name]
        elif SPEED.fullmatch(path.name):
            cost, scene = "wall_per_sim_second", None
        else:
            continue
        is_quick = quick(path)
        runs, shortest = timing.repeats(is_quick), timing.min_run_cpu(is_quick)
        for n, row in enumerate(read_rows(path), start=1):
            if row.get(cost) in (None, ""):
                continue  # no cost in this row: nothing timed
            repeats, short = _number(row.get("repeats")), _number(row.get("shortest_run_cpu_seconds"))
            if repeats is None or repeats < runs:
                found.append(f"{path.name} row {n}: a cost from {row.get('repeats') or 'no count of'} timed runs "
                             f"(at least {runs}: a median and a range)")
            if (scene is None or row.get(scene) not in FIXED_LENGTH) and (short is None or short < shortest):
                found.append(f"{path.name} row {n}: a timed run of {row.get('shortest_run_cpu_seconds') or 'unknown'}"
                             f" CPU s (at least {shortest:g}: long enough to time)")
    return found

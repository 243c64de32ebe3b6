"""Like with like across engines (experiments/peers.py, the first screen's
"best other engine"): which runs of a scene may be compared, and who wins.

Two runs compare only at the same step, on the same surface where friction
acts, and with a figure the engine can get wrong: a joint error of an
engine that builds the joint into its coordinates is zero by construction,
not a result. Among the runs that compare, the best figure wins; among
equal figures the cheapest by median CPU time, and every other whose
fastest run is not slower than the cheapest's slowest ties with it."""

import re

from .timing import overlap

# Scenes whose contacts stick or slide, so that the friction coefficient
# decides the figure (test1, test9 and test10 are head-on impacts; test2
# and test8 have no contact).
FRICTION_ACTS = ("test3", "test4", "test5", "test6", "test7")
# ODE's friction in each scene (tests/scenes/*.cpp: dInfinity but test3's 1.0).
ODE_FRICTION = {"test3": "1"}
INFINITE = "infinite"
# peers/Surfaces.h: no peer takes an infinite coefficient; 100 (a friction
# cone of 89.4 degrees) is the peers' never-sliding contact, ODE's infinity.
NO_SLIP = "100"
ENGINE_DEFAULT = "engine default"
# Figures an engine cannot get wrong: (engine, scene) -> why.
BY_CONSTRUCTION = {
    ("mujoco", "test7"): "zero by construction (MuJoCo's joints are generalized coordinates)",
    ("mujoco", "test8"): "zero by construction (MuJoCo's hinge is a generalized coordinate)",
}


def ode_friction(scene):
    return ODE_FRICTION.get(scene, INFINITE)


def peer_friction(first_line):
    """The friction a peer run used, from the settings line it prints first
    ("...; friction 100 on every shape"): the coefficient, or "engine
    default" when the line names none."""
    found = re.search(r"friction (\d+(?:\.\d+)?)", first_line or "")
    return f"{float(found.group(1)):g}" if found else ENGINE_DEFAULT


def like_surface(scene, friction):
    """Whether a run at `friction` stands on ODE's surface for `scene`."""
    if scene not in FRICTION_ACTS:
        return True
    ode = ode_friction(scene)
    return friction == ode or (ode == INFINITE and friction == NO_SLIP)


def surface_text(scene, friction):
    if scene not in FRICTION_ACTS:
        return "friction does not act"
    if friction == NO_SLIP:
        return "friction 100 (no-slip, as ODE's infinite)"
    return "friction " + friction


def why_not_compared(row):
    """Why a peers.csv row (a dict) takes no part in a comparison, or None."""
    if row.get("by_construction"):
        return row["by_construction"]
    if not row.get("like_ode_surface", 1):
        return f"friction differs ({row['friction']} against ODE's {ode_friction(row['scene'])})"
    return None


def standings(rows, lower_is_better, floor_of=lambda row: 0.0):
    """(winners, excluded) among `rows` (dicts with value, cpu_median,
    cpu_min, cpu_max; all at one step and one kind of setting): winners is
    the best figure's cheapest row first, then the rows tied with it within
    the timing's scatter ([] when no row compares); excluded: (row, why)
    for the rows that do not compare. A lower-is-better value below
    floor_of(row) is rounding and counts as the floor."""
    excluded = [(r, why_not_compared(r)) for r in rows if why_not_compared(r)]
    rows = [r for r in rows if r["value"] is not None and not why_not_compared(r)]
    if not rows:
        return [], excluded

    def score(r):
        return max(r["value"], floor_of(r)) if lower_is_better else -r["value"]

    best = min(score(r) for r in rows)
    equal = [r for r in rows if score(r) == best]
    timed = [r for r in equal if r.get("cpu_median") is not None]
    if not timed:
        return equal, excluded
    cheapest = min(timed, key=lambda r: r["cpu_median"])
    tied = [r for r in timed if r is not cheapest and overlap(r["cpu_min"], r["cpu_max"], cheapest["cpu_min"],
                                                           cheapest["cpu_max"])]
    return [cheapest] + sorted(tied, key=lambda r: r["cpu_median"]), excluded

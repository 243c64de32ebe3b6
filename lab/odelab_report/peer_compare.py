"""Like with like across engines (experiments/peers.py, the first screen's
"best other engine"): which runs of a scene may be compared, and who wins.

Every engine runs the scene's own world (`testN --engine E`: the scene's
program describes its ODE world as data and the engine's adapter builds
it), so every run stands on the scene's surface by construction; what an
engine could not express exactly it says in translation notes, listed
beside its figure. Two runs compare only at the same step and with a
figure the engine can get wrong: a joint error of an engine that builds
the joint into its coordinates is zero by construction, not a result.
Among the runs that compare, the best figure wins; among equal figures the
cheapest by median engine seconds (the engine's own collision and step
calls) per simulated second, and every other whose fastest run is not
slower than the cheapest's slowest ties with it."""

from .timing import overlap

# Scenes whose contacts stick or slide, so that the friction coefficient
# decides the figure (test1, test9 and test10 are head-on impacts; test2
# and test8 have no contact): the first screen names their mu.
FRICTION_ACTS = ("test3", "test4", "test5", "test6", "test7")
# Scenes whose figure is a joint's error: zero on an engine whose joints
# are generalized coordinates.
JOINT_FIGURES = ("test7", "test8")
# Words of a translation note saying a joint is a generalized coordinate.
GENERALIZED = "generalized coordinate"
# Figures an engine cannot get wrong, when its adapter's notes do not say
# so themselves (the fallback): (engine, scene) -> why.
BY_CONSTRUCTION = {
    ("mujoco", "test7"): "zero by construction (MuJoCo's joints are generalized coordinates)",
    ("mujoco", "test8"): "zero by construction (MuJoCo's hinge is a generalized coordinate)",
}


def _number(value):
    return f"{value:g}" if isinstance(value, (int, float)) and not isinstance(value, bool) else str(value)


def mu_text(surface, infinite="infinite"):
    """A surface's mu in words: "infinite" (or `infinite`) or "0.5"."""
    mu = surface.get("mu")
    return infinite if mu in ("infinity", "inf", "infinite") else _number(mu)


def default_surface(world):
    """The surface of every pair the world does not list (world-format.md)."""
    surfaces = world.get("surfaces") or [{}]
    index = world.get("default_surface", 0)
    return surfaces[index] if 0 <= index < len(surfaces) else surfaces[0]


def surface_words(world):
    """The world's surface in words (an --export-world file, parsed): "mu
    infinite"; "mu 1, restitution 1 (bounce velocity 0.01 m/s)"; soft ERP and
    CFM where set; "+ N pair surfaces" where pairs of geoms have their own."""
    surface = default_surface(world)
    words = "mu " + mu_text(surface)
    if surface.get("restitution"):
        words += f", restitution {_number(surface['restitution'])}"
        if surface.get("bounce_velocity") is not None:
            words += f" (bounce velocity {_number(surface['bounce_velocity'])} m/s)"
    for key, name in (("soft_erp", "soft ERP"), ("soft_cfm", "soft CFM")):
        if surface.get(key) is not None:
            words += f", {name} {_number(surface[key])}"
    pairs = world.get("pair_surfaces") or []
    if pairs:
        words += f" + {len(pairs)} pair surface{'s' if len(pairs) != 1 else ''}"
    return words


def surface_short(world):
    """The surface in few characters, for a matrix cell: "mu ∞", "mu 1, e 1",
    "mu ∞ + 49 pairs"."""
    surface = default_surface(world)
    text = "mu " + mu_text(surface, "∞")
    if surface.get("restitution"):
        text += f", e {_number(surface['restitution'])}"
    pairs = world.get("pair_surfaces") or []
    return text + (f" + {len(pairs)} pairs" if pairs else "")


def by_construction(engine, scene, notes):
    """Why the figure of `engine` on `scene` cannot be wrong ("" when it can):
    a translation note saying its joints are generalized coordinates, where
    the figure is a joint's error; else the BY_CONSTRUCTION table."""
    if scene in JOINT_FIGURES:
        for note in notes or []:
            if GENERALIZED in note.lower():
                return f"zero by construction ({note})"
    return BY_CONSTRUCTION.get((engine, scene), "")


def why_not_compared(row):
    """Why a peers.csv row (a dict) takes no part in a comparison, or None."""
    if row.get("by_construction"):
        return row["by_construction"]
    if not row.get("like_ode_surface", 1):
        return "surface differs (" + (row.get("surface") or "not the scene's") + ")"
    return None


def standings(rows, lower_is_better, floor_of=lambda row: 0.0):
    """(winners, excluded) among `rows` (dicts with value, cost_median,
    cost_min, cost_max: the engine seconds per simulated second of the
    timed runs; all at one step and one kind of setting): winners is the
    best figure's cheapest row first, then the rows tied with it within the
    timing's scatter ([] when no row compares); excluded: (row, why) for the
    rows that do not compare. A lower-is-better value below floor_of(row) is
    rounding and counts as the floor."""
    excluded = [(r, why_not_compared(r)) for r in rows if why_not_compared(r)]
    rows = [r for r in rows if r["value"] is not None and not why_not_compared(r)]
    if not rows:
        return [], excluded

    def score(r):
        return max(r["value"], floor_of(r)) if lower_is_better else -r["value"]

    best = min(score(r) for r in rows)
    equal = [r for r in rows if score(r) == best]
    timed = [r for r in equal if r.get("cost_median") is not None]
    if not timed:
        return equal, excluded
    cheapest = min(timed, key=lambda r: r["cost_median"])
    tied = [r for r in timed if r is not cheapest and overlap(r["cost_min"], r["cost_max"], cheapest["cost_min"],
                                                           cheapest["cost_max"])]
    return [cheapest] + sorted(tied, key=lambda r: r["cost_median"]), excluded

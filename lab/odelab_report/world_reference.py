"""What each measurement of a world report is graded against (lab/odelab-report
--world), the strongest reference the world gives, in this order:

1. analytic: an answer the world states or the measurement is defined by
   (the period a `period` measure expects, a measure's `expect`, the exact
   ballistic arc, a joint that holds, rigid bodies that do not interpenetrate,
   a rigid wall that stops every body);
2. conservation: a law the world implies (its energy where nothing can take
   energy out; its momentum where nothing outside acts on its bodies);
3. self-consistency: the same engine and setting at a much finer step
   (FINER times smaller), never another engine's run.

Agreement with ODE's own finest run is kept beside it, labelled as that.

A difference a step's timing explains (an event moved by less than one
step) is said as such and does not count against the engine: a time within
one step of the reference, an arc within what one step at the body's
fastest speed moves it. The rules apply to made-up rows as to measured ones
(lab/tests/test_world_reference.py)."""

import math

ANALYTIC, CONSERVATION, SELF = "analytic", "conservation", "self-consistency"
STRENGTH = {ANALYTIC: 0, CONSERVATION: 1, SELF: 2}
FINER = 10  # self-consistency: the same engine at the step / FINER


class Reference:
    def __init__(self, kind, why, value=None):
        self.kind, self.why, self.value = kind, why, value  # value None: the finer run's own (SELF)

    def text(self):
        return f"{self.kind}: {self.why}"


def _vec_zero(v):
    return all(abs(x) == 0 for x in v)


def _bits(geom, key):
    return int(geom.get(key, 0xFFFFFFFF))


def may_touch(world, a, b):
    """Whether geoms a and b may touch: as World::mayTouch (WorldJson.cpp)."""
    geoms = world.get("geoms", [])
    ga, gb = geoms[a], geoms[b]
    ba, bb = ga.get("body", -1), gb.get("body", -1)
    if ba < 0 and bb < 0 or ba == bb:
        return False
    if not (_bits(ga, "category") & _bits(gb, "collide") or _bits(gb, "category") & _bits(ga, "collide")):
        return False
    if ba >= 0 and bb >= 0:
        for j in world.get("joints", []):
            if {j.get("body1", -1), j.get("body2", -1)} == {ba, bb}:
                return False
    return True


def touching_pairs(world):
    n = len(world.get("geoms", []))
    return [(a, b) for b in range(n) for a in range(b) if may_touch(world, a, b)]


def surface_between(world, a, b):
    for pair in world.get("pair_surfaces", []):
        if sorted(pair["geoms"]) == sorted((a, b)):
            return world["surfaces"][pair["surface"]]
    return world["surfaces"][world.get("default_surface", 0)]


def _lossless(surface):
    """A contact that gives back every joule: restitution 1 from every
    impact speed, no friction, no softness."""
    return (surface.get("restitution") == 1 and not surface.get("bounce_velocity")
            and surface.get("mu") in (0, 0.0) and "soft_erp" not in surface and "soft_cfm" not in surface)


def energy_conserved(world):
    """(True, why) when nothing in the world can take energy out: no contact
    that loses any (every pair that may touch bounces with restitution 1
    without friction), no kinematic body, no angular speed cap."""
    bodies = world.get("bodies", [])
    if any(b.get("kinematic") for b in bodies):
        return False, "a kinematic body moves from outside"
    if any("max_angular_speed" in b for b in bodies):
        return False, "an angular speed cap takes energy out"
    pairs = touching_pairs(world)
    if any(not _lossless(surface_between(world, a, b)) for a, b in pairs):
        return False, "a contact can take energy out (friction, restitution below 1 or softness)"
    return True, ("no two geoms can touch" if not pairs else "every contact is elastic (restitution 1) and "
                  "frictionless") + ", no kinematic body, no speed cap: energy is conserved"


def momentum_conserved(world):
    """(True, why) when nothing outside acts on the bodies: no gravity on any
    body, no joint to the static world, no static geom a body may touch, no
    kinematic body."""
    bodies = world.get("bodies", [])
    gravity = world.get("settings", {}).get("gravity", [0, 0, 0])
    if not _vec_zero(gravity) and any(b.get("gravity", True) for b in bodies):
        return False, "gravity acts"
    if any(j.get("body1", -1) < 0 or j.get("body2", -1) < 0 for j in world.get("joints", [])):
        return False, "a joint holds a body to the static world"
    if any(b.get("kinematic") for b in bodies):
        return False, "a kinematic body moves from outside"
    geoms = world.get("geoms", [])
    if any(geoms[a].get("body", -1) < 0 or geoms[b].get("body", -1) < 0 for a, b in touching_pairs(world)):
        return False, "a body may touch static geometry"
    return True, "no gravity, no static contact, no joint to the world: momentum is conserved"


def _fastest_speed(world, body, until):
    """An upper bound of the body's speed up to `until` s in free flight:
    its starting speed plus gravity's."""
    b = world["bodies"][body]
    v = math.sqrt(sum(x * x for x in b.get("linear_velocity", [0, 0, 0])))
    g = math.sqrt(sum(x * x for x in world.get("settings", {}).get("gravity", [0, 0, 0])))
    return v + g * until


def reference_of(world, measurement):
    """The strongest Reference for `measurement` (world_measures.Measurement)."""
    measure = measurement.measure or {}
    name, kind = measurement.name, measurement.kind
    if kind == "ballistic":
        return Reference(ANALYTIC, "the exact ballistic arc (the metric is the distance from it)", 0.0)
    if kind == "period":
        return Reference(ANALYTIC, f"the period the world states, {measure['expected']:g} s", float(measure["expected"]))
    if kind == "joint_error":
        return Reference(ANALYTIC, "a joint holds its bodies together exactly", 0.0)
    if kind == "penetration":
        return Reference(ANALYTIC, "rigid bodies do not interpenetrate", 0.0)
    if name == "tunnelled_bodies":
        expect = measure.get("expect", 0)
        return Reference(ANALYTIC, f"{expect} bodies pass the wall (the world's expect)" if "expect" in measure
                         else "a rigid wall stops every body", float(expect))
    if name == "tunnelling_crossings" and not measure.get("expect"):
        return Reference(ANALYTIC, "a rigid wall is never crossed", 0.0)
    if name == "time_to_rest_s" and "expect" in measure:
        if measure["expect"] == "never":
            return Reference(ANALYTIC, "the body never comes to rest (the world's expect)", math.inf)
        return Reference(ANALYTIC, f"at rest at {measure['expect']:g} s (the world's expect)", float(measure["expect"]))
    if name == "energy_drift" and "expect" in measure:
        return Reference(ANALYTIC, f"an energy drift of {measure['expect']:g} (the world's expect)",
                         float(measure["expect"]))
    if kind == "probe" and isinstance(measure.get("expect"), (int, float)):
        return Reference(ANALYTIC, f"{measure['expect']:g}, the answer the world states for the probe "
                                   f"{measure.get('name', name)}", float(measure["expect"]))
    if kind == "energy":
        conserved, why = energy_conserved(world)
        if conserved:
            return Reference(CONSERVATION, why, 0.0)
    if kind == "momentum":
        conserved, why = momentum_conserved(world)
        if conserved:
            return Reference(CONSERVATION, why, 0.0)
    return Reference(SELF, f"the same engine and setting at a {FINER} times finer step")


def step_resolution(world, measurement, step):
    """The difference one step's timing explains for this measurement, or
    None: a time (period, time to rest) within one step; a ballistic arc
    within one step at the body's fastest speed up to the measure's `until`."""
    measure = measurement.measure or {}
    if measurement.name.endswith("_period_s") or measurement.name == "time_to_rest_s":
        return step
    if measurement.kind == "probe" and measure.get("take") == "first_crossing":
        return step  # a probe's first crossing is a time
    if measurement.kind == "ballistic" and math.isfinite(measure.get("until", math.inf)):
        return _fastest_speed(world, measure["body"], measure["until"]) * step
    return None


def grade(world, measurement, reference, value, finer_value, step):
    """(deviation, at_step_resolution) of one measured value against its
    reference: |value - target| / scale, inf where the value is missing or
    the outcome is the other one (at rest where it should slide); a
    difference within step_resolution is 0, said as such (True)."""
    target = finer_value if reference.kind == SELF else reference.value
    if target is None or (isinstance(target, float) and math.isnan(target)):
        return None, False
    if isinstance(target, float) and math.isinf(target):  # expected never: a value at all is the other outcome
        return (0.0 if value is None else math.inf), False
    if value is None or not math.isfinite(value):
        return math.inf, False
    resolution = step_resolution(world, measurement, step)
    if resolution is not None and abs(value - target) <= resolution:
        return 0.0, abs(value - target) > 0
    # A time expected to be 0 (at rest from the start) has no size of its own: 1 s is its scale.
    scale = measurement.scale_for(target) or (1.0 if measurement.name.endswith("_s") else None)
    if not scale:
        return None, False
    return abs(value - target) / scale, False


def outcome_words(measurement, value):
    """The outcome a run shows, by rule, in words, or None: a tunnelling
    measure's "stops" / "tunnels", a rest measure's "stays" (comes to rest)
    / "slides" (never does)."""
    if measurement.name == "tunnelled_bodies":
        return None if value is None else ("stops" if value == 0 else "tunnels")
    if measurement.name == "time_to_rest_s":
        return "slides" if value is None else "stays"
    return None


def expected_outcome(measurement):
    """The outcome the world's answer implies, or None where it states none."""
    measure = measurement.measure or {}
    if measurement.name == "tunnelled_bodies":
        return "stops" if not measure.get("expect") else "tunnels"
    if measurement.name == "time_to_rest_s" and "expect" in measure:
        return "slides" if measure["expect"] == "never" else "stays"
    return None

"""What the lab measures on a user's world file (lab/odelab-report --world):
the metrics its `measures` list asks odelab for (doc/world-format.md), each
with the rule that says how far a run is from the reference run.

Every measurement has a scale, and a run's deviation is
|value - reference| / scale, so that "within 1%" is one test for all:
- "relative": a quantity whose reference is a size of its own (a period, a
  time to rest): the scale is |reference|;
- "absolute": an error or drift whose reference is about 0 (an energy drift, a
  joint's separation): a relative figure would divide by ~0, so the scale is
  the quantity's own unit of comparison (the energy scale the metric is
  already divided by, 1 rad, or the world's smallest body geom for lengths);
- "count": a count of events (bodies through a wall): any difference is one
  event or more, so the scale is 1 and only an equal count is within 1%.

A `probe` (one number of a body's state, doc/world-format.md) is relative to
its `expect` where the world states one other than 0, so "within 1%" is
within 1% of the analytic answer; an `expect` of 0 has no size of its own,
so the probe's own stated tolerance counts as 1% of one (scale: 100
tolerances), and "within 1%" is within the tolerance the world states;
without `expect` it is relative to the finer run's value.

A world without `measures` (or an odelab that does not know the field yet)
gives no measurement of its own: then the run's own numeric metrics that
describe the physics (contacts, sleeping bodies) are compared, as counts."""

import math

RELATIVE, ABSOLUTE, COUNT = "relative", "absolute", "count"

# Per measure kind: (metric, rule, scale) with scale a number or "length" (the
# world's length scale, world_length_scale). Only the metrics that say how
# well the physics came out; the J and scale metrics describe the world.
KINDS = {
    "energy": [("energy_max_deviation", ABSOLUTE, 1.0), ("energy_drift", ABSOLUTE, 1.0)],
    "momentum": [("linear_momentum_drift", ABSOLUTE, 1.0), ("angular_momentum_drift", ABSOLUTE, 1.0)],
    "joint_error": [("joint_error_max_m", ABSOLUTE, "length"), ("joint_axis_error_max_rad", ABSOLUTE, 1.0)],
    "penetration": [("penetration_max_m", ABSOLUTE, "length")],
    "tunnelling": [("tunnelled_bodies", COUNT, 1.0), ("tunnelling_crossings", COUNT, 1.0)],
    "ballistic": [("{name}_error_max_m", ABSOLUTE, "length")],
    "period": [("{name}_period_s", RELATIVE, None)],
    "rest": [("time_to_rest_s", RELATIVE, None)],
}
SCALE_WORDS = {"joint_axis_error_max_rad": "1 rad"}
# Metrics odelab already divides by a scale of the world's: (the metric that
# gives that scale, its unit), said beside the rule.
DIVIDED_BY = {"energy_max_deviation": ("energy_scale_J", "J"), "energy_drift": ("energy_scale_J", "J"),
              "linear_momentum_drift": ("linear_momentum_scale", "kg m/s"),
              "angular_momentum_drift": ("angular_momentum_scale", "kg m^2/s")}
# Without measures: these metrics of every run describe what happened.
FALLBACK = ["contacts", "disabled_bodies"]


class Measurement:
    def __init__(self, name, kind, rule, scale=None, scale_text="", measure=None):
        self.name, self.kind, self.rule = name, kind, rule
        self.measure = measure  # the world's entry in `measures` it comes from (None: a fallback)
        self.scale = scale  # None: |reference| (RELATIVE)
        self.scale_text = scale_text

    def scale_for(self, reference):
        if self.rule == RELATIVE:
            return abs(reference) if reference else None
        return self.scale

    def deviation(self, value, reference):
        """|value - reference| / scale; inf when the run gave no value where
        the reference did; None when there is no reference to compare with."""
        if reference is None or not _finite(reference):
            return None
        scale = self.scale_for(reference)
        if not scale:
            return None
        if value is None or not _finite(value):
            return math.inf
        return abs(value - reference) / scale

    def rule_text(self):
        if self.rule == RELATIVE:
            return "relative: |value - reference| / |reference|"
        if self.rule == COUNT:
            return "count: |value - reference| (an equal count is within every tolerance)"
        return f"absolute (reference about 0): |value - reference| / {self.scale_text or format(self.scale, 'g')}"


def _finite(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(value)


def world_length_scale(world):
    """The smallest extent of a geom on a body (a box's shortest side, a
    sphere's diameter, a capsule's or cylinder's diameter), m: a length
    error of 1% of it is 1% of the smallest thing that moves. None if no
    body carries a geom."""
    sizes = []
    for geom in world.get("geoms", []):
        if geom.get("body", -1) < 0:
            continue
        shape = geom.get("shape")
        if shape == "box" and geom.get("size"):
            sizes.append(min(geom["size"]))
        elif shape in ("sphere", "capsule", "cylinder") and geom.get("radius"):
            sizes.append(2 * geom["radius"])
    return min(sizes) if sizes else None


def measurements(world):
    """The Measurements the world's `measures` list gives, in its order; the
    fallback metrics (as counts) when it has none."""
    found = []
    length = world_length_scale(world)
    for measure in world.get("measures") or []:
        kind = measure.get("kind")
        for metric, rule, scale in KINDS.get(kind, []):
            name = metric.format(name=measure.get("name") or kind)
            text = SCALE_WORDS.get(name, "")
            if scale == "length":
                if length is None:
                    continue  # nothing moving has a size: no length to compare with
                scale, text = length, f"{length:.3g} m, the smallest geom on a body"
            found.append(Measurement(name, kind, rule, scale, text, measure))
        if kind == "probe":
            found.append(probe_measurement(measure))
    if not found:
        found = [Measurement(name, "run", COUNT, 1.0, "1") for name in FALLBACK]
    return found


def probe_measurement(measure):
    """A probe's `<name>_value`, scaled as the module's docstring says."""
    name = f"{measure.get('name') or 'probe' + str(measure.get('body', 0))}_value"
    expect = measure.get("expect")
    if isinstance(expect, (int, float)) and expect == 0:
        tolerance = measure.get("tolerance")
        if isinstance(tolerance, (int, float)) and tolerance > 0:
            return Measurement(name, "probe", ABSOLUTE, 100 * float(tolerance),
                               f"{100 * tolerance:g}: its expect is 0, so its own tolerance {tolerance:g} "
                               "counts as 1%", measure)
    return Measurement(name, "probe", RELATIVE, None, "", measure)


def from_metrics(world, metrics):
    """The measurements of `world` that the reference run's `metrics` hold:
    an odelab that wrote none of a kind's metrics leaves it out (and says
    which, second value)."""
    wanted = measurements(world)
    kept = [m for m in wanted if m.name in metrics]
    for m in kept:
        if m.name in DIVIDED_BY:
            scale, unit = DIVIDED_BY[m.name]
            said = f"{metrics[scale]:.3g} {unit}" if isinstance(metrics.get(scale), (int, float)) else "its scale"
            m.scale_text = f"1 (the metric is already divided by {scale} = {said}, the measure's scale)"
    return kept, [m.name for m in wanted if m.name not in metrics]


def max_deviation(deviations):
    """A setting's deviation over every measurement: the largest (inf where
    one is inf); None when none could be judged."""
    known = [d for d in deviations if d is not None]
    return max(known) if known else None

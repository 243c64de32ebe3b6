"""test8: the largest relative elongation of the heavy pendulum against CFM
at ERP 0.4 and 1.0 (the thesis's figure 11), and against the bob's mass,
beside the spring-damper estimate stretch = F h CFM / ERP."""

import math

from .. import markdown as md
from ..claims import Claim, q
from ..plots import limits as plots
from ..runner import RunSpec
from .base import Experiment, Outcome

FAILURE_ELONGATION = 0.01  # the failure rule: the hinge stretched by more than 1% of its length
STEP = 0.001


def _sweep(column, **where):
    return q("limit-test8.csv", column, sweep="cfm", bob_mass_kg=5000, **where)


def _limit(what):
    return q("limit-test8-limits.csv", "measured", limit=what)


CFM_LIMITS = ("ERP 0.4, 5000 kg: largest CFM within 1%", "ERP 1, 5000 kg: largest CFM within 1%")
HEADLINE = Claim("headline.test8", "test8: at ERP 0.4 the 5000 kg pendulum stretches {s4:n} at CFM 1e-4 (spring "
                 "estimate {e4:n}) and {s0:n} at CFM 0; the 1% rule allows CFM up to {l4:n} at ERP 0.4 and {l1:n} at "
                 "ERP 1.0.", {"s4": _sweep("max_relative_elongation", erp=0.4, cfm=1e-4),
                              "e4": _sweep("estimate_F_h_CFM_over_ERP", erp=0.4, cfm=1e-4),
                              "s0": _sweep("max_relative_elongation", erp=0.4, cfm=0),
                              "l4": _limit(CFM_LIMITS[0]), "l1": _limit(CFM_LIMITS[1])},
                 "s0 < s4 and e4 > 0 and l4 > 0 and l1 > 0")


def pendulum(r):
    """(mass, anchor to centre of mass d, inertia about the hinge axis,
    gravity) of the composite pendulum of test8 run `r`, as the program
    built it (its metrics: the scene's constants live in the program)."""
    return (r.m("composite_mass_kg"), r.m("start_length_m"), r.m("inertia_about_axis_kg_m2"),
            r.m("gravity_m_s2"))


def bottom_load(r):
    """Hinge load at the bottom of a swing released from horizontal:
    m g (1 + 2 m d^2 / I) (weight plus centripetal force)."""
    mass, d, inertia, gravity = pendulum(r)
    return mass * gravity * (1 + 2 * mass * d * d / inertia)


def estimate(r, cfm, erp, step=STEP):
    """Relative stretch of the pendulum of run `r` if its hinge acts as a
    spring of stiffness ERP / (step CFM): F step CFM / (ERP l0)."""
    return bottom_load(r) * step * cfm / (erp * pendulum(r)[1])


def run_spec(erp, cfm, bob_mass, seconds, measures_blow_ups=False):
    return RunSpec("test8", ["--erp", erp, "--cfm", cfm, "--bob-mass", bob_mass, "--step", STEP,
                             "--seconds", seconds, "--sample-interval", 3600], measures_blow_ups=measures_blow_ups)


def crossing(points, threshold):
    """Largest x (log-log interpolation) at which y stays <= threshold, on
    points sorted by x; None if the first point already fails."""
    best = None
    for (x0, y0), (x1, y1) in zip(points, points[1:]):
        if y0 > threshold:
            return best
        best = x0
        if y1 > threshold and x0 > 0 and y0 > 0:
            f = (math.log(threshold) - math.log(y0)) / (math.log(y1) - math.log(y0))
            return math.exp(math.log(x0) + f * (math.log(x1) - math.log(x0)))
    if points and points[-1][1] <= threshold:
        return points[-1][0]
    return best


class LimitTest8(Experiment):
    name = "limit-test8"
    title = "test8: hinge elongation against CFM and bob mass"
    section = 2
    programs = ("test8",)
    cost = (5.0, 1.0)

    def run(self, ctx):
        quick = ctx.quick
        seconds = 10 if quick else 60
        cfms = [0.0, 1e-6, 1e-4, 1e-2] if quick else [0.0, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2]
        masses = [5.0, 5000.0, 1e6] if quick else [0.33, 5.0, 50.0, 500.0, 5000.0, 5e4, 1e6]
        plan = [("cfm", erp, cfm, 5000.0) for erp in (0.4, 1.0) for cfm in cfms]
        plan += [("mass", 0.4, cfm, m) for cfm in (1e-4, 0.0) for m in masses]
        specs = [run_spec(erp, cfm, m, seconds, measures_blow_ups=True) for _, erp, cfm, m in plan]
        ctx.expect(len(specs))
        results = ctx.runner.map(specs)
        ctx.advance(len(specs))
        rows = []
        for (sweep, erp, cfm, mass), r in zip(plan, results):
            elongation = r.m("max_relative_elongation")
            lowest = r.m("lowest_bob_height_m")
            failed = r.rc != 0 or elongation is None or elongation > FAILURE_ELONGATION or (lowest or 0) < 0
            rows.append(dict(sweep=sweep, erp=erp, cfm=cfm, bob_mass_kg=mass, step_s=STEP, seconds=seconds,
                             max_relative_elongation=elongation,
                             estimate_F_h_CFM_over_ERP=estimate(r, cfm, erp),
                             deflection_at_max_deg=r.m("deflection_at_max_elongation_deg"),
                             lowest_bob_height_m=lowest, bottom_load_N=bottom_load(r),
                             exit_status=r.rc, failed=failed))
        csv = ctx.write_csv("limit-test8", list(rows[0].keys()), rows,
                            notes=["failure rule: max_relative_elongation > 0.01 or lowest_bob_height_m < 0",
                                   "estimate = F step CFM / (ERP l0), F = m g (1 + 2 m d^2 / I), the load at the "
                                   "bottom of a swing released from horizontal"])
        ctx.register_files(plots.elongation(ctx.out_dir, "limit-test8", rows, FAILURE_ELONGATION))

        limits = []
        heavy = results[plan.index(("cfm", 0.4, 1e-4, 5000.0))]  # any 5000 kg run: the pendulum is the same
        for erp in (0.4, 1.0):
            pts = sorted((row["cfm"], row["max_relative_elongation"]) for row in rows
                         if row["sweep"] == "cfm" and row["erp"] == erp and row["cfm"] > 0)
            limits.append((CFM_LIMITS[int(erp == 1.0)], crossing(pts, FAILURE_ELONGATION),
                           0.01 * erp * pendulum(heavy)[1] / (bottom_load(heavy) * STEP)))
        pts = sorted((row["bob_mass_kg"], row["max_relative_elongation"]) for row in rows
                     if row["sweep"] == "mass" and row["cfm"] == 1e-4)
        limits.append(("ERP 0.4, CFM 1e-4: heaviest bob within 1%", crossing(pts, FAILURE_ELONGATION), None))
        cfm_rows = [[md.num(row["erp"]), md.num(row["cfm"]), md.num(row["max_relative_elongation"]),
                     md.num(row["estimate_F_h_CFM_over_ERP"]) if row["cfm"] > 0 else "0 (rigid)",
                     md.num(row["deflection_at_max_deg"], 2), md.num(row["lowest_bob_height_m"], 3),
                     "fails" if row["failed"] else "holds"]
                    for row in rows if row["sweep"] == "cfm"]
        mass_rows = [[md.num(row["bob_mass_kg"]), md.num(row["cfm"]), md.num(row["max_relative_elongation"]),
                      md.num(row["estimate_F_h_CFM_over_ERP"]) if row["cfm"] > 0 else "0 (rigid)",
                      "fails" if row["failed"] else "holds"]
                     for row in rows if row["sweep"] == "mass"]
        limits_csv = ctx.write_csv("limit-test8-limits", ["limit", "measured", "model"],
                                   [dict(limit=what, measured=value, model=model) for what, value, model in limits],
                                   notes=["measured: log-log interpolation between the points of limit-test8.csv where "
                                          "max_relative_elongation crosses 0.01 (empty: none measured); model: the "
                                          "spring estimate F h CFM / (ERP l0) solved for 1%"])
        limit_rows = [[what, md.num(value) if value is not None else "none measured",
                       md.num(model) if model else "-"] for what, value, model in limits]
        text = f"""**Failure rule.** The bob's centre more than 1% of the pendulum's length (3.3 cm)
from where a rigid hinge holds it (`max_relative_elongation` > 0.01), or the bob
below the ground (`lowest_bob_height_m` < 0). Step 0.001 s, QuickStep 20
iterations, released from horizontal, {seconds} s per run. The estimate treats
the hinge as ODE's spring of stiffness ERP / (step x CFM) loaded by the bottom
of the swing, F = m g (1 + 2 m d^2 / I) ({bottom_load(heavy) / (pendulum(heavy)[0] * pendulum(heavy)[3]):.3g} m g for the 5000 kg bob):
relative stretch = F h CFM / (ERP l0).

{md.table(["ERP", "CFM", "max relative elongation", "estimate", "deflection at max (deg)",
           "lowest bob point (m)", "rule"], cfm_rows)}

{md.table(["bob mass (kg)", "CFM", "max relative elongation", "estimate", "rule"], mass_rows)}

Limits by the rule (log-log interpolation between measured points; the model
column solves the estimate for 1%):

{md.table(["limit", "measured", "model"], limit_rows)}

{md.figure("limit-test8", "test8: largest relative elongation against CFM (left) and bob mass (right), "
           "with the spring estimate F h CFM / ERP")}

{md.files_line([csv, limits_csv])}"""
        return Outcome(text, [HEADLINE])

"""test4: the heaviest big cube a 5 kg cube holds for 20 s, at steps 1e-3,
5e-4, 2e-4, 1e-4, for QuickStep (20 iterations) and dWorldStep."""

from .. import markdown as md
from ..claims import Claim, q, slot
from ..plots import limits as plots
from ..runner import RunSpec
from ..search import highest_passing
from .base import Experiment, Outcome

MAX_PENETRATION = 0.05  # m: a tenth of the small cube's side
SOLVERS = [("QuickStep 20", ["--solver", "quick", "--iterations", 20]), ("dWorldStep", ["--solver", "step"])]
RULE = ("a run fails when the state becomes non-finite (exit 3) or ODE reports an error (exit 4), when the big "
        "cube's centre moves more than 0.5 m sideways or sinks more than 0.1 m below its start (test4's `held` = 0), "
        f"or when any overlap (`max_penetration`) exceeds {MAX_PENETRATION} m")


def _held(column="heaviest_held_kg", agg="one", **where):
    return q("limit-test4.csv", column, agg, **where)


_AT_0001 = {"qs": _held(solver="QuickStep 20", step_s=0.001), "dw": _held(solver="dWorldStep", step_s=0.001),
            "s": _held("hold_seconds", solver="QuickStep 20", step_s=0.001)}
_HELD = "qs > 0 and dw > 0 and s > 0"  # each solver held some mass, for a stated time
_HEADLINE = "test4: at step 0.001 QuickStep holds up to {qs:n} kg on the 5 kg cube for {s:n} s, dWorldStep {dw:n} kg"
HEADLINE = [Claim("headline.test4", _HEADLINE + " (thesis: {thesis}; Havok {havok}).",
                  dict(_AT_0001, thesis=q("thesis.csv", "thesis_ode_0_11_1", "text", key="test4_fast"),
                       havok=q("thesis.csv", "havok_6_5_quoted", "text", key="test4_fast")), _HELD),
            Claim("headline.test4.alone", _HEADLINE + ".", _AT_0001, _HELD)]
_BY_STEP = {"qs": _held(agg="list", solver="QuickStep 20"), "qh": _held("step_s", "list", solver="QuickStep 20"),
            "dw": _held(agg="list", solver="dWorldStep"), "dh": _held("step_s", "list", solver="dWorldStep"),
            "coarse": "qs[qh.index(max(qh))]", "fine": "qs[qh.index(min(qh))]", "hmin": "min(qh)",
            "ratios": "[dw[dh.index(h)] / m for h, m in zip(qh, qs) if h in dh and m and dw[dh.index(h)]]"}
READING = {
    "step": [Claim("limit-test4.step", "A smaller step raises the mass QuickStep 20 holds: {coarse:n} kg at step "
                   "0.001, {fine:n} kg at {hmin:n}.", _BY_STEP, "fine > coarse and max(qh) == 0.001"),
             Claim("limit-test4.step.not", "A smaller step does not raise the mass QuickStep 20 holds: {coarse:n} kg "
                   "at step 0.001, {fine:n} kg at {hmin:n}.", _BY_STEP, "fine <= coarse and max(qh) == 0.001")],
    "solver": [Claim("limit-test4.solver", "dWorldStep (the exact LCP solver) holds more at every step measured: "
                     "{ratios:r} times QuickStep 20's mass.", _BY_STEP, "len(ratios) > 0 and min(ratios) > 1"),
               Claim("limit-test4.solver.mixed", "dWorldStep (the exact LCP solver) holds {ratios:r} times QuickStep "
                     "20's mass across the steps: not more at every step.", _BY_STEP,
                     "len(ratios) > 0 and min(ratios) <= 1")],
}


def hold_seconds(quick):
    return 5.0 if quick else 20.0


def judge(r):
    """(passed, reason) of one test4 run by the failure rule."""
    if r.blew_up:
        return False, "non-finite state"
    if r.ode_error:
        return False, "ODE error"
    if not r.m("held", 0):
        return False, f"fell after {r.m('seconds_held'):.3g} s"
    if r.m("max_penetration", 0) > MAX_PENETRATION:
        return False, f"overlap {r.m('max_penetration'):.3g} m"
    return True, "held"


EXPECTED_PROBES = (8, 4)  # about how many runs a search makes (full, quick)


def search_heaviest(runner, step, solver_args, quick, on_probe=None):
    """The heaviest mass held (SearchResult; probe info = (RunResult, reason))."""
    seconds = hold_seconds(quick)

    def probe(mass):
        r = runner.run(RunSpec("test4", ["--big-mass", mass, "--step", step, *solver_args, "--seconds", seconds],
                               priority=0, measures_blow_ups=True))
        passed, reason = judge(r)
        return passed, (r, reason)

    return highest_passing(probe, start=5000.0, factor=10.0 if quick else 4.0, ratio=3.0 if quick else 1.1,
                           low=50.0, high=1e9, on_probe=on_probe)


class LimitTest4(Experiment):
    name = "limit-test4"
    title = "test4: heaviest cube held on a 5 kg cube"
    section = 2
    programs = ("test4",)
    cost = (150.0, 8.0)

    def run(self, ctx):
        steps = [1e-3, 2e-4] if ctx.quick else [1e-3, 5e-4, 2e-4, 1e-4]
        configs = [(s, name, args) for s in steps for name, args in SOLVERS]
        def one(config):
            step, _, args = config
            on_probe, finished = ctx.search_units(EXPECTED_PROBES[ctx.quick])
            result = search_heaviest(ctx.runner, step, args, ctx.quick, on_probe)
            finished()
            return result

        results = ctx.runner.parallel([lambda c=c: one(c) for c in configs])
        seconds = hold_seconds(ctx.quick)
        limits, probes = [], []
        for (step, solver, _), res in zip(configs, results):
            failed_reason = next((info[1] for v, p, info in res.probes if v == res.lowest_fail), "")
            limits.append(dict(step_s=step, solver=solver, hold_seconds=seconds, heaviest_held_kg=res.highest_pass,
                               lightest_failed_kg=res.lowest_fail, failure_at_lightest_failed=failed_reason,
                               probes=len(res.probes), search_capped=res.capped))
            for mass, passed, (r, reason) in res.probes:
                probes.append(dict(step_s=step, solver=solver, big_mass_kg=mass, passed=passed, outcome=reason,
                                   seconds_held=r.m("seconds_held"), max_tilt_degrees=r.m("max_tilt_degrees"),
                                   max_penetration_m=r.m("max_penetration"), exit_status=r.rc,
                                   wall_seconds=r.m("wall_seconds")))
        notes = ["failure rule: " + RULE,
                 "search: masses x4 from 5000 kg until a run fails (or passes, going down), then geometric "
                 "bisection to 10%; assumes failing is monotone in the mass; seed 1"]
        csv = ctx.write_csv("limit-test4", list(limits[0].keys()), limits, notes)
        csv_probes = ctx.write_csv("limit-test4-probes", list(probes[0].keys()), probes, notes)
        ctx.register_files(plots.heaviest_mass(ctx.out_dir, "limit-test4", limits))
        rows = [[md.num(x["step_s"]), x["solver"],
                 md.num(x["heaviest_held_kg"], 3, "kg") + (" (search cap)" if x["search_capped"] and
                                                           x["lightest_failed_kg"] is None else ""),
                 md.num(x["lightest_failed_kg"], 3, "kg"), x["failure_at_lightest_failed"] or "-"]
                for x in limits]
        text = f"""**Failure rule.** {RULE[0].upper() + RULE[1:]}. Each run holds for {seconds:g} s
(ERP 0.2, CFM 1e-6, seed 1). The search multiplies the mass by {10 if ctx.quick else 4} from
5000 kg until a run fails, then bisects geometrically to within {"a factor 3" if ctx.quick else "10%"}; it
assumes failing is monotone in the mass (masses above the first failure are not all tried).

{md.table(["step (s)", "solver", "heaviest held", "lightest failed", "how the lightest failed"], rows)}

{md.figure("limit-test4", "test4: heaviest big cube held on the 5 kg cube against the step (log-log), "
           "QuickStep 20 iterations and dWorldStep, with the thesis's figures")}

{md.files_line([csv, csv_probes])}

How to read it: the bar between the heaviest held and the lightest failed mass
is the limit's uncertainty. {slot("step")} {slot("solver")}"""
        return Outcome(text, [HEADLINE], claims=READING)

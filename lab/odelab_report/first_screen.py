"""The table at the top of RESULTS.md: a row per scene, test0 to test10, read
from the CSVs the experiments wrote (so it stays true on another machine or
ODE build): what is measured and how it is defined, ODE's figure at the
thesis's settings, the thesis's figure and the verdict, what decides the
figure with its measured effect, the cheapest setting within 1% / 0.1%, and
the best other engine. Every cell is a Claim (claims.py); a cell whose data
this report lacks says so."""

from . import markdown as md
from .claims import Claim, q

COLUMNS = ["scene", "measured quantity (definition)", "ODE at the thesis's settings",
           "thesis (ODE 0.11.1) and verdict", "what decides it (measured)", "cheapest within 1% / 0.1%",
           "best other engine at step 0.001"]
NOT_MEASURED = "not in this report"


def thesis_cell(key):
    return Claim(f"first.{key}.thesis", "{thesis} (**{verdict}**)",
                 {"thesis": q("thesis.csv", "thesis_ode_0_11_1", "text", key=key),
                  "verdict": q("thesis.csv", "verdict", "text", key=key)})


def value(key, name, agg="one"):
    return q("thesis-values.csv", "value", agg, key=key, name=name)


def figure_from_thesis(scene, key, name, template="{v:n}"):
    return Claim(f"first.{scene}.figure", template, {"v": value(key, name)})


def speed_lookups(scene):
    f = f"speed-{scene}.csv"
    return {"solvers": q(f, "solver", "texts"), "steps": q(f, "step_s", "list"), "errors": q(f, "error", "list"),
            "cost": q(f, "wall_per_sim_second", "list"), "wmin": q(f, "wall_seconds_min", "list"),
            "wmax": q(f, "wall_seconds_max", "list"), "timed": q(f, "timed_sim_seconds", "list"),
            "names": "[s + ' at ' + num(h) for s, h in zip(solvers, steps)]",
            "lo": "[a / t for a, t in zip(wmin, timed)]", "hi": "[a / t for a, t in zip(wmax, timed)]"}


def cheapest_cell(scene):
    values = speed_lookups(scene)
    values.update(c1="cheapest(names, errors, cost, lo, hi, 0.01, 'QuickStep 20 at 0.001')",
                  c01="cheapest(names, errors, cost, lo, hi, 0.001, 'QuickStep 20 at 0.001')")
    return Claim(f"first.{scene}.cheapest", "1%: {c1}; 0.1%: {c01}", values)


def step_decides(scene):
    """The step decides when the solvers agree at step 0.001 (within 1% of
    the error) and the step moves QuickStep 20's error 10x or more."""
    values = speed_lookups(scene)
    values.update(at=q(f"speed-{scene}.csv", "error", "list", step_s=0.001),
                  coarse=q(f"speed-{scene}.csv", "error", solver="QuickStep 20", step_s=0.01),
                  fine=q(f"speed-{scene}.csv", "error", solver="QuickStep 20", step_s=0.0001),
                  spread="(max(at) - min(at)) / max(at)")
    return Claim(f"first.{scene}.decides.step",
                 "the step: QuickStep 20 {coarse:n2} at step 0.01, {fine:n2} at 0.0001; at step 0.001 every "
                 "solver within {spread:p1} of the largest error",
                 values, "spread < 0.01 and coarse / fine >= 10")


def solver_decides(scene):
    """The solver (iterations) decides when, at step 0.001, the solvers'
    errors span more than 10x what the step moves QuickStep 20's."""
    f = f"speed-{scene}.csv"
    values = {"q5": q(f, "error", solver="QuickStep 5", step_s=0.001),
              "q10": q(f, "error", solver="QuickStep 10", step_s=0.001),
              "q20": q(f, "error", solver="QuickStep 20", step_s=0.001),
              "dw": q(f, "error", solver="dWorldStep", step_s=0.001),
              "by_step": q(f, "error", "list", solver="QuickStep 20"),
              "step_span": "max(by_step) / min(by_step)",
              "solver_span": "max(q5, q10, q20) / min(q5, q10, q20)"}
    return Claim(f"first.{scene}.decides.solver",
                 "the iterations: at step 0.001 QuickStep 5 {q5:n2}, 10 {q10:n2}, 20 {q20:n2}, dWorldStep "
                 "{dw:n2}; the step moves QuickStep 20 by {step_span:n3}x at most",
                 values, "solver_span > 10 * step_span")


def peer_cell(scene, quantity, higher_better, figure="{v:n}"):
    """The best engine other than ODE at step 0.001 in peers.csv; no cell
    when no other engine ran the scene."""
    f = "peers.csv"
    values = {"engines": q(f, "engine", "texts", scene=scene, step=0.001),
              "settings": q(f, "setting", "texts", scene=scene, step=0.001),
              "vals": q(f, "value", "list", scene=scene, step=0.001),
              "costs": q(f, "wall_s_per_sim_s", "list", scene=scene, step=0.001),
              "others": "[i for i, e in enumerate(engines) if e != 'ode' and vals[i] is not None]",
              "i": f"others[best_of([engines[j] for j in others], [vals[j] for j in others], "
                   f"[costs[j] for j in others], {higher_better})]",
              "name": "engines[i] + ' (' + settings[i] + ')'",
              "v": "vals[i]", "c": "costs[i]"}
    return Claim(f"first.{scene}.peer", "{name}: " + figure + " " + quantity + " at {c:n2} wall s per simulated s",
                 values, "len(others) > 0")


STACKS = {"ten": q("limit-test5.csv", "tallest_plates", "list", setting="simple, 10 iterations"),
          "twenty": q("limit-test5.csv", "tallest_plates", "list", setting="simple, 20 iterations"),
          "spaces": q("limit-test5.csv", "tallest_plates", "list", iterations=20)}


def CCD_COST(column):
    return q("remedy-test10.csv", column, kind="cost", setting="--ccd", launch_velocity=200)


def rows():
    """(scene, definition, [claims per column...]) for test0 to test10; a
    list of claims in a cell is alternatives, the first that holds shown."""
    return [
        ("test0", "bodies at rest on the platform; the thesis gives no figure", [
            [figure_from_thesis("test0", "test0_hang", "resting", "{v:n} bodies at rest after 20 s")], [thesis_cell("test0_hang")], [], [], []]),
        ("test1", "largest |apex2 / apex1 - e^2| over the balls, e >= 0.1", [
            [figure_from_thesis("test1", "test1", "rebound_error")], [thesis_cell("test1")],
            [Claim("first.test1.decides", "CFM: at CFM 1e-3 {b:n} balls rebound", {"b": value("test1", "bounced_cfm")})],
            [], [peer_cell("test1", "largest rebound error", False)]]),
        ("test2", "total energy (max - min) / max over 60 s, as the thesis", [
            [figure_from_thesis("test2", "test2", "variation", "{v:p2}")], [thesis_cell("test2")],
            [step_decides("test2"), solver_decides("test2")], [cheapest_cell("test2")],
            [peer_cell("test2", "largest |E - E0| / E0", False)]]),
        ("test3", "simulated seconds per wall second, physics only (median of the repeats)", [
            [Claim("first.test3.figure", "{v:n} x real time (runs {lo:n} to {hi:n}, {n:n} runs)",
                   {"v": value("test3", "real_time_factor"), "lo": q("thesis-values.csv", "value_min", key="test3",
                                                                      name="real_time_factor"),
                    "hi": q("thesis-values.csv", "value_max", key="test3", name="real_time_factor"),
                    "n": q("thesis-values.csv", "repeats", key="test3", name="real_time_factor")}, "n > 1"),
             figure_from_thesis("test3", "test3", "real_time_factor", "{v:n} x real time (one run)")],
            [thesis_cell("test3")],
            [Claim("first.test3.decides", "auto-disable and iterations: without auto-disable {a:n} x at 8 "
                   "iterations, {b:n} x at 20", {"a": value("test3", "real_time_factor_8"),
                                                 "b": value("test3", "real_time_factor_20")})], [],
            [peer_cell("test3", "of the dominoes fallen in 20 s", True, "{v:p2}")]]),
        ("test4", "heaviest big cube (kg) held on the 5 kg cube, QuickStep 20, step 0.001", [
            [Claim("first.test4.figure", "{v:n} kg held {h:n} s", {
                "v": q("limit-test4.csv", "heaviest_held_kg", solver="QuickStep 20", step_s=0.001),
                "h": q("limit-test4.csv", "hold_seconds", solver="QuickStep 20", step_s=0.001)})],
            [thesis_cell("test4_fast")],
            [Claim("first.test4.decides", "the solver: dWorldStep holds {dw:n} kg at step 0.001; the step: "
                   "QuickStep 20 holds {fine:n} kg at 0.0001",
                   {"dw": q("limit-test4.csv", "heaviest_held_kg", solver="dWorldStep", step_s=0.001),
                    "fine": q("limit-test4.csv", "heaviest_held_kg", solver="QuickStep 20", step_s=0.0001)})],
            [], [peer_cell("test4", "kg", True)]]),
        ("test5", "tallest stack (plates) aligned and in real time, simple space, 20 iterations, step 0.001", [
            [Claim("first.test5.figure", "median {v:n} plates ({all:r} over {n:n} searches)", {
                "v": q("limit-test5.csv", "tallest_plates", "median", setting="simple, 20 iterations"),
                "all": q("limit-test5.csv", "tallest_plates", "list", setting="simple, 20 iterations"),
                "n": q("limit-test5.csv", "tallest_plates", "count", setting="simple, 20 iterations")}, "n > 1"),
             Claim("first.test5.figure.one", "{v:n} plates (one search)", {
                 "v": q("limit-test5.csv", "tallest_plates", setting="simple, 20 iterations")})],
            [thesis_cell("test5")],
            [Claim("first.test5.decides", "iterations: 10 iterations {ten:r} plates, 20 iterations {twenty:r} "
                   "(simple space, every search)", STACKS, "min(ten) > max(twenty) or min(twenty) > max(ten)"),
             Claim("first.test5.decides.overlap", "no choice measured stands out: 10 iterations {ten:r} plates, "
                   "20 iterations {twenty:r}, the ranges overlap (simple space); the spaces at 20 iterations "
                   "{spaces:r}", STACKS, "True")], [], [peer_cell("test5", "plates", True)]]),
        ("test6", "seconds the ball-joint axis system stays upright, QuickStep 20 (median over seeds)", [
            [Claim("first.test6.figure", "{v:n} s (seeds {all:r}, {n:n} seeds)",
                   {"v": q("remedy-test6.csv", "seconds_upright", "median", step_s=0.001,
                           setting="QuickStep 20, step 0.001 (plain)"),
                    "all": q("remedy-test6.csv", "seconds_upright", "list", setting="QuickStep 20, step 0.001 (plain)"),
                    "n": q("remedy-test6.csv", "seconds_upright", "count", setting="QuickStep 20, step 0.001 (plain)")}),
             figure_from_thesis("test6", "test6", "seconds_upright", "{v:n} s")],
            [thesis_cell("test6")],
            [Claim("first.test6.decides", "the solver: over the seeds dWorldStep stays up {dw:r} s, QuickStep 20 {qs:r} s",
                   {"dw": q("remedy-test6.csv", "seconds_upright", "list", setting="dWorldStep, step 0.001 (remedy)"),
                    "qs": q("remedy-test6.csv", "seconds_upright", "list", setting="QuickStep 20, step 0.001 (plain)")},
                   "min(dw) > max(qs)")], [], [peer_cell("test6", "s upright (of 60)", True)]]),
        ("test7", "largest joint error (m) over 3 throws", [
            [figure_from_thesis("test7", "test7", "joint_error", "{v:n} m")], [thesis_cell("test7")], [], [],
            [peer_cell("test7", "m joint error (no angular speed cap)", False)]]),
        ("test8", "largest |l - l0| / l0 of the hinge over 60 s, 5000 kg bob, ERP 0.4, CFM 1e-4", [
            [figure_from_thesis("test8", "test8_a", "elongation")], [thesis_cell("test8_a")],
            [Claim("first.test8.decides", "CFM: {c0:n2} at CFM 0, {c4:n2} at 1e-4 (ERP 0.4)",
                   {"c0": q("limit-test8.csv", "max_relative_elongation", sweep="cfm", erp=0.4, cfm=0),
                    "c4": q("limit-test8.csv", "max_relative_elongation", sweep="cfm", erp=0.4, cfm=0.0001)},
                   "c4 > 10 * c0"),
             solver_decides("test8"), step_decides("test8")],
            [cheapest_cell("test8")], [peer_cell("test8", "|l - l0| / l0", False)]]),
        ("test9", "apex error after 20 bounces / drop height, ERP 0.2, CFM 0", [
            [figure_from_thesis("test9", "test9_a", "apex_error_20")], [thesis_cell("test9_a")],
            [solver_decides("test9"), step_decides("test9")], [cheapest_cell("test9")],
            [peer_cell("test9", "apex error", False)]]),
        ("test10", "highest launch velocity (m/s) with every cube stopped by the wall, step 0.001", [
            [Claim("first.test10.figure", "{v:n} m/s", {"v": q("limit-test10.csv", "max_velocity", step_s=0.001)}),
             figure_from_thesis("test10", "test10_a", "max_velocity", "{v:n} m/s")],
            [thesis_cell("test10_a")],
            [Claim("first.test10.decides", "the step ({a:n} / {b:n} / {c:n} m/s at step 0.01 / 0.001 / 0.0001) "
                   "unless `--ccd`: {d:n4} m/s at 0.001 (the scan's limit), its wall time per launch {e:p2} against plain "
                   "(pairs {lo:p2} to {hi:p2}, 200 m/s launches)",
                   {"a": q("limit-test10.csv", "max_velocity", step_s=0.01),
                    "b": q("limit-test10.csv", "max_velocity", step_s=0.001),
                    "c": q("limit-test10.csv", "max_velocity", step_s=0.0001),
                    "d": q("remedy-test10.csv", "max_velocity", kind="scan", setting="--ccd",
                           case="face on, fixed launch point", step_s=0.001),
                    "e": CCD_COST("extra_wall_per_launch"), "lo": CCD_COST("extra_wall_per_launch_min"),
                    "hi": CCD_COST("extra_wall_per_launch_max")}, "a < b < c < d"),
             Claim("first.test10.decides.step", "the step ({a:n} / {b:n} / {c:n} m/s at step 0.01 / 0.001 / 0.0001)",
                   {"a": q("limit-test10.csv", "max_velocity", step_s=0.01),
                    "b": q("limit-test10.csv", "max_velocity", step_s=0.001),
                    "c": q("limit-test10.csv", "max_velocity", step_s=0.0001)}, "a < b < c")],
            [], [peer_cell("test10", "m/s", True)]]),
    ]


def table(sentences):
    """The markdown table; `sentences` (claims.Sentences) records each
    claim shown."""
    body = []
    for scene, definition, cells in rows():
        row = [scene, definition]
        for alternatives in cells:
            row.append((sentences.say(*alternatives) if alternatives else None) or NOT_MEASURED)
        body.append(row)
    return md.table(COLUMNS, body)

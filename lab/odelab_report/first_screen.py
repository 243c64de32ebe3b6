"""The first screen of RESULTS.md: a row per scene of the scenes' list, that
answers which ODE setting, at what cost, and whether another engine does
better: the quantity and the setting the row is about (its definition),
ODE's figure there, the thesis's verdict in one word, the cheapest ODE
setting within 1% and the best other engine, costs in CPU seconds per
simulated second (the other engine's: its own seconds, collision and step
calls, per simulated second). Every cell reads the row's quantity at the row's setting
(readings.py says what each source reads); a source that reads another
gives "n/a: <why>", never its figure. Every figure cell is a Claim
(claims.py), read from the CSVs the experiments wrote.

What decides each figure, and the long material (tie lists, the engines'
matrix, the thesis's table, the machine), stand in sections below, which the
first screen links to (decides_table here, the rest in results_md.py and the
experiments)."""

from . import markdown as md
from . import readings, scenes
from .claims import Claim, _matches, q
from .peer_compare import FRICTION_ACTS

COLUMNS = ["scene", "quantity, setting", "ODE there", "thesis", "cheapest ODE within 1%",
           "best other engine, step 0.001"]
DECIDES_COLUMNS = ["scene", "what decides ODE's figure (measured)"]
VERDICTS = ("reproduced", "partly", "differs", "untested")
# The options of each speed sweep's runs but the solver's, the step and
# --seconds (experiments/speed_accuracy.py's scene_args): how runs.csv names
# the timed runs of a point.
SPEED_OPTIONS = {"test2": {"--erp": 0.4, "--cfm": 0, "--sample-interval": 3600},
                 "test8": {"--erp": 0.4, "--cfm": 0, "--sample-interval": 3600},
                 "test9": {"--erp": 0.2, "--cfm": 0}}
TIES_SECTION = "3"  # RESULTS.md's "Speed against accuracy"


def thesis_cell(key):
    """The thesis's verdict, one word (thesis.csv's verdict before any ';')."""
    return Claim(f"first.{key}.thesis", "{word}",
                 {"verdict": q("thesis.csv", "verdict", "text", key=key),
                  "word": "verdict.split(';')[0].strip()"}, f"word in {VERDICTS!r}")


def value(key, name, agg="one"):
    return q("thesis-values.csv", "value", agg, key=key, name=name)


def figure_from_thesis(scene, key, name, template, rule):
    """ODE's figure from thesis-values.csv, shown when `rule` (on v) says it
    is a figure of its kind (a count, a share, an error)."""
    return Claim(f"first.{scene}.figure", template, {"v": value(key, name)}, rule)


def speed_lookups(scene):
    f = f"speed-{scene}.csv"
    return {"solvers": q(f, "solver", "texts"), "steps": q(f, "step_s", "list"), "errors": q(f, "error", "list"),
            "cost": q(f, "wall_per_sim_second", "list"), "wmin": q(f, "wall_seconds_min", "list"),
            "wmax": q(f, "wall_seconds_max", "list"), "timed": q(f, "timed_sim_seconds", "list"),
            "names": "[s + ' @ ' + num(h) for s, h in zip(solvers, steps)]",
            "lo": "[a / t for a, t in zip(wmin, timed)]", "hi": "[a / t for a, t in zip(wmax, timed)]"}


def cheapest_cells(scene):
    """The cheapest setting within 1%, judged by wall time as
    speed_accuracy.py judges it: a tie within the timing's scatter links to
    the speed section; one setting gives its CPU cost over its timed runs
    (runs.csv)."""
    values = speed_lookups(scene)
    values.update(tied="cheapest_set(errors, cost, lo, hi, 0.01)")
    tie = Claim(f"first.{scene}.cheapest.tie", f"[tie (see §{TIES_SECTION})](#exp-speed-{scene})", values,
                "len(tied) > 1")
    runs = {name: q("runs.csv", column, agg, program=scene, timed=1) for name, column, agg in (
        ("args", "arguments", "texts"), ("cpu", "cpu_seconds", "list"), ("sim", "sim_seconds", "list"),
        ("share", "cpu_share", "list"), ("repeat", "repeat", "list"))}
    one = dict(values, **runs, i="tied[0]", scene_options=repr(SPEED_OPTIONS[scene]),
               c="runs_cost([args, cpu, sim, share, repeat], speed_options(solvers[i], steps[i], scene_options), "
                 "timed[i])")
    single = Claim(f"first.{scene}.cheapest", "{name}: {m:k2} [{a:k2}-{b:k2}]",
                   dict(one, name="names[i]", m="c[0]", a="c[1]", b="c[2]"), "len(tied) == 1 and c[3] > 1")
    once = Claim(f"first.{scene}.cheapest.once", "{name}: {m:k2} (1 run)", dict(one, name="names[i]", m="c[0]"),
                 "len(tied) == 1 and c[3] == 1")
    return [tie, single, once]


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


PEERS_SECTION = "5"  # RESULTS.md's section of experiments/peers.py


def peer_cell(scene, higher_better, figure="{v:k2}", step=0.001):
    """The best engine other than ODE in peers.csv at the row's step, at
    its defaults (as ODE's figure is at the thesis's settings: defaults
    beside defaults), like with like (peer_compare.py): every engine runs
    the scene's own world, so a run with a figure zero by construction (or
    one marked as not on the scene's surface) takes no part; the cell shows
    the step where it is not the column's 0.001 (and the scene's mu where
    friction acts) and the engine's own seconds per simulated second,
    median [range] of the timed runs; an equal figure whose cost range
    overlaps the cheapest's is a tie."""
    f = "peers.csv"
    where = dict(scene=scene, step=step, setting="default")
    values = {"engines": q(f, "engine", "texts", **where), "vals": q(f, "value", "list", **where),
              "costs": q(f, "engine_s_per_sim_s", "list", **where),
              "lo": q(f, "engine_s_per_sim_s_min", "list", **where),
              "hi": q(f, "engine_s_per_sim_s_max", "list", **where), "like": q(f, "like_ode_surface", "list", **where),
              "made": q(f, "by_construction", "texts", **where), "mus": q(f, "mu", "texts", **where),
              "others": "[i for i, e in enumerate(engines) if e != 'ode' and vals[i] is not None]",
              "fair": "[i for i in others if like[i] == 1 and not made[i] and costs[i] is not None]",
              "i": "fair[best_of([engines[j] for j in fair], [vals[j] for j in fair], [costs[j] for j in fair], "
                   f"{higher_better})] if fair else 0",
              "tied": "[j for j in fair if j != i and vals[j] == vals[i] and lo[j] <= hi[i]]",
              "name": "engines[i]", "v": "vals[i]", "c": "costs[i]", "a": "lo[i]", "b": "hi[i]",
              # the scene's friction, where it acts (peer_compare.FRICTION_ACTS),
              # as the matrix writes it (peer_compare.surface_short): "mu ∞"
              "surface": "' mu ' + ('∞' if mus[i] == 'infinite' else mus[i])" if scene in FRICTION_ACTS else "''"}
    at = "" if step == 0.001 else f" @{md.num(step)}"  # the column's step: said in its header
    return [Claim(f"first.{scene}.peer.tie", f"[tie (see §{PEERS_SECTION})](#exp-peers)", values,
                  "len(fair) > 0 and len(tied) > 0"),
            Claim(f"first.{scene}.peer", "{name} " + figure + at + "{surface}, {c:k2} [{a:k2}-{b:k2}]", values,
                  "len(fair) > 0 and len(tied) == 0"),
            Claim(f"first.{scene}.peer.friction", "n/a: surface differs", values,
                  "len(others) > 0 and len(fair) == 0 and any(like[j] == 0 for j in others)"),
            Claim(f"first.{scene}.peer.construction", "n/a: zero by construction", values,
                  "len(others) > 0 and len(fair) == 0 and all(made[j] for j in others)"),
            Claim(f"first.{scene}.peer.none", "n/a: no other engine reached a figure", values,
                  "len(others) == 0 and any(e != 'ode' for e in engines)")]


STACKS = {"ten": q("limit-test5.csv", "tallest_plates", "list", setting="simple, 10 iterations"),
          "twenty": q("limit-test5.csv", "tallest_plates", "list", setting="simple, 20 iterations"),
          "spaces": q("limit-test5.csv", "tallest_plates", "list", iterations=20)}


def CCD_COST(column):
    return q("remedy-test10.csv", column, kind="cost", setting="--ccd", launch_velocity=200)



def definition(scene, text, quantity, **setting):
    """A row's definition cell: `text`, and (for check_report.py) the quantity
    and settings it fixes, as constant values of its claim."""
    values = {"quantity": repr(quantity), **{k: repr(v) for k, v in setting.items()}}
    return Claim(f"first.{scene}.definition", text, values), dict(quantity=quantity, **setting)


def rows():
    """(scene, definition, figure, thesis, decides, cheapest, peer) for each
    scene of the list (tests/scenes/scenes.txt), in its order: each a list
    of alternative claims (the first that holds shown); None where no
    experiment measures it (a scene the lab has no experiment for has a row
    of them)."""
    measured = {row[0]: row for row in measured_rows()}
    return [measured.get(scene) or unmeasured_row(scene) for scene in scenes.names()]


def unmeasured_row(scene):
    return (scene, definition(scene, "no quantity: the lab has no experiment for this scene", "none"),
            None, None, None, None, None)


def measured_rows():
    """The rows of the scenes the lab's experiments measure."""
    test3_runs = {"v": value("test3", "real_time_factor"),
                  "lo": q("thesis-values.csv", "value_min", key="test3", name="real_time_factor"),
                  "hi": q("thesis-values.csv", "value_max", key="test3", name="real_time_factor"),
                  "n": q("thesis-values.csv", "repeats", key="test3", name="real_time_factor")}
    plain6 = "QuickStep 20, step 0.001 (plain)"
    tilted6 = "remedy-test6-tilted.csv"  # each run scored against the analytic fall (experiments/remedy_test6.py)
    return [
        ("test0", definition("test0", "bodies at rest after 20 s", "bodies at rest"),
         [figure_from_thesis("test0", "test0_hang", "resting", "{v:n} bodies", "v >= 0 and v == round(v)")],
         [thesis_cell("test0_hang")],
         [], None, None),
        ("test1", definition("test1", "max |apex2/apex1 - e^2|, e >= 0.1", "rebound error"),
         [figure_from_thesis("test1", "test1", "rebound_error", "{v:k2}", "v >= 0")], [thesis_cell("test1")],
         [Claim("first.test1.decides", "CFM: at CFM 1e-3 {b:n} balls rebound",
                {"b": value("test1", "bounced_cfm"), "n": value("test1", "balls")}, "b < n")],
         None, peer_cell("test1", False)),
        ("test2", definition("test2", "energy (max-min)/max, 60 s, CFM 0", "energy (max-min)/max",
                             cfm=0, seconds=60),
         [figure_from_thesis("test2", "test2", "variation", "{v:p2}", "0 <= v < 1")], [thesis_cell("test2")],
         [step_decides("test2"), solver_decides("test2")], cheapest_cells("test2"), peer_cell("test2", False)),
        ("test3", definition("test3", "simulated s per wall s", "real-time factor"),
         [Claim("first.test3.figure", "{v:n}x ({lo:n}-{hi:n}, {n:n} runs)", test3_runs, "n > 1"),
          figure_from_thesis("test3", "test3", "real_time_factor", "{v:n}x (1 run)", "v > 0")],
         [thesis_cell("test3")],
         [Claim("first.test3.decides", "auto-disable and iterations: without auto-disable {a:n} x at 8 "
                "iterations, {b:n} x at 20", {"a": value("test3", "real_time_factor_8"),
                                              "b": value("test3", "real_time_factor_20"),
                                              "on": value("test3", "real_time_factor")}, "on > a > b > 0")],
         None, peer_cell("test3", True, "{v:p2}", step=0.005)),
        ("test4", definition("test4", "heaviest cube held 20 s, QuickStep 20, 0.001", "heaviest cube held"),
         [Claim("first.test4.figure", "{v:n} kg", {
             "v": q("limit-test4.csv", "heaviest_held_kg", solver="QuickStep 20", step_s=0.001)}, "v > 0")],
         [thesis_cell("test4_fast")],
         [Claim("first.test4.decides", "the solver: dWorldStep holds {dw:n} kg at step 0.001; the step: "
                "QuickStep 20 holds {fine:n} kg at 0.0001",
                {"dw": q("limit-test4.csv", "heaviest_held_kg", solver="dWorldStep", step_s=0.001),
                 "fine": q("limit-test4.csv", "heaviest_held_kg", solver="QuickStep 20", step_s=0.0001),
                 "qs": q("limit-test4.csv", "heaviest_held_kg", solver="QuickStep 20", step_s=0.001)},
                "dw > qs and fine > qs")],
         None, peer_cell("test4", True, "{v:k2} kg")),
        ("test5", definition("test5", "real-time stack, 20 iterations", "tallest stack"),
         [Claim("first.test5.figure", "{v:n} plates (median, {n:n})", {
             "v": q("limit-test5.csv", "tallest_plates", "median", setting="simple, 20 iterations"),
             "n": q("limit-test5.csv", "tallest_plates", "count", setting="simple, 20 iterations")}, "n > 1"),
          Claim("first.test5.figure.one", "{v:n} plates (1 search)", {
              "v": q("limit-test5.csv", "tallest_plates", setting="simple, 20 iterations")})],
         [thesis_cell("test5")],
         [Claim("first.test5.decides", "iterations: 10 iterations {ten:r} plates, 20 iterations {twenty:r} "
                "(simple space, every search)", STACKS, "min(ten) > max(twenty) or min(twenty) > max(ten)"),
          Claim("first.test5.decides.overlap", "no choice measured stands out: 10 iterations {ten:r} plates, "
                "20 iterations {twenty:r}, the ranges overlap (simple space); the spaces at 20 iterations "
                "{spaces:r}", STACKS, "not (min(ten) > max(twenty) or min(twenty) > max(ten))")], None, peer_cell("test5", True, "{v:n} plates")),
        ("test6", definition("test6", "fall-time error, 0.01° tilt, QuickStep 20", "fall-time error"),
         [Claim("first.test6.figure", "{v:p2} (median, {n:n})",
                {"v": q(tilted6, "fall_time_error", "median", setting=plain6, tilt_degrees=0.01),
                 "n": q(tilted6, "fall_time_error", "count", setting=plain6, tilt_degrees=0.01)},
                "n >= 1 and v > -1")],
         [thesis_cell("test6")],
         [Claim("first.test6.decides", "the solver: from a 0.01 deg tilt dWorldStep falls {dw:p2} off the analytic "
                "time, QuickStep 20 {qs:p2} (step 0.0001: {small:p2})",
                {"dw": q(tilted6, "fall_time_error", "median", setting="dWorldStep, step 0.001 (remedy)",
                         tilt_degrees=0.01),
                 "qs": q(tilted6, "fall_time_error", "median", setting=plain6, tilt_degrees=0.01),
                 "small": q(tilted6, "fall_time_error", "median", setting="QuickStep 20, step 0.0001 (smaller step)",
                            tilt_degrees=0.01)},
                "abs(dw) < abs(qs)")], None, peer_cell("test6", True, "{v:n} s")),
        ("test7", definition("test7", "joint error (m), 3 throws, speed cap on", "joint error",
                             angular_speed_cap="on"),
         [figure_from_thesis("test7", "test7", "joint_error", "{v:k2} m", "v >= 0")], [thesis_cell("test7")], [],
         None, peer_cell("test7", False, "{v:k2} m")),
        ("test8", definition("test8", "max |l-l0|/l0, 60 s, ERP 0.4, CFM 1e-4", "relative elongation",
                             erp=0.4, cfm=0.0001, seconds=60, bob_mass_kg=5000),
         [figure_from_thesis("test8", "test8_a", "elongation", "{v:k2}", "v >= 0")], [thesis_cell("test8_a")],
         [Claim("first.test8.decides", "CFM: {c0:n2} at CFM 0, {c4:n2} at 1e-4 (ERP 0.4)",
                {"c0": q("limit-test8.csv", "max_relative_elongation", sweep="cfm", erp=0.4, cfm=0),
                 "c4": q("limit-test8.csv", "max_relative_elongation", sweep="cfm", erp=0.4, cfm=0.0001)},
                "c4 > 10 * c0"),
          solver_decides("test8"), step_decides("test8")],
         cheapest_cells("test8"), peer_cell("test8", False)),
        ("test9", definition("test9", "20th apex error, ERP 0.2, CFM 0", "apex error after 20 bounces",
                             erp=0.2, cfm=0),
         [figure_from_thesis("test9", "test9_a", "apex_error_20", "{v:k2}", "v >= 0")], [thesis_cell("test9_a")],
         [solver_decides("test9"), step_decides("test9")], cheapest_cells("test9"), peer_cell("test9", False)),
        ("test10", definition("test10", "fastest cube stopped, step 0.001", "velocity stopped"),
         [Claim("first.test10.figure", "{v:n} m/s", {"v": q("limit-test10.csv", "max_velocity", step_s=0.001)}, "v > 0"),
          figure_from_thesis("test10", "test10_a", "max_velocity", "{v:n} m/s", "v > 0")],
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
         None, peer_cell("test10", True, "{v:k2} m/s (phase scan)")),
    ]


NO_SWEEP = "n/a: not swept"
NO_PEERS = "n/a: no engine ran it"


def reads_elsewhere(data, claims, setting):
    """How the lookups of `claims` read another quantity or setting than the
    row's definition (another quantity said first), or None (readings.py)."""
    found = []
    for claim in claims:
        for spec in claim.values.values():
            if not isinstance(spec, dict) or spec["file"] in readings.NOT_READINGS:
                continue
            where = spec.get("where", {})
            rows = [row for row in data.rows(spec["file"])
                    if all(_matches(row.get(k), v) for k, v in where.items())]
            read = readings.facts(spec, rows)
            other_quantity = "quantity" in read and read["quantity"] != setting["quantity"]
            phrases = readings.differences(setting, read)  # another quantity comes first
            found += [(0 if other_quantity and i == 0 else 1, phrase) for i, phrase in enumerate(phrases)]
    return sorted(found, key=lambda kind_phrase: kind_phrase[0])[0][1] if found else None


# The thesis column of a report whose thesis experiment did not run (--only).
NO_THESIS = "n/a: not run"


def cell(sentences, claims, setting, source, absent):
    """A cell: the first claim that holds, when its source reads the row's
    quantity at the row's setting; else "n/a: <why>"."""
    if claims is None:
        return absent
    other = reads_elsewhere(sentences.data, claims, setting)
    if other:
        return f"n/a: {source} {other.split(', not ')[0]}"
    return sentences.say(*claims) or absent


def table(sentences):
    """The first screen's markdown table; `sentences` (claims.Sentences)
    records each claim shown."""
    body = []
    for scene, (defined, setting), figure, thesis, _, cheapest, peer in rows():
        body.append([scene, sentences.say(defined), cell(sentences, figure, setting, "ODE reads", "n/a: not measured"),
                     cell(sentences, thesis, setting, "the thesis reads", NO_THESIS),
                     cell(sentences, cheapest, setting, "sweep reads", NO_SWEEP),
                     cell(sentences, peer, setting, "engines read", NO_PEERS)])
    return md.table(COLUMNS, body)


def decides_table(sentences, place):
    """What decides each figure, measured: a section below the first screen."""
    body = [[scene, sentences.say(*decides, place=place) or "not measured in this report"]
            for scene, _, _, _, decides, _, _ in rows()]
    return md.table(DECIDES_COLUMNS, body)

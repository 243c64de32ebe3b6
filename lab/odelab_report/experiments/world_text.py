"""The world report's files (lab/odelab-report --world): its CSVs, plots
and the markdown of its sections, every conclusion a claim slot
(world_first_screen.py's claims and the per-measurement ones here)."""

import math

from .. import markdown as md
from .. import peers_notes, timing
from ..claims import slot
from ..plots import peers as peer_plots
from ..plots import speed as speed_plots
from ..plots import world as world_plots
from ..plots.common import SOLVER_COLOURS
from ..world_first_screen import cheapest, knob, questions
from ..world_rules import BOUND, LEVELS, cheapest_within
from .base import Outcome

COST_COLUMNS = ["timed_sim_seconds", "repeats", "shortest_run_cpu_seconds", "engine_s_per_sim_s",
                "engine_s_per_sim_s_min", "engine_s_per_sim_s_max", "cpu_s_per_sim_s", "cpu_s_per_sim_s_min",
                "cpu_s_per_sim_s_max", "wall_s_per_sim_s", "wall_s_per_sim_s_min", "wall_s_per_sim_s_max"]


def _row(point, measures):
    row = dict(point.fields)
    values, devs = getattr(point, "values", {}), getattr(point, "devs", {})
    artefacts, ode_devs = getattr(point, "artefacts", {}), getattr(point, "ode_devs", {})
    for m in measures:
        row[m.name] = values.get(m.name)
        row["dev_" + m.name] = devs.get(m.name)
        row["step_artefact_" + m.name] = int(bool(artefacts.get(m.name)))
        row["ode_dev_" + m.name] = ode_devs.get(m.name)
    row["max_dev"] = getattr(point, "max_dev", None)
    row["ode_max_dev"] = getattr(point, "ode_max_dev", None)
    outcomes = getattr(point, "outcomes", {})
    row["outcome"] = "; ".join(f"{m}: {got or 'no value'}" for m, (got, _) in outcomes.items())
    row["outcome_expected"] = "; ".join(f"{m}: {want}" for m, (_, want) in outcomes.items())
    row["outcome_as_expected"] = (int(all(got == want for got, want in outcomes.values())) if outcomes else None)
    row["exit_status"] = point.run.rc if point.run is not None else None
    return row


def cost_cell(row):
    if row.get("engine_s_per_sim_s") is None:
        return "not timed"
    return (f"{md.num(row['engine_s_per_sim_s'], 2)} [{md.num(row['engine_s_per_sim_s_min'], 2)}-"
            f"{md.num(row['engine_s_per_sim_s_max'], 2)}]")


def dev_cell(value):
    return "-" if value is None else ("missing" if math.isinf(value) else md.pct(value))


def write_outputs(ctx, exp, points, reference, engines, limits, measures, absent, listed):
    names = [m.name for m in measures]
    dev_columns = [c for n in names for c in (n, "dev_" + n, "step_artefact_" + n, "ode_dev_" + n)]
    outcome_columns = ["outcome", "outcome_expected", "outcome_as_expected"]
    rows = []
    for p in points:
        row = _row(p, measures)
        row.update(setting=p.name, groups=";".join(dict.fromkeys(p.groups)), own=int("own" in p.groups),
                   reference=int(p is reference), **{f"in_{g}": int(g in p.groups) for g in ("step", "erp", "cfm")})
        rows.append(row)
    sweep = ctx.write_csv("world-sweep", ["setting", "groups", "solver", "iterations", "step_s", "erp", "cfm",
                                          "own", "reference", "in_step", "in_erp", "in_cfm", "exit_status",
                                          *dev_columns, "max_dev", "ode_max_dev", *outcome_columns,
                                          *COST_COLUMNS],
                          rows, notes=[
        f"world: {exp.path}; ODE through build/tests/odelab --world at each setting, one run of the world's length "
        "for the measurements",
        "dev_X = |X - X's reference| / X's scale, X's reference the strongest the world gives "
        "(world-measures.csv: analytic, conservation, or self-consistency: ODE's own run of the row with "
        f"reference 1, {reference.name}: dWorldStep, the finest step of the sweep, the world's ERP and CFM); "
        "step_artefact_X 1: X differs from its reference by no more than one step's timing explains, counted as 0; "
        "max_dev: the largest over the measurements (inf: a measurement missing or the other outcome); "
        "ode_dev_X and ode_max_dev: agreement with that ODE run, whatever X's reference",
        f"groups (and in_step, in_erp, in_cfm): step (the step-solver grid), own (the world's own settings), "
        f"erp, cfm (swept at the world's step and solver), reference; costs: engine_wall_seconds / sim_seconds "
        f"(engine_s_per_sim_s), median, min and max over `repeats` interleaved timed runs of timed_sim_seconds, "
        f"each stretched to at least "
        f"{timing.min_run_cpu(ctx.quick):g} CPU s (timing.py); rows with the same arguments share their timed runs"])
    ref_row = next(r for r in rows if r["reference"])
    measure_rows = []
    for m in measures:
        ref = exp.references[m.name]
        measure_rows.append(dict(measurement=m.name, kind=m.kind, rule=m.rule, reference_kind=ref.kind,
                                 reference_why=ref.why, expected=ref.value, reference=ref_row.get(m.name),
                                 scale=m.scale_for(ref.value if ref.value is not None else ref_row.get(m.name)),
                                 how=m.rule_text()))
    measures_csv = ctx.write_csv("world-measures", ["measurement", "kind", "rule", "reference_kind", "reference_why",
                                                    "expected", "reference", "scale", "how"],
                                 measure_rows, notes=[
        "reference_kind: what each measurement is graded against, the strongest the world gives "
        "(world_reference.py): analytic (expected: the answer), conservation (expected: no drift) or "
        "self-consistency (each engine's own run at a 10 times finer step); reference: ODE's finest run's value, "
        "for agreement with ODE only",
        "every measurement the world's `measures` gives (doc/world-format.md), its value at the reference run, the "
        "scale its deviation is divided by and the rule (world_measures.py); absent from the reference run: "
        + (", ".join(absent) or "none")])
    limit_csv = ctx.write_csv("world-limit", ["search", "step_s", "exit_status", "max_dev", "passed", "capped"],
                              limits, notes=[
        f"two searches along the step at the world's own solver, ERP and CFM: blow-up (passed: status 0) and "
        f"bound (passed: status 0 and max_dev <= {BOUND:g}); a ladder by a factor from the world's step, then "
        "bisection; failing taken as monotone in the step; capped 1: the ladder reached odelab's largest (0.1 s) "
        "or smallest step tried without a bracket"])
    engine_rows = []
    for e in engines:
        row = _row(e, measures)
        row.update(notes=peers_notes.notes_of(e.run), translation_note_count=len(peers_notes.notes_of(e.run)))
        engine_rows.append(row)
    engines_csv = ctx.write_csv("world-engines", ["engine", "version", "setting", "status", "reason", "step_s",
                                                  "exit_status", "finer_step_s", "finer_exit_status", *dev_columns,
                                                  "max_dev", "ode_max_dev", *outcome_columns,
                                                  "translation_note_count", *COST_COLUMNS], engine_rows, notes=[
        "every engine odelab --list-engines names, at its defaults and its best (its adapter's; ODE: the world's "
        "settings and dWorldStep) at the world's step; status: ran, missing (reason: --list-engines), refused "
        "(odelab's exit status 2, reason its message) or the status the run ended with; dev_X against X's "
        "reference (world-measures.csv), a self-consistency reference being the same engine and setting at "
        "finer_step_s, never another engine; ode_dev_X, ode_max_dev: agreement with ODE's finest run, shown apart"])
    note_rows = peers_notes.rows_of(("world", r["engine"], r["setting"], r["notes"]) for r in engine_rows)
    notes_csv = ctx.write_csv("world-notes", peers_notes.COLUMNS, note_rows, notes=[
        "what each engine could not express exactly of the world: its run's translation_notes, each once"])

    # plots
    plot_rows = [dict(solver=r["solver"], step_s=r["step_s"], wall_per_sim_second=r["engine_s_per_sim_s"],
                      **{k: r.get(k) for k in COST_COLUMNS if k.startswith("engine_s")},
                      error=r["max_dev"] if r["max_dev"] is not None and math.isfinite(r["max_dev"]) else None)
                 for r in rows if "step" in r["groups"] and r["solver"] in SOLVER_COLOURS]
    steps = [r["step_s"] for r in plot_rows] or [exp.own["step"]]
    finest = []  # (level, the cheapest point within it) for the plot's rings
    for level in LEVELS:
        chosen = cheapest_within(plot_rows, level, "error")
        finest.append((level, plot_rows[chosen[0]] if chosen else None))
    files = speed_plots.speed_accuracy(ctx.out_dir, "world-speed", plot_rows, finest,
                                       "largest deviation from the reference (every measurement)",
                                       "your world: deviation against cost (the world's ERP and CFM)",
                                       world_plots.FLOOR,
                                       xlabel="cost: engine seconds (its collision and step calls) per simulated "
                                              "second, median of the timed runs (this machine)",
                                       subtitle=f"one curve per solver setting, steps {max(steps):g} s (left) to "
                                                f"{min(steps):g} s (right)")
    files += world_plots.step_limit(ctx.out_dir, "world-limit", rows, limits, ref_row_solver(rows), BOUND)
    files += world_plots.erp_cfm(ctx.out_dir, "world-erp-cfm", rows)
    ran = [dict(r, value=r["max_dev"] if r["max_dev"] is not None and math.isfinite(r["max_dev"]) else None,
                step=r["step_s"]) for r in engine_rows if r["status"] == "ran"]
    if ran:
        files += peer_plots.peers_speed_accuracy(ctx.out_dir, "world-engines", ran,
                                                 "largest deviation from ODE's reference", True, None,
                                                 world_plots.FLOOR)
    ctx.register_files(files)
    return Outcome(markdown(ctx, exp, rows, engine_rows, note_rows, measure_rows, absent, bool(ran),
                            [sweep, measures_csv, limit_csv, engines_csv, notes_csv]),
                   claims=claims(measures))


def ref_row_solver(rows):
    return next(r["solver"] for r in rows if r["own"])


def claims(measures):
    said = {}
    for n, (question, sentences) in enumerate(questions()):
        for k, alternatives in enumerate(sentences):
            said[f"q{n}.{k}"] = alternatives
    for m in measures:
        for level in LEVELS:
            said[f"m.{m.name}.{level:g}"] = [cheapest(level, "dev_" + m.name, m.name)]
    said["erp"], said["cfm"] = [knob("erp", "ERP")], [knob("cfm", "CFM")]
    return said


def first_screen():
    """The first screen's markdown: each question and its slots."""
    lines = []
    for n, (question, sentences) in enumerate(questions()):
        lines.append(f"**{question}** " + " ".join(slot(f"q{n}.{k}") for k in range(len(sentences))))
        lines.append("")
    return "\n".join(lines)


def markdown(ctx, exp, rows, engine_rows, note_rows, measure_rows, absent, engines_plotted, files):
    own = exp.own
    measures_table = md.table(["measurement", "graded against", "expected", "ODE's finest run", "scale", "rule"],
                              [[r["measurement"], f"{r['reference_kind']}: {r['reference_why']}",
                                "-" if r["expected"] is None else ("never" if math.isinf(r["expected"])
                                                                   else md.num(r["expected"])),
                                md.num(r["reference"]), md.num(r["scale"]), r["how"]]
                               for r in measure_rows])
    per_measure = "\n".join(f"- {r['measurement']}: " + " ".join(slot(f"m.{r['measurement']}.{level:g}")
                                                                 for level in LEVELS) for r in measure_rows)
    sweep_table = md.table(["setting", "groups", "status", "largest deviation", "engine s / sim s, median [range]"],
                           [[r["setting"], r["groups"], md.num(r["exit_status"]), dev_cell(r["max_dev"]),
                             cost_cell(r)] for r in rows])
    engine_table = md.table(["engine", "setting", "status", "largest deviation from its reference",
                             "outcome (expected)", "agreement with ODE's finest run",
                             "engine s / sim s, median [range]", "translation notes"],
                            [[r["engine"] + (f" {r['version']}" if r["version"] else ""), r["setting"],
                              r["status"] + (f": {r['reason']}" if r["reason"] else ""), dev_cell(r["max_dev"]),
                              (f"{r['outcome']} ({r['outcome_expected']})" if r["outcome"] else "-"),
                              dev_cell(r["ode_max_dev"]),
                              cost_cell(r), md.num(r["translation_note_count"]) if r["status"] == "ran" else "-"]
                             for r in engine_rows])
    notes = peers_notes.per_engine(note_rows)
    notes_text = "\n".join(f"- {engine}:\n" + "\n".join(f"  - {peers_notes.note_line(note, s)}" for note, s in said)
                           for engine, said in notes.items()) or "No engine gave a translation note on this world."
    source = ("The world names no `measures` (doc/world-format.md): compared are the run's own counts, contacts "
              "and sleeping bodies at the end." if all(r["kind"] == "run" for r in measure_rows) else
              "The world's `measures` give these measurements.")
    missing = (f" The reference run wrote none of {', '.join(absent)}: those measurements are left out."
               if absent else "")
    return f"""## The measurements

{source} Each
measurement is graded against the strongest reference the world gives: an
analytic answer (one the world states, or the law the measurement is defined
by), else a conservation law the world implies, else the same engine and
setting at a 10 times finer step (self-consistency; for ODE's sweep, dWorldStep
at the finest step of the sweep with the world's ERP {own["erp"]:g} and CFM
{own["cfm"]:g}). The deviation is |value - reference| / scale; "within 1%"
means a deviation of at most 0.01 on every measurement. A quantity whose
reference is a size of its own is compared relative to it; an error or drift
whose reference is about 0 is compared as an absolute difference against the
scale given; a count must be equal. A difference that one step's timing
explains (a time within one step, an arc within one step at the body's fastest
speed) is at the step's resolution: said (step_artefact_X in the CSVs) and
counted as 0.{missing}

{measures_table}

## Accurate enough at the least cost

ODE at steps from 10 times the world's step ({own["step"]:g} s) to a tenth of
it, with dWorldStep and QuickStep at several iteration counts; ERP and CFM
swept at the world's step and solver. Cost: the engine's own seconds
(`engine_wall_seconds`) per simulated second, the median [min-max] of
{timing.repeats(ctx.quick)} interleaved timed runs, each of at least
{timing.min_run_cpu(ctx.quick):g} CPU s; a setting whose fastest run is not
slower than the cheapest's slowest ties with it.

The cheapest per measurement:

{per_measure}

{md.figure("world-speed", "largest deviation from the reference against engine seconds per simulated second, one "
           "curve per solver, steps large (left) to small (right); rings: the cheapest within 1% and 0.1%")}

{sweep_table}

## Where it breaks

Two searches along the step at the world's own solver, ERP and CFM, up to
odelab's largest step (0.1 s): the largest step before a blow-up (status 3),
and the largest before a measurement departs from the reference by more
than {md.pct(BOUND)} (world-limit.csv lists every probe).

{md.figure("world-limit", "largest deviation against the step: the sweep's solvers, the search's probes, "
           "blow-ups at the top")}

## ERP and CFM

At the world's step and solver: {slot("erp")} {slot("cfm")}

{md.figure("world-erp-cfm", "largest deviation against ERP and CFM at the world's step and solver")}

## Other engines

Every engine `odelab --list-engines` names, at its defaults and its best
(doc/peers.md), at the world's step; ODE's default is the world's settings,
its best dWorldStep. Each is graded against each measurement's reference
above; where that is self-consistency, against its own run at a 10 times finer
step, never another engine's. Agreement with ODE's finest run is shown apart,
labelled as that: it is agreement with converged ODE, contact model included,
not with an exact answer. An outcome is said by rule from the run: a
tunnelling measure "stops" or "tunnels", a rest measure "stays" (comes to
rest) or "slides" (never does), beside what the world expects.

{engine_table}

What each engine could not express exactly (its translation notes, each once; world-notes.csv):

{notes_text}

{md.figure("world-engines", "largest deviation from ODE's reference against engine seconds per simulated second, "
           "each engine at its defaults and its best") if engines_plotted else ""}

{md.files_line(files)}"""

"""The lab on a user's world file (lab/odelab-report --world FILE): ODE at
steps around the world's own, with dWorldStep and QuickStep at several
iteration counts, ERP and CFM swept at the world's step; the step searched
upward for where the world blows up or its measurements depart from the
reference; every engine --list-engines has at its defaults and best at the
world's step. Every measurement (world_measures.py) is graded against the
strongest reference the world gives (world_reference.py: an analytic answer,
a conservation law, or the same engine at a finer step: for ODE's sweep, its
reference run, dWorldStep at the finest step of the sweep with the world's
ERP and CFM); agreement with that ODE run is kept apart, labelled as such. Costs: the engine's own seconds per simulated second, median
and range of timed runs interleaved (timing.py)."""

import json
from pathlib import Path

from .. import timing
from .. import world_measures as wm
from .. import world_reference as wr
from ..inputs import read_text
from ..runner import LabError, RunSpec
from ..search import highest_passing
from ..world_probe import REFUSED, probe
from ..world_rules import passes_bound
from .base import Experiment, Outcome, log_space
from .peers import ENGINES, costs, engine_name, list_engines
from .world_text import write_outputs

PROGRAM = "odelab"
MAX_WORLD_BYTES = 64 * 1024 * 1024
MIN_STEP, MAX_STEP = 1e-6, 0.1  # odelab's --step range
ITERATIONS = {True: (10, 20), False: (5, 10, 20, 50, 100)}  # QuickStep's, quick and full
ERPS = {True: (0.1, 0.5, 1.0), False: (0.1, 0.2, 0.4, 0.6, 0.8, 1.0)}
CFMS = {True: (0.0, 1e-6, 1e-3), False: (0.0, 1e-9, 1e-7, 1e-5, 1e-3, 1e-2)}
STEP_POINTS = {True: 5, False: 9}  # from 10x the world's step to a tenth of it


def read_world(path):
    return json.loads(read_text(Path(path), MAX_WORLD_BYTES, "the world file"))


def own_settings(world):
    """The world's own solver settings, with the defaults of doc/world-format.md."""
    s = world.get("settings", {})
    return dict(solver=s.get("solver", "quick"), iterations=int(s.get("iterations", 20)),
                step=float(s["step"]), erp=float(s.get("erp", 0.2)), cfm=float(s.get("cfm", 1e-5)))


def solver_name(solver, iterations):
    return "dWorldStep" if solver == "step" else f"QuickStep {iterations}"


def step_grid(step, quick):
    """Steps from 10x the world's step to a tenth of it (within odelab's
    range), the world's own exactly among them."""
    steps = log_space(min(MAX_STEP, 10 * step), max(MIN_STEP, step / 10), STEP_POINTS[quick])
    steps = [s for s in steps if abs(s / step - 1) > 0.01] + [step]
    return sorted(set(steps), reverse=True)


class Point:
    """One ODE setting (or engine setting) of the world, its runs and figures."""

    def __init__(self, name, args, **fields):
        self.name, self.args, self.fields = name, list(args), fields
        self.groups = []
        self.run = None
        self.timed = []


class WorldSweep(Experiment):
    name = "world"
    title = "your world"
    section = 1
    programs = (PROGRAM,)
    cost = (900.0, 60.0)

    def __init__(self, path):
        self.path = Path(path).resolve()
        self.world = read_world(self.path)
        self.own = own_settings(self.world)

    # ---- the settings ------------------------------------------------------------------
    def ode_args(self, solver, iterations, step, erp, cfm):
        args = ["--world", self.path, "--solver", solver, "--step", step, "--erp", erp, "--cfm", cfm]
        return args + (["--iterations", iterations] if solver == "quick" else [])

    def plan(self, quick):
        """The ODE points, unique by their arguments: the step-solver grid,
        ERP and CFM at the world's step (a point may be in several groups)."""
        own = self.own
        points = {}

        def add(group, solver, iterations, step, erp, cfm):
            args = self.ode_args(solver, iterations, step, erp, cfm)
            key = tuple(str(a) for a in args)
            if key not in points:
                name = f"{solver_name(solver, iterations)} @ {step:g}"
                name += "".join(f", {label} {value:g}" for label, value, mine in
                                (("ERP", erp, own["erp"]), ("CFM", cfm, own["cfm"])) if value != mine)
                points[key] = Point(name, args, solver=solver_name(solver, iterations), iterations=iterations,
                                    step_s=step, erp=erp, cfm=cfm)
            points[key].groups.append(group)
            return points[key]

        solvers = [("step", own["iterations"])] + [("quick", n) for n in ITERATIONS[quick]]
        steps = step_grid(own["step"], quick)
        for solver, iterations in solvers:
            for step in steps:
                add("step", solver, iterations, step, own["erp"], own["cfm"])
        mine = (own["solver"], own["iterations"], own["step"])
        add("own", *mine, own["erp"], own["cfm"])
        for erp in sorted(set(ERPS[quick]) | {own["erp"]}):
            add("erp", *mine, erp, own["cfm"])
        for cfm in sorted(set(CFMS[quick]) | {own["cfm"]}):
            add("cfm", *mine, own["erp"], cfm)
        reference = add("reference", "step", own["iterations"], min(steps), own["erp"], own["cfm"])
        return list(points.values()), reference

    # ---- the run -----------------------------------------------------------------------
    def run(self, ctx):
        runner = ctx.runner
        listed = list_engines(runner.ask(PROGRAM, ["--world", self.path, "--list-engines"]))
        points, reference = self.plan(ctx.quick)
        engines = self.engine_points(ctx, listed)
        repeats = timing.repeats(ctx.quick)
        ctx.expect(len(points) * (2 + repeats) + len(engines) * (3 + repeats) + 30)
        runs = runner.map([RunSpec(PROGRAM, p.args, measures_blow_ups=True) for p in points])
        for p, r in zip(points, runs):
            p.run = r
        ctx.advance(len(points))
        if reference.run.rc != 0:
            raise LabError(f"the reference run ({reference.name}, {reference.run.spec.command_line()}) ended with "
                           f"status {reference.run.rc}: nothing to measure the world against")
        measures, absent = wm.from_metrics(self.world, reference.run.metrics)
        self.references = {m.name: wr.reference_of(self.world, m) for m in measures}
        ref_values = {m.name: reference.run.m(m.name) for m in measures}
        # ODE's sweep: its own finest run (the reference run) is its self-consistency reference.
        for p in points:
            self.judge(p, measures, ref_values, ref_values)
        ran = [e for e in engines if e.fields["status"] == "ran"]
        # Each engine also at a FINER times finer step: its own self-consistency reference.
        runs = runner.map([RunSpec(PROGRAM, e.args, measures_blow_ups=True) for e in ran] +
                          [RunSpec(PROGRAM, self.finer_args(e), measures_blow_ups=True) for e in ran])
        for e, r, fine in zip(ran, runs[:len(ran)], runs[len(ran):]):
            e.run, e.fine_run = r, fine
            e.fields["status"] = "ran" if r.rc == 0 else f"ended with status {r.rc}"
            e.fields["finer_step_s"] = e.fields["step_s"] / wr.FINER
            e.fields["finer_exit_status"] = fine.rc
            self.judge(e, measures, ref_values, {m.name: (fine.m(m.name) if fine.rc == 0 else None)
                                                 for m in measures})
        ctx.advance(len(engines) + len(ran))
        limits = self.limits(ctx, measures, ref_values)
        self.time_points(ctx, [p for p in points + engines if p.run is not None and p.run.rc == 0])
        return write_outputs(ctx, self, points, reference, engines, limits, measures, absent, listed)

    def finer_args(self, point):
        """The same engine and setting at the step / FINER."""
        args = list(point.args)
        at = args.index("--step")
        args[at + 1] = float(args[at + 1]) / wr.FINER
        return args

    def judge(self, point, measures, ref_values, finer_values):
        """Each measurement graded against its reference (world_reference.py:
        analytic, conservation, or `finer_values`, the same engine's finer
        run): devs and max_dev; agreement with ODE's finest run apart:
        ode_devs and ode_max_dev."""
        r = point.run
        ok = r.rc == 0
        step = float(point.args[point.args.index("--step") + 1])
        point.values = {m.name: (r.m(m.name) if ok else None) for m in measures}
        point.ode_devs = {m.name: (m.deviation(point.values[m.name], ref_values[m.name]) if ok else None)
                          for m in measures}
        point.ode_max_dev = wm.max_deviation(point.ode_devs.values()) if ok else None
        point.devs, point.artefacts = {}, {}
        for m in measures:
            dev, artefact = wr.grade(self.world, m, self.references[m.name], point.values[m.name],
                                     finer_values.get(m.name), step) if ok else (None, False)
            point.devs[m.name], point.artefacts[m.name] = dev, artefact
        point.max_dev = wm.max_deviation(point.devs.values()) if ok else None
        point.outcomes = {m.name: (wr.outcome_words(m, point.values[m.name]), wr.expected_outcome(m))
                          for m in measures if ok and wr.expected_outcome(m)}

    # ---- where it breaks -----------------------------------------------------------------
    def limits(self, ctx, measures, ref_values):
        """Two searches along the step at the world's own solver settings:
        the largest step that runs (no blow-up, status 3) and the largest
        whose measurements all stay within world_rules.BOUND of the reference."""
        own = self.own
        seen = {}

        def run_at(step):
            point = Point(f"{step:g}", self.ode_args(own["solver"], own["iterations"], step, own["erp"], own["cfm"]),
                          step_s=step)
            point.run = ctx.runner.run(RunSpec(PROGRAM, point.args, priority=0, measures_blow_ups=True))
            self.judge(point, measures, ref_values, ref_values)
            seen[step] = point
            ctx.advance()
            return point

        def search(passed):
            return highest_passing(lambda s: (passed(run_at(s)), None), start=own["step"],
                                   factor=4.0 if ctx.quick else 2.0, ratio=1.5 if ctx.quick else 1.1,
                                   low=max(MIN_STEP, own["step"] / 100), high=MAX_STEP)

        blow_up, bound = ctx.runner.parallel([
            lambda: search(lambda p: p.run.rc == 0),
            lambda: search(lambda p: passes_bound(p.run.rc, p.max_dev))])
        rows = []
        for kind, result in (("blow-up", blow_up), ("bound", bound)):
            for step, passed, _ in result.probes:
                p = seen[step]
                rows.append(dict(search=kind, step_s=step, exit_status=p.run.rc, max_dev=p.max_dev,
                                 passed=int(passed), capped=int(result.capped)))
        return rows

    # ---- other engines ---------------------------------------------------------------------
    def engine_points(self, ctx, listed):
        """A Point per engine and setting at the world's step: "ran" when the
        engine is here and takes the world, else why not (never fatal)."""
        own = self.own
        points = []
        for engine in ENGINES:
            info = listed.get(engine)
            for setting in ("default", "best"):
                fields = dict(engine=engine, version=(info or {}).get("version", ""), setting=setting,
                              step_s=own["step"], status="ran", reason="")
                if engine == "ode":  # ODE's default: the world's settings; its best: dWorldStep there
                    solver, iterations = (own["solver"], own["iterations"]) if setting == "default" else (
                        "step", own["iterations"])
                    args = self.ode_args(solver, iterations, own["step"], own["erp"], own["cfm"])
                else:
                    args = ["--world", self.path, "--engine", engine, "--engine-setting", setting,
                            "--step", own["step"]]
                if not info or not info["available"]:
                    fields.update(status="missing", reason=(info or {}).get("missing") or
                                  "not listed by odelab --list-engines")
                elif engine != "ode":
                    rc, message = probe(ctx.runner.build_dir, [*args, "--headless", "--seconds", own["step"]])
                    if rc == REFUSED:
                        fields.update(status="refused", reason=message)
                    elif rc not in (0, 3):
                        fields.update(status=f"failed (status {rc})", reason=message)
                points.append(Point(f"{engine_name(engine, info)} {setting}", args, **fields))
        return points

    # ---- costs ---------------------------------------------------------------------------------
    def time_points(self, ctx, points):
        """timing.repeats timed runs of every point that ran, each stretched to
        last timing.min_run_cpu seconds, interleaved; points with the same
        arguments share their timed runs."""
        unique = {}
        for p in points:
            unique.setdefault(tuple(str(a) for a in p.args), p.args)
        keys = list(unique)
        minimum = timing.min_run_cpu(ctx.quick)
        lengths = ctx.runner.parallel([lambda a=unique[k]: timing.stretched(ctx.runner, PROGRAM, a, minimum)
                                       for k in keys])
        ctx.advance(len(keys))
        timed = timing.interleaved_long_enough(ctx.runner, [(PROGRAM, a) for a in lengths],
                                                timing.repeats(ctx.quick), minimum)
        ctx.advance(len(keys) * timing.repeats(ctx.quick))
        by_key = dict(zip(keys, timed))
        for p in points:
            p.timed = by_key[tuple(str(a) for a in p.args)]
            p.fields.update(costs(p.timed))

"""The accuracy atlas (lab/odelab-report --atlas): every case of doc/atlas/
(a world file whose `probe` measures state its analytic answer and
tolerance) on every engine --list-engines has, at its defaults and its best,
at the steps people use. A cell's mark is a rule on the run's own probes
(odelab checks each against its `expect`): "right" when every probe is
within its tolerance, "off" with the worst error in tolerances when one is
not, "no figure" when a probe never got a reading (an event that never came),
and the run's status otherwise (a blow-up, an engine that failed or refused
the world). No engine is the reference for another. Cost: the engine's own
calls per simulated second (costs.py), the link and the whole run's CPU
beside it, the median and range of interleaved timed runs (timing.py)."""

import csv
import json
import math
from pathlib import Path

from .. import costs, timing
from ..inputs import read_text
from ..runner import LabError, RunSpec
from .base import Experiment, Outcome
from .peers import ENGINES, engine_name, list_engines

PROGRAM = "odelab"
MAX_CASE_BYTES = 1024 * 1024
# The steps people use: a display's frame, a common physics rate, a millisecond.
STEPS = {True: (1 / 240,), False: (1 / 60, 1 / 240, 1 / 1000)}
SETTINGS = ("default", "best")
INDEX = "families.csv"  # case,family: the atlas's own list of its families


def step_name(step):
    return f"1/{round(1 / step)}"


class Case:
    def __init__(self, path, family):
        self.path = Path(path).resolve()
        self.name = self.path.stem
        self.world = json.loads(read_text(self.path, MAX_CASE_BYTES, "the atlas case"))
        self.family = family
        self.title = self.world.get("title") or self.name
        self.probes = [m for m in self.world.get("measures", []) if m.get("kind") == "probe" and "expect" in m]
        if not self.probes:
            raise ValueError(f"{self.path}: an atlas case needs a probe with an `expect` (doc/world-format.md)")


def read_cases(folder):
    """The cases of `folder` in the order of its families.csv (every .json
    listed there, each once, with its family); a case missing from the list
    or listed without a file is refused by name."""
    folder = Path(folder)
    index = folder / INDEX
    rows = list(csv.DictReader(read_text(index, MAX_CASE_BYTES, "the atlas's family list").splitlines()))
    listed = [r["case"] for r in rows]
    files = sorted(p.stem for p in folder.glob("*.json"))
    unlisted = sorted(set(files) - set(listed))
    if unlisted:
        raise ValueError(f"{index}: no family for {', '.join(unlisted)}")
    missing = [c for c in listed if c not in files]
    if missing:
        raise ValueError(f"{index}: no file for {', '.join(missing)}")
    if len(set(listed)) != len(listed):
        raise ValueError(f"{index}: a case listed twice")
    return [Case(folder / f"{r['case']}.json", r["family"]) for r in rows]


def cell_args(case, engine, setting, step):
    """ODE's default: the case's own settings; its best: dWorldStep. Another
    engine: its own default or best (doc/peers.md). The step overrides the case's."""
    if engine == "ode":
        return ["--world", case.path, "--step", step] + (["--solver", "step"] if setting == "best" else [])
    return ["--world", case.path, "--engine", engine, "--engine-setting", setting, "--step", step]


def judge(case, result):
    """(mark, probes within, worst probe, its |error| / tolerance, its error, its tolerance)."""
    worst = (None, -1.0, None, None)
    within = 0
    for probe in case.probes:
        name = probe.get("name") or f"probe{probe.get('body', '')}"
        error, tolerance = result.m(f"{name}_error"), result.m(f"{name}_tolerance")
        if result.m(f"{name}_within") == 1:
            within += 1
        if error is None:
            return "no figure", within, name, None, None, tolerance
        ratio = abs(error) / tolerance if tolerance else (0.0 if error == 0 else math.inf)
        if ratio > worst[1]:
            worst = (name, ratio, error, tolerance)
    mark = "right" if within == len(case.probes) else "off"
    return (mark, within, *worst)


def atlas_outcome(ctx, files):
    """The atlas's markdown and heat maps, made from its CSVs as written
    (lab/check_atlas_report.py makes the markdown again from them)."""
    from .. import atlas_text
    from ..csvout import read_csv
    from ..plots import atlas as plots
    rows = read_csv(ctx.out_dir / files[0])[2]
    engine_rows = read_csv(ctx.out_dir / files[1])[2]
    files = files + [ctx.write_csv("atlas-notes", list(atlas_text.NOTE_COLUMNS), atlas_text.note_rows(rows), notes=[
        f"what odelab --list-engines says each engine does, from atlas.csv: at step {atlas_text.SHOWN_STEP} s, "
        "per setting, the cases it gets right out of all, and the others with their mark"])]
    for family in dict.fromkeys(r["family"] for r in rows):
        ctx.register_files(plots.heat_map(ctx.out_dir, atlas_text.family_stem(family), family,
                                          [r for r in rows if r["family"] == family]))
    return atlas_text.markdown(rows, engine_rows, files)


class Atlas(Experiment):
    name = "atlas"
    title = "the accuracy atlas"
    section = 1
    programs = (PROGRAM,)
    cost = (1800.0, 300.0)

    def __init__(self, folder):
        self.folder = Path(folder).resolve()
        self.cases = read_cases(self.folder)

    def run(self, ctx):
        runner = ctx.runner
        listed = list_engines(runner.ask(PROGRAM, ["--world", self.cases[0].path, "--list-engines"]))
        engines = [e for e in ENGINES if listed.get(e, {}).get("available")]
        self.missing = {e: (listed.get(e) or {}).get("missing") or "not listed by odelab --list-engines"
                        for e in ENGINES if e not in engines}
        self.versions = {e: engine_name(e, listed.get(e)) for e in engines}
        cells = [dict(case=c, engine=e, setting=s, step=h) for c in self.cases for e in engines
                 for s in SETTINGS for h in STEPS[ctx.quick]]
        repeats = 1 if ctx.quick else timing.REPEATS
        ctx.expect(len(cells) * (1 if ctx.quick else 1 + repeats))

        def one(cell):
            args = cell_args(cell["case"], cell["engine"], cell["setting"], cell["step"])
            try:
                # --quick: the one run is timed itself (no stretch, no repeat): a smoke run, not a timing.
                return runner.run(RunSpec(PROGRAM, args, timed=ctx.quick, measures_blow_ups=True)), ""
            except LabError as error:  # refused (2) or the engine failed (7): the cell says so, no figure
                return None, str(error).splitlines()[0]

        ran = runner.parallel([lambda c=c: one(c) for c in cells])
        ctx.advance(len(cells))
        for cell, (result, why) in zip(cells, ran):
            cell["result"], cell["why"] = result, why
        ok = [c for c in cells if c["result"] is not None and c["result"].rc == 0]
        if ctx.quick:
            for c in ok:
                c["timed"] = [c["result"]]
        else:
            self.time_cells(ctx, ok, repeats)
        rows = [self.row(c) for c in cells]
        name = ctx.write_csv("atlas", list(rows[0].keys()), rows, notes=[
            "each case (doc/atlas/) on each engine and setting at each step: odelab --world CASE --headless "
            "[--engine E --engine-setting S] --step H (ODE best: --solver step); mark: right (every probe "
            "within its tolerance), off (worst: the probe with the largest |error| / tolerance), no figure (a "
            "probe without a reading), blew up (status 3), ODE error (status 4), or why the run gave none",
            ("costs per simulated second from the one run itself (--quick: not stretched, not repeated; a smoke "
             "run, not a timing): " if ctx.quick else
             f"costs per simulated second, median [min-max] of {repeats} interleaved timed runs, each run "
             f"stretched to {timing.min_run_cpu(ctx.quick):g} CPU s: ") + "; ".join(
                f"{costs.COLUMNS[d]}: {costs.DEFINITIONS[d]}" for d in costs.DEFINITIONS)])
        engine_rows = [dict(engine=e, name=self.versions.get(e, engine_name(e)), available=int(e in engines),
                            missing=self.missing.get(e, "")) for e in ENGINES]
        engines_name = ctx.write_csv("atlas-engines", list(engine_rows[0].keys()), engine_rows, notes=[
            "every engine odelab --list-engines names: whether it ran here, and why not"])
        return Outcome(atlas_outcome(ctx, [name, engines_name]), [])

    def time_cells(self, ctx, cells, repeats):
        unique = {}
        for c in cells:
            unique.setdefault(tuple(str(a) for a in c["result"].spec.args), list(c["result"].spec.args))
        keys = list(unique)
        minimum = timing.min_run_cpu(ctx.quick)
        lengths = ctx.runner.parallel([lambda a=unique[k]: timing.stretched(ctx.runner, PROGRAM, a, minimum)
                                       for k in keys])
        timed = timing.interleaved_long_enough(ctx.runner, [(PROGRAM, a) for a in lengths], repeats, minimum)
        ctx.advance(len(keys) * repeats)
        by_key = dict(zip(keys, timed))
        for c in cells:
            c["timed"] = by_key[tuple(str(a) for a in c["result"].spec.args)]

    def row(self, cell):
        case, result = cell["case"], cell["result"]
        row = dict(case=case.name, family=case.family, title=case.title, engine=cell["engine"],
                   version=self.versions[cell["engine"]], setting=cell["setting"], step=step_name(cell["step"]),
                   step_s=cell["step"], exit_status=result.rc if result else None, probes=len(case.probes),
                   probes_within=None, mark=None, worst_probe=None, worst_tolerances=None, worst_error=None,
                   worst_tolerance=None, why=cell["why"])
        if result is None:
            row["mark"] = "no run"
        elif result.rc == 3:
            row["mark"] = "blew up"
        elif result.rc == 4:
            row["mark"] = "ODE error"
        else:
            mark, within, probe, ratio, error, tolerance = judge(case, result)
            row.update(mark=mark, probes_within=within, worst_probe=probe, worst_error=error,
                       worst_tolerance=tolerance, worst_tolerances=ratio if ratio is None or math.isfinite(ratio)
                       else None)
        timed = cell.get("timed", [])
        row.update(repeats=len([r for r in timed if r.rc == 0]), **costs.columns(timed))
        return row

"""The sample runs the docs quote: each command of
lab/reference/doc-samples.csv (a doc, a program and its arguments) is run
headless and every metric it reports goes to doc-samples.csv, so that a
figure a doc quotes from a sample run is held by the committed report and
lab/check_docs.py fails once the programs stop giving it. Untimed: the docs
quote no wall times from these runs."""

import shlex
from pathlib import Path

from .. import markdown as md
from .. import scenes
from ..runner import RunSpec
from .base import Experiment, Outcome
from .thesis_choices import read_csv

SAMPLES = Path(__file__).resolve().parents[2] / "reference" / "doc-samples.csv"
# Metrics that are timings or machine facts: not kept (the docs quote none).
TIMINGS = ("wall_seconds", "real_time_factor", "ms_per_step", "cpu_ms_per_step", "collide_step_seconds")


def samples():
    rows = read_csv(SAMPLES)
    for row in rows:
        if not row["program"].startswith("test"):
            raise RuntimeError(f"{SAMPLES}: '{row['program']}' is not one of the test programs")
    return rows


class DocSamples(Experiment):
    name = "doc-samples"
    title = "The sample runs the docs quote"
    section = 6
    programs = tuple(scenes.names())
    cost = (30.0, 30.0)

    def run(self, ctx):
        rows = samples()
        ctx.expect(len(rows))
        results = ctx.runner.map([RunSpec(r["program"], shlex.split(r["arguments"])) for r in rows])
        ctx.advance(len(rows))
        out = []
        for row, result in zip(rows, results):
            for metric, value in sorted(result.metrics.items()):
                if isinstance(value, (int, float)) and not isinstance(value, bool) and metric not in TIMINGS:
                    out.append(dict(doc=row["doc"], program=row["program"], arguments=row["arguments"],
                                    metric=metric, value=float(value), exit_status=result.rc))
        csv_name = ctx.write_csv("doc-samples", ["doc", "program", "arguments", "metric", "value", "exit_status"],
                                 out, notes=["every numeric metric (timings left out) of each sample run listed in "
                                             "lab/reference/doc-samples.csv, run with --headless --metrics-json"])
        table = md.table(["doc", "command (build/tests/...)", "metrics kept", "exit status"],
                         [[r["doc"], f"`{r['program']} {r['arguments']}`",
                           sum(1 for x in out if x["arguments"] == r["arguments"] and x["program"] == r["program"]),
                           res.rc] for r, res in zip(rows, results)])
        text = f"""The runs whose figures doc/tests/*.md quote, with every numeric metric each
reported (timings left out: the docs quote none from these). lab/check_docs.py
fails when a doc quotes a figure that no committed CSV holds, so a figure the
programs stop giving fails the docs check once this report is regenerated.

{table}

{md.files_line([csv_name])}"""
        return Outcome(text)

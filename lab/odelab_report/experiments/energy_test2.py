"""test2: the energy curves of the thesis's figure 4 (potential, kinetic and
total energy of the pendulum over 60 s at ERP 0.4, CFM 0, step 0.001)."""

from .. import markdown as md
from ..plots import limits as plots
from ..runner import RunSpec
from .base import Experiment, Outcome

FAILURE_FRACTION = 0.01  # the failure rule: total energy more than 1% from its start
THESIS_MIN, THESIS_MAX = 29.250, 29.471


def read_output_file(path):
    """Rows (time, potential, kinetic, total) of Test2_output.txt, skipping `#`
    lines and the first other line, which names the columns."""
    rows, header_seen = [], False
    for line in path.read_text().splitlines():
        if line.startswith("#") or not line.strip():
            continue
        if not header_seen:
            header_seen = True
            continue
        rows.append(tuple(float(v) for v in line.split("\t")))
    return rows


class EnergyTest2(Experiment):
    name = "energy-test2"
    title = "test2: energy over a minute (the thesis's figure 4)"
    section = 2
    programs = ("test2",)
    cost = (0.5, 0.3)

    def run(self, ctx):
        seconds = 20 if ctx.quick else 60
        ctx.expect(1)
        r = ctx.runner.run(RunSpec("test2", ["--erp", 0.4, "--cfm", 0, "--step", 0.001, "--seconds", seconds,
                                             "--sample-interval", 0.02]))
        ctx.advance()
        samples = read_output_file(r.workdir / "Test2_output.txt")
        start = r.m("energy_start_J")
        rows = [dict(time_s=t, potential_J=p, kinetic_J=k, total_J=e, total_relative_deviation=(e - start) / start)
                for t, p, k, e in samples]
        worst = max(abs(r.m("energy_max_J") - start), abs(start - r.m("energy_min_J"))) / start
        csv = ctx.write_csv("energy-test2", list(rows[0].keys()), rows,
                            notes=["from Test2_output.txt of test2 --headless --erp 0.4 --cfm 0 --step 0.001 "
                                   f"--seconds {seconds} --sample-interval 0.02",
                                   "failure rule: |total - start| / start > 0.01 at any step"])
        ctx.register_files(plots.energy_curves(ctx.out_dir, "energy-test2", rows, start,
                                               (THESIS_MIN, THESIS_MAX), FAILURE_FRACTION))
        table = md.table(["quantity", "thesis (ODE 0.11.1)", "this build"], [
            ["start energy", "about 29.4 J", md.num(start, 6, "J")],
            ["min / max total", f"{THESIS_MIN} / {THESIS_MAX} J",
             f"{md.num(r.m('energy_min_J'), 6)} / {md.num(r.m('energy_max_J'), 6)} J"],
            ["relative variation (max - min) / max", "0.75%", md.pct(r.m("energy_rel_variation"), 3)],
            ["largest deviation from the start (every step)", "-", md.pct(worst, 3)],
            ["drift (end against start)", "-", md.pct(r.m("energy_drift"), 3)],
            ["period (exact 4.201234 s)", "-", md.num(r.m("period_seconds"), 7, "s")],
            ["rule (1% from the start)", "-", "fails" if worst > FAILURE_FRACTION else "holds"],
        ])
        text = f"""**Failure rule.** The total energy more than 1% away from its start at any step
(energy growing or draining by a stated fraction). Settings: the thesis's
ERP 0.4, CFM 0, step 0.001 s, QuickStep 20 iterations, {seconds} s; energies
from `Test2_output.txt` every 0.02 s, the extremes from the metrics (every step).

{table}

{md.figure("energy-test2", "test2: potential, kinetic and total energy (top) and the total's deviation "
           "from its start (bottom), against the thesis's range")}

{md.files_line([csv])}"""
        headline = [f"test2: the pendulum keeps its energy within {md.pct(worst, 2)} over {seconds} s at the thesis's "
                    f"settings (thesis: 0.75% variation)."]
        return Outcome(text, headline)

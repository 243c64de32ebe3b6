"""Speed against accuracy: for test2 (energy error), test8 (elongation) and
test9 (apex error), the error against the exact answer and the wall time per
simulated second, for dWorldStep and QuickStep with 5-100 iterations, at
steps log-spaced from 1e-2 to 1e-4. The cheapest setting reaching 1%, 0.1%
and 0.01% is marked and tabulated."""

from .. import markdown as md
from .. import swing_energy
from ..claims import Claim, q, slot
from ..first_screen import speed_lookups
from ..plots import speed as plots
from .. import timing
from ..runner import RunSpec, median
from .base import Experiment, Outcome, log_space

SOLVERS = [("dWorldStep", ["--solver", "step"])] + [
    (f"QuickStep {n}", ["--solver", "quick", "--iterations", n]) for n in (5, 10, 20, 50, 100)]
THRESHOLDS = [1e-2, 1e-3, 1e-4]
ZERO_FLOOR = 1e-16  # an error of exactly 0 is drawn here (below double precision's reach)
# Timings: timing.repeats interleaved runs per point, each stretched from the
# point's accuracy run to last timing.MIN_RUN_CPU_SECONDS of CPU (a run of a
# few milliseconds is timed mostly by the scheduler and the start-up, not by
# ODE); the cheapest setting is picked by its median and its ties by the range.


class SpeedAccuracy(Experiment):
    section = 3
    program = ""
    error_label = ""
    error_name = ""
    exact = ""

    def scene_args(self, quick):
        raise NotImplementedError

    def error_of(self, r):
        raise NotImplementedError

    def run(self, ctx):
        steps = log_space(1e-2, 1e-4, 3 if ctx.quick else 9)
        args, sim_seconds = self.scene_args(ctx.quick)
        plan = [(solver, solver_args, step) for solver, solver_args in SOLVERS for step in steps]
        repeats = timing.repeats(ctx.quick)
        ctx.expect(len(plan) * (1 + repeats))
        # The error from one run of the scene's length per point; its timings
        # from runs stretched from it (timing.stretched), interleaved.
        accuracy_args = [[*args, *solver_args, "--step", step] for _, solver_args, step in plan]
        accuracy = ctx.runner.map([RunSpec(self.program, a, measures_blow_ups=True) for a in accuracy_args])
        minimum = timing.min_run_cpu(ctx.quick)
        lengths = ctx.runner.parallel([lambda a=a: timing.stretched(ctx.runner, self.program, a, minimum)
                                       for a in accuracy_args])
        ctx.advance(len(plan))
        timed = timing.interleaved_long_enough(ctx.runner, [(self.program, a) for a in lengths], repeats, minimum)
        ctx.advance(len(plan) * repeats)
        measured = list(zip(accuracy, timed))
        rows = []
        for (solver, _, step), (first, results) in zip(plan, measured):
            walls = [r.m("wall_seconds") for r in results]
            sim = results[0].m("sim_seconds")
            error = self.error_of(first) if first.rc == 0 else None
            rows.append(dict(solver=solver, step_s=step, accuracy_sim_seconds=first.m("sim_seconds"),
                             timed_sim_seconds=sim, repeats=len(results),
                             shortest_run_cpu_seconds=min(r.cpu_seconds for r in results),
                             wall_seconds_median=median(walls), wall_seconds_min=min(w for w in walls if w is not None),
                             wall_seconds_max=max(w for w in walls if w is not None),
                             wall_per_sim_second=median([r.wall_per_sim_second() for r in results]),
                             cpu_per_sim_second=median([r.cpu_seconds / r.m("sim_seconds") for r in results]),
                             cpu_share=median([r.cpu_share for r in results]),
                             error=error, exit_status=first.rc, cheapest_for=""))
        cheapest = []
        for threshold in THRESHOLDS:
            candidates = [r for r in rows if r["error"] is not None and r["error"] <= threshold]
            best = min(candidates, key=lambda r: r["wall_per_sim_second"]) if candidates else None
            cheapest.append((threshold, best))
            if best:
                best["cheapest_for"] = (best["cheapest_for"] + ";" if best["cheapest_for"] else "") + md.pct(threshold)
        stem = self.name
        csv = ctx.write_csv(stem, list(rows[0].keys()), rows, notes=[
            f"error: {self.error_name}; exact answer: {self.exact}",
            f"error from a run of accuracy_sim_seconds; x: wall_per_sim_second = median of the program's "
            f"wall_seconds over `repeats` interleaved runs of timed_sim_seconds (stretched from the accuracy "
            f"run to last {timing.min_run_cpu(ctx.quick):g} CPU s or more) / timed_sim_seconds; "
            "min and max: their range",
            "cheapest_for: the error levels for which this is the cheapest setting measured"])
        ctx.register_files(plots.speed_accuracy(ctx.out_dir, stem, rows, cheapest, self.error_label,
                                                self.plot_title, ZERO_FLOOR))
        table_rows = []
        for threshold, best in cheapest:
            if best is None:
                table_rows.append([md.pct(threshold), "not reached by any setting measured", "-", "-", "-"])
            else:
                table_rows.append([md.pct(threshold), best["solver"], md.num(best["step_s"]),
                                   md.num(best["error"], 2), md.num(best["wall_per_sim_second"], 3)])
        text = f"""Error: {self.error_name}; the exact answer is {self.exact}. {self.settings_text(ctx.quick)}
One point per solver setting and step. The error comes from one run of the
length above; x is the program's own `wall_seconds` per simulated second, from
the median of {repeats} interleaved runs, each stretched from the accuracy run to last
{timing.min_run_cpu(ctx.quick):g} s of CPU or more; a setting whose fastest run is not slower than the
cheapest's slowest ties with it.
{slot("blown")}

{md.table(["error at most", "cheapest setting", "step (s)", "its error", "wall s per simulated s"], table_rows)}

{md.figure(stem, f"{self.program}: error against wall time per simulated second (log-log), one curve per solver "
                 "setting, steps 1e-2 (left) to 1e-4 (right); rings mark the cheapest setting per error level")}

{md.files_line([csv])}

How to read it: go to the dotted line of the error you can accept and take the
leftmost point below it. A curve that falls as it moves right is limited by the
step; a curve that stays flat is limited by the solver (more iterations help, a
smaller step does not)."""
        summary = [[f"{self.program}: {self.error_name}", md.pct(t)] +
                   ([b["solver"], md.num(b["step_s"]), md.num(b["error"], 2), md.num(b["wall_per_sim_second"], 3)]
                    if b else ["not reached", "-", "-", "-"]) for t, b in cheapest]
        return Outcome(text, [self.headline()], summary=summary, claims={"blown": self.blown()})

    def blown(self):
        """The runs that ended with a non-zero status (not plotted), from the CSV."""
        f = f"speed-{self.program}.csv"
        return Claim(f"{self.name}.blown", "Runs that blew up (not plotted): {which}.",
                     {"solvers": q(f, "solver", "texts"), "steps": q(f, "step_s", "list"),
                      "status": q(f, "exit_status", "list"),
                      "which": "', '.join(s + ' at step ' + num(h) for s, h, x in zip(solvers, steps, status) if x)"},
                     "any(status)")

    def headline(self):
        """The cheapest settings per error level, ties within the timing's
        scatter as a set (claims.cheapest), from the CSV."""
        values = speed_lookups(self.program)
        levels = []
        for n, level in enumerate(THRESHOLDS):
            values[f"c{n}"] = f"cheapest(names, errors, cost, lo, hi, {level!r}, 'QuickStep 20 at 0.001')"
            levels.append(f"{md.pct(level)}: {{c{n}}}")
        return Claim(f"headline.{self.program}.cheapest", f"{self.program} ({self.error_name}): cheapest for "
                     + "; ".join(levels) + ".", values, "len(names) > 0")

    def settings_text(self, quick):
        return ""

    @staticmethod
    def with_seconds(args, seconds):
        """`args` with its --seconds value replaced."""
        args = list(args)
        args[args.index("--seconds") + 1] = seconds
        return args


class SpeedTest2(SpeedAccuracy):
    name = "speed-test2"
    title = "test2: energy error against cost"
    program = "test2"
    programs = ("test2",)
    cost = (50.0, 4.0)
    error_name = "largest energy error |E - E0| / (m g d) over every step, m g d the swing's energy"
    error_label = "largest energy error |E - E0| / (m g d)"
    plot_title = "test2 pendulum: energy error against cost (ERP 0.4, CFM 0)"
    exact = "a constant total energy E0 (no friction, no damping); " + swing_energy.header()

    def scene_args(self, quick):
        seconds = 5 if quick else 20
        return ["--erp", 0.4, "--cfm", 0, "--seconds", seconds, "--sample-interval", 3600], seconds

    def error_of(self, r):
        # Against the swing's energy, not E0 (whose potential counts from the ground 7 m down).
        return swing_energy.of_run(r)

    def settings_text(self, quick):
        return (f"ERP 0.4, CFM 0, {5 if quick else 20} s from horizontal (about {1 if quick else 5} periods); "
                "`Test2_output.txt` reduced to one row so that writing it costs nothing.")


class SpeedTest8(SpeedAccuracy):
    name = "speed-test8"
    title = "test8: hinge elongation against cost"
    program = "test8"
    programs = ("test8",)
    cost = (50.0, 4.0)
    error_name = "largest relative elongation |l - l0| / l0"
    error_label = "largest relative elongation |l - l0| / l0"
    plot_title = "test8 heavy pendulum: hinge elongation against cost (ERP 0.4, CFM 0)"
    exact = "0 (a rigid hinge keeps the length)"

    def scene_args(self, quick):
        seconds = 5 if quick else 20
        return ["--erp", 0.4, "--cfm", 0, "--seconds", seconds, "--sample-interval", 3600], seconds

    def error_of(self, r):
        return r.m("max_relative_elongation")

    def settings_text(self, quick):
        return (f"5000 kg bob, ERP 0.4, CFM 0 (a rigid hinge: with CFM > 0 the stretch is set by CFM, see the "
                f"test8 limit), {5 if quick else 20} s; `Test8_output.txt` reduced to one row.")


class SpeedTest9(SpeedAccuracy):
    name = "speed-test9"
    title = "test9: apex error against cost"
    program = "test9"
    programs = ("test9",)
    cost = (12.0, 1.0)
    error_name = "relative apex error after 20 bounces"
    error_label = "relative apex error after 20 bounces"
    plot_title = "test9 perfect bounce: apex error against cost (ERP 0.2, CFM 0)"
    exact = "0 (a bounce of 1.0 returns the ball to its start)"

    def scene_args(self, quick):
        return ["--erp", 0.2, "--cfm", 0, "--seconds", 21], 21

    def error_of(self, r):
        return r.m("apex_error_20")

    def settings_text(self, quick):
        return "ERP 0.2, CFM 0, 21 s (20 bounces)."

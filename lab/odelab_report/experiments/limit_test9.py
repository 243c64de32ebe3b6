"""test9: apex error of a perfect bounce against the bounce count, for
CFM 0, 1e-8, 1e-7, 1e-6, 1e-5 (ERP 0.2, step 0.001, QuickStep 20)."""

from .. import markdown as md
from ..plots import limits as plots
from ..runner import RunSpec
from .base import Experiment, Outcome

FAILURE_FRACTION = 0.01      # the failure rule: apex more than 1% of the drop below the start

CFMS = [0.0, 1e-8, 1e-7, 1e-6, 1e-5]


def apex_errors(r):
    """[(bounce, relative apex error)] of a test9 run, every digit, from its
    metrics apex_error_1 ... apex_error_N (N = its `bounces`)."""
    return [(n, r.m(f"apex_error_{n}")) for n in range(1, int(r.m("bounces", 0)) + 1)]


def drop_height(r):
    """The drop the errors are relative to: the ball's lowest point above the ground at the start."""
    return r.m("start_height_m") - r.m("ball_radius_m")


def reading(summary):
    """What the table shows, each figure computed: how the error grows from
    10 to 20 bounces (2x when the loss per bounce is constant), and how much
    each decade of CFM multiplies the error after 20 bounces."""
    twenty = [(c, e10, e20) for c, _, _, _, e10, e20, _ in summary if e10 and e20]
    growth = [e20 / e10 for _, e10, e20 in twenty if e20 < FAILURE_FRACTION * 100]
    parts = []
    if growth:
        parts.append(f"from 10 to 20 bounces the error grows {md.num(min(growth), 3)}x to {md.num(max(growth), 3)}x "
                     f"across the CFMs (2x is a constant loss per bounce)")
    decades = [(a, b, eb / ea) for (a, _, ea), (b, _, eb) in zip(twenty, twenty[1:]) if a > 0 and b == 10 * a]
    if decades:
        parts.append("each decade of CFM multiplies the error after 20 bounces by " +
                     ", ".join(f"{md.num(ratio, 2)}x ({md.num(a)} to {md.num(b)})" for a, b, ratio in decades))
    zero = [e20 for c, _, e20 in twenty if c == 0]
    if zero:
        parts.append(f"CFM 0 loses {md.num(zero[0] / 20, 2)} of the drop per bounce")
    return "; ".join(parts) + "." if parts else "no CFM gave 20 bounces."


class LimitTest9(Experiment):
    name = "limit-test9"
    title = "test9: apex error against bounce count"
    section = 2
    programs = ("test9",)
    cost = (1.0, 0.5)

    def run(self, ctx):
        seconds = 10 if ctx.quick else 25
        args = lambda cfm: ["--erp", 0.2, "--cfm", cfm, "--step", 0.001, "--seconds", seconds]  # noqa: E731
        ctx.expect(len(CFMS))
        results = ctx.runner.map([RunSpec("test9", args(c)) for c in CFMS])
        ctx.advance(len(CFMS))
        rows, series, summary = [], {}, []
        drop = drop_height(results[0])
        for cfm, result in zip(CFMS, results):
            points = apex_errors(result)
            for bounce, error in points:
                rows.append(dict(cfm=cfm, bounce=bounce, relative_error=error, dy_m=error * drop))
            series[cfm] = points
            failing = [n for n, e in points if e > FAILURE_FRACTION]
            within = (failing[0] - 1) if failing else (points[-1][0] if points else 0)
            by = {n: e for n, e in points}
            summary.append((cfm, within, bool(failing), by.get(5), by.get(10), by.get(20), len(points)))
        csv = ctx.write_csv("limit-test9", ["cfm", "bounce", "relative_error", "dy_m"], rows,
                            notes=[f"relative_error: test9's metric apex_error_<bounce>, |dy| / {drop:g} m (the drop, "
                                   f"from its metrics start_height_m - ball_radius_m); dy_m: |dy|; failure rule: "
                                   f"relative_error > {FAILURE_FRACTION:g}"])
        ctx.register_files(plots.apex_error(ctx.out_dir, "limit-test9", series, FAILURE_FRACTION, None))
        table = md.table(
            ["CFM", "apex error after 5 / 10 / 20 bounces", "bounces within 1%", "apexes in the run"],
            [[md.num(c), " / ".join(md.pct(e, 2) if e is not None else "-" for e in (e5, e10, e20)),
              (f"{w}" if failed else f"all {w} (no failure)"), n]
             for c, w, failed, e5, e10, e20, n in summary])
        text = f"""**Failure rule.** An apex more than 1% of the drop ({md.num(100 * FAILURE_FRACTION * drop, 2)} cm) below the start. The
exact answer for a bounce of 1.0 is that every apex is back at the start.
Per-bounce figures are test9's metrics `apex_error_1` ... `apex_error_N`, with
every digit. Settings: ERP 0.2, step 0.001 s, QuickStep 20
iterations, {seconds} s per run.

{table}

{md.figure("limit-test9", "test9: relative apex error against bounce count, one curve per CFM (log scale)")}

{md.files_line([csv])}

How to read it: {reading(summary)}"""
        lost = {c: e20 for c, _, _, _, _, e20, _ in summary}
        headline = []
        if lost.get(1e-6) is not None and lost.get(0.0) is not None:
            headline.append(f"test9: a perfect bounce stays exact at CFM 0 ({lost[0.0]:.1e} after 20 bounces); "
                            f"CFM 1e-6 loses {md.pct(lost[1e-6])} of the height after 20 bounces, "
                            f"CFM 1e-5 {md.pct(lost.get(1e-5))}.")
        return Outcome(text, headline)


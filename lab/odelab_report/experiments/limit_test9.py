"""test9: apex error of a perfect bounce against the bounce count, for
CFM 0, 1e-8, 1e-7, 1e-6, 1e-5 (ERP 0.2, step 0.001, QuickStep 20)."""

from .. import markdown as md
from ..claims import Claim, q, slot
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


def _apex(column, agg="list", **where):
    return q("limit-test9.csv", column, agg, **where)


# The error after 10 and 20 bounces by CFM (a CFM whose run gave fewer apexes has none).
_BY_CFM = {"c10": _apex("cfm", bounce=10), "e10": _apex("relative_error", bounce=10),
           "c20": _apex("cfm", bounce=20), "e20": _apex("relative_error", bounce=20),
           "d20": "{c: e for c, e in zip(c20, e20)}",
           "growth": "[d20[c] / e for c, e in zip(c10, e10) if c in d20 and e and d20[c] < 1]",
           "decades": "[(a, b, d20[b] / d20[a]) for a in sorted(d20) for b in sorted(d20) "
                      "if a > 0 and math.isclose(b, 10 * a)]",
           "each": "', '.join(num(r, 2) + 'x (' + num(a) + ' to ' + num(b) + ')' for a, b, r in decades)",
           "zero": "d20[0] / 20 if 0 in d20 else None"}
READING = {
    "growth": Claim("limit-test9.growth", "From 10 to 20 bounces the error grows {growth:r} times across the CFMs "
                    "(2 times is a constant loss per bounce).", _BY_CFM, "len(growth) > 0"),
    "decades": Claim("limit-test9.decades", "Each decade of CFM multiplies the error after 20 bounces by {each}.",
                     _BY_CFM, "len(decades) > 0"),
    "zero": Claim("limit-test9.zero", "CFM 0 loses {zero:n2} of the drop per bounce.", _BY_CFM, "zero is not None"),
}
_LOST = {"z": _apex("relative_error", "one", cfm=0, bounce=20),
         "m6": _apex("relative_error", "one", cfm=1e-6, bounce=20),
         "m5": _apex("relative_error", "one", cfm=1e-5, bounce=20)}
_LOSSES = "; CFM 1e-6 loses {m6:p} of the height after 20 bounces, CFM 1e-5 {m5:p}."
# Exact as the thesis has it: to six decimals of the drop.
HEADLINE = [Claim("headline.test9.exact", "test9: a perfect bounce stays exact to six decimals at CFM 0 ({z:.1e} "
                  "after 20 bounces)" + _LOSSES, _LOST, "z < 1e-6"),
            Claim("headline.test9.inexact", "test9: a perfect bounce is not exact to six decimals at CFM 0 ({z:.1e} "
                  "after 20 bounces)" + _LOSSES, _LOST, "z >= 1e-6")]


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

How to read it: {slot("growth")} {slot("decades")} {slot("zero")}"""
        return Outcome(text, [HEADLINE], claims=READING)


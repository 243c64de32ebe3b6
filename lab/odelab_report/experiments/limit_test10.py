"""test10: the highest launch velocity with every launch stopped, at steps
log-spaced from 1e-2 to 1e-4, beside v = (a + w) / h (SYMBOLS)."""

from .. import markdown as md
from ..claims import Claim, q, slot
from ..plots import limits as plots
from ..runner import RunSpec
from .base import Experiment, Outcome, log_space

BAND_FACTOR = 1.6
# The geometry's symbols, defined once here (each CSV of test10 says them; doc/lab.md too):
# h is the step, as in ODE's own ERP and CFM formulas and test8's estimate F h CFM / ERP.
SYMBOLS = ("symbols: a the cube's half-size (cube_half_size_m), w the wall's thickness (wall_thickness_m), "
           "h the step (step_s); geometric_prediction = (a + w) / h, guaranteed_stop_velocity = (a + w/2) / h")


def _scan(column, agg="one", **where):
    return q("limit-test10.csv", column, agg, **where)


_LIMITS = {"a": _scan("max_velocity", step_s=0.001), "b": _scan("max_velocity", step_s=0.0001),
           "pa": _scan("geometric_prediction", step_s=0.001), "pb": _scan("geometric_prediction", step_s=0.0001)}
# the headline's reading: the finer step stops faster cubes, measured and predicted
_FINER_STOPS_FASTER = "a < b and pa < pb"
_HEADLINE = ("test10: the wall stops every cube up to {a:n4} m/s at step 0.001 and {b:n4} m/s at 0.0001 (prediction "
             "(a + w) / h: {pa:n4} / {pb:n4} m/s")
HEADLINE = [Claim("headline.test10", _HEADLINE + "; thesis: {ta:n} / about {tb:n}).",
                  dict(_LIMITS, ta=q("thesis.csv", "thesis_figure", key="test10_a"),
                       tb=q("thesis.csv", "thesis_figure", key="test10_b")), _FINER_STOPS_FASTER),
            Claim("headline.test10.alone", _HEADLINE + ").", _LIMITS, _FINER_STOPS_FASTER)]
_ALL = {"v": _scan("max_velocity", "list"), "g": _scan("geometric_prediction", "list"),
        "g2": _scan("guaranteed_stop_velocity", "list"), "ratios": "[a / b for a, b in zip(v, g)]"}
READING = {
    "ratio": Claim("limit-test10.ratio", "the measured limit is {ratios:r} times v = (a + w) / h across the "
                   "steps (the column limit / ((a + w) / h)).", _ALL, "len(ratios) > 1"),
    "phase": [Claim("limit-test10.phase", "At every step the limit is at or above (a + w/2) / h, below which "
                    "every arrival phase is stopped;", _ALL, "all(a >= b for a, b in zip(v, g2))"),
              Claim("limit-test10.phase.below", "At some step the limit is below (a + w/2) / h, which every "
                    "arrival phase should pass: the geometry does not explain it;", _ALL,
                    "any(a < b for a, b in zip(v, g2))")],
}


def scan_spec(step, extra=(), launches=1, phase_jitter=False):
    """test10's velocity scan at `step`."""
    args = ["--find-max-velocity", "--step", step, "--band-factor", BAND_FACTOR, "--launches", launches, *extra]
    if phase_jitter:
        args.append("--phase-jitter")
    return RunSpec("test10", args)


def scan_row(step, r):
    return dict(
        step_s=step,
        max_velocity=r.m("max_velocity"),
        resolution=r.m("max_velocity_resolution"),
        first_failure_velocity=r.m("first_failure_velocity"),
        band_upper_velocity=r.m("band_upper_velocity"),
        velocities_stopped_in_band=r.m("velocities_stopped_in_band"),
        velocities_passed_in_band=r.m("velocities_passed_in_band"),
        highest_stopped_velocity_in_band=r.m("highest_stopped_velocity_in_band"),
        # The scene's sizes and what they predict, as the program reports them.
        cube_half_size_m=r.m("cube_half_size_m"),
        wall_thickness_m=r.m("wall_thickness_m"),
        geometric_prediction=r.m("geometric_prediction"),
        guaranteed_stop_velocity=r.m("guaranteed_stop_velocity"),
        launches=r.m("launches"),
        passed_through=r.m("passed_through"),
        exit_status=r.rc,
    )


class LimitTest10(Experiment):
    name = "limit-test10"
    title = "test10: fastest cube the wall stops, against the step"
    section = 2
    programs = ("test10",)
    cost = (2.0, 0.6)

    def run(self, ctx):
        steps = log_space(1e-2, 1e-4, 5 if ctx.quick else 9)
        ctx.expect(len(steps))
        results = ctx.runner.map([scan_spec(s) for s in steps])
        ctx.advance(len(steps))
        rows = [scan_row(s, r) for s, r in zip(steps, results)]
        csv = ctx.write_csv("limit-test10", list(rows[0].keys()), rows,
                            notes=["test10 --headless --find-max-velocity --step S --band-factor 1.6 --launches 1 "
                                   "(ERP 0.3, CFM 0, QuickStep 20, fixed launch point x = -4)",
                                   "failure rule (test10's): a launch fails when the whole cube ends beyond the "
                                   "wall's far face", SYMBOLS])
        ctx.register_files(plots.velocity_limit(ctx.out_dir, "limit-test10", rows))
        table_rows = []
        for row in rows:
            band = "-"
            if row["velocities_stopped_in_band"]:
                band = (f"{md.num(row['first_failure_velocity'], 4)}-{md.num(row['band_upper_velocity'], 4)}: "
                        f"{int(row['velocities_passed_in_band'])} pass, {int(row['velocities_stopped_in_band'])} "
                        f"stopped again (highest {md.num(row['highest_stopped_velocity_in_band'], 4)})")
            table_rows.append([md.num(row["step_s"]), md.num(row["max_velocity"], 5),
                               md.num(row["geometric_prediction"], 4), md.num(row["guaranteed_stop_velocity"], 4),
                               md.num(row["max_velocity"] / row["geometric_prediction"], 3), band])
        text = f"""**Failure rule** (test10's own): a launch fails when the whole cube ends beyond
the wall's far face. The limit is the highest tested velocity with every
launch up to it stopped, found by test10's scan (1 m/s steps to 1000 m/s, 0.1%
above); after the first failure the scan goes on to {BAND_FACTOR} times it, to show
velocities that are stopped again (the band). ERP 0.3, CFM 0, QuickStep 20,
surface layer 0, one launch per velocity from the fixed launch point.
Symbols: a the cube's half-size ({md.num(rows[0]["cube_half_size_m"])} m), w the wall's thickness
({md.num(rows[0]["wall_thickness_m"])} m), h the step.

{md.table(["step h (s)", "limit (m/s)", "(a + w) / h", "(a + w/2) / h", "limit / ((a + w) / h)",
           "band above the limit"], table_rows)}

{md.figure("limit-test10", "test10: highest velocity with every launch stopped against the step (log-log), "
           "with the geometric predictions and the band where stops come back")}

{md.files_line([csv])}

How to read it: {slot("ratio")} {slot("phase")}
between (a + w/2) / h and (a + w) / h whether a cube is stopped depends on where it
happens to be at the steps around the wall, which is why bands of stopped velocities appear
above the first failure."""
        return Outcome(text, [HEADLINE], claims=READING)

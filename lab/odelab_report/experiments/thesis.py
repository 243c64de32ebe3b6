"""The thesis reproduced: each row of the thesis's figures
(lab/reference/thesis-figures.csv) measured at the thesis's settings, with
the thesis's ODE 0.11.1 figure, the Havok 6.5 figure it quotes, this build's
figure, and a verdict computed by a stated rule."""

import csv
from pathlib import Path

from .. import markdown as md
from .. import swing_energy
from ..claims import Claim, q, slot
from ..header import ode_version
from ..runner import LabError, RunSpec, median
from .base import Experiment, Outcome
from .limit_test5 import SETTLE, SPAWN_INTERVAL, stack_spec, step_cost
from .limit_test8 import estimate, run_spec as test8_spec
from .limit_test10 import scan_spec
from . import thesis_choices as choices
from . import thesis_claims as claims
from . import thesis_statements as statements

REFERENCE = Path(__file__).resolve().parents[2] / "reference" / "thesis-figures.csv"
CLOSE = 1.5  # "about X" is reproduced when this build's figure is within a factor 1.5 of X
HANG_SECONDS = 300  # test0's run for a body left hanging (about 5 s of wall time)
SETTLED_DEG = 1.0   # test8 has stopped swinging: under 1 degree peak to peak over its last 10 s
_VERDICTS = {"v": q("thesis.csv", "verdict", "texts"), "first": "[x.split(';')[0] for x in v]",
             "n": "len(v)", "ok": "first.count('reproduced')", "partly": "first.count('partly')",
             "differs": "first.count('differs')", "untested": "first.count('not tested')",
             "choice": "sum('; reproduced with' in x for x in v)"}
COUNTS = Claim("thesis.counts", "{ok} reproduced, {partly} partly, {differs} differ at the scenes' defaults, "
               "{untested} not tested (no metric shows them); {choice} of those not reproduced are reproduced with "
               "another value of a choice the thesis does not state (the last column: what was varied, over which "
               "values, and what it gave).", _VERDICTS, "n > 0")
HEADLINE = Claim("headline.thesis", "The thesis: {ok} of {n} claims reproduced, {partly} partly, {differs} differ at "
                 "the scenes' defaults, {untested} not tested; {choice} of the others reproduced with another value "
                 "of a choice the thesis does not state (details in section 1).", _VERDICTS, "n > 0")


def about(measured, thesis):
    """(verdict, how) for a figure the thesis gives as "about X"."""
    if measured is None:
        return "differs", "no figure measured"
    ratio = measured / thesis
    if 1 / CLOSE <= ratio <= CLOSE:
        return "reproduced", f"within a factor {CLOSE} of the thesis's figure ({ratio:.2f}x)"
    return "differs", f"{ratio:.3g}x the thesis's figure"


# The rows of thesis-figures.csv, in order, as thesis_choices.py names them.
ROW_KEYS = ["test1", "test2", "test3", "test4_fast", "test4_small", "test5", "test6", "test7", "test8_a", "test8_b",
            "test8_c", "test9_a", "test9_b", "test10_a", "test10_b",
            "test0_hang", "test2_cfm", "test3_active", "test7_faster", "test8_settles", "test10_sharp",
            "test10_settings"] + claims.KEYS

# The figures the first table and the docs quote, per row: (row key, name,
# the run's key, its metric, definition). A run key naming repeats gives
# their median, least and largest.
VALUES = [
    ("test0_hang", "resting", "t0", "bodies_resting_on_platform", "bodies slower than 0.05 m/s on the platform"),
    ("test0_hang", "hanging", "t0_hang", "max_hanging_disabled_bodies",
     "most disabled bodies at once with nothing within 0.05 m below them"),
    ("test0_hang", "woken", "t0_hang", "hanging_bodies_woken", "hanging bodies woken (by a touch) later in the run"),
    ("test8_settles", "swing", "t8_c", "swing_last_10s_deg", "peak-to-peak swing over the run's last 10 s (deg), CFM 1e-2"),
    ("test8_settles", "swing_cfm_0", "t8_e", "swing_last_10s_deg", "peak-to-peak swing over the run's last 10 s (deg), CFM 0"),
    ("test1", "rebound_error", "t1", "max_rebound_error", "largest |apex2/apex1 - e^2| over the balls, e >= 0.1"),
    ("test1", "balls", "t1", "balls_measured", "balls measured (e >= 0.1)"),
    ("test1", "bounced_cfm", "t1_cfm", "balls_bounced", "balls that rebound at CFM 1e-3"),
    ("test2", "variation", "t2", "energy_rel_variation", "(max - min) / max of the total energy over 60 s"),
    # test2's energy errors per the swing's energy m g d, not E0 (swing_energy.py)
    ("test2", "max_swing_error", "t2", swing_energy.of_run,
     "largest |E - E0| / (m g d) over 60 s, m g d the swing's energy"),
    ("test2_cfm", "drift", "t2_cfm", swing_energy.drift_of_run,
     "(last - first) / (m g d) of the total energy, CFM 1e-4"),
    ("test3", "real_time_factor", "t3", "real_time_factor", "simulated s per wall s, auto-disable on"),
    ("test3", "real_time_factor_8", "t3_8", "real_time_factor", "simulated s per wall s, no auto-disable, 8 iterations"),
    ("test3", "real_time_factor_20", "t3_20", "real_time_factor", "simulated s per wall s, no auto-disable, 20 iterations"),
    ("test3_active", "active_bodies", "t3", "active_bodies", "bodies not disabled at the end, auto-disable on"),
    ("test3_active", "active_bodies_off", "t3_8", "active_bodies", "bodies not disabled at the end, no auto-disable"),
    ("test6", "seconds_upright", "t6", "seconds_upright", "seconds before the axis system tips"),
    ("test7", "joint_error", "t7", "max_joint_error", "largest joint error over 3 throws (m)"),
    ("test7_faster", "energy_1", "t7", "energy_after_throw_1", "the pair's energy after throw 1 (J)"),
    ("test7_faster", "energy_2", "t7", "energy_after_throw_2", "the pair's energy after throw 2 (J)"),
    ("test7_faster", "energy_3", "t7", "energy_after_throw_3", "the pair's energy after throw 3 (J)"),
    ("test8_a", "elongation", "t8_a", "max_relative_elongation", "largest |l - l0| / l0 over 60 s"),
    ("test8_b", "elongation", "t8_b", "max_relative_elongation", "largest |l - l0| / l0 over 60 s"),
    ("test8_c", "elongation", "t8_c", "max_relative_elongation", "largest |l - l0| / l0 over 60 s"),
    ("test8_c", "lowest", "t8_c", "lowest_bob_height_m", "the bob's lowest point above the ground (m)"),
    ("test9_a", "apex_error_20", "t9_0", "apex_error_20", "apex error after 20 bounces / drop height"),
    ("test9_b", "apex_error_5", "t9_6", "apex_error_5", "apex error after 5 bounces / drop height"),
    ("test9_b", "apex_error_10", "t9_6", "apex_error_10", "apex error after 10 bounces / drop height"),
    ("test9_b", "apex_error_20", "t9_6", "apex_error_20", "apex error after 20 bounces / drop height"),
    ("test10_a", "max_velocity", "t10_3", "max_velocity", "highest velocity with every launch stopped (m/s)"),
    ("test10_b", "max_velocity", "t10_4", "max_velocity", "highest velocity with every launch stopped (m/s)"),
    ("test10_sharp", "stopped_above", "t10_3", "velocities_stopped_in_band",
     "velocities stopped above the first failure, up to 1.6x the limit"),
] + [("test10_settings", label, f"t10_{label}", "max_velocity", f"highest velocity stopped, {label.replace('_', ' ')} "
      "(m/s)") for label in ("iterations_5", "iterations_50", "sor_1", "erp_0.1", "erp_0.9")]
TEST10_SETTINGS = {"iterations_5": ["--iterations", 5], "iterations_50": ["--iterations", 50], "sor_1": ["--sor", 1.0],
                   "erp_0.1": ["--erp", 0.1], "erp_0.9": ["--erp", 0.9]}


def figures(reference):
    """The thesis's figures of a row of thesis-figures.csv, as numbers."""
    return [float(x) for x in reference["figure"].split("/")] if reference["figure"] else []


def reference_rows():
    with open(REFERENCE, newline="") as stream:
        return list(csv.DictReader(stream))


class Thesis(Experiment):
    name = "thesis"
    title = "The thesis, reproduced"
    section = 1
    # The program of each row (test0 included: its body left hanging).
    programs = tuple(dict.fromkeys(key.split("_")[0] for key in ROW_KEYS))
    cost = (60.0, 20.0)  # with the sweeps of thesis_choices.py

    def run(self, ctx):
        q = ctx.quick
        h4 = 5 if q else 20          # test4 hold time
        s8 = 10 if q else 60         # test8 run length
        n_small, n_large = (15, 30) if q else (40, 90)  # test5 plate counts (limit-test5's ladder)
        specs = {
            "t0": RunSpec("test0", ["--seconds", 20, "--spawn-interval", 0.5]),
            # Long enough for supports to expire (30 s lifetime) and for later
            # objects to fall on what was left hanging.
            "t0_hang": RunSpec("test0", ["--seconds", HANG_SECONDS, "--spawn-interval", 1]),
            "t1": RunSpec("test1", ["--erp", 0, "--cfm", 0, "--seconds", 15]),
            "t1_cfm": RunSpec("test1", ["--erp", 0, "--cfm", 1e-3, "--seconds", 10]),
            "t2": RunSpec("test2", ["--erp", 0.4, "--cfm", 0, "--step", 0.001, "--seconds", 60,
                                    "--sample-interval", 3600]),
            "t2_cfm": RunSpec("test2", ["--erp", 0.4, "--cfm", 1e-4, "--step", 0.001, "--seconds", 60,
                                        "--sample-interval", 3600]),
            "t4_3": RunSpec("test4", ["--big-mass", 5000.0, "--step", 1e-3, "--solver", "quick", "--iterations", 20,
                                      "--seconds", float(h4)]),
            "t5_cfm": RunSpec("test5", ["--cfm", 1e-4, "--plates", n_small, "--spawn-interval", SPAWN_INTERVAL,
                                        "--seconds", round(n_small * SPAWN_INTERVAL + SETTLE, 3)]),
            "t6": RunSpec("test6", ["--seconds", 10 if q else 20]),
            # Its row's rule asks for a finite state: a blow-up is its "differs".
            "t7": RunSpec("test7", ["--max-angular-speed", 10, "--throws", 3], measures_blow_ups=True),
            "t8_a": test8_spec(0.4, 1e-4, 5000.0, s8),
            "t8_b": test8_spec(1.0, 0.0, 5000.0, s8),
            "t8_c": test8_spec(0.4, 1e-2, 5000.0, s8),
            "t8_d": test8_spec(1.0, 1e-4, 5000.0, s8),
            "t8_e": test8_spec(0.4, 0.0, 5000.0, s8),
            "t8_light": test8_spec(0.4, 1e-4, 5.0, s8),
            "t8_heavy": test8_spec(0.4, 1e-4, 1e6, s8),
            "t9_0": RunSpec("test9", ["--erp", 0.2, "--cfm", 0.0, "--step", 0.001, "--seconds", 25]),
            "t9_6": RunSpec("test9", ["--erp", 0.2, "--cfm", 1e-6, "--step", 0.001, "--seconds", 25]),
            "t10_3": scan_spec(0.001),
            "t10_4": scan_spec(0.0001),
        }
        for mass in (15000.0, 75000.0, 150000.0):
            specs[f"t4_4_{int(mass)}"] = RunSpec("test4", ["--big-mass", mass, "--step", 1e-4, "--solver", "quick",
                                                           "--iterations", 20, "--seconds", float(h4)])
        for label, extra in TEST10_SETTINGS.items():
            specs[f"t10_{label}"] = scan_spec(0.001, extra)
        for space in ("simple", "hash"):
            for n in (n_small, n_large):
                specs[f"t5_{space}_{n}"] = stack_spec(space, 20, 0.001, n)
        timed = {
            "t3": ("test3", ["--seconds", 10 if q else 20]),
            "t3_8": ("test3", ["--seconds", 10 if q else 20, "--no-auto-disable", "--iterations", 8]),
            "t3_20": ("test3", ["--seconds", 10 if q else 20, "--no-auto-disable", "--iterations", 20]),
        }
        # The unstated choices swept for the rows not reproduced (thesis_choices.py).
        sweeps = choices.sweeps(q, h4, s8)
        for sweep in sweeps:
            specs.update(sweep.specs())
        # The thesis's claims without a figure (thesis_claims.py).
        specs.update(claims.specs(q, h4, s8, n_small, SPAWN_INTERVAL, SETTLE))
        for space in ("simple", "hash"):
            specs[f"t5_{space}_{n_large}_4"] = stack_spec(space, 20, 0.001, n_large, extra=("--max-contacts", 4))
        claim_timed = claims.timed_specs(q)
        ctx.expect(len(specs) + len(timed) + len(claim_timed))
        keys = list(specs)
        results = dict(zip(keys, ctx.runner.map([specs[k] for k in keys])))
        ctx.advance(len(specs))
        repeats = 1 if q else 3
        timed_results = ctx.runner.parallel([lambda a=a: ctx.runner.run_timed(*a, repeats) for a in timed.values()])
        results.update({k: v for k, v in zip(timed, timed_results)})
        ctx.advance(len(timed))
        results.update(claims.split_timed(ctx.runner.map(claim_timed)))
        ctx.advance(len(claim_timed))

        second = self.second_build(ctx, specs, timed, keys)
        rows = []
        rebuilt = choices.rebuild_rows()
        quoted = statements.read()
        derived = self.derived_sensitivity(results, n_large)
        for key, reference, judge in zip(ROW_KEYS, reference_rows(),
                                         self.judges(results, q, h4, s8, n_small, n_large)):
            measured, verdict, how, rule, command = judge(reference)
            sensitivity, reproducing = choices.sensitivity(key, sweeps, results, derived.get(key, ""))
            if verdict not in ("reproduced", "not tested") and figures(reference):
                if not sensitivity:
                    raise RuntimeError(f"thesis row {key} is '{verdict}' and nothing was varied for it")
                if reproducing:
                    verdict += "; reproduced with " + ", ".join(reproducing)
            rows.append(dict(key=key, test=reference["test"], quantity=reference["quantity"],
                             conditions=reference["conditions"],
                             thesis_ode_0_11_1=reference["ode_0_11_1_thesis"], thesis_figure=reference["figure"],
                             ode_0_11_1_rebuild=choices.rebuild_figure(key, rebuilt),
                             havok_6_5_quoted=reference["havok_6_5_quoted_by_thesis"],
                             thesis_note=reference["note"], thesis_quotes=statements.quotes_for(key, quoted),
                             this_build=measured, verdict=verdict, how=how,
                             sensitivity=sensitivity, rule=rule, command=command))
            if second:
                rows[-1][second["column"]] = second["rows"][len(rows) - 1]
        values_name = ctx.write_csv("thesis-values", ["key", "name", "definition", "value", "value_min", "value_max",
                                                      "repeats"], self.values(results),
                                    notes=["the figures of thesis.csv's rows by name; value_min / value_max: the "
                                           "least and largest over the repeats (one run: the value)"])
        second_note = [f"{second['column']}: {second['note']}"] if second else []
        csv_name = ctx.write_csv("thesis", list(rows[0].keys()), rows,
                                 notes=[f"reference: lab/reference/thesis-figures.csv (a copy of the project's "
                                        f"thesis figures); 'about X' is reproduced within a factor {CLOSE}",
                                        f"ode_0_11_1_rebuild: lab/reference/ode-0.11.1-rebuild.csv (the programs of commit "
                                        f"{choices.rebuild_commit()}, not this one, built against ODE 0.11.1 rebuilt "
                                        "from its tag)",
                                        "sensitivity: the thesis's unstated choices varied for the rows not "
                                        "reproduced (experiments/thesis_choices.py)"] + second_note)
        statements_name = ctx.write_csv("thesis-statements", statements.COLUMNS, statements.report_rows(rows),
                                        notes=["every checkable statement of the thesis, quoted (Czech, verbatim) "
                                               "with its section: the rows that judge it and their verdicts, or "
                                               "the reason it has no row (lab/reference/thesis-statements.csv)"])
        rebuild_commit = choices.rebuild_commit()
        extra = [second["column"]] if second else []
        table = md.table(["test", "quantity", "conditions", "thesis ODE 0.11.1",
                          f"ODE 0.11.1 rebuilt (programs of commit {rebuild_commit})"] +
                         [f"{c} (--second-build)" for c in extra] +
                         ["Havok 6.5 (quoted)", "this build", "verdict", "how", "unstated choices varied"],
                         [[r["test"], r["quantity"], r["conditions"], r["thesis_ode_0_11_1"], r["ode_0_11_1_rebuild"]] +
                          [r[c] for c in extra] +
                          [r["havok_6_5_quoted"] or "-", r["this_build"], f"**{r['verdict']}**", r["how"],
                           r["sensitivity"] or "-"]
                          for r in rows])
        commands = md.table(["test", "conditions", "rule for the verdict", "command (build/tests/...)"],
                            [[r["test"], r["conditions"], r["rule"], f"`{r['command']}`"] for r in rows])
        text = f"""Each row of the thesis's figures, measured at the thesis's settings{" (quick: shorter runs)" if q else ""}.
A verdict is computed from the measurement by the rule in the second table: a figure the thesis gives as
"about X" is reproduced within a factor {CLOSE}; a yes/no observation by the stated check.
{slot("counts")} The "ODE 0.11.1 rebuilt" column is
the programs of commit {rebuild_commit} built against the thesis's ODE version (lab/reference/ode-0.11.1-rebuild.csv){', and the "--second-build" column these programs built against another ODE' if second else ''}.

{table}

Rules and commands (every command adds `--headless`):

{commands}

The thesis's checkable statements, each quoted with its section, point at these rows or say why they have
none: {statements_name}.

{md.files_line([csv_name, values_name, statements_name])}"""
        return Outcome(text, [HEADLINE], claims={"counts": COUNTS})

    def second_build(self, ctx, specs, timed, keys):
        """The rows measured again with the programs of --second-build: the
        same runs (not the sweeps), judged by the same rules. None without."""
        runner = getattr(ctx.runner, "second", None)
        if runner is None:
            return None
        base = [k for k in keys if not k.startswith("sweep:")]

        def kept(call):
            # A run the other build cannot make (an older ODE may lack what a
            # program asks of it) leaves its rows "not measured", not the report.
            try:
                return call()
            except LabError as error:
                if str(error) == "interrupted":
                    raise
                return None

        results = dict(zip(base, runner.parallel([lambda k=k: kept(lambda: runner.run(specs[k])) for k in base])))
        repeats = 1 if ctx.quick else 3
        results.update(zip(timed, runner.parallel([lambda a=a: kept(lambda: runner.run_timed(*a, repeats))
                                                   for a in timed.values()])))
        claim_timed = kept(lambda: runner.map(claims.timed_specs(ctx.quick)))
        if claim_timed:
            results.update(claims.split_timed(claim_timed))
        q = ctx.quick
        n_small, n_large = (15, 30) if q else (40, 90)
        judged = []
        for reference, judge in zip(reference_rows(), self.judges(results, q, 5 if q else 20, 10 if q else 60,
                                                                  n_small, n_large)):
            try:
                judged.append(judge(reference)[:2])
            except (TypeError, ValueError, KeyError, AttributeError, ZeroDivisionError) as error:
                # A run that failed or a metric the other build did not report: said, not fatal.
                judged.append((f"not measured ({type(error).__name__})", "-"))
        version = ode_version(runner.build_dir).split(",")[0]
        this = ode_version(ctx.runner.build_dir).split(",")[0]
        commit = dict(ctx.header).get("commit", "unknown")[:7]
        column = f"ode_{version.replace('.', '_')}_beside_{this.replace('.', '_')}_programs_{commit}"
        return dict(column=column, rows=[f"{measured} ({verdict})" for measured, verdict in judged],
                    note=(f"these programs (project commit {commit}) built against ODE {version} (as its test2 "
                          f"reports) at {runner.build_dir}, beside this build's ODE {this}; the same runs as "
                          "this_build (not the sweeps), judged by the same rules"))

    @staticmethod
    def values(results):
        rows = []
        for key, name, run_key, metric, definition in VALUES:
            result = results[run_key]
            runs = result if isinstance(result, list) else [result]
            read = [metric(x) if callable(metric) else x.m(metric) for x in runs]  # a callable: a derived figure
            got = [v for v in read if v is not None]
            if not got:
                continue
            rows.append(dict(key=key, name=name, definition=definition, value=median(got), value_min=min(got),
                             value_max=max(got), repeats=len(got)))
        return rows

    def derived_sensitivity(self, r, n_large):
        """What the rows' own measurements say about a choice, without more runs."""
        a = r["t2"]
        share, ratio = a.m("rotational_energy_max_fraction"), a.m("inertia_centre_over_axis")
        thesis_variation = choices.figure_of("test2", "ERP 0.4, CFM 0")[0]
        rest = (f"; the thesis's {md.pct(thesis_variation)} would need I_centre / I_axis = "
                f"{ratio * thesis_variation / share:.3g}" if share else "")
        t10 = r["t10_4"]
        thesis_limit = choices.figure_of("test10", "step 0.0001")[0]
        simple, hash_ = (step_cost(r[f"t5_{s}_{n_large}_4"]) for s in ("simple", "hash"))
        return {
            "test2": (f"leaving out the spin makes the total dip by the spin's share at the bottom, "
                      f"{md.pct(share, 2)} of the start energy with this rig (I_centre / I_axis = {ratio:.3g})"
                      + rest),
            "test10_b": (f"the launch velocity scanned: first failure at {t10.m('first_failure_velocity'):.5g} m/s, "
                         f"stopped launches above it reach {t10.m('highest_stopped_velocity_in_band'):.5g} m/s "
                         f"(the thesis's 'about {thesis_limit:g}' is within a factor {CLOSE} of the latter: "
                         f"{'yes' if choices.within(t10.m('highest_stopped_velocity_in_band'), thesis_limit) else 'no'})"),
            "test5": (f"contacts per pair (default {choices.default_of('test5', 'contacts per pair')}) varied: 4 per pair, {n_large} plates: ms per step simple "
                      f"{simple:.3g}, hash {hash_:.3g} (hash cheaper by 1.5x: {'yes' if hash_ < simple / 1.5 else 'no'})"),
        }

    # ---- one judge per row of thesis-figures.csv, in its order ------------------------------
    def judges(self, r, q, h4, s8, n_small, n_large):
        def expect(test, conditions_start):
            def wrap(function):
                def judge(reference):
                    if reference["test"] != test or not reference["conditions"].startswith(conditions_start):
                        raise RuntimeError(f"thesis-figures.csv changed: expected a {test} row '{conditions_start}...', "
                                           f"found {reference['test']} '{reference['conditions']}'")
                    return function(reference)
                return judge
            return wrap

        @expect("test1", "gravity 0.25g")
        def test1(reference):
            a, b = r["t1"], r["t1_cfm"]
            ok = a.m("max_rebound_error", 1) < 0.01 and a.m("balls_measured") == 45
            damped = b.m("balls_bounced") == 0
            measured = (f"apex2/apex1 within {a.m('max_rebound_error'):.2g} of e^2 for all "
                        f"{int(a.m('balls_measured'))} balls with e >= 0.1; CFM 1e-3: "
                        f"{int(b.m('balls_bounced'))} balls rebound")
            verdict = "reproduced" if ok and damped else ("partly" if ok or damped else "differs")
            how = (f"{'every' if ok else 'not every'} ball's rebound within 0.01 of e^2; CFM 1e-3: "
                   f"{'no ball rebounds' if damped else format(b.m('balls_bounced'), 'g') + ' balls rebound'}")
            return (measured, verdict, how,
                    "max_rebound_error < 0.01 over all 45 balls; CFM 1e-3: balls_bounced = 0",
                    "test1 --erp 0 --cfm 0 --seconds 15; test1 --erp 0 --cfm 1e-3 --seconds 10")

        @expect("test2", "ERP 0.4, CFM 0")
        def test2(reference):
            a, b = r["t2"], r["t2_cfm"]
            variation = a.m("energy_rel_variation")
            figure, = figures(reference)
            verdict, how = about(variation, figure)
            how += (f"; the same definition as the thesis's; |E - E0| / (m g d) at most "
                    f"{md.pct(swing_energy.of_run(a), 2)} (m g d the swing's energy)"
                    if swing_energy.of_run(a) is not None else "")
            return (f"{md.pct(variation, 2)} (min {a.m('energy_min_J'):.4f} J / max {a.m('energy_max_J'):.4f} J)",
                    verdict, how, f"energy_rel_variation within a factor {CLOSE} of {md.pct(figure)}",
                    "test2 --erp 0.4 --cfm 0 --step 0.001 --seconds 60 [--cfm 1e-4]")

        @expect("test3", "thresholds 0.1/0.1")
        def test3(reference):
            rtf = median([x.m("real_time_factor") for x in r["t3"]])
            f8 = median([x.m("real_time_factor") for x in r["t3_8"]])
            f20 = median([x.m("real_time_factor") for x in r["t3_20"]])
            fallen = r["t3"][0].m("fallen_fraction")
            figure, = figures(reference)
            verdict = "reproduced" if rtf >= figure and fallen == 1 else "differs"
            how = (f"{'faster' if rtf >= 1 else 'slower'} than real time (physics only, this machine, median of "
                   f"{len(r['t3'])}); without auto-disable 8 iterations {'faster' if f8 > f20 else 'not faster'} "
                   f"than 20 by {100 * (f8 / f20 - 1):+.0f}% (physics only; the thesis's figure is a frame rate)")
            return (f"{rtf:.3g} x real time, {md.pct(fallen)} fallen; without auto-disable 8 against 20 iterations: "
                    f"{f8:.3g} x against {f20:.3g} x ({100 * (f8 / f20 - 1):+.0f}%)", verdict, how,
                    f"real_time_factor >= {figure:g} and every domino falls",
                    f"test3 --seconds {10 if q else 20} [--no-auto-disable --iterations 8|20]")

        @expect("test4", "step 0.001")
        def test4_fast(reference):
            a = r["t4_3"]
            held = bool(a.m("held"))
            mass, = figures(reference)
            if mass != 5000:
                raise RuntimeError("thesis-figures.csv: test4's run is made at 5000 kg, the row says " + str(mass))
            return (f"5000 kg {'holds' if held else 'falls after ' + format(a.m('seconds_held'), '.3g') + ' s'} for "
                    f"{h4} s (max tilt {a.m('max_tilt_degrees'):.2g} deg, overlap {a.m('max_penetration'):.2g} m)",
                    "differs" if held else "reproduced",
                    f"this build's QuickStep holds the thesis's 5000 kg at step 0.001 with mu "
                    f"{'dInfinity' if a.m('mu_infinite') else a.m('mu')} (see limit-test4 for the limit)"
                    if held else "fails at 5000 kg as the thesis saw",
                    "the thesis's 'fails at 5000 kg' is reproduced when test4's held = 0",
                    f"test4 --big-mass 5000 --step 0.001 --seconds {h4}")

        @expect("test4", "step 0.0001")
        def test4_small(reference):
            if figures(reference) != [15000, 75000]:
                raise RuntimeError("thesis-figures.csv: test4's step-0.0001 runs are made at 15 t, 75 t and twice "
                                   f"that; the row says {reference['figure']}")
            held = {m: bool(r[f"t4_4_{m}"].m("held")) for m in (15000, 75000, 150000)}
            measured = ", ".join(f"{m / 1000:g} t {'holds' if h else 'falls'}" for m, h in held.items())
            if held[15000] and held[75000] and held[150000]:
                verdict, how = "differs", "holds at least twice the thesis's 75 t (see limit-test4 for the limit)"
            elif held[15000] and held[75000]:
                verdict, how = "reproduced", "holds 15 t and 75 t, not twice that"
            elif held[15000]:
                verdict, how = "partly", "holds 15 t, not 75 t"
            else:
                verdict, how = "differs", "does not hold 15 t"
            return (measured + f" for {h4} s", verdict, how,
                    "reproduced when 15 t and 75 t hold and 150 t does not",
                    f"test4 --big-mass M --step 0.0001 --seconds {h4}")

        @expect("test5", "ERP 0.2, CFM 0")
        def test5(reference):
            cost = {(s, n): step_cost(r[f"t5_{s}_{n}"]) for s in ("simple", "hash") for n in (n_small, n_large)}
            slows = cost[("simple", n_large)] > 1.3 * cost[("simple", n_small)]
            hash_helps = cost[("hash", n_large)] < cost[("simple", n_large)] / 1.5
            c = r["t5_cfm"]
            twisted = c.m("max_twist_degrees", 0) > 2 or c.m("max_axis_offset", 0) > 0.1
            verdict = "reproduced" if slows and hash_helps and twisted else (
                "partly" if slows or hash_helps or twisted else "differs")
            measured = (f"ms per step (CPU-share adjusted), simple space: {cost[('simple', n_small)]:.3g} at {n_small} plates, "
                        f"{cost[('simple', n_large)]:.3g} at {n_large}; hash space: {cost[('hash', n_small)]:.3g} / "
                        f"{cost[('hash', n_large)]:.3g}; CFM 1e-4, {n_small} plates: twist "
                        f"{c.m('max_twist_degrees'):.2g} deg, offset {c.m('max_axis_offset'):.2g} m")
            how = (f"slows as it grows: {'yes' if slows else 'no'}; hash space cheaper by 1.5x: "
                   f"{'yes' if hash_helps else 'no'}; CFM 1e-4 twists the stack: {'yes' if twisted else 'no'} "
                   "(see limit-test5 for the heights)")
            return (measured, verdict, how,
                    "slows: ms_per_step (x CPU share) up 30% from the small to the large stack; hash doubles the "
                    "height: hash's below simple's / 1.5; CFM 1e-4 twists: twist > 2 deg or offset > 0.1 m",
                    f"test5 --space simple|hash --plates N --spawn-interval {SPAWN_INTERVAL}; "
                    f"test5 --cfm 1e-4 --plates {n_small}")

        @expect("test6", "defaults")
        def test6(reference):
            a = r["t6"]
            fell = bool(a.m("fell"))
            return (f"falls after {a.m('seconds_upright'):.3g} s" if fell else "stays upright",
                    "reproduced" if fell else "differs",
                    (f"falls after {a.m('seconds_upright'):.3g} s (see remedy-test6 for other seeds and solvers)"
                     if fell else f"stays upright for {a.m('seconds_upright'):.3g} s"),
                    "reproduced when test6's fell = 1", f"test6 --seconds {10 if q else 20}")

        @expect("test7", "defaults")
        def test7(reference):
            a = r["t7"]
            ok = a.rc == 0 and a.m("max_joint_error", 1) < 0.02
            return (f"joints hold to {a.m('max_joint_error'):.3g} m over 3 throws, state finite" if a.rc == 0 else
                    f"the state became non-finite (status {a.rc})",
                    "reproduced" if ok else "differs",
                    f"joints {'hold' if ok else 'do not hold'} within 0.02 m, state {'finite' if a.rc == 0 else 'not finite'}",
                    "max_joint_error < 0.02 m and a finite state", "test7 --max-angular-speed 10 --throws 3")

        @expect("test8", "ERP 0.4, CFM 1e-4")
        def test8_a(reference):
            value = r["t8_a"].m("max_relative_elongation")
            figure, = figures(reference)
            verdict, how = about(value, figure)
            how += f"; the spring estimate F h CFM / ERP gives {estimate(r['t8_a'], 1e-4, 0.4):.3g}"
            return (f"{value:.3g}", verdict, how, f"within a factor {CLOSE} of {figure:g}",
                    f"test8 --erp 0.4 --cfm 1e-4 --seconds {s8}")

        @expect("test8", "ERP 1.0, CFM 0")
        def test8_b(reference):
            value = r["t8_b"].m("max_relative_elongation")
            figure, = figures(reference)
            verdict, how = about(value, figure)
            ratio = r["t8_a"].m("max_relative_elongation") / r["t8_d"].m("max_relative_elongation")
            ratio0 = r["t8_e"].m("max_relative_elongation") / value
            how += f"; ERP 1.0 divides the error of ERP 0.4 by {ratio:.2f} at CFM 1e-4, {ratio0:.2f} at CFM 0 " \
                   "(thesis: halves)"
            return (f"{value:.3g}", verdict, how, f"within a factor {CLOSE} of {figure:g}",
                    f"test8 --erp 1 --cfm 0 --seconds {s8}")

        @expect("test8", "ERP 0.4, CFM 1e-2")
        def test8_c(reference):
            a = r["t8_c"]
            through = a.m("lowest_bob_height_m", 1) < 0
            light, heavy = r["t8_light"].m("max_relative_elongation"), r["t8_heavy"].m("max_relative_elongation")
            mass_note = (f"the thesis saw no dependence on the bob's mass; here CFM 1e-4 stretches 5 kg by "
                         f"{light:.2g} and 1000 t by {heavy:.2g} ({heavy / light:.3g}x)")
            return (f"max elongation {a.m('max_relative_elongation'):.3g}; the bob's lowest point "
                    f"{a.m('lowest_bob_height_m'):.2g} m", "reproduced" if through else "differs",
                    ("goes through the ground" if through else "stays above the ground") + "; " + mass_note,
                    "reproduced when lowest_bob_height_m < 0", f"test8 --cfm 1e-2 --seconds {s8}; "
                    f"test8 --bob-mass 5|1e6 --seconds {s8}")

        @expect("test9", "ERP 0.2 (any), CFM 0")
        def test9_a(reference):
            a = r["t9_0"]
            error = a.m("apex_error_20")
            tolerance, = figures(reference)
            drop = a.m("start_height_m") - a.m("ball_radius_m")
            exact = error is not None and error * drop < tolerance
            return (f"relative apex error after 20 bounces {error:.2g} ({error * drop:.2g} m)",
                    "reproduced" if exact else "differs",
                    f"the 20th apex {error * drop:.2g} m from the start: {'within' if exact else 'beyond'} "
                    f"{tolerance:g} m",
                    f"the 20th apex within {tolerance:g} m of the start (six decimals)", "test9 --erp 0.2 --cfm 0")

        @expect("test9", "CFM 1e-6")
        def test9_b(reference):
            a = r["t9_6"]
            e5, e10, e20 = (a.m(f"apex_error_{n}") for n in (5, 10, 20))
            f5, f10, f20 = figures(reference)
            v5, _ = about(e5, f5)
            v10, _ = about(e10, f10)
            ok20 = e20 > f20
            n_ok = sum([v5 == "reproduced", v10 == "reproduced", ok20])
            verdict = "reproduced" if n_ok == 3 else ("partly" if n_ok else "differs")
            return (f"{md.pct(e5, 2)} / {md.pct(e10, 2)} / {md.pct(e20, 2)}", verdict,
                    f"{e5 / f5:.2g}x / {e10 / f10:.2g}x the thesis's {md.pct(f5)} / {md.pct(f10)}; after 20: "
                    f"{'more' if ok20 else 'less'} than {md.pct(f20)}",
                    f"5 and 10 bounces within a factor {CLOSE} of {md.pct(f5)} and {md.pct(f10)}; 20 bounces above "
                    f"{md.pct(f20)}",
                    "test9 --cfm 1e-6")

        @expect("test10", "step 0.001")
        def test10_a(reference):
            a = r["t10_3"]
            v = a.m("max_velocity")
            band = a.m("velocities_stopped_in_band", 0)
            figure, = figures(reference)
            verdict = "reproduced" if abs(v - figure) <= 1 else "differs"
            how = (f"limit {'equals' if verdict == 'reproduced' else 'differs from'} {figure:g} m/s; not sharp across "
                   f"velocities: above the first failure ({a.m('first_failure_velocity'):.4g} m/s) {int(band)} "
                   f"velocities are stopped again, up to {a.m('highest_stopped_velocity_in_band'):.4g} m/s"
                   if band else "and sharp: no velocity above the first failure is stopped again")
            return (f"{v:.4g} m/s", verdict, how, f"max_velocity within 1 m/s of {figure:g} (the scan's resolution)",
                    "test10 --find-max-velocity --band-factor 1.6")

        @expect("test10", "step 0.0001")
        def test10_b(reference):
            a = r["t10_4"]
            v = a.m("max_velocity")
            figure, = figures(reference)
            verdict, how = about(v, figure)
            highest = a.m("highest_stopped_velocity_in_band")
            how += (f"; the first window of passing velocities is narrow: above it, velocities up to "
                    f"{highest:.4g} m/s are stopped again" if highest else "")
            return (f"{v:.4g} m/s", verdict, how, f"within a factor {CLOSE} of {figure:g} m/s",
                    "test10 --find-max-velocity --step 0.0001 --band-factor 1.6")

        @expect("test0", "defaults")
        def test0_hang(reference):
            a = r["t0_hang"]
            hung, woken = a.m("max_hanging_disabled_bodies"), a.m("hanging_bodies_woken")
            command = f"test0 --seconds {HANG_SECONDS} --spawn-interval 1"
            if hung is None or woken is None:
                return ("-", "not tested", "test0 reported no hanging bodies' metrics", "-", command)
            verdict = "reproduced" if hung >= 1 and woken >= 1 else "differs"
            how = ("a disabled body whose support expired stayed in the air until a falling object touched it"
                   if verdict == "reproduced" else
                   "no disabled body was left hanging" if hung < 1 else
                   "bodies were left hanging, but none was touched and woken in the run")
            return (f"{hung:g} left hanging at once, {woken:g} woken by a touch", verdict, how,
                    "reproduced when max_hanging_disabled_bodies >= 1 and hanging_bodies_woken >= 1 (hanging: "
                    "disabled, no geom within 0.05 m below its lowest point)", command)

        @expect("test2", "ERP 0.4, CFM 1e-4")
        def test2_cfm(reference):
            drift = swing_energy.drift_of_run(r["t2_cfm"])
            drains = drift < -0.01
            return (f"energy at the end {md.pct(drift, 2)} of m g d from the start", "reproduced" if drains else "differs",
                    f"CFM 1e-4 {'drains' if drains else 'does not drain'} more than 1% of m g d in 60 s",
                    "reproduced when (last - first) / (m g d) < -1% (the energy test's failure rule) at CFM 1e-4",
                    "test2 --erp 0.4 --cfm 1e-4 --step 0.001 --seconds 60")

        @expect("test3", "thresholds 0.1/0.1")
        def test3_active(reference):
            on, off = r["t3"], r["t3_8"]
            active_on, active_off = on[0].m("active_bodies"), off[0].m("active_bodies")
            slowest_on = min(x.m("real_time_factor") for x in on)
            fastest_off = max(x.m("real_time_factor") for x in off)
            follows = active_on < active_off and slowest_on > fastest_off
            return (f"{active_on:g} active bodies at the end with auto-disable, {active_off:g} without; real-time "
                    f"factor {slowest_on:.3g} x or more with, {fastest_off:.3g} x at most without",
                    "reproduced" if follows else "differs",
                    f"fewer active bodies {'run' if follows else 'do not run'} faster in every repeat",
                    "reproduced when auto-disable leaves fewer active bodies and its slowest repeat is faster than "
                    "the fastest without (8 iterations both)",
                    f"test3 --seconds {10 if q else 20} [--no-auto-disable --iterations 8]")

        @expect("test7", "defaults")
        def test7_faster(reference):
            a = r["t7"]
            energies = [a.m(f"energy_after_throw_{n}") for n in (1, 2, 3)]
            if None in energies:
                return ("-", "not tested", "test7 reported no energy after a throw", "-", "test7 --throws 3")
            rising = energies[0] < energies[1] < energies[2]
            return (" / ".join(f"{e:.3g} J" for e in energies), "reproduced" if rising else "differs",
                    f"the pair's energy {'grows' if rising else 'does not grow'} with each throw",
                    "reproduced when energy_after_throw_1 < _2 < _3", "test7 --max-angular-speed 10 --throws 3")

        @expect("test8", "ERP 0.4, CFM 1e-2")
        def test8_settles(reference):
            swing, rigid = r["t8_c"].m("swing_last_10s_deg"), r["t8_e"].m("swing_last_10s_deg")
            command = f"test8 --erp 0.4 --cfm 1e-2 --seconds {s8}"
            if swing is None or rigid is None:
                return ("-", "not tested", "test8 reported no swing over its last seconds", "-", command)
            stops = swing < SETTLED_DEG
            how = (f"it stops swinging: {swing:.3g} degrees over the last 10 s" if stops else
                   f"still swinging {swing:.3g} degrees peak to peak over the last 10 s of {s8} s "
                   f"({'damped' if swing < rigid else 'not damped'} against CFM 0's {rigid:.3g})")
            return (f"{swing:.3g} deg peak to peak, last 10 s", "reproduced" if stops else "differs", how,
                    f"reproduced when swing_last_10s_deg < {SETTLED_DEG:g} at CFM 1e-2, ERP 0.4", command)

        @expect("test10", "step 0.001")
        def test10_sharp(reference):
            a = r["t10_3"]
            band = a.m("velocities_stopped_in_band", 0)
            return (f"{band:g} velocities stopped above the first failure ({a.m('first_failure_velocity'):.4g} m/s)",
                    "reproduced" if band == 0 else "differs",
                    "sharp" if band == 0 else f"not sharp: stopped again up to "
                    f"{a.m('highest_stopped_velocity_in_band'):.4g} m/s",
                    "reproduced when no velocity up to 1.6x the first failure is stopped",
                    "test10 --find-max-velocity --band-factor 1.6")

        @expect("test10", "step 0.001")
        def test10_settings(reference):
            base = r["t10_3"].m("max_velocity")
            moved = {label: r[f"t10_{label}"].m("max_velocity") for label in TEST10_SETTINGS}
            still = all(abs(v - base) <= 1 for v in moved.values())
            return (", ".join(f"{label.replace('_', ' ')}: {v:.4g} m/s" for label, v in moved.items()),
                    "reproduced" if still else "differs",
                    f"{'none moves' if still else 'some move'} the limit ({base:.4g} m/s at the defaults) by more "
                    "than the scan's 1 m/s", "reproduced when every setting's limit is within 1 m/s of the default's",
                    "test10 --find-max-velocity --band-factor 1.6 --iterations 5|50 | --sor 1 | --erp 0.1|0.9")

        def claim(key, function):
            def judge(reference):
                if reference["test"] != key.split("_")[0]:
                    raise RuntimeError(f"thesis-figures.csv changed: expected a {key.split('_')[0]} row for {key}, "
                                       f"found {reference['test']} '{reference['conditions']}'")
                return function(reference)
            return judge

        return [test1, test2, test3, test4_fast, test4_small, test5, test6, test7, test8_a, test8_b, test8_c,
                test9_a, test9_b, test10_a, test10_b, test0_hang, test2_cfm, test3_active, test7_faster,
                test8_settles, test10_sharp, test10_settings] + [
            claim(key, function) for key, function in zip(claims.KEYS, claims.judges(r, q, s8))]

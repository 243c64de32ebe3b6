"""Unit checks of the world report's rules (lab/odelab-report --world) on
made-up rows: deviations per measurement rule, the cheapest setting within a
tolerance (ties within the timing's scatter), the stability limit along the
step, and the first screen's sentences read from CSVs.
Run: /usr/bin/python3 -m unittest discover -s lab/tests (CTest: lab_executor_units)."""

import math
import shutil
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report import csvout, world_first_screen as wfs, world_measures as wm  # noqa: E402
from odelab_report.claims import Data, Sentences  # noqa: E402
from odelab_report.world_rules import cheapest_within, passes_bound, step_limit  # noqa: E402

HEADER = [("ODE", "test")]


def row(name, dev, cost, low=None, high=None, **more):
    return dict(setting=name, max_dev=dev, engine_s_per_sim_s=cost, engine_s_per_sim_s_min=low or cost,
                engine_s_per_sim_s_max=high or cost, **more)


class Deviations(unittest.TestCase):
    def test_relative_absolute_count(self):
        period = wm.Measurement("swing_period_s", "period", wm.RELATIVE)
        self.assertAlmostEqual(period.deviation(2.02, 2.0), 0.01)
        drift = wm.Measurement("energy_drift", "energy", wm.ABSOLUTE, 1.0)
        # reference about 0: the difference against the scale, not against the reference
        self.assertAlmostEqual(drift.deviation(0.004, 1e-9), 0.004 - 1e-9)
        count = wm.Measurement("tunnelled_bodies", "tunnelling", wm.COUNT, 1.0)
        self.assertEqual(count.deviation(1, 1), 0)
        self.assertGreater(count.deviation(2, 1), 0.01)

    def test_missing_value_or_reference(self):
        rest = wm.Measurement("time_to_rest_s", "rest", wm.RELATIVE)
        self.assertEqual(rest.deviation(None, 3.0), math.inf)  # the run never came to rest
        self.assertIsNone(rest.deviation(3.0, None))  # no reference: not judged
        self.assertIsNone(wm.max_deviation([None, None]))
        self.assertEqual(wm.max_deviation([0.1, None, 0.3]), 0.3)

    def test_measurements_from_the_world(self):
        world = {"geoms": [{"shape": "plane", "body": -1}, {"shape": "box", "body": 0, "size": [0.2, 0.5, 1]},
                           {"shape": "sphere", "body": 1, "radius": 0.3}],
                 "measures": [{"kind": "energy"}, {"kind": "joint_error"},
                              {"kind": "period", "name": "swing", "body": 0}]}
        found = {m.name: m for m in wm.measurements(world)}
        self.assertEqual(list(found), ["energy_max_deviation", "energy_drift", "joint_error_max_m",
                                       "joint_axis_error_max_rad", "swing_period_s"])
        self.assertEqual(found["joint_error_max_m"].scale, 0.2)  # the smallest geom on a body
        self.assertEqual(found["swing_period_s"].rule, wm.RELATIVE)
        fallback = wm.measurements({"geoms": []})
        self.assertEqual([m.name for m in fallback], wm.FALLBACK)
        kept, absent = wm.from_metrics(world, {"energy_drift": 0.0, "energy_max_deviation": 0.0})
        self.assertEqual([m.name for m in kept], ["energy_max_deviation", "energy_drift"])
        self.assertIn("swing_period_s", absent)


class Cheapest(unittest.TestCase):
    def test_cheapest_within_and_ties(self):
        rows = [row("fine", 0.0, 10.0, 9.0, 11.0), row("mid", 0.005, 1.0, 0.9, 1.2),
                row("tied", 0.008, 1.1, 1.15, 1.3), row("coarse", 0.05, 0.1), row("blown", None, None)]
        self.assertEqual(cheapest_within(rows, 0.01), [1, 2])  # 'tied''s fastest run is not slower than mid's slowest
        self.assertEqual(cheapest_within(rows, 0.001), [0])
        self.assertEqual(cheapest_within(rows, 0.1), [3])
        self.assertEqual(cheapest_within([row("blown", None, None)], 0.01), [])

    def test_no_tie_outside_the_scatter(self):
        rows = [row("a", 0.001, 1.0, 0.95, 1.05), row("b", 0.001, 1.2, 1.1, 1.3)]
        self.assertEqual(cheapest_within(rows, 0.01), [0])


class StepLimit(unittest.TestCase):
    def test_bracketed(self):
        self.assertEqual(step_limit([(0.001, True), (0.004, True), (0.016, False), (0.008, False)]), (0.004, 0.008))

    def test_none_fails_or_all_fail(self):
        self.assertEqual(step_limit([(0.001, True), (0.1, True)]), (0.1, None))
        self.assertEqual(step_limit([(0.001, False), (1e-5, False)]), (None, 1e-5))

    def test_a_pass_above_the_first_failure_is_not_the_limit(self):
        self.assertEqual(step_limit([(0.001, True), (0.01, False), (0.05, True)]), (0.001, 0.01))

    def test_bound(self):
        self.assertTrue(passes_bound(0, 0.05))
        self.assertFalse(passes_bound(0, 0.2))
        self.assertFalse(passes_bound(3, None))
        self.assertFalse(passes_bound(0, None))


class FirstScreen(unittest.TestCase):
    def setUp(self):
        self.folder = Path(tempfile.mkdtemp(prefix="world-report-test-"))

    def tearDown(self):
        shutil.rmtree(self.folder)

    def write(self, name, rows):
        csvout.write_csv(self.folder / name, HEADER, list(rows[0].keys()), rows)

    def say(self, alternatives):
        sentences = Sentences(Data(self.folder))
        return sentences.say(*alternatives)

    def sweep(self, own_dev=0.02):
        self.write(wfs.SWEEP, [row("dWorldStep @ 0.0001", 0.0, 1.0, 0.9, 1.1, own=0, solver="dWorldStep",
                                   exit_status=0),
                               row("QuickStep 20 @ 0.001", own_dev, 0.1, 0.09, 0.11, own=1, solver="QuickStep 20",
                                   exit_status=0),
                               row("QuickStep 20 @ 0.0003", 0.005, 0.3, 0.28, 0.32, own=0, solver="QuickStep 20",
                                   exit_status=0)])

    def test_own_and_cheapest(self):
        self.sweep()
        self.assertEqual(self.say(wfs.own_setting()), "At its own settings (QuickStep 20 @ 0.001) the world stays "
                         "within 2% of the reference, at 0.1 [0.09-0.11] engine s per simulated s.")
        self.assertEqual(self.say([wfs.cheapest(0.01)]), "Cheapest within 1% of the reference on every "
                         "measurement: QuickStep 20 @ 0.0003 (0.3 s/s).")
        self.assertEqual(self.say([wfs.cheapest(0.001)]), "Cheapest within 0.1% of the reference on every "
                         "measurement: dWorldStep @ 0.0001 (1 s/s).")

    def test_a_long_tie_is_counted(self):
        self.write(wfs.SWEEP, [row(f"s{i}", 0.001, 1.0 + i / 100, 0.5, 2.0, own=int(i == 3)) for i in range(5)])
        self.assertEqual(self.say([wfs.cheapest(0.01)]), "Cheapest within 1% of the reference on every measurement: "
                         "a tie within the timing's scatter: s3 (1 s/s), s0 (1 s/s), s1 (1 s/s) and 2 more.")

    def test_erp_span(self):
        self.write(wfs.SWEEP, [dict(setting="a", erp=0.1, in_erp=1, max_dev=0.02),
                               dict(setting="b", erp=0.4, in_erp=1, max_dev=0.005),
                               dict(setting="c", erp=1.0, in_erp=1, max_dev=None),
                               dict(setting="d", erp=0.4, in_erp=0, max_dev=0.5)])
        self.assertEqual(self.say([wfs.knob("erp", "ERP")]), "ERP from 0.1 to 1: the largest deviation spans 0.5% "
                         "to 2%, the least at ERP 0.4; no figure at 1 of them (blown up or a measurement missing).")

    def test_own_missing_measurement(self):
        self.sweep(own_dev=math.inf)
        self.assertIn("is missing", self.say(wfs.own_setting()))

    def limits(self, probes):
        self.sweep()
        self.write(wfs.LIMIT, [dict(search=s, step_s=h, passed=int(p)) for s, h, p in probes])

    def test_limit_bracketed(self):
        self.limits([("blow-up", 0.001, True), ("blow-up", 0.004, True), ("blow-up", 0.016, False),
                     ("blow-up", 0.008, False), ("bound", 0.001, True), ("bound", 0.1, True)])
        self.assertEqual(self.say(wfs.limit("blow-up")), "Along the step (QuickStep 20, the world's ERP and CFM) it "
                         "blows up (status 3) at 0.008 s; the largest step below that runs is 0.004 s.")
        self.assertEqual(self.say(wfs.limit("bound")), "Along the step (QuickStep 20) nothing departs from the "
                         "reference by more than 10% up to 0.1 s, the largest step tried.")

    def test_limit_fails_everywhere(self):
        self.limits([("blow-up", 0.001, False), ("blow-up", 0.00025, False), ("bound", 0.001, False)])
        self.assertEqual(self.say(wfs.limit("blow-up")), "Along the step (QuickStep 20) it blows up (status 3) "
                         "even at 0.00025 s, the smallest step tried.")

    def engines(self, rows, kinds=("analytic", "conservation")):
        self.write(wfs.ENGINES, [dict(engine=e, setting=s, status=st, max_dev=d, engine_s_per_sim_s=c)
                                 for e, s, st, d, c in rows])
        self.write(wfs.MEASURES, [dict(measurement=f"m{i}", reference_kind=k) for i, k in enumerate(kinds)])

    def test_engine_best_beyond_the_spread_or_a_tie(self):
        self.engines([("ode", "default", "ran", 0.02, 0.1), ("ode", "best", "ran", 0.015, 0.3),
                      ("bullet", "default", "ran", 0.05, 0.2), ("bullet", "best", "ran", 0.001, 0.5),
                      ("jolt", "default", "missing", None, None), ("jolt", "best", "missing", None, None)])
        self.assertEqual(self.say(wfs.engines()), "Closest to each measurement's reference (analytic, conservation; "
                         "world-measures.csv) at the world's step: bullet (best), largest deviation 0.1%, ahead of "
                         "every other engine and setting by more than 0.1%, at 0.5 engine s per simulated s; ODE at "
                         "the world's settings: 2%.")
        # 0.05% apart: within the spread, so no one engine is named
        self.engines([("ode", "default", "ran", 0.0010, 0.1), ("bullet", "default", "ran", 0.0015, 0.2),
                      ("mujoco", "default", "ran", 0.05, 0.2)])
        self.assertEqual(self.say(wfs.engines()), "No engine is closest alone to each measurement's reference "
                         "(analytic, conservation; world-measures.csv) at the world's step: a tie within 0.1%: "
                         "ode (default, 0.1%), bullet (default, 0.15%).")

    def test_ode_missing_a_measurement(self):
        self.engines([("ode", "default", "ran", math.inf, 0.1), ("bullet", "default", "ran", 0.05, 0.2)])
        self.assertIn("bullet (default), largest deviation 5%", self.say(wfs.engines()))
        self.engines([("ode", "default", "ran", math.inf, 0.1), ("bullet", "default", "ran", math.inf, 0.2)])
        self.assertIn("No engine ran the world with every measurement", self.say(wfs.engines()))

    def test_no_other_engine_ran(self):
        self.engines([("ode", "default", "ran", 0.001, 0.1), ("ode", "best", "ran", 0.0, 0.2),
                      ("havok", "default", "refused", None, None), ("havok", "best", "refused", None, None)])
        self.assertEqual(self.say(wfs.engines()), "No other engine ran the world (1 listed; world-engines.csv "
                         "says why).")


if __name__ == "__main__":
    unittest.main()

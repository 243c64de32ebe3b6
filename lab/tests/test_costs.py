"""The three costs (costs.py): each read from its own metric, per simulated
second, and a comparison that mixes two of them refused by name."""

import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report import costs  # noqa: E402


class Run:
    def __init__(self, rc=0, cpu_seconds=None, **metrics):
        self.rc, self.cpu_seconds, self.metrics = rc, cpu_seconds, metrics

    def m(self, name, default=None):
        return self.metrics.get(name, default)


class Costs(unittest.TestCase):
    def test_each_cost_reads_its_own_measure(self):
        run = Run(cpu_seconds=3.0, engine_wall_seconds=1.0, link_wall_seconds=0.5, sim_seconds=2.0, steps=2000)
        self.assertEqual(costs.per_sim_second(run, costs.ENGINE), 0.5)
        self.assertEqual(costs.per_sim_second(run, costs.LINK), 0.25)
        self.assertEqual(costs.per_sim_second(run, costs.WHOLE_RUN), 1.5)
        self.assertEqual(costs.per_step(run, costs.ENGINE), 0.0005)

    def test_columns_are_named_by_their_definition(self):
        runs = [Run(cpu_seconds=c, engine_wall_seconds=e, link_wall_seconds=0.0, sim_seconds=1.0)
                for c, e in ((2.0, 0.2), (3.0, 0.3), (4.0, 0.1))] + [Run(rc=3, cpu_seconds=99.0, sim_seconds=1.0)]
        out = costs.columns(runs)
        self.assertEqual((out["engine_s_per_sim_s"], out["engine_s_per_sim_s_min"], out["engine_s_per_sim_s_max"]),
                         (0.2, 0.1, 0.3))
        self.assertEqual(out["cpu_s_per_sim_s_max"], 4.0)  # the failed run is not timed
        for column in out:
            self.assertIn(costs.definition_of(column), costs.DEFINITIONS)

    def test_a_comparison_of_two_kinds_is_refused(self):
        self.assertEqual(costs.one_definition([("ode", costs.ENGINE), ("havok", costs.ENGINE)]), costs.ENGINE)
        with self.assertRaisesRegex(ValueError, "whole run: havok"):
            costs.one_definition([("ode", costs.ENGINE), ("havok", costs.WHOLE_RUN)])
        with self.assertRaisesRegex(ValueError, "not a cost column"):
            costs.definition_of("ms_per_step")


class RealTimeAcrossEngines(unittest.TestCase):
    def test_every_engine_is_held_to_its_own_calls(self):
        from odelab_report.experiments import limit_test5
        # A Node.js engine's program spends little CPU of its own (the engine
        # works in the other process): by the program's CPU it keeps up, by
        # the engine's own calls it does not.
        run = Run(cpu_seconds=1.0, ms_per_step=2.5, cpu_ms_per_step=0.2, threads=1, plate_thickness_m=0.1,
                  stack_height=4.0, max_axis_offset=0.0, max_twist_degrees=0.0)
        self.assertTrue(limit_test5.judge(run, 40, 0.001)[0])
        passed, reason = limit_test5.judge(run, 40, 0.001, cost=limit_test5.engine_step_cost)
        self.assertFalse(passed)
        self.assertEqual(reason, "2.5 ms per step")


if __name__ == "__main__":
    unittest.main()

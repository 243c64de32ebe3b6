"""What the world report grades each measurement against (world_reference.py)
and how it ranks engines, on worlds of known answer written here
(lab/tests/worlds/): an engine that is exact must never be ranked below one
that is not. The engines' figures are made up in the shape odelab gives them,
each the kind of error the engines were seen to make (a sub-step shift, a
collision that loses energy, a block that sticks above its friction angle).
Run: /usr/bin/python3 -m unittest discover -s lab/tests."""

import json
import math
import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report import world_measures as wm  # noqa: E402
from odelab_report import world_reference as wr  # noqa: E402
from odelab_report.claims import best_or_tie  # noqa: E402
from odelab_report.world_first_screen import ACCURACY_SPREAD  # noqa: E402

WORLDS = Path(__file__).resolve().parent / "worlds"


def world(name):
    return json.loads((WORLDS / f"{name}.json").read_text())


def graded(w, metrics, finer, step):
    """An engine's largest deviation, as the report grades it."""
    devs = []
    for m in wm.measurements(w):
        dev, _ = wr.grade(w, m, wr.reference_of(w, m), metrics.get(m.name), finer.get(m.name), step)
        devs.append(dev)
    return wm.max_deviation(devs)


def ranking(devs):
    """best_or_tie over finite deviations, as the first screen ranks them."""
    names = [n for n, d in devs.items() if d is not None and math.isfinite(d)]
    order = best_or_tie([devs[n] for n in names], [devs[n] - ACCURACY_SPREAD / 2 for n in names],
                        [devs[n] + ACCURACY_SPREAD / 2 for n in names])
    return [names[i] for i in order]


class References(unittest.TestCase):
    def test_elastic_collision_is_graded_by_conservation(self):
        w = world("elastic_unequal_spheres")
        kinds = {m.name: wr.reference_of(w, m).kind for m in wm.measurements(w)}
        self.assertEqual(kinds, {"energy_max_deviation": wr.CONSERVATION, "energy_drift": wr.CONSERVATION,
                                 "linear_momentum_drift": wr.CONSERVATION, "angular_momentum_drift": wr.CONSERVATION})

    def test_friction_or_gravity_leave_self_consistency(self):
        w = world("elastic_unequal_spheres")
        w["surfaces"][0]["mu"] = 0.5  # friction may take energy out
        w["settings"]["gravity"] = [0, -9.81, 0]  # an outside force
        kinds = {m.name: wr.reference_of(w, m).kind for m in wm.measurements(w)}
        self.assertEqual(set(kinds.values()), {wr.SELF})

    def test_incline_expectations_are_analytic(self):
        for name, outcome in (("incline_below_friction_angle", "stays"), ("incline_above_friction_angle", "slides")):
            w = world(name)
            (m,) = wm.measurements(w)
            self.assertEqual(wr.reference_of(w, m).kind, wr.ANALYTIC)
            self.assertEqual(wr.expected_outcome(m), outcome)

    def test_a_time_within_one_step_is_the_steps_resolution(self):
        w = world("incline_below_friction_angle")
        (m,) = wm.measurements(w)
        w["measures"][0]["expect"] = 1.0
        ref = wr.reference_of(w, m)
        self.assertEqual(wr.grade(w, m, ref, 1.0008, None, 0.001), (0.0, True))  # under one step late
        dev, artefact = wr.grade(w, m, ref, 1.02, None, 0.001)
        self.assertFalse(artefact)
        self.assertAlmostEqual(dev, 0.02)


class Probes(unittest.TestCase):
    def test_a_probe_with_expect_is_graded_against_the_worlds_answer(self):
        w = world("head_on_probes")
        ms = {m.name: m for m in wm.measurements(w)}
        self.assertEqual(list(ms), ["v0_after_value", "v1_after_value", "passes_value"])
        self.assertEqual({n: wr.reference_of(w, m).kind for n, m in ms.items()}, dict.fromkeys(ms, wr.ANALYTIC))
        # An answer other than 0: relative to it (1% of 2 m/s is 0.02 m/s).
        m = ms["v1_after_value"]
        self.assertAlmostEqual(wr.grade(w, m, wr.reference_of(w, m), 1.98, None, 0.001)[0], 0.01)
        # An answer of 0 has no size: the probe's own tolerance counts as 1% (half of it: 0.5%).
        m = ms["v0_after_value"]
        self.assertAlmostEqual(wr.grade(w, m, wr.reference_of(w, m), 0.005, None, 0.001)[0], 0.005)
        # A crossing time within one step of the answer is the step's timing, not an error.
        m = ms["passes_value"]
        self.assertEqual(wr.grade(w, m, wr.reference_of(w, m), 0.6508, None, 0.001), (0.0, True))
        # A probe that never read (the crossing never came) is as far as can be.
        self.assertEqual(wr.grade(w, m, wr.reference_of(w, m), None, None, 0.001), (math.inf, False))

    def test_a_probe_without_expect_is_its_engines_own_finer_run(self):
        w = world("head_on_probes")
        del w["measures"][1]["expect"], w["measures"][1]["tolerance"]
        m = [m for m in wm.measurements(w) if m.name == "v1_after_value"][0]
        self.assertEqual(wr.reference_of(w, m).kind, wr.SELF)
        self.assertAlmostEqual(wr.grade(w, m, wr.reference_of(w, m), 1.9, 2.0, 0.001)[0], 0.05)

    def test_exact_velocities_outrank_a_lossy_collision(self):
        w = world("head_on_probes")
        exact = dict(v0_after_value=0.0, v1_after_value=2.0, passes_value=0.6504)
        lossy = dict(v0_after_value=0.001, v1_after_value=1.997, passes_value=0.6511)  # 0.15% lost
        devs = {"lossy": graded(w, lossy, lossy, 0.001), "exact": graded(w, exact, exact, 0.001)}
        self.assertEqual(devs["exact"], 0.0)
        self.assertAlmostEqual(devs["lossy"], 0.0017, places=4)  # the crossing 1.1 ms late, out of 0.65 s
        self.assertEqual(ranking(devs), ["exact"])


class ExactIsNeverRankedBelow(unittest.TestCase):
    def test_elastic_collision(self):
        w = world("elastic_unequal_spheres")
        # 'exact' keeps energy and momentum; 'lossy' loses 0.3% of the energy at the impact
        # and 0.15% of the momentum (its contact acts before the spheres meet).
        exact = dict(energy_max_deviation=0.0, energy_drift=0.0, linear_momentum_drift=0.0, angular_momentum_drift=0.0)
        lossy = dict(energy_max_deviation=0.003, energy_drift=-0.003, linear_momentum_drift=0.0015,
                     angular_momentum_drift=0.0)
        devs = {"exact": graded(w, exact, exact, 0.001), "lossy": graded(w, lossy, lossy, 0.001)}
        self.assertEqual(ranking(devs), ["exact"])

    def test_the_engines_own_finer_run_not_anothers(self):
        w = world("elastic_unequal_spheres")
        w["surfaces"][0]["mu"] = 0.5  # self-consistency: each against its own finer run
        # 'steady' gives the same drift at both steps (converged); 'unsteady' moves by 2% with the step.
        steady = dict(energy_max_deviation=0.01, energy_drift=-0.01, linear_momentum_drift=0.0,
                      angular_momentum_drift=0.0)
        unsteady = dict(steady, energy_drift=-0.03)
        devs = {"steady": graded(w, steady, steady, 0.001), "unsteady": graded(w, unsteady, steady, 0.001)}
        self.assertEqual(ranking(devs), ["steady"])

    def test_a_block_that_sticks_above_its_friction_angle_is_not_ranked(self):
        above, below = world("incline_above_friction_angle"), world("incline_below_friction_angle")
        # 'exact' slides above the angle (never at rest) and stays below it (at rest from the start);
        # 'sticky' stays on both.
        exact = {"above": graded(above, {"time_to_rest_s": None}, {}, 0.001),
                 "below": graded(below, {"time_to_rest_s": 0.0}, {}, 0.001)}
        sticky = {"above": graded(above, {"time_to_rest_s": 0.0}, {}, 0.001),
                  "below": graded(below, {"time_to_rest_s": 0.0}, {}, 0.001)}
        self.assertEqual(exact, {"above": 0.0, "below": 0.0})
        self.assertEqual(sticky["above"], math.inf)
        self.assertEqual(ranking({"exact": exact["above"], "sticky": sticky["above"]}), ["exact"])
        (m,) = wm.measurements(above)
        self.assertEqual((wr.outcome_words(m, 0.0), wr.outcome_words(m, None)), ("stays", "slides"))


class BestOrTie(unittest.TestCase):
    def test_named_only_beyond_the_spread(self):
        self.assertEqual(best_or_tie([0.5, 0.1, 0.9], [0.4, 0.05, 0.8], [0.6, 0.15, 1.0]), [1])
        self.assertEqual(best_or_tie([0.5, 0.1, 0.12], [0.4, 0.05, 0.11], [0.6, 0.15, 0.13]), [1, 2])
        self.assertEqual(best_or_tie([None, 0.2], [None, 0.2], [None, 0.2]), [1])
        self.assertEqual(best_or_tie([None], [None], [None]), [])


if __name__ == "__main__":
    unittest.main()

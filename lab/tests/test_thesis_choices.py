"""The thesis's stated settings are never 'reproduced with' another value."""

import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report.experiments import thesis_choices as choices  # noqa: E402
from odelab_report.runner import RunSpec  # noqa: E402


class FakeResult:
    def __init__(self, value):
        self.value = value

    def m(self, name, default=None):
        return self.value if name == "max_relative_elongation" else default


class StatedStep(unittest.TestCase):
    def test_test8_step_is_stated_by_section_5_9(self):
        # Section 5.9: test8 is test2 with a heavier bob, so chapter 5's
        # step 0.001 is the thesis's own setting, not an unstated choice.
        self.assertTrue(choices.stated_by_thesis("test8", "step"))

    def test_another_step_reproducing_the_figure_is_not_a_reproduction(self):
        base = RunSpec("test8", ["--erp", 0.4, "--cfm", 1e-4])
        sweep = choices.Sweep("test8_a", "step", base, [("step 0.0001", ["--step", 0.0001])],
                              lambda r: ("1e-3", True))
        said, reproducing = sweep.summary({"sweep:test8_a:step:step 0.0001": FakeResult(1e-3)})
        self.assertEqual(reproducing, [])
        self.assertIn("never a reproduction", said)


if __name__ == "__main__":
    unittest.main()

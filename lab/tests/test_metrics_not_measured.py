"""The programs' one rule for metrics that are not finite numbers
(utils/Metrics.h, doc/manual.md "Outputs"), as the lab
reads it: null is a metric not measured (no figure, not a failure); a
measured NaN or infinity, written "nan", "inf" or "-inf", is never taken for
a number, and a run that gives one as a result is refused naming the metric.
Run: /usr/bin/python3 -m unittest discover -s lab/tests -p test_metrics_not_measured.py
(CTest: lab_metrics_not_measured_or_not_finite)."""

import json
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report.runner import LabError, RunResult, RunSpec  # noqa: E402

# As test2 writes them (Metrics::toJson): a short run has no period yet.
WRITTEN = """{
  "steps": 50,
  "sim_seconds": 0.05,
  "wall_seconds": 0.01,
  "non_finite": 0,
  "period_seconds": null,
  "energy_drift": %s
}
"""


def run_with(energy_drift, folder):
    spec = RunSpec("test2", ["--seconds", "0.05"])
    metrics = json.loads(WRITTEN % energy_drift)
    return spec, RunResult(spec, 0, metrics, "", "", 0.01, folder, "here")


class MetricsNotMeasuredOrNotFinite(unittest.TestCase):
    def setUp(self):
        self._folder = tempfile.TemporaryDirectory()
        self.folder = self._folder.name

    def tearDown(self):
        self._folder.cleanup()

    def test_not_measured_is_no_figure_and_no_failure(self):
        spec, result = run_with("0.001", self.folder)
        result.check(spec)  # no LabError
        self.assertIsNone(result.m("period_seconds"))
        self.assertEqual(result.m("energy_drift"), 0.001)

    def test_a_measured_nan_is_refused_naming_the_metric(self):
        for written in ('"nan"', '"inf"', '"-inf"'):
            spec, result = run_with(written, self.folder)
            with self.assertRaises(LabError) as refused:
                result.check(spec)
            self.assertIn("energy_drift = " + written.strip('"'), str(refused.exception))
            self.assertNotIn("period_seconds", str(refused.exception))

    def test_a_measured_nan_is_never_a_number(self):
        spec, result = run_with('"nan"', self.folder)
        self.assertIsNone(result.m("energy_drift"))
        self.assertEqual(result.m("energy_drift", 0.0), 0.0)


if __name__ == "__main__":
    unittest.main()

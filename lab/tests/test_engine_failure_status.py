"""An engine that failed (status 7: its Node.js process died, answered
nonsense, missed a deadline) is never read as physics: RunResult.check
refuses it even for an experiment that counts blow-ups (the peers'
searches), where a blow-up (status 3) is a result.
Run: /usr/bin/python3 -m unittest discover -s lab/tests -p test_engine_failure_status.py
(CTest: lab_engine_failure_not_physics)."""

import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report.runner import LabError, RunResult, RunSpec  # noqa: E402

METRICS = {"steps": 10, "sim_seconds": 0.01, "wall_seconds": 0.01, "non_finite": 0, "engine_failed": 1}


def result(rc, spec):
    stderr = "error: engine jolt failed: Jolt's Node.js engine server ended while answering 'step' (killed by signal 9)"
    return RunResult(spec, rc, METRICS, "", stderr, 0.01, "/nonexistent", "here")


class EngineFailureIsNotPhysics(unittest.TestCase):
    def test_a_search_that_counts_blow_ups_refuses_an_engine_failure(self):
        spec = RunSpec("test10", ["--engine", "jolt"], measures_blow_ups=True)
        with self.assertRaises(LabError) as refused:
            result(7, spec).check(spec)
        self.assertIn("the engine failed", str(refused.exception))
        self.assertIn("never counted as a blow-up", str(refused.exception))
        self.assertFalse(result(7, spec).blew_up)

    def test_a_blow_up_is_still_a_result_where_blow_ups_are_counted(self):
        spec = RunSpec("test10", ["--engine", "jolt"], measures_blow_ups=True)
        result(3, spec).check(spec)  # no LabError: the search's rule counts it

    def test_an_experiment_without_blow_ups_names_the_engine_failure(self):
        spec = RunSpec("test2", ["--engine", "jolt"])
        with self.assertRaises(LabError) as refused:
            result(7, spec).check(spec)
        self.assertIn("not a physics result", str(refused.exception))


if __name__ == "__main__":
    unittest.main()

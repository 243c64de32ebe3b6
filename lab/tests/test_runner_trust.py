"""Unit checks of what the runner trusts: a run's status, counts and values
are checked in one place (RunResult.check) before an experiment sees them;
a timed run is a new process every time it is asked for, and timed repeats
that come back identical fail; a run's whole process group ends with it;
and no run waits for a slot that can never come.
Run: /usr/bin/python3 -m unittest discover -s lab/tests (CTest: lab_executor_units)."""

import json
import os
import sys
import tempfile
import threading
import time
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report.executors.local_executor import LocalExecutor  # noqa: E402
from odelab_report.runner import LabError, Runner, RunSpec, Slots  # noqa: E402

GOOD = {"steps": 100, "sim_seconds": 0.1, "wall_seconds": 0.01, "non_finite": 0, "energy_J": 1.5}


class ScriptedExecutor:
    """Stands in for an executor: each run writes `metrics` (and `files`)
    into its folder and ends with `rc`; counts the runs it was asked for."""

    cores = 4
    description = "scripted"
    timing_host = "here"

    def __init__(self, rc=0, metrics=None, files=None):
        self.rc, self.metrics, self.files = rc, GOOD if metrics is None else metrics, files or {}
        self.calls = 0
        self._lock = threading.Lock()

    def execute(self, argv, folder, timeout, timed):
        with self._lock:  # runs come from several threads at once
            self.calls += 1
            number = self.calls
        folder = Path(folder)
        (folder / "stdout.txt").write_text("")
        (folder / "stderr.txt").write_text("scripted\n")
        metrics = self.metrics(number) if callable(self.metrics) else self.metrics
        # json.dumps writes NaN and Infinity as the programs' JSON would carry them.
        (folder / "metrics.json").write_text(json.dumps(metrics))
        for name, text in self.files.items():
            (folder / name).write_text(text)
        return dict(rc=self.rc, cpu_seconds=0.01, host="here")

    def abort(self):
        pass

    def close(self):
        pass


class RunnerCase(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory()
        self.tmp = Path(self._tmp.name)
        self.runners = []

    def tearDown(self):
        for runner in self.runners:
            runner.close()
        self._tmp.cleanup()

    def runner(self, executor, build_dir=None):
        runner = Runner(build_dir or self.tmp, 2, self.tmp, executor, retry=False)
        self.runners.append(runner)
        return runner

    def refused(self, executor, spec, *words):
        with self.assertRaises(LabError) as caught:
            self.runner(executor).run(spec)
        for word in words:
            self.assertIn(word, str(caught.exception))
        return str(caught.exception)


class EveryResultChecked(RunnerCase):
    def test_a_blow_up_is_refused_where_the_experiment_does_not_measure_blow_ups(self):
        message = self.refused(ScriptedExecutor(rc=3), RunSpec("test2", ["--seconds", 1]),
                               "test2 --seconds 1", "blew up (status 3", "does not measure blow-ups")
        self.assertNotIn("Traceback", message)

    def test_an_ode_error_is_refused_there_too(self):
        self.refused(ScriptedExecutor(rc=4), RunSpec("test2", []), "ODE error (status 4)")

    def test_a_blow_up_is_a_result_where_the_experiment_measures_blow_ups(self):
        result = self.runner(ScriptedExecutor(rc=3, metrics={"steps": 5, "energy_J": float("nan")})).run(
            RunSpec("test4", [], measures_blow_ups=True))
        self.assertTrue(result.blew_up)

    def test_a_shared_run_is_judged_for_each_experiment(self):
        runner = self.runner(ScriptedExecutor(rc=3))
        runner.run(RunSpec("test4", ["--big-mass", 9], measures_blow_ups=True))
        with self.assertRaises(LabError) as caught:
            runner.run(RunSpec("test4", ["--big-mass", 9]))  # the same run, from the cache
        self.assertIn("does not measure blow-ups", str(caught.exception))

    def test_non_finite_metrics_are_refused(self):
        for value in (float("nan"), float("inf"), float("-inf")):
            self.refused(ScriptedExecutor(metrics=dict(GOOD, energy_max_J=value)), RunSpec("test2", []),
                         "metrics are not finite", f"energy_max_J = {value!r}")

    def test_nested_non_finite_metrics_are_refused(self):
        self.refused(ScriptedExecutor(metrics=dict(GOOD, apexes=[0.1, float("nan")])), RunSpec("test9", []),
                     "apexes[1] = nan")

    def test_a_non_finite_count_is_refused(self):
        self.refused(ScriptedExecutor(metrics=dict(GOOD, non_finite=2)), RunSpec("test2", []),
                     "counted 2 non-finite values")

    def test_a_run_without_a_step_is_refused(self):
        self.refused(ScriptedExecutor(metrics=dict(GOOD, steps=0)), RunSpec("test2", []), "took no step")

    def test_a_non_finite_number_in_an_output_file_is_refused(self):
        output = "# test2, ODE 0.16\n# note: inf is only a word here\ntime_s\ttotal_J\n0\t1.5\n0.02\tnan\n"
        self.refused(ScriptedExecutor(files={"Test2_output.txt": output}), RunSpec("test2", []),
                     "Test2_output.txt line 5 holds a non-finite number")

    def test_finite_output_files_pass(self):
        output = "# infinite care\ntime_s\tinfo_J\n0\t1.5e+00\n0.02\t-1.5E-3\n"
        result = self.runner(ScriptedExecutor(files={"Test2_output.txt": output})).run(RunSpec("test2", []))
        self.assertEqual(result.rc, 0)

    def test_another_status_is_refused_with_the_programs_message(self):
        self.refused(ScriptedExecutor(rc=1), RunSpec("test2", []), "exited with status 1", "scripted")


class TimedRunsAreNewRuns(RunnerCase):
    PROGRAM = """#!/bin/sh
# Its metrics carry its own process id: two runs are two processes.
echo "{\\"steps\\": 10, \\"sim_seconds\\": 0.01, \\"wall_seconds\\": 0.$$, \\"pid\\": $$}" >metrics.json
"""

    def test_repeats_of_one_timed_spec_launch_new_processes(self):
        program = self.tmp / "prog"
        program.write_text(self.PROGRAM)
        program.chmod(0o755)
        runner = self.runner(LocalExecutor(), build_dir=self.tmp)
        # The same spec (repeat and all) asked for three times, as test5's
        # repeated searches did, and once more through run_timed.
        spec = RunSpec("prog", ["--plates", 40], timed=True)
        results = runner.map([spec, spec, spec]) + runner.run_timed("prog", ["--plates", 40], 2)
        pids = [r.m("pid") for r in results]
        self.assertEqual(len(set(pids)), 5, pids)
        self.assertEqual(len({r.workdir for r in results}), 5)
        self.assertEqual(len(runner.runs), 5)

    def test_untimed_runs_are_still_shared(self):
        executor = ScriptedExecutor()
        runner = self.runner(executor)
        runner.map([RunSpec("test9", ["--cfm", 0])] * 3)
        self.assertEqual(executor.calls, 1)

    def test_timed_repeats_that_come_back_identical_fail(self):
        executor = ScriptedExecutor()  # the same metrics, to the last digit, every time
        runner = self.runner(executor)
        runner.run(RunSpec("test3", ["--seconds", 10], timed=True))
        with self.assertRaises(LabError) as caught:
            runner.run(RunSpec("test3", ["--seconds", 10], timed=True, repeat=1))
        self.assertIn("identical metrics to the last digit", str(caught.exception))
        self.assertEqual(executor.calls, 2)

    def test_timed_repeats_that_differ_pass(self):
        executor = ScriptedExecutor(metrics=lambda n: dict(GOOD, wall_seconds=0.01 + n * 1e-9))
        runner = self.runner(executor)
        results = runner.run_timed("test3", ["--seconds", 10], 3)
        self.assertEqual(len({r.m("wall_seconds") for r in results}), 3)


class ProcessGroups(RunnerCase):
    def test_an_abort_ends_the_children_of_a_program_that_does_not_exec(self):
        program = self.tmp / "wrapper"
        program.write_text("#!/bin/sh\nsleep 300 &\necho $! >child.pid\nwait\n")
        program.chmod(0o755)
        runner = self.runner(LocalExecutor(), build_dir=self.tmp)
        outcome = []
        thread = threading.Thread(target=lambda: outcome.append(self.attempt(runner)), daemon=True)
        thread.start()
        child = self.wait_for_child()
        self.assertTrue(alive(child))
        runner.abort()
        thread.join(10)
        self.assertFalse(thread.is_alive())
        deadline = time.monotonic() + 5
        while alive(child) and time.monotonic() < deadline:
            time.sleep(0.05)
        self.assertFalse(alive(child), f"the wrapper's child {child} outlived the abort")

    def test_a_program_that_starts_as_the_abort_comes_is_ended(self):
        # An abort between a program's start and the executor's note of it
        # cannot see it: the executor ends it as it notes it (seen once under
        # load, where the wrapper above then ran out its 300 s).
        program = self.tmp / "sleeper"
        program.write_text("#!/bin/sh\nsleep 300\n")
        program.chmod(0o755)
        executor = LocalExecutor()
        executor.abort()
        started = time.monotonic()
        done = executor.execute([str(program)], self.tmp, 600, False)
        self.assertLess(time.monotonic() - started, 10)
        self.assertEqual(done["rc"], -9)

    def test_what_a_finished_program_left_running_is_ended(self):
        program = self.tmp / "leaver"
        program.write_text("#!/bin/sh\nsleep 300 &\necho $! >child.pid\n"
                           "echo '{\"steps\": 1, \"sim_seconds\": 1}' >metrics.json\n")
        program.chmod(0o755)
        result = self.runner(LocalExecutor(), build_dir=self.tmp).run(RunSpec("leaver", []))
        child = int((result.workdir / "child.pid").read_text())
        deadline = time.monotonic() + 5
        while alive(child) and time.monotonic() < deadline:
            time.sleep(0.05)
        self.assertFalse(alive(child))

    @staticmethod
    def attempt(runner):
        try:
            return runner.run(RunSpec("wrapper", []))
        except LabError as error:
            return error

    def wait_for_child(self):
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline:
            found = list(self.tmp.glob("wrapper-*/child.pid"))
            if found and found[0].read_text().strip():
                return int(found[0].read_text())
            time.sleep(0.05)
        self.fail("the wrapper never started its child")


def alive(pid):
    """Running, and not a zombie waiting for its parent."""
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


class NoSlotNeverComes(unittest.TestCase):
    def test_zero_slots_are_refused(self):
        for jobs, cores in ((0, 4), (4, 0)):
            with self.assertRaises(LabError, msg=(jobs, cores)):
                Slots(jobs, cores)

    def test_an_abort_frees_a_run_waiting_for_a_slot(self):
        slots = Slots(1, 1)
        slots.acquire(1, False)  # the one slot, taken
        outcome = []

        def wait():
            try:
                slots.acquire(1, False)
                outcome.append("started")
            except LabError as error:
                outcome.append(str(error))
        thread = threading.Thread(target=wait, daemon=True)
        thread.start()
        time.sleep(0.2)
        slots.abort()
        thread.join(5)
        self.assertEqual(outcome, ["interrupted"])


if __name__ == "__main__":
    unittest.main()

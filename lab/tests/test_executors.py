"""Unit checks of the lab's executor plumbing that need no cluster: the
--executor values, Slurm's CPU count, the one-timing-host rule, packing a
run's files, and which --out folders may be replaced; a dask port out of
range and an srun allocation without a CPU are refused by the value check.
Run: /usr/bin/python3 -m unittest discover -s lab/tests (CTest: lab_executor_units)."""

import sys
import tempfile
import unittest
from pathlib import Path
from types import SimpleNamespace

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report import executors, output_folder  # noqa: E402
from odelab_report.executors import process  # noqa: E402
from odelab_report.executors.srun_executor import cpus_of_allocation  # noqa: E402
from odelab_report.main import _check_timing_hosts  # noqa: E402


def run(host, timed):
    return SimpleNamespace(host=host, spec=SimpleNamespace(timed=timed))


class ExecutorValues(unittest.TestCase):
    def test_accepted(self):
        self.assertEqual(executors.parse("local"), ("local", None))
        self.assertEqual(executors.parse("srun", {"SLURM_JOB_ID": "1"}), ("srun", None))
        self.assertEqual(executors.parse("dask:tcp://127.0.0.1:8786"), ("dask", "tcp://127.0.0.1:8786"))
        self.assertEqual(executors.parse("dask:node1:8786"), ("dask", "node1:8786"))

    def test_refused(self):
        for text in ("", "dask:", "dask", "slurm", "Local", "dask:nonsense", "dask:tcp://host"):
            with self.assertRaises(ValueError, msg=text):
                executors.parse(text)

    def test_a_port_out_of_range_is_refused(self):
        for text in ("dask:127.0.0.1:99999", "dask:tcp://node1:0", "dask:node1:65536"):
            with self.assertRaises(ValueError, msg=text) as caught:
                executors.parse(text)
            self.assertIn("a port is 1 to 65535", str(caught.exception))
        self.assertEqual(executors.parse("dask:node1:65535"), ("dask", "node1:65535"))

    def test_srun_needs_an_allocation_with_a_cpu(self):
        self.assertEqual(executors.parse("srun", {"SLURM_JOB_ID": "7", "SLURM_JOB_CPUS_PER_NODE": "2(x2)"}),
                         ("srun", None))
        for environ, words in (({}, "SLURM_JOB_ID is not set"),
                               ({"SLURM_JOB_ID": "7", "SLURM_JOB_CPUS_PER_NODE": "0"}, "offers no CPU"),
                               ({"SLURM_JOB_ID": "7", "SLURM_JOB_CPUS_PER_NODE": "0(x3)"}, "offers no CPU"),
                               ({"SLURM_JOB_ID": "7", "SLURM_JOB_CPUS_PER_NODE": "many"}, "cannot read")):
            with self.assertRaises(ValueError, msg=environ) as caught:
                executors.parse("srun", environ)
            self.assertIn(words, str(caught.exception))


class SlurmCpus(unittest.TestCase):
    def test_forms(self):
        self.assertEqual(cpus_of_allocation("16(x4)"), 64)
        self.assertEqual(cpus_of_allocation("2,4(x2)"), 10)
        self.assertEqual(cpus_of_allocation("2"), 2)

    def test_garbage(self):
        with self.assertRaises(ValueError):  # an option's problem: refused before any run
            cpus_of_allocation("two")


class TimingHosts(unittest.TestCase):
    executor = SimpleNamespace(timing_host="a")

    def test_untimed_runs_may_come_from_anywhere(self):
        runs = [run("a", True), run("a", True), run("b", False), run("c", False)]
        self.assertEqual(_check_timing_hosts(SimpleNamespace(runs=runs), self.executor), {})

    def test_timed_runs_from_two_hosts_are_refused(self):
        runs = [run("a", True), run("b", True)]
        refusal = _check_timing_hosts(SimpleNamespace(runs=runs), self.executor)
        self.assertIn("a, b", refusal["timing"])


class Packing(unittest.TestCase):
    def test_files_status_and_cpu_come_back(self):
        packed = process.from_json(process.to_json(process.run_packed(
            ["/bin/sh", "-c", "echo out; echo err >&2; printf x > data.txt; exit 3"], 30)))
        with tempfile.TemporaryDirectory() as folder:
            result = process.unpack(packed, folder)
            self.assertEqual(result["rc"], 3)  # a result, not an error
            self.assertEqual((Path(folder) / "stdout.txt").read_text(), "out\n")
            self.assertEqual((Path(folder) / "stderr.txt").read_text(), "err\n")
            self.assertEqual((Path(folder) / "data.txt").read_text(), "x")
            self.assertGreaterEqual(result["cpu_seconds"], 0.0)
            self.assertTrue(result["host"])

    def test_a_file_name_with_a_slash_is_refused(self):
        with tempfile.TemporaryDirectory() as folder:
            with self.assertRaises(ValueError):
                process.unpack(dict(rc=0, files={"../x": b""}), folder)


class OutFolder(unittest.TestCase):
    def test_rules(self):
        with tempfile.TemporaryDirectory() as root:
            root = Path(root)
            output_folder.check(root / "new")  # does not exist: fine
            (root / "empty").mkdir()
            output_folder.check(root / "empty")
            (root / "report").mkdir()
            (root / "report" / output_folder.MARKER).write_text("")
            (root / "report" / "RESULTS.md").write_text("")
            output_folder.check(root / "report")
            (root / "sources").mkdir()
            (root / "sources" / "main.cpp").write_text("")
            (root / "file").write_text("")
            (root / "link").symlink_to(root / "report")
            for refused in ("sources", "file", "link"):
                with self.assertRaises(output_folder.Refused, msg=refused):
                    output_folder.check(root / refused)


if __name__ == "__main__":
    unittest.main()

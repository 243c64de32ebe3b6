"""Runs each program as a step of the Slurm allocation the lab runs in:
`srun --exact -n1 -c1`, one CPU per run, started at once inside the
allocation (no scheduler cycle, unlike one sbatch job per run).

process.py runs on the node (the lab's folder and the build at the same path
on every node) and prints the run's result as one JSON line. srun is started
in its own session, so a Ctrl-C on the terminal reaches the lab only; the
lab then ends the steps with SIGTERM, which srun passes to them.

Timed runs go to the allocation's first node (srun -w), so that wall times
in the report are comparable; see doc/cluster.md."""

import os
import signal
import subprocess
import sys
import threading
from pathlib import Path

from . import ExecutorError, cpus_of_allocation, process


class SrunExecutor:
    def __init__(self):
        self.job = os.environ.get("SLURM_JOB_ID")
        if not self.job:
            raise ExecutorError("--executor srun runs inside a Slurm allocation (salloc or sbatch), "
                                "and SLURM_JOB_ID is not set here")
        try:
            self.cores = cpus_of_allocation(os.environ.get("SLURM_JOB_CPUS_PER_NODE", "1"))
        except ValueError as error:  # parse() refused it already; here for callers that skip it
            raise ExecutorError(str(error)) from None
        nodes = subprocess.run(["scontrol", "show", "hostnames", os.environ.get("SLURM_JOB_NODELIST", "")],
                               capture_output=True, text=True)
        names = nodes.stdout.split()
        if nodes.returncode != 0 or not names:
            raise ExecutorError(f"cannot list the nodes of allocation {self.job}: {nodes.stderr.strip()}")
        self.timing_host = names[0]
        self.description = f"srun (Slurm allocation {self.job}: {len(names)} nodes, {self.cores} CPUs)"
        self._running = set()
        self._lock = threading.Lock()
        self._aborted = False

    def missing_programs(self, paths):
        return {}  # a missing program fails its step with a clear status

    def execute(self, argv, folder, timeout, timed):
        command = ["srun", "--exact", "--ntasks=1", "--cpus-per-task=1", "--nodes=1", "--quiet",
                   "--job-name=odelab-run"]
        if timed:
            command.append(f"--nodelist={self.timing_host}")
        command += [sys.executable, str(Path(process.__file__).resolve()), str(timeout), *argv]
        child = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                 stdin=subprocess.DEVNULL, start_new_session=True)
        with self._lock:
            self._running.add(child)
            aborted = self._aborted
        if aborted:  # an abort between the start and here did not see this step
            child.send_signal(signal.SIGTERM)
        try:
            out, err = child.communicate()
        finally:
            with self._lock:
                self._running.discard(child)
        if self._aborted:
            raise ExecutorError("interrupted")
        lines = out.decode(errors="replace").strip().splitlines()
        if child.returncode != 0 or not lines:
            tail = "\n".join(err.decode(errors="replace").strip().splitlines()[-5:])
            raise ExecutorError(f"srun could not run {Path(argv[0]).name} in Slurm allocation {self.job} "
                                f"(srun exit status {child.returncode}); was the allocation cancelled or "
                                f"did it run out of time?\n{tail}")
        return process.unpack(process.from_json(lines[-1]), folder)

    def abort(self):
        """Ends every running step (Ctrl-C): srun passes SIGTERM to its step."""
        with self._lock:
            self._aborted = True  # a step starting now ends itself (execute)
            running = list(self._running)
        for child in running:
            try:
                child.send_signal(signal.SIGTERM)
            except OSError:
                pass

    def close(self):
        pass

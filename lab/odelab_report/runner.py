"""Runs the test programs, each a separate process (here or remote, through an executor), at most `jobs` at a time.

Every run gets its own working folder (so output files such as
Test2_output.txt never collide), writes its metrics with --metrics-json,
and is timed twice: by the program itself (its `wall_seconds` metric, the
run loop only) and by the kernel (user + system CPU seconds of the child,
from wait4). Identical runs within one report are made once and shared
between experiments (the cache), so an experiment that needs another's
measurement does not pay for it twice.
"""

import heapq
import itertools
import json
import shlex
import subprocess
import tempfile
import threading
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path

from .executors import ExecutorError
from .executors.process import MAX_PACKED_BYTES
from .inputs import InputError, check_regular, read_text

# Exit statuses of the test programs (doc/manual.md). 3 and 4 are results
# (the simulation blew up / ODE reported an error), not mistakes of the lab.
EXIT_OK, EXIT_BLEW_UP, EXIT_ODE_ERROR = 0, 3, 4
# Timed runs that got less than this share of a processor are made again...
RETRY_SHARE = 0.9
# ...up to this many times in all, when one run is shorter than this (seconds),
RETRY_ATTEMPTS = 2
RETRY_MAX_WALL = 2.0
# ...unless the machine is busy for good: the median share of the last
# RECENT timed runs below BUSY_SHARE says a retry would fare no better.
RECENT = 15
BUSY_SHARE = 0.6
RESULT_STATUSES = (EXIT_OK, EXIT_BLEW_UP, EXIT_ODE_ERROR)
# What a run may leave in its folder, in all (the bound the remote executors
# already put on a run's files) and in its metrics JSON.
MAX_RUN_BYTES = MAX_PACKED_BYTES
MAX_METRICS_BYTES = 16 * 1024 * 1024


class LabError(Exception):
    """A mistake the user or the lab must fix; the report is not written."""


class RunSpec:
    """One program run. `timed`: its wall time is a result, so it never
    shares the machine with more runs than there are cores; `repeat` tells
    repeated timings apart; `priority` 0 goes before 1 (the runs of a
    search, which waits for each before choosing the next)."""

    def __init__(self, program, args, timed=False, repeat=0, timeout=600, priority=1):
        self.program = program
        self.args = tuple(str(a) for a in args)
        self.timed = timed
        self.repeat = repeat
        self.timeout = timeout
        self.priority = priority

    def key(self):
        return (self.program, self.args, self.repeat)

    def command_line(self):
        return " ".join([self.program] + [shlex.quote(a) for a in self.args])


class RunResult:
    def __init__(self, spec, rc, metrics, stdout, stderr, cpu_seconds, workdir, host):
        self.spec = spec
        self.rc = rc
        self.metrics = metrics
        self.stdout = stdout
        self.stderr = stderr
        self.cpu_seconds = cpu_seconds
        self.workdir = Path(workdir)
        self.host = host  # which machine ran it: wall times compare only within one host
        self.attempts = 1

    def m(self, name, default=None):
        value = self.metrics.get(name)
        return default if value is None else value

    @property
    def blew_up(self):
        return self.rc == EXIT_BLEW_UP

    @property
    def ode_error(self):
        return self.rc == EXIT_ODE_ERROR

    @property
    def cpu_share(self):
        """CPU time over wall time (at most 1): below 1, the run waited for
        the processor and its wall time is inflated by about 1 / share. Runs
        too short to tell (under 20 ms) count as 1."""
        wall = self.m("wall_seconds")
        if not wall or wall < 0.02:
            return 1.0
        return min(1.0, self.cpu_seconds / wall)

    def wall_per_sim_second(self):
        wall, sim = self.m("wall_seconds"), self.m("sim_seconds")
        return wall / sim if wall is not None and sim else None


class Slots:
    """Admits runs in order of (priority, arrival): at most `jobs` at once,
    and at most `cores` at once while a timed run is among them."""

    def __init__(self, jobs, cores):
        self._jobs, self._cores = jobs, cores
        self._running = 0
        self._timed_running = 0
        self._waiting = []
        self._arrival = itertools.count()
        self._condition = threading.Condition()

    def _may_start(self, timed):
        if self._running >= self._jobs:
            return False
        if (timed or self._timed_running) and self._running >= self._cores:
            return False
        return True

    def acquire(self, priority, timed):
        with self._condition:
            ticket = (priority, next(self._arrival))
            heapq.heappush(self._waiting, ticket)
            while self._waiting[0] != ticket or not self._may_start(timed):
                self._condition.wait()
            heapq.heappop(self._waiting)
            self._running += 1
            self._timed_running += 1 if timed else 0
            self._condition.notify_all()

    def release(self, timed):
        with self._condition:
            self._running -= 1
            self._timed_running -= 1 if timed else 0
            self._condition.notify_all()


class Runner:
    """Runs RunSpecs through an executor (executors/: local processes, Dask
    tasks or Slurm steps); `cores` of the Slots is what the executor offers."""

    def __init__(self, build_dir, jobs, tmp_root, executor, retry=True):
        self.build_dir = Path(build_dir)
        self.jobs = jobs
        self._executor = executor
        self._slots = Slots(jobs, executor.cores)
        self._tmp_root = Path(tmp_root)
        self._cache = {}
        self._help = {}
        self._lock = threading.Lock()
        self._pool = ThreadPoolExecutor(max_workers=256, thread_name_prefix="run")
        self._aborted = False
        self._lost = None  # the executor's failure (a lost scheduler...), once it happened
        self._retry = retry
        self._children = set()  # the lab's own children outside the executor (--help)
        self.runs = []  # every RunResult, in completion order (for runs.csv)

    # ---- public -------------------------------------------------------------
    def run(self, spec):
        """Runs `spec` (or waits for the identical run already made)."""
        with self._lock:
            future = self._cache.get(spec.key())
            owner = future is None
            if owner:
                future = Future()
                self._cache[spec.key()] = future
        if owner:
            try:
                future.set_result(self._execute_timed(spec) if spec.timed else self._execute(spec))
            except BaseException as error:  # noqa: BLE001 - handed to every waiter
                future.set_exception(error)
        return future.result()

    def map(self, specs):
        """Runs every spec, in parallel within the slots; results in order."""
        futures = [self._pool.submit(self.run, spec) for spec in specs]
        return [f.result() for f in futures]

    def parallel(self, calls):
        """Calls every function (e.g. a search that makes its runs one after
        another) in parallel with the others; their results, in order."""
        futures = [self._pool.submit(call) for call in calls]
        return [f.result() for f in futures]

    def run_timed(self, program, args, repeats):
        """`repeats` identical timed runs; the results, in repeat order."""
        return self.map([RunSpec(program, args, timed=True, repeat=r) for r in range(repeats)])

    def help_text(self, program):
        """`program --help`, to see which options this build has."""
        with self._lock:
            if program in self._help:
                return self._help[program]
        if self._aborted:
            raise LabError("interrupted")
        child = subprocess.Popen([str(self.build_dir / program), "--help"], stdout=subprocess.PIPE,
                                 stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL, text=True)
        with self._lock:
            self._children.add(child)  # abort() ends it too
        try:
            text, _ = child.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            child.kill()
            raise LabError(f"{program} --help gave no answer within 60 s") from None
        finally:
            with self._lock:
                self._children.discard(child)
        if self._aborted:
            raise LabError("interrupted")
        with self._lock:
            self._help[program] = text
        return text

    @property
    def aborted(self):
        return self._aborted

    def abort(self):
        """Stops every running program, here or remote (Ctrl-C); new runs fail at once."""
        self._aborted = True
        self._executor.abort()
        with self._lock:
            children = list(self._children)
        for child in children:
            child.kill()

    def close(self):
        self._pool.shutdown(wait=False, cancel_futures=True)
        self._executor.close()

    def _busy(self):
        with self._lock:
            recent = [r.cpu_share for r in self.runs if r.spec.timed][-RECENT:]
        return len(recent) >= RECENT and median(recent) < BUSY_SHARE

    # ---- one process ----------------------------------------------------------
    def _execute_timed(self, spec):
        """A timed run that did not have the processor to itself (CPU share
        below RETRY_SHARE) is made again, up to RETRY_ATTEMPTS times in all
        when it is short, and the run with the largest share is kept."""
        best = self._execute(spec)
        attempts = 1
        while (self._retry and best.cpu_share < RETRY_SHARE and attempts < RETRY_ATTEMPTS
               and (best.m("wall_seconds") or 0) < RETRY_MAX_WALL and not self._busy()):
            again = self._execute(spec)
            attempts += 1
            if again.cpu_share > best.cpu_share:
                best = again
        best.attempts = attempts
        return best

    def _execute(self, spec):
        if self._aborted:
            raise LabError("interrupted")
        if self._lost:
            raise LabError(self._lost)
        executable = self.build_dir / spec.program
        workdir = Path(tempfile.mkdtemp(prefix=Path(spec.program).name + "-", dir=self._tmp_root))  # a peer is ../peers/NAME
        argv = [str(executable), "--headless", *spec.args, "--metrics-json", "metrics.json"]
        self._slots.acquire(spec.priority, spec.timed)
        try:
            if self._aborted:
                raise LabError("interrupted")
            done = self._executor.execute(argv, workdir, spec.timeout, spec.timed)
        except OSError as error:  # a program that cannot be started here (not executable, gone)
            raise LabError(f"cannot run {executable}: {error.strerror or error}") from None
        except ExecutorError as error:
            if not self._aborted:
                with self._lock:
                    self._lost = self._lost or str(error)  # every later run fails with the first cause
            raise LabError(str(error)) from None
        finally:
            self._slots.release(spec.timed)
        rc = done["rc"]
        if self._aborted:
            raise LabError("interrupted")
        try:
            check_run_folder(workdir)
            stdout = read_text(workdir / "stdout.txt", MAX_RUN_BYTES, "the run's standard output")
            stderr = read_text(workdir / "stderr.txt", MAX_RUN_BYTES, "the run's standard error")
        except InputError as error:
            raise LabError(f"{spec.command_line()} --headless (in {workdir}): {error}") from None
        if rc not in RESULT_STATUSES:
            tail = "\n".join(stderr.strip().splitlines()[-5:])
            raise LabError(f"{spec.command_line()} --headless exited with status {rc}"
                           f" (on {done['host']}, in {workdir}):\n{tail}")
        metrics = {}
        metrics_file = workdir / "metrics.json"
        if metrics_file.exists():
            try:
                metrics = json.loads(read_text(metrics_file, MAX_METRICS_BYTES, "the metrics file"))
            except (ValueError, InputError) as error:
                raise LabError(f"{spec.command_line()} wrote an invalid metrics file (in {workdir}): {error}") from None
            if not isinstance(metrics, dict):
                raise LabError(f"{spec.command_line()} wrote a metrics file that is not a JSON object (in {workdir})")
        elif rc == EXIT_OK:
            raise LabError(f"{spec.command_line()} wrote no metrics file (in {workdir})")
        if rc == EXIT_OK and metrics.get("steps") == 0:
            # A run that never happened is no result, however good its figures look.
            raise LabError(f"{spec.command_line()} ended with status 0 but took no step (in {workdir})")
        result = RunResult(spec, rc, metrics, stdout, stderr, done["cpu_seconds"], workdir, done["host"])
        with self._lock:
            self.runs.append(result)  # every attempt, kept or not
        return result


def check_run_folder(folder):
    """What a run left is read later by the experiments (its output files):
    only regular files, not followed through links, MAX_RUN_BYTES in all.
    Raises InputError."""
    total = 0
    for entry in sorted(Path(folder).iterdir()):
        check_regular(entry, MAX_RUN_BYTES, "the run's file")
        total += entry.lstat().st_size
        if total > MAX_RUN_BYTES:
            raise InputError(f"the run's files exceed {MAX_RUN_BYTES} bytes in all (at {entry.name})")


def median(values):
    values = sorted(v for v in values if v is not None)
    if not values:
        return None
    middle = len(values) // 2
    return values[middle] if len(values) % 2 else 0.5 * (values[middle - 1] + values[middle])

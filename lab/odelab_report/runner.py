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
import math
import re
import shlex
import statistics
import subprocess
import tempfile
import threading
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path

from .executors import ExecutorError
from .executors.process import MAX_PACKED_BYTES, kill_group
from .inputs import InputError, check_regular, read_text

# Exit statuses of the test programs (doc/manual.md). 3 and 4 are results
# (the simulation blew up / ODE reported an error), not mistakes of the lab.
EXIT_OK, EXIT_BLEW_UP, EXIT_ODE_ERROR = 0, 3, 4
# 7: the engine --engine or --compare named failed (its process died or was
# killed, it answered what is not the protocol, it missed a deadline). Not
# physics: never a result, not even where an experiment counts blow-ups (an
# engine killed for memory is no stability limit).
EXIT_ENGINE_FAILED = 7
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
    shares the machine with more runs than there are cores, and it is made
    anew for every request; `repeat` tells repeated timings apart in
    runs.csv; `priority` 0 goes before 1 (the runs of a search, which waits
    for each before choosing the next). `measures_blow_ups`: the experiment
    judges a blown-up run (status 3) or an ODE error (status 4) by its own
    failure rule, so such a run is a result; otherwise it fails the report."""

    def __init__(self, program, args, timed=False, repeat=0, timeout=600, priority=1, measures_blow_ups=False):
        self.program = program
        self.args = tuple(str(a) for a in args)
        self.timed = timed
        self.repeat = repeat
        self.timeout = timeout
        self.priority = priority
        self.measures_blow_ups = measures_blow_ups

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
        """A metric as the program wrote it: a number, or a list (of strings,
        e.g. "engine" or "translation_notes"), or `default` when absent, not
        measured (null) or measured but not finite ("nan", "inf", "-inf":
        never a number; check() refuses a run that gives one as a result)."""
        value = self.metrics.get(name)
        return default if value is None or is_non_finite_metric(value) else value

    def texts(self, name):
        """A metric that lists texts (e.g. "translation_notes"), as a list of
        strings: [] when absent; a lone string or number becomes a list of one."""
        value = self.metrics.get(name)
        if value is None:
            return []
        if isinstance(value, list):
            return [str(v) for v in value if v is not None]
        return [str(value)]

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

    def check(self, spec):
        """Raises LabError unless this run may give figures to the experiment
        that asked for it with `spec`: the one place where a run's status,
        counts and values are judged (the cache shares a run between
        experiments, so it is judged again for each request)."""
        where = f"{spec.command_line()} --headless (on {self.host}, in {self.workdir})"
        if self.rc == EXIT_ENGINE_FAILED:
            tail = "\n".join(self.stderr.strip().splitlines()[-5:])
            raise LabError(f"{where}: the engine failed (status 7: its process died, answered what is not the "
                           f"protocol or missed a deadline); that is not a physics result, so the run gives no "
                           f"figure and is never counted as a blow-up:\n{tail}")
        if self.rc not in RESULT_STATUSES:
            tail = "\n".join(self.stderr.strip().splitlines()[-5:])
            raise LabError(f"{where} exited with status {self.rc}:\n{tail}")
        if self.rc in (EXIT_BLEW_UP, EXIT_ODE_ERROR):
            if spec.measures_blow_ups:
                return  # its experiment's failure rule counts it; its figures may well be non-finite
            what = "blew up (status 3: a non-finite state)" if self.blew_up else "met an ODE error (status 4)"
            raise LabError(f"{where} {what}; this experiment does not measure blow-ups, so the run gives no "
                           f"figure and the report is not written")
        if not self.metrics:
            raise LabError(f"{where} ended with status 0 and wrote no metrics")
        steps = self.metrics.get("steps")
        if steps is not None and not (_is_number(steps) and steps >= 1 and steps == int(steps)):
            # A run that never happened is no result, however good its figures look.
            raise LabError(f"{where} ended with status 0 but took no step (steps = {steps!r})")
        if self.metrics.get("non_finite", 0) != 0:
            raise LabError(f"{where} ended with status 0 but counted {self.metrics['non_finite']!r} "
                           f"non-finite values (non_finite)")
        bad = non_finite_metrics(self.metrics)
        if bad:
            raise LabError(f"{where} ended with status 0 but its metrics are not finite: {', '.join(bad[:5])}")
        found = non_finite_in_outputs(self.workdir)
        if found:
            raise LabError(f"{where} ended with status 0 but {found} holds a non-finite number")


class Slots:
    """Admits runs in order of (priority, arrival): at most `jobs` at once,
    and at most `cores` at once while a timed run is among them."""

    def __init__(self, jobs, cores):
        if jobs < 1 or cores < 1:
            # No run could ever start: every experiment would wait for good.
            raise LabError(f"no run could start: {jobs} job slots and {cores} cores offered")
        self._jobs, self._cores = jobs, cores
        self._aborted = False
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
            while not self._aborted and (self._waiting[0] != ticket or not self._may_start(timed)):
                self._condition.wait()
            if self._aborted:
                self._waiting.remove(ticket)
                heapq.heapify(self._waiting)
                raise LabError("interrupted")
            heapq.heappop(self._waiting)
            self._running += 1
            self._timed_running += 1 if timed else 0
            self._condition.notify_all()

    def abort(self):
        """Every run still waiting for a slot fails at once (an interrupt)."""
        with self._condition:
            self._aborted = True
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
        self._cache = {}  # untimed runs only
        self._timings = {}  # (program, args) -> the metrics of each timed run, as text
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
        """Runs `spec`, checked (RunResult.check). An untimed run may be the
        identical run already made (or being made); a timed run is always a
        new process: a repeat is a new measurement, never a replay."""
        if spec.timed:
            result = self._execute_timed(spec)
            self._note_timing(spec, result)
        else:
            with self._lock:
                future = self._cache.get(spec.key())
                owner = future is None
                if owner:
                    future = Future()
                    self._cache[spec.key()] = future
            if owner:
                try:
                    future.set_result(self._execute(spec))
                except BaseException as error:  # noqa: BLE001 - handed to every waiter
                    future.set_exception(error)
            result = future.result()
        result.check(spec)
        return result

    def _note_timing(self, spec, result):
        """Timed runs of one command must differ somewhere in their metrics
        (a wall time to the last digit at least): two or more that are all
        identical were not measured anew, and no figure is taken from them."""
        fingerprint = json.dumps(result.metrics, sort_keys=True)
        with self._lock:
            seen = self._timings.setdefault((spec.program, spec.args), [])
            seen.append(fingerprint)
            replayed = len(seen) >= 2 and len(set(seen)) == 1
        if replayed and result.rc == EXIT_OK:
            raise LabError(f"{spec.command_line()} --headless: {len(seen)} timed runs came back with identical "
                           f"metrics to the last digit (wall_seconds {result.m('wall_seconds')!r}): repeated "
                           f"timings were replayed, not measured")

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
        """`repeats` timed runs of one command, each a new process; the results, in repeat order."""
        return self.map([RunSpec(program, args, timed=True, repeat=r) for r in range(repeats)])

    def help_text(self, program):
        """`program --help`, to see which options this build has."""
        return self.ask(program, ["--help"])

    def ask(self, program, args):
        """The standard output of `program args` run here, once per report
        (cached): a question to the program, not a measurement (--help,
        --list-engines)."""
        key = (program, tuple(str(a) for a in args))
        with self._lock:
            if key in self._help:
                return self._help[key]
        if self._aborted:
            raise LabError("interrupted")
        asked = " ".join((program,) + key[1])
        child = subprocess.Popen([str(self.build_dir / program), *key[1]], stdout=subprocess.PIPE,
                                 stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL, text=True,
                                 start_new_session=True)  # abort() ends its whole group
        with self._lock:
            self._children.add(child)  # abort() ends it too
        try:
            text, _ = child.communicate(timeout=60)
        except subprocess.TimeoutExpired:
            kill_group(child)
            raise LabError(f"{asked} gave no answer within 60 s") from None
        finally:
            with self._lock:
                self._children.discard(child)
        if self._aborted:
            raise LabError("interrupted")
        with self._lock:
            self._help[key] = text
        return text

    def export_world(self, program):
        """The world `program --export-world FILE` writes (doc/world-format.md),
        parsed; once per report (cached)."""
        with self._lock:
            if (program, "world") in self._help:
                return self._help[(program, "world")]
        folder = Path(tempfile.mkdtemp(prefix=Path(program).name + "-world-", dir=self._tmp_root))
        path = folder / "world.json"
        self.ask(program, ["--export-world", str(path)])
        try:
            world = json.loads(read_text(path, MAX_METRICS_BYTES, "the exported world"))
        except (OSError, ValueError, InputError) as error:
            raise LabError(f"{program} --export-world wrote no readable world ({path}): {error}") from None
        if not isinstance(world, dict):
            raise LabError(f"{program} --export-world wrote a world that is not a JSON object ({path})")
        with self._lock:
            self._help[(program, "world")] = world
        return world

    @property
    def aborted(self):
        return self._aborted

    def abort(self):
        """Stops every running program, here or remote (Ctrl-C); new runs fail at once."""
        self._aborted = True
        self._slots.abort()
        self._executor.abort()
        with self._lock:
            children = list(self._children)
        for child in children:
            kill_group(child)

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
        metrics = {}
        metrics_file = workdir / "metrics.json"
        if rc in RESULT_STATUSES and metrics_file.exists():  # another status: RunResult.check says why
            try:
                metrics = json.loads(read_text(metrics_file, MAX_METRICS_BYTES, "the metrics file"))
            except (ValueError, InputError) as error:
                raise LabError(f"{spec.command_line()} wrote an invalid metrics file (in {workdir}): {error}") from None
            if not isinstance(metrics, dict):
                raise LabError(f"{spec.command_line()} wrote a metrics file that is not a JSON object (in {workdir})")
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
    """The median of the figures a run produced (None: the run had none), or None if none had one."""
    known = [v for v in values if v is not None]
    return statistics.median(known) if known else None


def _is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


# The programs' one rule for values that are not finite numbers
# (utils/Metrics.h, doc/manual.md "Outputs"): a metric
# not measured is null (None here) and nothing else is; a measured NaN or
# infinity is one of these strings, never a number and never null.
NON_FINITE_METRIC_TEXTS = ("nan", "inf", "-inf")


def is_non_finite_metric(value):
    """True for a measured value that is not finite, as the programs write
    it (a string of NON_FINITE_METRIC_TEXTS) or as a float."""
    return (isinstance(value, str) and value in NON_FINITE_METRIC_TEXTS) or (
        isinstance(value, float) and not math.isfinite(value))


def non_finite_metrics(metrics, prefix=""):
    """The names of the metrics (nested ones as a.b, a[0]) that were
    measured NaN or infinite; a metric not measured (null) is not one."""
    bad = []
    items = metrics.items() if isinstance(metrics, dict) else enumerate(metrics)
    for name, value in items:
        label = f"{prefix}.{name}" if isinstance(metrics, dict) and prefix else (
            f"{prefix}[{name}]" if not isinstance(metrics, dict) else str(name))
        if is_non_finite_metric(value):
            bad.append(f"{label} = {value if isinstance(value, str) else repr(value)}")
        elif isinstance(value, (dict, list)):
            bad.extend(non_finite_metrics(value, label))
    return bad


# A number that is not one: nan, inf, infinity, with a sign or not, as a
# field of its own (a word such as "info" is not one).
_NON_FINITE = re.compile(rb"(?<![\w.])[-+]?(?:nan|inf(?:inity)?)(?![\w.])", re.IGNORECASE)
_NOT_OUTPUTS = ("stdout.txt", "stderr.txt", "metrics.json")


def non_finite_in_outputs(folder):
    """'FILE line N' of the first non-finite number in the output files a run
    left (its data lines; `#` comment lines and its streams are not data), or None."""
    for entry in sorted(Path(folder).iterdir()):
        if entry.name in _NOT_OUTPUTS or not entry.is_file() or entry.is_symlink():
            continue
        with open(entry, "rb") as stream:
            for number, line in enumerate(stream, 1):
                if not line.startswith(b"#") and _NON_FINITE.search(line):
                    return f"{entry.name} line {number}"
    return None

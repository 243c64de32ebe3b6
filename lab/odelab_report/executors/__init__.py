"""Where a program run happens: `--executor local` (a process on this
machine), `dask:ADDRESS` (a task on a Dask distributed cluster) or `srun`
(a step of the Slurm allocation the lab runs in).

An executor does one thing: run a program with its arguments and bring back
its exit status, CPU time, host name, and the files it wrote (metrics JSON,
output files, stdout.txt, stderr.txt) into a folder on this machine. The
runner's cache, job slots, CPU-share accounting and searches stay in
runner.py, the same for every executor."""

import os
import re


class ExecutorError(Exception):
    """The executor itself failed (a lost scheduler, a cancelled allocation,
    an unreachable cluster): the report cannot be finished."""


def parse(text, environ=None):
    """Checks an --executor value, and for srun the allocation it would run
    in (`environ`, os.environ by default), before any run: a value that can
    only fail or hang later is refused now. Returns (kind, address). Raises
    ValueError naming what is wrong."""
    if text == "local":
        return text, None
    if text == "srun":
        check_allocation(os.environ if environ is None else environ)
        return text, None
    if text.startswith("dask:"):
        address = text[len("dask:"):]
        found = re.fullmatch(r"(?:[a-z]+://)?[^/\s]+:(\d+)", address)
        if not found:
            raise ValueError(f"dask: needs the scheduler's address with its port, e.g. "
                             f"dask:tcp://127.0.0.1:8786, not {address!r}")
        if not 1 <= int(found.group(1)) <= 65535:
            raise ValueError(f"dask: the port of {address!r} is {int(found.group(1))}; a port is 1 to 65535")
        return "dask", address
    raise ValueError(f"unknown executor {text!r}; use local, dask:ADDRESS or srun")


def check_allocation(environ):
    """The Slurm allocation srun would run in: a job, and at least one CPU
    (with none, no run could ever start and the report would wait for good)."""
    if not environ.get("SLURM_JOB_ID"):
        raise ValueError("srun runs inside a Slurm allocation (salloc or sbatch), and SLURM_JOB_ID is not set here")
    text = environ.get("SLURM_JOB_CPUS_PER_NODE", "1")
    cpus = cpus_of_allocation(text)
    if cpus < 1:
        raise ValueError(f"the Slurm allocation offers no CPU (SLURM_JOB_CPUS_PER_NODE={text!r}), so no run could start")


def cpus_of_allocation(text):
    """Total CPUs from SLURM_JOB_CPUS_PER_NODE, e.g. '16(x4)' or '2,4(x2)'. Raises ValueError."""
    total = 0
    for part in text.split(","):
        match = re.fullmatch(r"(\d+)(?:\(x(\d+)\))?", part.strip())
        if not match:
            raise ValueError(f"cannot read SLURM_JOB_CPUS_PER_NODE={text!r}")
        total += int(match.group(1)) * int(match.group(2) or 1)
    return total


def make(text):
    """The executor an --executor value names (already checked by parse)."""
    kind, address = parse(text)
    if kind == "dask":
        from .dask_executor import DaskExecutor
        return DaskExecutor(address)
    if kind == "srun":
        from .srun_executor import SrunExecutor
        return SrunExecutor()
    from .local_executor import LocalExecutor
    return LocalExecutor()

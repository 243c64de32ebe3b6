"""Where a program run happens: `--executor local` (a process on this
machine), `dask:ADDRESS` (a task on a Dask distributed cluster) or `srun`
(a step of the Slurm allocation the lab runs in).

An executor does one thing: run a program with its arguments and bring back
its exit status, CPU time, host name, and the files it wrote (metrics JSON,
output files, stdout.txt, stderr.txt) into a folder on this machine. The
runner's cache, job slots, CPU-share accounting and searches stay in
runner.py, the same for every executor."""

import re


class ExecutorError(Exception):
    """The executor itself failed (a lost scheduler, a cancelled allocation,
    an unreachable cluster): the report cannot be finished."""


def parse(text):
    """Checks an --executor value; returns (kind, address). Raises ValueError."""
    if text == "local" or text == "srun":
        return text, None
    if text.startswith("dask:"):
        address = text[len("dask:"):]
        if not re.fullmatch(r"(?:[a-z]+://)?[^/\s]+:\d+", address):
            raise ValueError(f"dask: needs the scheduler's address with its port, e.g. "
                             f"dask:tcp://127.0.0.1:8786, not {address!r}")
        return "dask", address
    raise ValueError(f"unknown executor {text!r}; use local, dask:ADDRESS or srun")


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

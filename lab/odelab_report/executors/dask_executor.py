"""Runs each program as a task on a Dask distributed cluster.

The lab's code reaches the workers by value: process.py is pickled with the
task (cloudpickle's register_pickle_by_value), so the workers need only
Debian's python3-distributed and the test programs at the same path as here.

A task returns the program's exit status as a result, whatever it is, so
Dask never retries a run because the program failed; a task whose worker
died is rescheduled by the scheduler itself (its `allowed-failures`, 3 by
default), and after that the run fails with KilledWorker.

Timed runs go to the workers of one host only (a host restriction, so a
restarted worker on that host still counts), so that wall times in the
report are comparable; see doc/cluster.md."""

import socket
import threading
import uuid
from concurrent.futures import CancelledError

from . import ExecutorError, process


def _quiet_library_logs():
    """Dask logs a lost connection with its tracebacks; the lab says what
    was lost in one message of its own instead."""
    import logging
    names = [n for n in logging.root.manager.loggerDict if n.split(".")[0] in ("distributed", "tornado", "asyncio")]
    for name in names + ["distributed", "tornado", "asyncio"]:
        logging.getLogger(name).setLevel(logging.CRITICAL + 1)


class DaskExecutor:
    def __init__(self, address, connect_timeout=15):
        try:
            import cloudpickle
            import distributed
        except ImportError:
            raise ExecutorError("--executor dask needs Debian's python3-distributed on this machine "
                                "(scripts/odelab.sh installs it)") from None
        cloudpickle.register_pickle_by_value(process)
        _quiet_library_logs()
        self._distributed = distributed
        self.address = address
        try:
            self._client = distributed.Client(address, timeout=connect_timeout, set_as_default=False)
        except (OSError, TimeoutError, ValueError) as error:
            raise ExecutorError(f"cannot reach the Dask scheduler at {address}: {error}") from None
        try:
            self._client.wait_for_workers(1, timeout=connect_timeout)
        except (OSError, TimeoutError):
            self._client.close()
            raise ExecutorError(f"the Dask scheduler at {address} has no workers "
                                f"(waited {connect_timeout} s)") from None
        workers = self._client.scheduler_info()["workers"]
        threads_by_host = {}
        for info in workers.values():
            threads_by_host[info["host"]] = threads_by_host.get(info["host"], 0) + info["nthreads"]
        self.cores = sum(threads_by_host.values())
        # Timed runs: the host with the most worker threads (the first by name on a tie).
        self._timing_address = sorted(threads_by_host, key=lambda h: (-threads_by_host[h], h))[0]
        self.timing_host = self._client.run(socket.gethostname, workers=[
            a for a, info in workers.items() if info["host"] == self._timing_address][:1])
        self.timing_host = next(iter(self.timing_host.values()))
        self.description = (f"dask:{address} ({len(workers)} workers, {self.cores} threads on "
                            f"{len(threads_by_host)} hosts)")
        self._outstanding = set()
        self._lock = threading.Lock()
        self._aborted = False
        self._tag = uuid.uuid4().hex  # in every program's environment: abort() finds them by it

    def missing_programs(self, paths):
        """{worker: [programs it cannot execute]} over every worker."""
        def check(paths):
            import os
            return [p for p in paths if not os.access(p, os.X_OK)]
        found = self._client.run(check, [str(p) for p in paths])
        return {worker: missing for worker, missing in found.items() if missing}

    def execute(self, argv, folder, timeout, timed):
        name = argv[0].rsplit("/", 1)[-1]
        future = self._client.submit(
            process.run_packed, argv, timeout, self._tag, key=f"odelab-{name}-{uuid.uuid4().hex}", pure=False,
            workers=[self._timing_address] if timed else None, allow_other_workers=False)
        with self._lock:
            self._outstanding.add(future)
        try:
            result = future.result()
        except self._distributed.KilledWorker as error:
            raise ExecutorError(f"{name}: its Dask worker died every time it was tried "
                                f"(the scheduler's allowed-failures): {error}") from None
        except CancelledError:
            if self._aborted:
                raise ExecutorError("interrupted") from None
            with self._lock:
                lost = len(self._outstanding)
            raise ExecutorError(f"lost the Dask scheduler at {self.address}: {lost} runs were outstanding "
                                f"(this one: {' '.join(argv)})") from None
        except OSError as error:  # the connection to the scheduler, broken mid-way
            raise ExecutorError(f"lost the Dask scheduler at {self.address}: {error}") from None
        finally:
            with self._lock:
                self._outstanding.discard(future)
        return process.unpack(result, folder)

    def abort(self):
        """Cancels every outstanding run on the cluster (Ctrl-C) and ends the
        programs already running; gives up after 10 s (a lost scheduler)."""
        self._aborted = True
        with self._lock:
            outstanding = list(self._outstanding)

        def cancel():
            try:
                if outstanding:
                    self._client.cancel(outstanding, force=True)
                # Cancelling forgets a running task but cannot stop its thread: end its program.
                self._client.run(process.kill_tagged, self._tag)
            except Exception:  # noqa: BLE001 - the scheduler may be gone already; nothing more to cancel
                pass
        canceller = threading.Thread(target=cancel, daemon=True)
        canceller.start()
        canceller.join(10)

    def close(self):
        try:
            self._client.close(timeout=10)
        except Exception:  # noqa: BLE001 - closing a client whose scheduler is gone
            pass

"""Runs each program as a child process of the lab (the default), each in a
session and process group of its own, which an interrupt ends as a whole."""

import os
import socket
import threading

from .process import kill_group, run_in_folder


class LocalExecutor:
    description = "local (child processes of the lab)"

    def __init__(self):
        self.cores = os.cpu_count() or 1
        self.timing_host = socket.gethostname()
        self._running = set()
        self._lock = threading.Lock()
        self._aborted = False

    def missing_programs(self, paths):
        return {}  # the lab checks its own build before it starts

    def execute(self, argv, folder, timeout, timed):
        def started(process):
            with self._lock:
                self._running.add(process)
                aborted = self._aborted
            # An abort between the start and here did not see this program.
            if aborted:
                kill_group(process)
        try:
            return run_in_folder(argv, folder, timeout, started)
        finally:
            with self._lock:
                self._running = {p for p in self._running if p.returncode is None}

    def abort(self):
        with self._lock:
            self._aborted = True  # a program starting now ends itself (execute's `started`)
            running = list(self._running)
        for process in running:
            # The program's whole group: a wrapper that does not exec leaves
            # children that the program's own death would not end.
            if process.returncode is None:  # reaped: its pid may be another's by now
                kill_group(process)

    def close(self):
        pass

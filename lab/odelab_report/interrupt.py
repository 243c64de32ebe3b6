"""Ctrl-C, SIGTERM and SIGHUP at any moment: status 130, nothing
half-written, no temporary folder and no program of the lab left behind.

Signals reach Python's handler in the main thread. Where the main thread
waits on something outside the lab (a FIFO, a program that hangs, a slow
import), the first signal raises Interrupted there, which unwinds through
the `finally` blocks that remove the temporaries (subprocess.run kills its
child on the way). Inside `deferred()` blocks (starting and waiting for the
runs, the renames that publish the report, cleaning up) it only sets a flag,
which the code checks where stopping is safe, so nothing lands mid-rename or
mid-thread-start. Interrupted is raised at most once, so cleanup is never
itself interrupted. Threads still busy at exit (in matplotlib's C++, say)
are not unwound by the interpreter's shutdown: the process ends with
os._exit instead, which also avoids glibc's "FATAL: exception not rethrown"."""

import contextlib
import os
import signal
import sys
import threading
import time

# Every signal that asks a process to stop and can be caught. SIGHUP: the
# terminal or session went away (setsid, ssh); by default it killed the lab
# mid-way, leaving its staging folder and its runs.
STOP_SIGNALS = tuple(getattr(signal, name) for name in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, name))

_flag = threading.Event()
_state = {"raising": False, "raised": False}


class Interrupted(BaseException):
    """A stop signal came while the main thread was outside deferred()."""


def _raise_once():
    if not _state["raised"]:
        _state["raised"] = True
        raise Interrupted()


def _handler(signum, frame):
    _flag.set()
    if _state["raising"]:
        _raise_once()


def install():
    """Routes the stop signals to the flag, which is returned. A signal
    ignored when the lab started (nohup, `&` in a script) stays ignored."""
    for number in STOP_SIGNALS:
        if signal.getsignal(number) is not signal.SIG_IGN:
            signal.signal(number, _handler)
    # The launcher starts Python with them blocked; one that came meanwhile
    # is delivered now, to the handler. Every thread and program of the lab
    # starts after this, unblocked.
    signal.pthread_sigmask(signal.SIG_UNBLOCK, STOP_SIGNALS)
    return _flag


def start_raising():
    """From here on the main thread raises Interrupted outside deferred();
    called first thing inside the `try` that catches it (a signal that came
    before is raised here)."""
    _state["raising"] = True
    check()


@contextlib.contextmanager
def deferred():
    """Inside, a signal only sets the flag; leaving does not raise (call
    check() where the caller can stop)."""
    previous = _state["raising"]
    _state["raising"] = False
    try:
        yield
    finally:
        _state["raising"] = previous


def check():
    """Raises Interrupted if a signal came (and none was raised yet)."""
    if _flag.is_set():
        _raise_once()


def close(status):
    """The final exit status. The stop signals are ignored from here on: one
    that came during the interpreter's shutdown (which gives the handlers
    back to the system) would kill the lab with 128 + its number after its
    report was written. One that came before gives 130 (finish)."""
    for number in STOP_SIGNALS:
        if signal.getsignal(number) is _handler:
            signal.signal(number, signal.SIG_IGN)
    return finish(status) if _flag.is_set() else status


def wait_for(threads, seconds):
    deadline = time.monotonic() + seconds
    for thread in threads:
        thread.join(max(0.0, deadline - time.monotonic()))


def finish(status):
    """The exit status after an interrupt: always 130; says whether the
    report had already been written (the interrupt came during the rename)."""
    _state["raising"] = False
    if status == 0:
        sys.stderr.write("odelab-report: interrupted after the report was complete; it is in place\n")
    elif status != 130:
        sys.stderr.write("odelab-report: interrupted; nothing written\n")
    sys.stdout.flush()
    sys.stderr.flush()
    if any(t.daemon and t.is_alive() for t in threading.enumerate()):
        os._exit(130)
    return 130

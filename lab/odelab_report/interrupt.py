"""Ctrl-C and SIGTERM at any moment: status 130 and nothing half-written.

The handlers only set a flag, which the main thread checks where stopping is
safe, so no KeyboardInterrupt ever lands in the middle of a write, a rename
or a thread of the lab. Threads still busy at exit (in matplotlib's C++, say)
are not unwound by the interpreter's shutdown: the process ends with
os._exit instead, which also avoids glibc's "FATAL: exception not rethrown"."""

import os
import signal
import sys
import threading
import time

_flag = threading.Event()


def _handler(signum, frame):
    _flag.set()


def install():
    """Routes SIGINT and SIGTERM to the flag, which is returned. A signal
    ignored when the lab started (nohup, `&` in a script) stays ignored."""
    numbers = (signal.SIGINT, signal.SIGTERM)
    for number in numbers:
        if signal.getsignal(number) is not signal.SIG_IGN:
            signal.signal(number, _handler)
    # The launcher starts Python with them blocked; one that came meanwhile
    # is delivered now, to the handler. Every thread and program of the lab
    # starts after this, unblocked.
    signal.pthread_sigmask(signal.SIG_UNBLOCK, numbers)
    return _flag


def wait_for(threads, seconds):
    deadline = time.monotonic() + seconds
    for thread in threads:
        thread.join(max(0.0, deadline - time.monotonic()))


def finish(status):
    """The exit status after an interrupt: always 130; says whether the
    report had already been written (the interrupt came during the rename)."""
    if status == 0:
        sys.stderr.write("odelab-report: interrupted after the report was complete; it is in place\n")
    elif status != 130:
        sys.stderr.write("odelab-report: interrupted; nothing written\n")
    sys.stdout.flush()
    sys.stderr.flush()
    if any(t.daemon and t.is_alive() for t in threading.enumerate()):
        os._exit(130)
    return 130

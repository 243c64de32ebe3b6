"""Progress on standard error: experiments done / total, elapsed time and
an estimate of the time left, weighed by each experiment's estimated cost."""

import sys
import threading
import time


class TolerantStream:
    """Standard error that may go away (a closed pipe, a terminal that is
    gone): what the lab says there is advice, and losing it must not fail
    or falsify the report. Writes that fail are dropped, silently."""

    def __init__(self, stream):
        self._stream = stream

    def write(self, text):
        try:
            return self._stream.write(text)
        except (OSError, ValueError):
            return len(text)

    def flush(self):
        try:
            self._stream.flush()
        except (OSError, ValueError):
            pass

    def isatty(self):
        try:
            return self._stream.isatty()
        except (OSError, ValueError):
            return False

    def __getattr__(self, name):
        return getattr(self._stream, name)


def clock(seconds):
    seconds = int(round(seconds))
    return f"{seconds // 60}:{seconds % 60:02d}"


class Progress:
    def __init__(self, experiments, quick, stream=None):
        self._weights = {e.name: e.cost[1 if quick else 0] for e in experiments}
        self._fractions = {e.name: 0.0 for e in experiments}
        self._done = set()
        self._started = time.monotonic()
        self._stream = stream or sys.stderr  # looked up now: main() may have wrapped it
        self._tty = self._stream.isatty()
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._loop, daemon=True)
        self._last_width = 0

    def start(self):
        self._started = time.monotonic()
        self._thread.start()

    def update(self, name, fraction):
        with self._lock:
            self._fractions[name] = max(self._fractions[name], min(fraction, 0.95))  # 1 when finished

    def finished(self, name, ok):
        with self._lock:
            self._fractions[name] = 1.0
            self._done.add(name)
        self._print(f"{'done' if ok else 'FAILED'}: {name:15s} " + self.line())

    def stop(self):
        self._stop.set()
        self._thread.join()
        if self._tty:
            self._stream.write("\r" + " " * self._last_width + "\r")
        self._stream.write(self.line() + "\n")
        self._stream.flush()

    def elapsed(self):
        return time.monotonic() - self._started

    def line(self):
        with self._lock:
            total = sum(self._weights.values()) or 1.0
            fraction = sum(self._weights[n] * f for n, f in self._fractions.items()) / total
            done = len(self._done)
            running = [n for n, f in self._fractions.items() if n not in self._done and f > 0]
        elapsed = self.elapsed()
        if fraction >= 1.0:
            left = "done"
        elif fraction > 0.02 and elapsed > 2:
            left = f"about {clock(elapsed * (1 - fraction) / fraction)} left"
        else:
            left = "estimating time left"
        text = (f"[{done}/{len(self._weights)} experiments] {100 * fraction:3.0f}%  elapsed {clock(elapsed)}, "
                f"{left}")
        if running:
            text += "  (running: " + ", ".join(running[:3]) + (" ..." if len(running) > 3 else "") + ")"
        return text

    def _print(self, message):
        with self._lock:
            if self._tty:
                self._stream.write("\r" + " " * self._last_width + "\r")
                self._last_width = 0
            self._stream.write(message + "\n")
            self._stream.flush()

    def _loop(self):
        last = 0.0
        while not self._stop.wait(1.0):
            line = self.line()
            if self._tty:
                with self._lock:
                    padding = max(0, self._last_width - len(line))
                    self._stream.write("\r" + line + " " * padding)
                    self._stream.flush()
                    self._last_width = len(line)
            elif time.monotonic() - last >= 15:
                last = time.monotonic()
                self._print(line)

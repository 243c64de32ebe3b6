"""Progress on standard error: tqdm's bar over the experiments' work,
weighed by each experiment's estimated cost, and a line as each ends."""

import sys
import threading
import time

from tqdm import tqdm


def clock(seconds):
    seconds = int(round(seconds))
    return f"{seconds // 60}:{seconds % 60:02d}"


# Without a terminal (a log, a pipe) there is no bar: a line each time the
# work done passes another tenth, so a long experiment still shows it moves.
LOG_STEP_PERCENT = 10


class Progress:
    """tqdm's bar over the experiments' weighed work, with a line for each
    experiment that ends. The bar is drawn on a terminal only; a log gets
    the lines, and one each time another tenth of the work is done."""

    def __init__(self, experiments, quick, stream=None):
        self._weights = {e.name: e.cost[1 if quick else 0] for e in experiments}
        self._fractions = {e.name: 0.0 for e in experiments}
        self._done = set()
        self._started = time.monotonic()
        self._stream = stream or sys.stderr  # looked up now: main() may have wrapped it
        self._lock = threading.Lock()
        self._bar = None
        self._logged_percent = 0

    def start(self):
        self._started = time.monotonic()
        # Counted in whole percent: whatever tqdm shows, a count reads "13/100",
        # never a weight's long fraction.
        self._bar = tqdm(total=100, file=self._stream, disable=None,
                         mininterval=1.0, dynamic_ncols=True,
                         bar_format="{desc} {percentage:3.0f}%|{bar}| elapsed {elapsed}, {remaining} left{postfix}")
        self._describe()

    def update(self, name, fraction):
        with self._lock:
            self._fractions[name] = max(self._fractions[name], min(fraction, 0.95))  # 1 when finished
            self._describe()

    def finished(self, name, ok):
        with self._lock:
            self._fractions[name] = 1.0
            self._done.add(name)
            self._describe()
        tqdm.write(f"{'done' if ok else 'FAILED'}: {name:15s} " + self.line(), file=self._stream)

    def stop(self):
        if self._bar is not None:
            self._bar.close()
        self._stream.write(self.line() + "\n")
        self._stream.flush()

    def elapsed(self):
        return time.monotonic() - self._started

    def _fraction(self):
        total = sum(self._weights.values()) or 1.0
        return sum(self._weights[n] * f for n, f in self._fractions.items()) / total

    def _running(self):
        return [n for n, f in self._fractions.items() if n not in self._done and f > 0]

    def _describe(self):
        """Moves the bar to the work done (the caller holds the lock, or it is start())."""
        if self._bar is None:
            return
        self._bar.set_description_str(f"[{len(self._done)}/{len(self._weights)} experiments]", refresh=False)
        running = self._running()
        self._bar.set_postfix_str("running: " + ", ".join(running[:3]) + (" ..." if len(running) > 3 else "")
                                  if running else "", refresh=False)
        self._bar.update(int(100 * self._fraction()) - self._bar.n)
        if self._bar.disable:
            self._log_tenths(running)

    def _log_tenths(self, running):
        """Without a terminal: a line as the work done passes each tenth (whole percentages)."""
        percent = int(100 * self._fraction()) // LOG_STEP_PERCENT * LOG_STEP_PERCENT
        if percent <= self._logged_percent or percent >= 100:
            return
        self._logged_percent = percent
        doing = ("; running: " + ", ".join(running)) if running else ""
        self._stream.write(self._line_unlocked() + doing + "\n")
        self._stream.flush()

    def line(self):
        with self._lock:
            return self._line_unlocked()

    def _line_unlocked(self):
        fraction = self._fraction()
        done = len(self._done)
        elapsed = self.elapsed()
        if fraction >= 1.0:
            left = "done"
        elif fraction > 0.02 and elapsed > 2:
            left = f"about {clock(elapsed * (1 - fraction) / fraction)} left"
        else:
            left = "estimating time left"
        return f"[{done}/{len(self._weights)} experiments] {100 * fraction:3.0f}%  elapsed {clock(elapsed)}, {left}"

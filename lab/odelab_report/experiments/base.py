"""What every experiment has: a name for --only, a section of the report,
the programs it needs, an estimate of its cost (for the time left), and
`run(ctx)`, which measures, writes its CSV and plots through `ctx`, and
returns the markdown of its part of RESULTS.md."""

import math
import threading

from .. import csvout


class Experiment:
    name = ""
    title = ""
    section = 0
    programs = ()
    # Estimated CPU seconds on this project's build machine (full, quick);
    # only used to weigh progress and estimate the time left.
    cost = (1.0, 1.0)

    def run(self, ctx):
        raise NotImplementedError


class Outcome:
    """An experiment's contribution to the report."""

    def __init__(self, markdown, headline=(), missing=(), summary=(), claims=None):
        self.markdown = markdown        # its conclusions as claims.slot(key), filled once every CSV is written
        # One-line findings for the top of RESULTS.md: each a Claim, or a list
        # of alternative Claims (the first that holds is shown).
        self.headline = list(headline)
        self.claims = dict(claims or {})  # slot key -> Claim or list of alternatives
        self.missing = list(missing)    # scene options the experiment needed and did not find
        self.summary = list(summary)    # rows for a table across a section's experiments


class Context:
    def __init__(self, runner, quick, out_dir, header, progress, experiment_name):
        self.runner = runner
        self.quick = quick
        self.out_dir = out_dir
        self.header = header
        self._progress = progress
        self._name = experiment_name
        self._done = 0
        self._total = 0
        self._lock = threading.Lock()
        self.files = []  # what this experiment wrote, relative to out_dir

    # ---- progress ---------------------------------------------------------------
    def expect(self, units):
        """Announces `units` more units of work (runs, searches...)."""
        with self._lock:
            self._total += units
        self._report()

    def advance(self, units=1):
        with self._lock:
            self._done += units
        self._report()

    def search_units(self, expected_probes):
        """For a search of about `expected_probes` runs: announces them and
        returns (on_probe, finished) callbacks that keep the progress true."""
        self.expect(expected_probes)
        made = [0]

        def on_probe():
            made[0] += 1
            if made[0] <= expected_probes:
                self.advance()

        def finished():
            self.advance(max(0, expected_probes - made[0]))

        return on_probe, finished

    def _report(self):
        if self._progress and self._total:
            self._progress.update(self._name, min(1.0, self._done / self._total))

    # ---- output -------------------------------------------------------------------
    def write_csv(self, stem, columns, rows, notes=()):
        name = stem + ".csv"
        csvout.write_csv(self.out_dir / name, self.header, columns, rows, notes)
        self.files.append(name)
        return name

    def register_files(self, names):
        self.files.extend(names)


def log_space(start, stop, count):
    """`count` values log-spaced from start to stop, both included, rounded to 3 digits."""
    if count == 1:
        return [start]
    a, b = math.log10(start), math.log10(stop)
    return [float("%.3g" % 10 ** (a + (b - a) * i / (count - 1))) for i in range(count)]

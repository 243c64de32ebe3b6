"""Sentences from data. A sentence of the report is a Claim: a template whose
figures are named lookups into the CSVs of the report folder (or expressions
over other names), and a rule over those figures. The sentence appears only
when its rule holds; every sentence shown goes to claims.csv with its
lookups and rule, so that check_report.py can recompute the text and the
rule from the CSVs alone, on this report or a committed one.

A lookup is {"file": "limit-test4.csv", "column": "heaviest_held_kg",
"where": {"solver": "QuickStep 20", "step_s": 0.001}, "agg": "one"}: the
rows whose cells equal `where` (numbers compared as numbers), and of their
`column` exactly one ("one", the default), all as a list ("list"), their
"median", "min", "max", "count", or as text ("text" for one cell,
"texts" for a list)."""

import csv
import json
import math
import re
import statistics
import string
from pathlib import Path

from . import markdown as md

_SAFE = {"abs": abs, "min": min, "max": max, "all": all, "any": any, "len": len, "sorted": sorted,
         "sum": sum, "round": round, "zip": zip, "range": range, "enumerate": enumerate, "math": math, "str": str,
         "float": float}


def cheapest(names, errors, cost, lo, hi, level, default=None):
    """The settings whose error is at most `level` and whose cost could be
    the lowest: the cheapest by its median cost, and every other whose
    fastest run (`lo`) is not slower than the cheapest's slowest (`hi`), a
    tie within the timing's scatter; the default first when it is one."""
    eligible = [i for i, e in enumerate(errors) if e is not None and cost[i] is not None and e <= level]
    if not eligible:
        return "none measured"
    best = min(eligible, key=lambda i: cost[i])
    tied = sorted((i for i in eligible if lo[i] <= hi[best]), key=lambda i: (names[i] != default, cost[i]))
    text = ", ".join(f"{names[i]} ({md.num(cost[i], 2)} s/s)" for i in tied)
    return text if len(tied) == 1 else "a tie within the timing's scatter: " + text


def best_of(engines, values, cost, higher_better):
    """Among other engines' rows, the index of the best value (the cheapest
    of equals)."""
    order = sorted(range(len(values)), key=lambda i: ((-values[i] if higher_better else values[i]), cost[i]))
    return order[0]


def best_or_tie(values, lo, hi):
    """The one rule for naming a winner (lower is better): the indices of
    the best value and of every other whose range [lo, hi] (its measured
    spread) reaches the best's; the best is named alone only when it beats
    every other by more than their spreads. None values take no part; []
    when none has a value."""
    known = [i for i, v in enumerate(values) if v is not None]
    if not known:
        return []
    best = min(known, key=lambda i: values[i])
    return [best] + sorted((i for i in known if i != best and lo[i] <= hi[best]), key=lambda i: values[i])


def cheapest_set(errors, cost, lo, hi, level):
    """The indices `cheapest` names, cheapest first: one, or a tie within the
    timing's scatter; empty when no setting reaches `level`."""
    eligible = [i for i, e in enumerate(errors) if e is not None and cost[i] is not None and e <= level]
    if not eligible:
        return []
    best = min(eligible, key=lambda i: cost[i])
    return [best] + sorted((i for i in eligible if i != best and lo[i] <= hi[best]), key=lambda i: cost[i])


def speed_options(solver, step, scene_options):
    """The options of a speed-accuracy point's timed runs but --seconds
    (experiments/speed_accuracy.py: the scene's, the solver's, the step)."""
    chosen = {"--solver": "step"} if solver == "dWorldStep" else {"--solver": "quick",
                                                                  "--iterations": solver.split()[-1]}
    return dict(scene_options, **chosen, **{"--step": step})


def runs_cost(runs, wanted, sim_seconds):
    """CPU seconds per simulated second of the timed runs of one point:
    `runs` is runs.csv's columns as lists (arguments, cpu_seconds,
    sim_seconds, cpu_share, repeat), `wanted` every option but --seconds,
    `sim_seconds` their simulated length. Of two runs of one repeat (a retry
    of a run the machine slowed) the one with the larger CPU share counts, as
    the lab keeps it. [median, min, max, runs]."""
    kept = {}
    for args, cpu, sim, share, repeat in zip(*runs):
        words = (args or "").split()
        options = {w: words[i + 1] for i, w in enumerate(words[:-1]) if w.startswith("--")}
        options.pop("--seconds", None)
        if (cpu is None or not sim or set(options) != set(wanted) or not math.isclose(sim, sim_seconds, rel_tol=1e-6)
                or not all(_matches(options[k], v) for k, v in wanted.items())):
            continue
        if repeat not in kept or (share or 0) > kept[repeat][1]:
            kept[repeat] = (cpu / sim, share or 0)
    costs = [cost for cost, _ in kept.values()]
    if not costs:
        raise ValueError(f"no run with {wanted} of {sim_seconds} s")
    return [statistics.median(costs), min(costs), max(costs), len(costs)]


_SAFE.update(median=statistics.median, cheapest=cheapest, cheapest_set=cheapest_set, best_of=best_of,
             best_or_tie=best_or_tie, num=md.num,
             pct=md.pct, speed_options=speed_options, runs_cost=runs_cost, dict=dict)


def read_rows(path):
    """The rows of a report CSV (its `# ` header lines skipped)."""
    with open(path, newline="") as stream:
        return list(csv.DictReader(line for line in stream if not line.startswith("#")))


def _number(cell):
    try:
        return float(cell)
    except (TypeError, ValueError):
        return None


def _matches(cell, wanted):
    if isinstance(wanted, (int, float)) and not isinstance(wanted, bool):
        value = _number(cell)
        return value is not None and math.isclose(value, wanted, rel_tol=1e-9, abs_tol=1e-15)
    return cell == str(wanted)


class Data:
    """The CSVs of one report folder, read once each."""

    def __init__(self, folder):
        self.folder = Path(folder)
        self._rows = {}

    def has(self, name):
        return (self.folder / name).exists()

    def rows(self, name):
        if name not in self._rows:
            self._rows[name] = read_rows(self.folder / name) if self.has(name) else []
        return self._rows[name]

    def lookup(self, spec):
        if not self.has(spec["file"]):
            raise LookupError(f"{spec['file']}: not in this report")
        rows = [row for row in self.rows(spec["file"])
                if all(_matches(row.get(k), v) for k, v in spec.get("where", {}).items())]
        agg = spec.get("agg", "one")
        if agg == "count":
            return len(rows)
        cells = [row.get(spec["column"]) for row in rows]
        if agg == "texts":
            return cells
        if agg in ("one", "text"):
            if len(cells) != 1:
                raise LookupError(f"{spec['file']}: {len(cells)} rows match {spec.get('where', {})} "
                                  f"for {spec['column']}, expected one")
            return cells[0] if agg == "text" else _float(cells[0], spec)
        if agg == "list":  # an empty cell is None: a run that gave no figure
            return [None if c in ("", None) else _float(c, spec) for c in cells]
        values = [_float(c, spec) for c in cells]
        if not values:
            raise LookupError(f"{spec['file']}: no row matches {spec.get('where', {})} for {spec['column']}")
        return {"median": statistics.median(values), "min": min(values), "max": max(values)}[agg]

    def available(self, specs):
        """Whether every lookup among `specs` finds its data."""
        try:
            for spec in specs.values():
                if isinstance(spec, dict):
                    self.lookup(spec)
        except (LookupError, ValueError):
            return False
        return True


def _float(cell, spec):
    value = _number(cell)
    if value is None:
        raise ValueError(f"{spec['file']}: {spec['column']} = {cell!r} is not a number")
    return value


def q(file, column, agg="one", **where):
    """A lookup, written compactly."""
    return {"file": file, "column": column, "where": where, "agg": agg}


class _Formatter(string.Formatter):
    """str.format with the report's number styles: `{x:n}` / `{x:n2}` a number
    with 3 / 2 significant digits (markdown.num), `{x:p}` / `{x:p3}` a share
    as a percentage (markdown.pct), `{x:r}` a list of numbers as its range
    'a to b', `{x:k2}` a number in few characters (markdown.short: 9.3e-5)."""

    def format_field(self, value, spec):
        if spec[:1] in ("n", "p", "r", "k") and (spec[1:].isdigit() or spec[1:] == ""):
            digits = int(spec[1:] or (2 if spec[0] == "p" else 3))
            if spec[0] == "n":
                return md.num(value, digits)
            if spec[0] == "p":
                return md.pct(value, digits)
            if spec[0] == "k":
                return md.short(value, digits)
            low, high = md.num(min(value), digits), md.num(max(value), digits)
            return f"{low} to {high}" if low != high else f"all {low}"
        return super().format_field(value, spec)


FORMAT = _Formatter()


def _eval(expression, env):
    # One namespace (no separate locals), so that comprehensions see every name.
    return eval(expression, {"__builtins__": {}, **_SAFE, **env})


class Claim:
    """One sentence: `template` filled from `values` (name -> lookup, or an
    expression over earlier names), shown when `rule` holds."""

    def __init__(self, key, template, values, rule="True"):
        self.key, self.template, self.values, self.rule = key, template, dict(values), rule

    def evaluate(self, data):
        """(text, holds); LookupError/ValueError when the data are absent."""
        env = {}
        for name, spec in self.values.items():
            env[name] = data.lookup(spec) if isinstance(spec, dict) else _eval(spec, env)
        holds = bool(_eval(self.rule, env))
        return FORMAT.format(self.template, **env), holds

    def row(self, data):
        text, holds = self.evaluate(data)
        return dict(key=self.key, text=text, rule=self.rule, holds=int(holds), template=self.template,
                    values=json.dumps(self.values))


FIRST_TABLE = "first table"  # where a claim shown in the table at the top stands
HEADLINE = "headline"        # ... in the headline findings
DECIDES = "what decides"     # ... in the table of what decides each figure, below the first screen
_SLOT = re.compile(r"\[\[claim:([\w.+-]+)\]\]")


def slot(key):
    """Where the sentence of the claims under `key` goes in an experiment's
    markdown: Sentences.fill replaces it once every CSV is written."""
    return f"[[claim:{key}]]"


class Sentences:
    """The claims a report shows, for claims.csv."""

    def __init__(self, data):
        self.data = data
        self.shown = []

    def say(self, *alternatives, place=FIRST_TABLE):
        """The text of the first alternative whose data exist and whose rule
        holds, or None; the claim shown is recorded with where it stands."""
        for claim in alternatives:
            try:
                row = claim.row(self.data)
            except (LookupError, ValueError, ZeroDivisionError):
                continue
            if row["holds"]:
                self.shown.append(dict(row, place=place))
                return row["text"]
        return None

    def fill(self, text, claims, place):
        """`text` with each slot(key) replaced by the sentence of the first of
        claims[key] (a Claim or a list of alternatives) that holds; a slot
        whose claims all fail is left empty: no sentence rather than a false one."""
        def sentence(match):
            alternatives = claims[match.group(1)]
            if isinstance(alternatives, Claim):
                alternatives = [alternatives]
            return self.say(*alternatives, place=place) or ""
        return _SLOT.sub(sentence, text)

    COLUMNS = ["key", "text", "rule", "holds", "template", "values", "place"]


def recheck(folder, rows):
    """For check_report.py: each claims.csv row recomputed from the CSVs of
    `folder`; a list of problems."""
    data = Data(folder)
    problems = []
    for row in rows:
        claim = Claim(row["key"], row["template"], json.loads(row["values"]), row["rule"])
        try:
            text, holds = claim.evaluate(data)
        except Exception as error:  # a claim whose data went missing is a problem, whatever the error
            problems.append(f"claim {row['key']}: cannot be evaluated: {error}")
            continue
        if not holds:
            problems.append(f"claim {row['key']}: its rule `{row['rule']}` does not hold on the CSVs")
        if text != row["text"]:
            problems.append(f"claim {row['key']}: the CSVs give '{text}', the report says '{row['text']}'")
    return problems

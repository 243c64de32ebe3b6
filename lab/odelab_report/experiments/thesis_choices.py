"""The thesis's unstated choices, swept (issue 12): for the thesis's figures
the lab does not reproduce, each plausible choice the thesis never states
(contact friction, how an energy is computed, the step, a mass marked
"proposed") is varied over a stated range, and the report says which values
reproduce the thesis's figure and how far the figure moves. Also the ODE
0.11.1 rebuild's figure for each row, read from lab/reference/."""

import csv
import re
from pathlib import Path

from .. import markdown as md
from ..runner import RunSpec

REBUILD = Path(__file__).resolve().parents[2] / "reference" / "ode-0.11.1-rebuild.csv"
FIGURES = Path(__file__).resolve().parents[2] / "reference" / "thesis-figures.csv"
CHOICES = Path(__file__).resolve().parents[2] / "reference" / "unstated-choices.csv"
CLOSE = 1.5  # as thesis.py: "about X" is reproduced within this factor

# Which rows of the rebuild's file speak to which row of the thesis's
# figures: (test, the rebuild row's conditions exactly, and optionally a
# part of its quantity). Selection only: the figures come from the file.
REBUILD_ROWS = {
    "test2": [("test2", "ERP 0.4, CFM 0, step 0.001, 60 s")],
    "test4_fast": [("test4", "step 0.001, mu dInfinity"), ("test4", "step 0.001, QuickStep 20, mu dInfinity"),
                   ("test4", "mu 1", "step 0.001")],
    "test4_small": [("test4", "step 0.0001, QuickStep 20, mu dInfinity"), ("test4", "mu 1", "step 0.0001")],
    "test6": [("test6", "defaults")],
    "test7": [("test7", "defaults, max angular speed 10")],
    "test8_a": [("test8", "ERP 0.4, CFM 1e-4, 60 s")],
    "test8_b": [("test8", "ERP 1.0, CFM 0, 60 s")],
    "test9_a": [("test9", "CFM 0")],
    "test9_b": [("test9", "CFM 1e-6")],
    "test10_a": [("test10", "step 0.001")],
    "test10_b": [("test10", "step 0.0001")],
}


def rebuild_rows():
    return read_csv(REBUILD)


def rebuild_commit():
    """The project commit whose programs made the rebuild's figures, as its
    file's header says ("as of commit X")."""
    found = re.search(r"as of commit (\w+)", REBUILD.read_text())
    return found.group(1) if found else "unknown"


def rebuild_figure(row_key, rows):
    """The ODE 0.11.1 rebuild's figures for a thesis row, "-" when it has none."""
    found = []
    for test, conditions, *quantity in REBUILD_ROWS.get(row_key, []):
        for row in rows:
            if row["test"] == test and row["conditions"] == conditions and all(q in row["quantity"] for q in quantity):
                text = f"{row['quantity']}: {row['ode_0_11_1_rebuilt']}"
                found.append(text + (f" ({row['note']})" if row["note"] else ""))
    return "; ".join(found) or "-"


def read_csv(path):
    with open(path, newline="") as stream:
        return list(csv.DictReader(line for line in stream if not line.startswith("#")))


def default_of(program, choice):
    """ "default (source)" for a scene's choice, from unstated-choices.csv;
    `choice` may carry a qualifier after the name ("contact mu at 15 t")."""
    for row in read_csv(CHOICES):
        if row["program"] == program and choice.startswith(row["choice"]):
            return f"{row['default']}, {row['source']}"
    raise RuntimeError(f"lab/reference/unstated-choices.csv has no {program} '{choice}'")


def stated_by_thesis(program, choice):
    """Whether the thesis states this choice (its source in
    unstated-choices.csv names a thesis section): another value of it then
    measures sensitivity and never reproduces the thesis."""
    return default_of(program, choice).split(", ", 1)[1].startswith("thesis")


def figure_of(test, conditions_start):
    """The thesis's figures (numbers) of the row of thesis-figures.csv for
    `test` whose conditions start so."""
    for row in read_csv(FIGURES):
        if row["test"] == test and row["conditions"].startswith(conditions_start) and row["figure"]:
            return [float(x) for x in row["figure"].split("/")]
    raise RuntimeError(f"lab/reference/thesis-figures.csv has no figure for {test} '{conditions_start}...'")


def within(value, target):
    return value is not None and target > 0 and 1 / CLOSE <= value / target <= CLOSE


class Sweep:
    """One unstated choice of one row: `values` are (label, extra arguments)
    added to `base`; `figure(result)` gives (text, reproduces)."""

    def __init__(self, row, choice, base, values, figure):
        self.row, self.choice, self.base, self.values = row, choice, base, values
        self.figure = figure
        self.default_label = default_of(base.program, choice)
        self.stated = stated_by_thesis(base.program, choice)

    def specs(self):
        return {f"sweep:{self.row}:{self.choice}:{label}": RunSpec(self.base.program, [*self.base.args, *extra])
                for label, extra in self.values}

    def summary(self, results):
        parts, reproducing = [], []
        for label, _ in self.values:
            text, ok = self.figure(results[f"sweep:{self.row}:{self.choice}:{label}"])
            parts.append(f"{label}: {text}")
            if ok and not self.stated:
                reproducing.append(label)
        said = f"{self.choice} (default {self.default_label}) varied: " + ", ".join(parts)
        if self.stated:
            said += " (the thesis states this value: another one shows the sensitivity, never a reproduction)"
        return said, reproducing


def held_text(result):
    return ("holds " + format(result.m("seconds_held"), ".3g") + " s" if result.m("held")
            else "falls after " + format(result.m("seconds_held"), ".3g") + " s")


def sweeps(quick, h4, s8):
    """Every sweep, by the thesis row it speaks to."""
    t2 = RunSpec("test2", ["--erp", 0.4, "--cfm", 0, "--step", 0.001, "--seconds", 60, "--sample-interval", 3600])
    t4 = RunSpec("test4", ["--big-mass", 5000.0, "--step", 1e-3, "--solver", "quick", "--iterations", 20,
                           "--seconds", float(h4)])
    mus = [0.5, 1, 2] if quick else [0.3, 0.5, 1, 2, 5]

    def energy(result):
        value = result.m("energy_rel_variation")
        return md.pct(value, 2), within(value, figure_of("test2", "ERP 0.4, CFM 0")[0])

    def elongation(target):
        def figure(result):
            value = result.m("max_relative_elongation")
            return format(value, ".3g"), within(value, target)
        return figure

    def bounce_errors(result):
        e5, e10, e20 = (result.m(f"apex_error_{n}") for n in (5, 10, 20))
        f5, f10, f20 = figure_of("test9", "CFM 1e-6")
        ok = within(e5, f5) and within(e10, f10) and e20 is not None and e20 > f20
        return f"{md.pct(e5, 2)} / {md.pct(e10, 2)} / {md.pct(e20, 2)}", ok

    def t8(erp, cfm, extra):
        return RunSpec("test8", ["--erp", erp, "--cfm", cfm, "--seconds", s8, "--sample-interval", 3600, *extra])

    found = [
        Sweep("test2", "kinetic energy", t2,
              [("with rotation", []), ("without rotation", ["--no-rotational-energy"])], energy),
        # The rig's shape (proposed): how much of the kinetic energy is spin
        # about the centre of mass, which is what the omission leaves out.
        Sweep("test2", "rod mass without rotation", t2,
              [(f"rod {m:g} kg without rotation", ["--no-rotational-energy", "--rod-mass", m])
               for m in (0.01, 0.015, 0.02, 0.05)],
              energy),
        Sweep("test2", "bob radius without rotation", t2,
              [(f"bob radius {r:g} m without rotation", ["--no-rotational-energy", "--bob-radius", r])
               for r in (0.1, 0.5)],
              energy),
        Sweep("test2", "rod mass with rotation", t2, [("rod 0.015 kg, with rotation", ["--rod-mass", 0.015])],
              energy),
        Sweep("test4_fast", "contact mu", t4, [(f"mu {m:g}", ["--mu", m]) for m in mus],
              lambda r: (held_text(r), not r.m("held"))),
        Sweep("test4_fast", "contacts per pair", t4, [(f"{n} per pair", ["--max-contacts", n]) for n in (1, 4)],
              lambda r: (held_text(r), not r.m("held"))),
        Sweep("test8_a", "bob mass", t8(0.4, 1e-4, ["--step", 0.001]),
              [(f"bob {m:g} kg", ["--bob-mass", m]) for m in (500.0, 1000.0)], elongation(figure_of("test8", "ERP 0.4, CFM 1e-4")[0])),
        Sweep("test8_a", "step", t8(0.4, 1e-4, ["--bob-mass", 5000.0]),
              [(f"step {s:g}", ["--step", s]) for s in (0.0005, 0.0001)],
              elongation(figure_of("test8", "ERP 0.4, CFM 1e-4")[0])),
        Sweep("test8_b", "step", t8(1.0, 0.0, ["--bob-mass", 5000.0]),
              [(f"step {s:g}", ["--step", s]) for s in (0.0005, 0.00025, 0.0001)], elongation(figure_of("test8", "ERP 1.0, CFM 0")[0])),
        Sweep("test9_b", "step", RunSpec("test9", ["--erp", 0.2, "--cfm", 1e-6, "--seconds", 25]),
              [(f"step {s:g}", ["--step", s]) for s in (0.0005, 0.002)], bounce_errors),
    ]
    # The thesis's figure at step 0.0001: 15 t held (and 75 t "with
    # hopping"); a mu reproduces it when 15 t holds and 150 t does not.
    small = RunSpec("test4", ["--step", 1e-4, "--solver", "quick", "--iterations", 20, "--seconds", float(h4)])
    for mass, should_hold in ((15000.0, True), (150000.0, False)):
        found.append(Sweep("test4_small", f"contact mu at {mass / 1000:g} t", small,
                           [(f"mu {m:g}", ["--big-mass", mass, "--mu", m]) for m in ((1, 5) if quick else (1, 2, 5))],
                           lambda r, hold=should_hold: (held_text(r), bool(r.m("held")) == hold)))
    return found


def sensitivity(row_key, sweep_list, results, derived=""):
    """(sensitivity text, the values that reproduce the figure) for a row."""
    texts, verdicts = [], {}
    for sweep in sweep_list:
        if sweep.row != row_key:
            continue
        said, ok = sweep.summary(results)
        texts.append(said)
        # A value swept in several runs of one row (mu at two masses)
        # reproduces the figure only if it does in every one of them.
        for label, _ in sweep.values:
            if not sweep.stated:
                verdicts[label] = verdicts.get(label, True) and label in ok
    reproducing = [label for label, ok in verdicts.items() if ok]
    if derived:
        texts.append(derived)
    if texts:
        texts.append("the thesis's figure is reproduced with " + ", ".join(reproducing) if reproducing
                     else "no value swept reproduces the thesis's figure")
    return "; ".join(texts), reproducing

"""The thesis quoted: every statement row of lab/reference/thesis-statements.csv
quotes the thesis verbatim and points at a row of the report or says why it
has none, and every figure lab/reference/thesis-figures.csv attributes to
the thesis is written in a quoted sentence.

The quotes are held to the thesis's text where it is on this machine
(ODELAB_THESIS_TEXT, else the seed copy in the shared folder beside the
checkout); the figures are held to
the quotes everywhere.
Run: /usr/bin/python3 -m unittest discover -s lab/tests."""

import csv
import glob
import math
import os
import re
import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

REFERENCE = Path(__file__).resolve().parents[1] / "reference"
STATEMENTS = REFERENCE / "thesis-statements.csv"
FIGURES = REFERENCE / "thesis-figures.csv"
# The project's shared folder lies beside the checkout (and beside CI's clone).
SEED_GLOB = str(Path(__file__).resolve().parents[2].parent / "shared" / "seeds" / "000_*.txt")

# Rows of thesis-figures.csv, in order (as thesis.ROW_KEYS, read here without
# importing the experiments, which need matplotlib).
HAVOK_TESTS = ("test1", "test2", "test4", "test5", "test6", "test7", "test9", "test10")
REASONS = ("not yet measured", "not checkable")

from odelab_report.thesis_quotes import number_of, quoted  # noqa: E402  (light: no experiments imported)

# A number as the reference texts write one: not inside a word (test8), with
# an optional exponent and percent sign.
NUMBER = re.compile(r"(?<![\w.])\d+(?:\.\d+)?(?:e-?\d+)?%?")


def numbers_in(text):
    return [float(x[:-1]) / 100 if x.endswith("%") else float(x) for x in NUMBER.findall(text)]


def read(path):
    with open(path, newline="", encoding="utf-8") as stream:
        return list(csv.DictReader(stream))


def thesis_text():
    path = os.environ.get("ODELAB_THESIS_TEXT") or next(iter(sorted(glob.glob(SEED_GLOB))), None)
    return Path(path).read_text(encoding="utf-8") if path and Path(path).is_file() else None


def row_keys():
    """thesis.csv's keys in the order of thesis-figures.csv's rows."""
    thesis = Path(__file__).resolve().parents[1] / "odelab_report" / "experiments"
    figures = re.search(r"ROW_KEYS = \[(.*?)\] \+ claims\.KEYS", (thesis / "thesis.py").read_text(), re.S)
    claims = re.search(r"^KEYS = \[(.*?)\]", (thesis / "thesis_claims.py").read_text(), re.S | re.M)
    return [k for block in (figures, claims) for k in re.findall(r'"(\w+)"', block.group(1))]


def tokens_for(statements, target):
    """(token, value) of every figure the statements pointing at target quote."""
    return [(t, number_of(t)) for s in statements if target in s["rows"].split()
            for t in filter(None, s["figures"].split(";"))]


def close(a, b):
    return math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-15)


class StatementRows(unittest.TestCase):
    def setUp(self):
        self.statements = read(STATEMENTS)

    def test_every_quote_is_verbatim_in_the_thesis(self):
        text = thesis_text()
        if text is None:
            self.skipTest(f"the thesis's text is not on this machine (ODELAB_THESIS_TEXT or {SEED_GLOB})")
        for s in self.statements:
            self.assertIn(s["quote"], text, f"section {s['section']}: not verbatim in the thesis")

    def test_every_statement_has_a_row_or_a_reason(self):
        keys, sections = set(row_keys()), set()
        for s in self.statements:
            sections.add(s["section"])
            self.assertTrue(s["quote"] and s["claim"], s)
            if s["rows"]:
                self.assertEqual(s["reason"], "", s["quote"])
                for target in s["rows"].split():
                    name, key = target.split(":")
                    self.assertIn(name, ("thesis.csv", "thesis-havok.csv"), target)
                    self.assertIn(key, keys if name == "thesis.csv" else HAVOK_TESTS, target)
            else:
                self.assertTrue(s["reason"].startswith(REASONS), f"{s['quote']}: no row and no stated reason")
        self.assertEqual(sections, {"2", *(f"5.{n}" for n in range(1, 12)), "6"})
        self.assertGreaterEqual(len(self.statements), 60)

    def test_every_written_figure_is_in_its_quote(self):
        for s in self.statements:
            for token in filter(None, s["figures"].split(";")):
                self.assertIn(token, s["quote"])
                number_of(token)  # parses

    def test_every_report_row_is_quoted(self):
        quoted = {t for s in self.statements for t in s["rows"].split()}
        for key in row_keys():
            self.assertIn(f"thesis.csv:{key}", quoted, "a thesis.csv row with no quoted sentence")
        for test in HAVOK_TESTS:
            self.assertIn(f"thesis-havok.csv:{test}", quoted)


class ThesisFiguresAreQuoted(unittest.TestCase):
    """No figure attributed to the thesis that a quoted sentence does not give."""

    def test_each_figure_is_a_quoted_figure(self):
        statements, rows = read(STATEMENTS), read(FIGURES)
        keys = row_keys()
        self.assertEqual(len(keys), len(rows))
        for key, row in zip(keys, rows):
            quoted = tokens_for(statements, f"thesis.csv:{key}")
            havok = quoted + tokens_for(statements, f"thesis-havok.csv:{row['test']}")
            claimed = [("figure", float(x), quoted) for x in filter(None, row["figure"].split("/"))]
            claimed += [("ode_0_11_1_thesis", x, quoted) for x in numbers_in(row["ode_0_11_1_thesis"])]
            claimed += [("havok_6_5_quoted_by_thesis", x, havok) for x in numbers_in(row["havok_6_5_quoted_by_thesis"])]
            for column, value, tokens in claimed:
                self.assertTrue(any(close(value, v) for _, v in tokens),
                                f"{key}: {column} gives {value:g}, which no quoted sentence of the row writes "
                                f"(quoted: {[t for t, _ in tokens]})")

    def test_a_lab_figure_given_as_the_thesiss_fails(self):
        # The old test8_mass row: the lab's own 3.47e-5 to 3.55e-5 as the thesis's.
        statements = read(STATEMENTS)
        tokens = tokens_for(statements, "thesis.csv:test8_mass")
        for value in numbers_in("3.47e-5 to 3.55e-5 whatever the mass"):
            self.assertFalse(any(close(value, v) for _, v in tokens))

    def test_numbers_as_the_thesis_writes_them(self):
        self.assertEqual(number_of("0.75%"), 0.0075)
        self.assertEqual(number_of("10\u22123"), 1e-3)
        self.assertEqual(number_of("3630.0 ms\u22121"), 3630.0)
        self.assertEqual(numbers_in("dips (test8) at 0.75% (min 29.250 J), 1e-6"), [0.0075, 29.25, 1e-6])


class ExperimentsJudgeByQuotedFigures(unittest.TestCase):
    """The figures the experiments judge the thesis by are read from the
    quoted sentences, not typed: a typed one would escape the checks above."""

    EXPERIMENTS = Path(__file__).resolve().parents[1] / "odelab_report" / "experiments"
    # The thesis's figures and settings each module compares with or runs at.
    READ = {"thesis_claims.py": ("THESIS_GAIN", "THESIS_HALVES", "THESIS_TENFOLD", "MASSES", "CFM_SMALL",
                                 "AUTO_DISABLE", "CAP"),
            "thesis_havok.py": ("THESIS_LOST", "THESIS_HAVOK_KG", "THESIS_HAVOK_MS")}

    def test_each_thesis_figure_is_read_from_a_quote(self):
        for module, names in self.READ.items():
            source = (self.EXPERIMENTS / module).read_text()
            for name in names:
                assignment = re.search(rf"^{name} = (.*)$", source, re.M)
                self.assertIsNotNone(assignment, f"{module}: no {name}")
                self.assertIn("quoted(", assignment.group(1), f"{module}: {name} is typed, not read from a quote")
        # Any other THESIS_ constant is a thesis figure too.
        for path in self.EXPERIMENTS.glob("*.py"):
            for name, value in re.findall(r"^(THESIS_\w+) = (.*)$", path.read_text(), re.M):
                self.assertIn("quoted(", value, f"{path.name}: {name} is typed, not read from a quote")

    def test_the_values_read(self):
        self.assertEqual(quoted("thesis.csv:test3_iterations_on", "20%"), 0.2)
        self.assertEqual(quoted("thesis.csv:test8_mass", "1000 tun"), 1e6)
        self.assertEqual(quoted("thesis.csv:test1_cfm6", "10\u22126"), 1e-6)
        self.assertEqual(quoted("thesis-havok.csv:test10", "350 ms\u22121"), 350.0)

    def test_a_figure_no_quote_lists_fails(self):
        with self.assertRaises(ValueError):
            quoted("thesis.csv:test3_iterations_on", "25%")
        with self.assertRaises(ValueError):  # quoted, but for another row
            quoted("thesis.csv:test10_step", "20%")


if __name__ == "__main__":
    unittest.main()

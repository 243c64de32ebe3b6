"""Unit checks that the docs cite the CSV row they quote (check_docs.py): a
figure in a citation link must be in the row its key selects, not merely in
some committed CSV; a page not marked `uncited` must cite every measured
figure.
Run: /usr/bin/python3 -m unittest discover -s lab/tests (CTest: lab_executor_units)."""

import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import check_docs  # noqa: E402

LIMITS = "# ODE: test\nsolver,step_s,heaviest_held_kg\nQuickStep 20,0.001,11892\ndWorldStep,0.001,1970000\n"


class DocCitations(unittest.TestCase):
    def setUp(self):
        self.root = Path(tempfile.mkdtemp())
        (self.root / "doc" / "results").mkdir(parents=True)
        (self.root / "doc" / "results" / "limit-test4.csv").write_text(LIMITS)
        subprocess.run(["git", "init", "-q", str(self.root)], check=True)
        subprocess.run(["git", "-C", str(self.root), "add", "doc/results/limit-test4.csv"], check=True)

    def problems(self, text, pending=""):
        (self.root / "doc" / "page.md").write_text(text)
        if pending:
            (self.root / "lab" / "reference").mkdir(parents=True, exist_ok=True)
            (self.root / "lab" / "reference" / "docs-pending.txt").write_text(pending)
        return [p for waiting, p in check_docs.check(self.root)[0] if not waiting]

    def test_a_figure_from_the_row_it_cites_passes(self):
        text = "QuickStep holds [11900 kg](results/limit-test4.csv#solver=QuickStep%2020&step_s=0.001).\n"
        self.assertEqual(self.problems(text), [])

    def test_a_figure_from_another_row_fails(self):
        # 1.97e6 is in the CSV, but in dWorldStep's row, not QuickStep's.
        text = "QuickStep holds [1.97e6 kg](results/limit-test4.csv#solver=QuickStep%2020&step_s=0.001).\n"
        problems = self.problems(text)
        self.assertEqual(len(problems), 1, problems)
        self.assertIn("1.97e6 kg is not in the row 'solver=QuickStep%2020&step_s=0.001'", problems[0])

    def test_a_key_that_selects_no_row_or_a_csv_not_committed_fails(self):
        missing_row = self.problems("[11900 kg](results/limit-test4.csv#solver=QuickStep%2010)\n")
        self.assertTrue(any("selects no row" in p for p in missing_row), missing_row)
        missing_column = self.problems("[11900 kg](results/limit-test4.csv#iterations=20)\n")
        self.assertTrue(any("a column it names is not in the CSV" in p for p in missing_column), missing_column)
        elsewhere = self.problems("[11900 kg](results/other.csv#solver=QuickStep%2020)\n")
        self.assertTrue(any("no committed CSV" in p for p in elsewhere), elsewhere)

    def test_an_uncited_figure_fails_unless_the_page_is_pending(self):
        text = "QuickStep holds 11900 kg.\n"
        problems = self.problems(text)
        self.assertEqual(len(problems), 1, problems)
        self.assertIn("11900 kg cites no CSV row", problems[0])
        self.assertEqual(self.problems(text, "doc/page.md uncited  # not cited yet\n"), [])

    def test_a_citation_in_a_code_span_is_an_example(self):
        self.assertEqual(self.problems("the form: `[figure](path.csv#column=value)`.\n"), [])


if __name__ == "__main__":
    unittest.main()

"""lab/refresh_doc_figures.py: a regenerated report's figures reach the docs
that quote them, each cited by its row; what cannot be placed is left for a
person, never guessed."""

import contextlib
import io
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
import check_docs  # noqa: E402
import refresh_doc_figures  # noqa: E402

OLD = """# header: a run header line
scene,setting,wall_seconds,energy_J
test1,plain,12.34,0.5531
test1,ccd,15.02,0.6148
"""
NEW = """# header: the new run
scene,setting,wall_seconds,energy_J
test1,plain,12.71,0.5531
test1,ccd,15.96,0.6203
"""
PAGE = """# A page

The plain run takes 12.34 s (see [the CSV](results/speed.csv)); with CCD
[15.02 s](results/speed.csv#scene=test1&setting=ccd). The energy 0.6148 J
and a short figure 0.55 stay where they were; 9.823 is the code's gravity.
"""


class RefreshDocFigures(unittest.TestCase):
    def setUp(self):
        self.root = Path(tempfile.mkdtemp())
        (self.root / "doc" / "results").mkdir(parents=True)
        (self.root / "src").mkdir()
        (self.root / "src" / "gravity.h").write_text("const double g = 9.823;\n")
        (self.root / "doc" / "results" / "speed.csv").write_text(OLD)
        (self.root / "doc" / "page.md").write_text(PAGE)
        (self.root / "README.md").write_text("# Readme\n")
        git = ["git", "-C", str(self.root), "-c", "user.name=t", "-c", "user.email=t@t"]
        subprocess.run(git[:3] + ["init", "-q"], check=True)
        subprocess.run(git + ["add", "-A"], check=True)
        subprocess.run(git + ["commit", "-qm", "old report"], check=True)
        (self.root / "doc" / "results" / "speed.csv").write_text(NEW)

    def refresh(self, *extra):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            status = refresh_doc_figures.main(["--from", "HEAD", "--root", str(self.root), *extra])
        return status, out.getvalue()

    def test_without_write_nothing_changes(self):
        status, printed = self.refresh()
        self.assertIn("12.34 s -> [12.71 s](results/speed.csv#scene=test1&setting=plain)", printed)
        self.assertEqual((self.root / "doc" / "page.md").read_text(), PAGE)

    def test_figures_take_todays_values_and_cite_their_rows(self):
        status, _ = self.refresh("--write")
        text = (self.root / "doc" / "page.md").read_text()
        self.assertEqual(status, 0)
        self.assertIn("takes [12.71 s](results/speed.csv#scene=test1&setting=plain)", text)
        self.assertIn("[15.96 s](results/speed.csv#scene=test1&setting=ccd)", text)
        self.assertIn("[0.6203 J](results/speed.csv#scene=test1&setting=ccd)", text)
        self.assertIn("a short figure 0.55 stay", text)  # still held; its cell cannot be told
        self.assertIn("9.823 is the code's gravity", text)
        problems, _, _ = check_docs.check(self.root)
        self.assertEqual([p for _, p in problems], [])

    def test_a_figure_in_no_single_cell_is_left_for_a_person(self):
        (self.root / "doc" / "page.md").write_text(PAGE + "\nA guess: 77.7 s.\n")
        status, printed = self.refresh("--write")
        self.assertEqual(status, 1)
        self.assertIn("left: doc/page.md:7: 77.7 s is held by no single cell", printed)

    def test_a_figure_is_not_read_from_a_column_of_another_unit(self):
        (self.root / "doc" / "page.md").write_text("# P\n\nIt took 0.6148 s ([speed.csv](results/speed.csv)).\n")
        status, printed = self.refresh("--write")
        self.assertEqual(status, 1)  # 0.6148 is an energy; no time holds it
        self.assertIn("0.6148 s is held by no single cell", printed)

    def test_formatting_keeps_the_precision_written(self):
        f = refresh_doc_figures.formatted
        self.assertEqual(f(12345.0, "11900", "kg", "11892"), "12300")
        self.assertEqual(f(2.034e6, "1.97e6", "kg", "1970000"), "2.03e6")
        self.assertEqual(f(0.0712, "0.064", "", "0.064"), "0.071")
        self.assertEqual(f(0.1812, "17%", "%", "0.1704"), "18%")
        self.assertEqual(f(653987.2, "653,119", "m/s", "653119"), "653,987")


if __name__ == "__main__":
    unittest.main()

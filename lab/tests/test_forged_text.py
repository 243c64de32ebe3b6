"""Text a world file gives (its title, its name) enters RESULTS.md as text:
no second heading, no table row, no HTML element; and lab/check_world_report.py
refuses a report where it did not.
Run: /usr/bin/python3 -m unittest discover -s lab/tests -p test_forged_text.py
(CTest: lab_forged_text)."""

import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import check_world_report  # noqa: E402
from odelab_report import markdown as md  # noqa: E402
from odelab_report.world_report import heading  # noqa: E402

FORGED = "Boxes\n# Forged heading\n| forged | row |\n<script>alert(1)</script>\r\n[link](http://x)"


class MarkdownText(unittest.TestCase):
    def test_one_line_no_element_no_mark(self):
        text = md.text(FORGED)
        self.assertNotIn("\n", text)
        self.assertNotIn("\r", text)
        self.assertNotIn("<", text)
        for mark in "#|[]":
            self.assertNotRegex(text, r"(?<!\\)\%s" % mark)
        self.assertIn("&lt;script&gt;", text)

    def test_plain_text_unchanged(self):
        self.assertEqual(md.text("Three boxes on a 2.5 m slope"), "Three boxes on a 2.5 m slope")

    def test_heading_is_one_line(self):
        line = heading(FORGED, "w<b>.json")
        self.assertEqual(len(line.splitlines()), 1)
        self.assertTrue(line.startswith("# ODE Lab: the world Boxes "))
        self.assertNotIn("<", line)


class ReportCheck(unittest.TestCase):
    def problems(self, first_line):
        with tempfile.TemporaryDirectory() as folder:
            Path(folder, "RESULTS.md").write_text(first_line + "\n\n## At a glance\n")
            return check_world_report.check(Path(folder))

    def test_forged_title_refused(self):
        raw = "# ODE Lab: the world " + FORGED + " (w.json)"
        found = self.problems(raw)
        self.assertTrue(any("top-level headings" in p for p in found), found)
        self.assertTrue(any("HTML element" in p for p in found), found)

    def test_escaped_title_passes_these_rules(self):
        found = self.problems(heading(FORGED, "w.json"))
        self.assertFalse(any("top-level headings" in p or "HTML element" in p for p in found), found)


if __name__ == "__main__":
    unittest.main()

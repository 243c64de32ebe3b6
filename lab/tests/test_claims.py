"""Unit checks of the report's sentences from data (claims.py) and of the
docs check's rule for measured figures (check_docs.py).
Run: /usr/bin/python3 -m unittest discover -s lab/tests (CTest: lab_executor_units)."""

import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import check_docs  # noqa: E402
import check_report  # noqa: E402
from odelab_report import csvout  # noqa: E402
from odelab_report.claims import HEADLINE, Claim, Data, Sentences, q, read_rows, recheck, slot  # noqa: E402

CSV = "# ODE: test\nsolver,step_s,error\nQuickStep 20,0.001,0.25\nQuickStep 20,0.01,0.5\ndWorldStep,0.001,1e-9\n"


class Claims(unittest.TestCase):
    def setUp(self):
        self.folder = Path(tempfile.mkdtemp())
        (self.folder / "speed.csv").write_text(CSV)

    def claim(self, rule="True"):
        return Claim("k", "QuickStep {a:p2} against {b:n2}",
                     {"a": q("speed.csv", "error", solver="QuickStep 20", step_s=0.001),
                      "b": q("speed.csv", "error", solver="dWorldStep", step_s=0.001)}, rule)

    def test_text_from_the_csv(self):
        self.assertEqual(self.claim().evaluate(Data(self.folder)), ("QuickStep 25% against 1e-09", True))

    def test_a_sentence_shows_only_when_its_rule_holds(self):
        sentences = Sentences(Data(self.folder))
        self.assertIsNone(sentences.say(self.claim("a < b")))
        self.assertEqual(sentences.say(self.claim("a < b"), self.claim("a > b")), "QuickStep 25% against 1e-09")
        self.assertEqual(len(sentences.shown), 1)

    def test_recheck_finds_a_changed_figure_and_a_broken_rule(self):
        sentences = Sentences(Data(self.folder))
        sentences.say(self.claim("a > b"))
        self.assertEqual(recheck(self.folder, sentences.shown), [])
        (self.folder / "speed.csv").write_text(CSV.replace("0.25", "1e-12"))
        problems = recheck(self.folder, sentences.shown)
        self.assertEqual(len(problems), 2, problems)  # the text differs and a > b fails

    def test_absent_data_is_no_sentence(self):
        sentences = Sentences(Data(self.folder))
        missing = Claim("m", "{a:n}", {"a": q("absent.csv", "x")})
        self.assertIsNone(sentences.say(missing))

    def test_lists_and_medians(self):
        data = Data(self.folder)
        self.assertEqual(data.lookup(q("speed.csv", "error", "median", solver="QuickStep 20")), 0.375)
        self.assertEqual(data.lookup(q("speed.csv", "solver", "texts", step_s=0.001)), ["QuickStep 20", "dWorldStep"])
        self.assertEqual(len(read_rows(self.folder / "speed.csv")), 3)


class SectionSentences(unittest.TestCase):
    """A conclusion in a section's prose or the headline findings is a claim
    like a cell of the first table: shown when its rule holds, recorded with
    where it stands, and checked there by check_report.py."""

    def setUp(self):
        self.folder = Path(tempfile.mkdtemp())
        (self.folder / "speed.csv").write_text(CSV)
        self.smaller = Claim("speed.smaller", "A smaller step lowers the error: {c:n2} at 0.01, {f:n2} at 0.001.",
                             {"c": q("speed.csv", "error", solver="QuickStep 20", step_s=0.01),
                              "f": q("speed.csv", "error", solver="QuickStep 20", step_s=0.001)}, "f < c")
        self.larger = Claim("speed.larger", "A smaller step does not lower the error.", dict(self.smaller.values),
                            "f >= c")

    def report(self, prose, headline):
        """RESULTS.md and claims.csv as results_md writes them."""
        sentences = Sentences(Data(self.folder))
        body = sentences.fill(prose, {"step": [self.larger, self.smaller]}, "speed")
        found = sentences.say(headline, place=HEADLINE)
        text = "\n".join(["# report", "", "## Headline findings", "", f"- {found}", "",
                           "### speed (`--only speed`)", "", body, ""])
        (self.folder / "RESULTS.md").write_text(text)
        csvout.write_csv(self.folder / "claims.csv", [("ODE", "test")], Sentences.COLUMNS, sentences.shown)
        return text

    def test_the_slot_takes_the_sentence_whose_rule_holds(self):
        sentences = Sentences(Data(self.folder))
        text = sentences.fill(f"How to read it: {slot('step')}", {"step": [self.larger, self.smaller]}, "speed")
        self.assertEqual(text, "How to read it: A smaller step lowers the error: 0.5 at 0.01, 0.25 at 0.001.")
        self.assertEqual([(row["key"], row["place"]) for row in sentences.shown], [("speed.smaller", "speed")])

    def test_no_sentence_when_no_rule_holds(self):
        sentences = Sentences(Data(self.folder))
        self.assertEqual(sentences.fill(f"[{slot('step')}]", {"step": self.larger}, "speed"), "[]")

    def test_the_check_passes_a_true_report(self):
        text = self.report(f"How to read it: {slot('step')}", self.smaller)
        self.assertEqual(check_report.check_sentences(self.folder, text), [])
        self.assertEqual(recheck(self.folder, read_rows(self.folder / "claims.csv")), [])

    def test_the_check_fails_a_sentence_whose_data_changed(self):
        self.report(f"How to read it: {slot('step')}", self.smaller)
        (self.folder / "speed.csv").write_text(CSV.replace("0.25", "0.75"))  # the step no longer helps
        problems = recheck(self.folder, read_rows(self.folder / "claims.csv"))
        self.assertTrue(any("does not hold" in p for p in problems), problems)

    def test_the_check_fails_a_typed_headline_or_an_edited_sentence(self):
        text = self.report(f"How to read it: {slot('step')}", self.smaller)
        typed = text.replace("## Headline findings\n\n", "## Headline findings\n\n- test2: exact, whatever.\n")
        self.assertTrue(any("no claim" in p for p in check_report.check_sentences(self.folder, typed)))
        edited = text.replace("0.25 at 0.001", "0.2 at 0.001")
        self.assertTrue(any("not in RESULTS.md's speed" in p for p in check_report.check_sentences(self.folder, edited)))


class DocsFigures(unittest.TestCase):
    def written(self, text):
        return [w for _, w, _, _ in check_docs.figures(text)]

    def test_what_counts(self):
        self.assertEqual(self.written("energy varies by 0.064% and 2.5x faster, 20 s long"),
                         ["0.064%", "2.5", "20"])

    def test_both_ends_of_a_range(self):
        self.assertEqual(self.written("CPU 0.24-0.27 s, 14.2-16.4 s"), ["0.24", "0.27", "14.2", "16.4"])

    def test_what_does_not(self):
        text = ("ODE 0.16.2 and ODE 0.11 on 2 cores, `--step 0.001`, exit status 2, chapter 5.10, test10, "
                "a 1280 x 720 window, 2026-11-24 at 6:16, [a](doc/x1.5.md)\n## 5.4 The scene")
        self.assertEqual(self.written(text), [])

    def test_held_at_the_written_precision(self):
        values = sorted([0.06403, 11892.07, 0.1704])
        self.assertTrue(check_docs.held(values, 0.064, check_docs.half_unit("0.064")))
        self.assertFalse(check_docs.held(values, 0.065, check_docs.half_unit("0.065")))
        self.assertTrue(check_docs.held(values, 11900, check_docs.half_unit("1.19e4")))
        self.assertTrue(check_docs.held(values, 11892, check_docs.half_unit("11892")))
        self.assertTrue(check_docs.held(values, 11900, check_docs.half_unit("11900")))
        self.assertFalse(check_docs.held(values, 11880, check_docs.half_unit("11880")))

    def test_significant_digits(self):
        self.assertEqual([check_docs.significant_digits(w) for w in ("5", "0.2", "500", "5e-3", "35", "0.064", "4.4%",
                                                                       "11900", "0.0640")], [1, 1, 1, 1, 2, 2, 2, 3, 3])


if __name__ == "__main__":
    unittest.main()

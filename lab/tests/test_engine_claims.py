"""What is written of an engine is held to what the atlas measured: the
notes --list-engines prints are made from atlas.csv's rows (note_rows), and
an `[atlas: ...]` tag in a hand-written note fails lab/check_engine_claims.py
when its mark is not the atlas's."""

import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import check_engine_claims  # noqa: E402
from odelab_report import atlas_text, csvout  # noqa: E402

COLUMNS = ["case", "engine", "setting", "step", "mark", "worst_probe", "worst_tolerances"]
ROWS = [dict(case="bounce-v1", engine="havok", setting="default", step="1/240", mark="off", worst_probe="apex",
             worst_tolerances="4.3"),
        dict(case="bounce-v5", engine="havok", setting="default", step="1/240", mark="right", worst_probe="apex",
             worst_tolerances="0.2"),
        dict(case="fall", engine="havok", setting="default", step="1/240", mark="no figure", worst_probe="lands",
             worst_tolerances=""),
        dict(case="bounce-v1", engine="havok", setting="default", step="1/60", mark="right", worst_probe="apex",
             worst_tolerances="0.5")]


def project_with(note):
    """A project folder with an atlas CSV and one adapter source holding `note`."""
    root = Path(tempfile.mkdtemp())
    (root / "doc" / "atlas-report").mkdir(parents=True)
    csvout.write_csv(root / "doc" / "atlas-report" / "atlas.csv", [], COLUMNS, ROWS)
    (root / "peers" / "engines").mkdir(parents=True)
    (root / "peers" / "engines" / "HavokNotes.cpp").write_text(note)
    return root


class NoteRows(unittest.TestCase):
    def test_counts_and_the_cases_not_right_at_the_shown_step(self):
        rows = csvout.read_csv(project_with("") / "doc" / "atlas-report" / "atlas.csv")[2]
        self.assertEqual(atlas_text.note_rows(rows), [dict(
            engine="havok", setting="default", step="1/240", right=1, cases=3,
            not_right="bounce-v1 off 4.3 tol; fall no figure (lands)")])


class Claims(unittest.TestCase):
    def problems(self, note):
        root = project_with(note)
        return check_engine_claims.problems_of(root, root / "doc" / "atlas-report")

    def test_a_tag_that_holds_passes(self):
        problems, count = self.problems('"slow bounces are lost [atlas: havok default bounce-v1 off; '
                                        'havok default bounce-v5 right]"')
        self.assertEqual((problems, count), ([], 2))

    def test_a_note_the_atlas_contradicts_fails_naming_it(self):
        problems, _ = self.problems('"applies restitution at every impact speed [atlas: havok default bounce-v1 right]"')
        self.assertEqual(len(problems), 1)
        self.assertIn("says havok default is 'right' on bounce-v1; the atlas measured 'off'", problems[0])
        self.assertIn("HavokNotes.cpp:1", problems[0])

    def test_a_tag_split_over_two_string_literals_is_read_whole(self):
        problems, count = self.problems('x = "slow bounces [atlas: havok default "\n    "bounce-v1 right]";')
        self.assertEqual(count, 1)
        self.assertIn("the atlas measured 'off'", problems[0])

    def test_a_case_the_atlas_lacks_and_a_malformed_tag_fail(self):
        problems, _ = self.problems("[atlas: havok default no-such-case off] [atlas: havok slides]")
        self.assertIn("atlas.csv has no row", problems[0])
        self.assertIn("is not ENGINE SETTING CASE MARK", problems[1])


if __name__ == "__main__":
    unittest.main()

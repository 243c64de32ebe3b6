"""The atlas's rules (experiments/atlas.py, atlas_text.py): a cell's mark from
the run's own probes against their stated tolerances, the case list refused
when a case has no family or a family no case, and the words made from the
CSV's rows alone."""

import json
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report import atlas_text, csvout  # noqa: E402
from odelab_report.experiments import atlas  # noqa: E402

CASE = {"format": "odelab-world", "version": 1, "title": "Bounce", "settings": {"step": 0.01},
        "measures": [{"kind": "probe", "name": "apex", "body": 0, "of": "position", "axis": "y", "take": "max",
                      "expect": 0.3, "relative_tolerance": 0.02},
                     {"kind": "probe", "name": "lands", "body": 0, "of": "position", "axis": "y",
                      "take": "first_crossing", "value": 0.0, "expect": 0.5, "tolerance": 0.01}]}


class Run:
    def __init__(self, rc=0, **metrics):
        self.rc, self.metrics = rc, metrics

    def m(self, name, default=None):
        return self.metrics.get(name, default)


def folder_with(cases, families):
    folder = Path(tempfile.mkdtemp())
    for name in cases:
        (folder / f"{name}.json").write_text(json.dumps(CASE))
    (folder / "families.csv").write_text("case,family\n" + "".join(f"{c},{f}\n" for c, f in families))
    return folder


class Marks(unittest.TestCase):
    def setUp(self):
        self.case = atlas.read_cases(folder_with(["bounce"], [("bounce", "contact")]))[0]

    def test_right_when_every_probe_is_within(self):
        run = Run(apex_error=0.003, apex_tolerance=0.006, apex_within=1, lands_error=-0.002, lands_tolerance=0.01,
                  lands_within=1)
        self.assertEqual(atlas.judge(self.case, run)[:4], ("right", 2, "apex", 0.5))

    def test_off_names_the_worst_probe_in_tolerances(self):
        run = Run(apex_error=0.003, apex_tolerance=0.006, apex_within=1, lands_error=0.04, lands_tolerance=0.01,
                  lands_within=0)
        mark, within, probe, ratio, error, tolerance = atlas.judge(self.case, run)
        self.assertEqual((mark, within, probe, error, tolerance), ("off", 1, "lands", 0.04, 0.01))
        self.assertAlmostEqual(ratio, 4.0)

    def test_a_probe_without_a_reading_is_no_figure(self):
        run = Run(apex_error=0.0, apex_tolerance=0.006, apex_within=1, lands_tolerance=0.01, lands_within=0)
        self.assertEqual(atlas.judge(self.case, run)[:3], ("no figure", 1, "lands"))


class CaseList(unittest.TestCase):
    def test_a_case_without_a_family_is_refused(self):
        with self.assertRaisesRegex(ValueError, "no family for extra"):
            atlas.read_cases(folder_with(["bounce", "extra"], [("bounce", "contact")]))

    def test_a_family_without_its_case_is_refused(self):
        with self.assertRaisesRegex(ValueError, "no file for gone"):
            atlas.read_cases(folder_with(["bounce"], [("bounce", "contact"), ("gone", "contact")]))


def row(case, engine, setting, mark, worst="", cost="0.01"):
    return dict(case=case, family="contact", title=case, engine=engine, setting=setting, step="1/240",
                mark=mark, worst_probe="apex", worst_tolerances=worst, repeats="1", engine_s_per_sim_s=cost,
                engine_s_per_sim_s_min=cost, engine_s_per_sim_s_max=cost)


class Words(unittest.TestCase):
    ROWS = [row("a", "ode", "default", "right", "0.2"), row("a", "ode", "best", "off", "3"),
            row("b", "ode", "default", "right", "0.1"), row("b", "ode", "best", "right", "0.1"),
            row("a", "jolt", "default", "blew up", cost=""), row("b", "jolt", "default", "right", "0.9"),
            row("a", "jolt", "best", "right", "0.5"), row("b", "jolt", "best", "right", "0.5")]
    ENGINES = [dict(engine="ode", available="1", missing=""), dict(engine="rapier", available="0",
                                                                   missing="no node")]

    def test_each_engine_sentence_counts_its_own_row(self):
        self.assertEqual(atlas_text.engine_sentences(self.ROWS, "ode"),
                         "At step 1/240 s, default: right on 2 of 2 cases. At step 1/240 s, best: right on 1 of 2 "
                         "cases; not on `a` (off 3 tol). Its best setting is worse than its default on `a`.")
        self.assertIn("not on `a` (blew up)", atlas_text.engine_sentences(self.ROWS, "jolt"))

    def test_the_text_is_the_same_from_the_csv_read_back(self):
        folder = Path(tempfile.mkdtemp())
        csvout.write_csv(folder / "atlas.csv", [], list(self.ROWS[0]), self.ROWS)
        read = csvout.read_csv(folder / "atlas.csv")[2]
        text = atlas_text.markdown(read, self.ENGINES, ["atlas.csv"])
        self.assertEqual(text, atlas_text.markdown(self.ROWS, self.ENGINES, ["atlas.csv"]))
        self.assertIn("Not run here: rapier (no node).", text)
        self.assertIn("| ode | default | 2 of 2 |", text)


if __name__ == "__main__":
    unittest.main()

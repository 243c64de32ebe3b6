"""Unit checks of the report's first screen (first_screen.py, readings.py) and
of what check_report.py holds it to: one quantity at one setting per row,
"n/a: <why>" rather than another setting's figure, costs in CPU seconds per
simulated second over the timed runs, a screen that fits.
Run: /usr/bin/python3 -m unittest discover -s lab/tests (CTest: lab_executor_units)."""

import shutil
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import check_report  # noqa: E402
from odelab_report import first_screen  # noqa: E402
from odelab_report.claims import Claim, Data, Sentences, q, runs_cost, speed_options  # noqa: E402

COMMITTED = Path(__file__).resolve().parents[2] / "doc" / "results"
HEADER = "# ODE: test\n"


def claim_rows(*claims, folder=COMMITTED):
    """claims.csv's rows for `claims`, as the report writes them."""
    sentences = Sentences(Data(folder))
    for claim in claims:
        sentences.say(claim)
    return sentences.shown


def definition(scene):
    return next(row[1][0] for row in first_screen.rows() if row[0] == scene)


class OneReadingPerRow(unittest.TestCase):
    """A row's cells read the quantity at the setting its definition states."""

    def test_a_cell_reading_the_sweep_at_cfm_0_is_refused_on_test8s_row(self):
        # test8's row is about CFM 1e-4; speed-test8.csv runs at CFM 0.
        sweep = Claim("first.test8.cheapest", "{e:n2}", {"e": q("speed-test8.csv", "error", solver="QuickStep 20",
                                                                 step_s=0.001)})
        problems = check_report.check_one_reading(COMMITTED, claim_rows(definition("test8"), sweep))
        self.assertTrue(any("first.test8.cheapest reads speed-test8.csv" in p and "CFM 0, not CFM 0.0001" in p
                            for p in problems), problems)

    def test_a_cell_reading_another_quantity_is_refused_on_test2s_row(self):
        # test2's row is (max - min) / max over 60 s; peers.csv has |E - E0| / (m g d) over 20 s.
        peer = Claim("first.test2.peer", "{v:n2}", {"v": q("peers.csv", "value", scene="test2", engine="bullet",
                                                            setting="best", step=0.001)})
        problems = check_report.check_one_reading(COMMITTED, claim_rows(definition("test2"), peer))
        self.assertTrue(any("energy |ΔE|/mgd, not energy (max-min)/max" in p for p in problems), problems)
        self.assertTrue(any("20 s, not 60 s" in p for p in problems), problems)

    def test_the_rows_own_quantity_and_setting_pass(self):
        sweep = Claim("first.test9.cheapest", "{e:n2}", {"e": q("speed-test9.csv", "error", solver="QuickStep 20",
                                                                 step_s=0.001)})
        problems = check_report.check_one_reading(COMMITTED, claim_rows(definition("test9"), sweep))
        self.assertEqual([p for p in problems if p.startswith("test9")], [])

    def test_a_row_without_its_definition_is_refused(self):
        problems = check_report.check_one_reading(COMMITTED, [])
        self.assertIn("test8: no definition claim (first.test8.definition) saying its quantity and setting",
                      problems)

    def test_the_builder_says_na_with_why_instead_of_another_settings_figure(self):
        sentences = Sentences(Data(COMMITTED))
        rows = {row[0]: row for row in first_screen.rows()}
        _, (_, setting8), _, _, _, cheapest8, peer8 = rows["test8"]
        self.assertEqual(first_screen.cell(sentences, cheapest8, setting8, "sweep reads", "-"),
                         "n/a: sweep reads CFM 0")
        self.assertEqual(first_screen.cell(sentences, peer8, setting8, "engines read", "-"), "n/a: engines read 20 s")
        _, (_, setting2), _, _, _, cheapest2, _ = rows["test2"]
        self.assertEqual(first_screen.cell(sentences, cheapest2, setting2, "sweep reads", "-"),
                         "n/a: sweep reads energy |ΔE|/mgd")

    def test_a_source_that_did_not_run_is_absent_not_another_quantity(self):
        # --quick runs no other engine on test1: the cell says so.
        folder = Path(tempfile.mkdtemp())
        self.addCleanup(shutil.rmtree, folder)
        (folder / "peers.csv").write_text(HEADER + "scene,engine,setting,step,quantity,value,cpu_s_per_sim_s\n"
                                          "test9,bullet,best,0.001,apex_error_20,1e-9,0.001\n")
        _, (_, setting), _, _, _, _, peer = next(row for row in first_screen.rows() if row[0] == "test1")
        self.assertEqual(first_screen.cell(Sentences(Data(folder)), peer, setting, "engines read",
                                           first_screen.NO_PEERS), "n/a: no engine ran it")


class Costs(unittest.TestCase):
    """One unit: CPU seconds per simulated second, median [min-max] over the runs."""

    def test_runs_cost_takes_the_timed_runs_of_the_point_and_a_retry_once(self):
        args = ["--erp 0.2 --cfm 0 --solver quick --iterations 20 --seconds 30.0 --step 0.001",
                "--erp 0.2 --cfm 0 --solver quick --iterations 20 --seconds 30 --step 0.001",
                "--erp 0.2 --cfm 0 --solver quick --iterations 20 --seconds 30 --step 0.001",
                "--erp 0.2 --cfm 0 --solver quick --iterations 20 --seconds 30 --step 0.001",  # repeat 2's retry
                "--erp 0.2 --cfm 0 --solver quick --iterations 10 --seconds 30 --step 0.001",
                "--erp 0.2 --cfm 0 --solver quick --iterations 20 --seconds 20 --step 0.001",  # the accuracy run
                "--solver quick --iterations 20 --seconds 30 --step 0.001"]  # another experiment's
        cpu, sim = [3.0, 6.0, 99.0, 9.0, 100.0, 100.0, 100.0], [30.0] * 5 + [20.0, 30.0]
        share, repeat = [1, 1, 0.5, 0.95, 1, 1, 1], [0, 1, 2, 2, 0, 0, 0]
        wanted = speed_options("QuickStep 20", 0.001, {"--erp": 0.2, "--cfm": 0})
        self.assertEqual(runs_cost([args, cpu, sim, share, repeat], wanted, 30), [0.2, 0.1, 0.3, 3])
        with self.assertRaises(ValueError):
            runs_cost([args, cpu, sim, share, repeat], dict(wanted, **{"--step": 0.01}), 30)

    def test_runs_cost_agrees_with_the_committed_sweeps(self):
        data = Data(COMMITTED)
        for scene, options in first_screen.SPEED_OPTIONS.items():
            runs = [data.lookup(q("runs.csv", column, agg, program=scene, timed=1)) for column, agg in (
                ("arguments", "texts"), ("cpu_seconds", "list"), ("sim_seconds", "list"), ("cpu_share", "list"),
                ("repeat", "list"))]
            for row in data.rows(f"speed-{scene}.csv"):
                cost = runs_cost(runs, speed_options(row["solver"], float(row["step_s"]), options),
                                 float(row["timed_sim_seconds"]))
                self.assertAlmostEqual(cost[0], float(row["cpu_per_sim_second"]), delta=1e-6 * cost[0])
                self.assertEqual(cost[3], int(row["repeats"]))

    def test_one_cheapest_setting_gives_its_cpu_cost_and_a_tie_links_below(self):
        folder = Path(tempfile.mkdtemp())
        self.addCleanup(shutil.rmtree, folder)
        speed = ("solver,step_s,timed_sim_seconds,wall_seconds_min,wall_seconds_max,wall_per_sim_second,error\n"
                 "QuickStep 20,0.01,300,1,2,0.005,0.001\nQuickStep 20,0.001,30,3,4,0.1,0.0001\n")
        runs = ("program,arguments,timed,cpu_seconds,sim_seconds,cpu_share,repeat\n"
                + "".join(f"test9,--erp 0.2 --cfm 0 --seconds 300 --solver quick --iterations 20 --step 0.01,1,{c},300,1,{r}\n"
                          for r, c in enumerate((1.5, 1.2, 2.1)))
                + "test9,--erp 0.2 --cfm 0 --seconds 30 --solver quick --iterations 20 --step 0.001,1,9,30,1,0\n")
        (folder / "speed-test9.csv").write_text(HEADER + speed)
        (folder / "runs.csv").write_text(HEADER + runs)
        sentences = Sentences(Data(folder))
        self.assertEqual(sentences.say(*first_screen.cheapest_cells("test9")), "QuickStep 20 @ 0.01: 0.005 [0.004-0.007]")
        (folder / "speed-test9.csv").write_text(HEADER + speed.replace(",3,4,0.1,", ",0.1,4,0.1,"))
        self.assertEqual(Sentences(Data(folder)).say(*first_screen.cheapest_cells("test9")),
                         "[tie (see §3)](#exp-speed-test9)")


class ScreenSize(unittest.TestCase):
    """The first screen fits: eleven rows in the first 40 lines, no line over
    160 characters, no row over 120 characters of cell text."""

    def lines(self, extra_cell=""):
        rows = [f"| test{n} | a | b | reproduced | n/a: x | n/a: y{extra_cell} |" for n in range(11)]
        return ["# report", "", "## At a glance", "", "| " + " | ".join(check_report.FIRST_COLUMNS) + " |",
                "|" + "---|" * 6] + rows + ["", "## Run"]

    def problems(self, lines):
        start = lines.index("## At a glance")
        table = [line for line in lines if line.startswith("|")]
        body = [check_report.cells(line) for line in table[2:]]
        return check_report.check_screen_size(lines, start, table, body)

    def test_a_short_screen_passes(self):
        self.assertEqual(self.problems(self.lines()), [])

    def test_a_long_row_and_a_long_line_are_refused(self):
        problems = self.problems(self.lines("z" * 130))
        self.assertTrue(any("characters of cell text (at most 120)" in p for p in problems), problems)
        self.assertTrue(any("of the first screen has" in p for p in problems), problems)

    def test_rows_past_line_40_are_refused(self):
        lines = self.lines()
        lines[3:3] = ["text"] * 30
        self.assertTrue(any("after the first 40" in p for p in self.problems(lines)))

    def test_a_link_counts_by_its_text(self):
        self.assertEqual(check_report.visible("[tie (see §3)](#exp-speed-test9)"), "tie (see §3)")

    def test_the_committed_first_screen_holds(self):
        text = (COMMITTED / "RESULTS.md").read_text()
        self.assertEqual(check_report.check_first_screen(COMMITTED, text), [])


if __name__ == "__main__":
    unittest.main()

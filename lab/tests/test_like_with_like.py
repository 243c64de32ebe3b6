"""Unit checks of like with like across engines and of timing with spread
(peer_compare.py, timing.py, the first screen's engines cell): a run on
another surface than ODE's or with a figure zero by construction takes no
part; defaults beside defaults; an equal figure whose timing range overlaps
the cheapest's is a tie; a timed run lasts long enough to time.
Run: /usr/bin/python3 -m unittest discover -s lab/tests (CTest: lab_executor_units, lab_like_with_like)."""

import shutil
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report import first_screen, peer_compare, timing, timing_check  # noqa: E402
from odelab_report.claims import Data, Sentences  # noqa: E402
from odelab_report import remedy_test4_claims as remedy_test4  # noqa: E402

HEADER = "# ODE: test\n"
COLUMNS = ("scene,engine,setting,step,quantity,value,friction,like_ode_surface,by_construction,"
           "cpu_s_per_sim_s,cpu_s_per_sim_s_min,cpu_s_per_sim_s_max\n")


def row(engine, value, cpu, low, high, friction="100", like=1, made="", scene="test3", setting="default"):
    return dict(scene=scene, engine=engine, setting=setting, value=value, friction=friction,
                like_ode_surface=like, by_construction=made, cpu_median=cpu, cpu_min=low, cpu_max=high)


class Standings(unittest.TestCase):
    def test_an_equal_figure_inside_the_cheapest_timing_range_is_a_tie(self):
        # test3 in the committed report: Havok 0.0880 against Bullet 0.0890 s/s, one run each.
        havok, bullet = row("havok", 1.0, 0.088, 0.085, 0.093), row("bullet", 1.0, 0.089, 0.086, 0.092)
        winners, _ = peer_compare.standings([bullet, havok], lower_is_better=False)
        self.assertEqual([r["engine"] for r in winners], ["havok", "bullet"])

    def test_a_cheaper_run_outside_the_scatter_wins_alone(self):
        havok, bullet = row("havok", 1.0, 0.05, 0.049, 0.051), row("bullet", 1.0, 0.089, 0.086, 0.092)
        winners, _ = peer_compare.standings([bullet, havok], lower_is_better=False)
        self.assertEqual([r["engine"] for r in winners], ["havok"])

    def test_another_surface_takes_no_part(self):
        # test4: the peers at their default friction against ODE's infinite.
        ode = row("ode", 4000.0, 0.01, 0.01, 0.01, friction="infinite", scene="test4")
        bullet = row("bullet", 1e6, 0.02, 0.02, 0.02, friction="engine default", like=0, scene="test4")
        winners, excluded = peer_compare.standings([ode, bullet], lower_is_better=False)
        self.assertEqual([r["engine"] for r in winners], ["ode"])
        self.assertIn("friction differs (engine default against ODE's infinite)", excluded[0][1])

    def test_a_figure_zero_by_construction_does_not_win(self):
        ode = row("ode", 0.0017, 0.004, 0.004, 0.004, scene="test7")
        made = peer_compare.BY_CONSTRUCTION[("mujoco", "test7")]
        mujoco = row("mujoco", 3.6e-15, 0.008, 0.008, 0.008, made=made, scene="test7")
        winners, excluded = peer_compare.standings([ode, mujoco], lower_is_better=True)
        self.assertEqual([r["engine"] for r in winners], ["ode"])
        self.assertIn("generalized coordinates", excluded[0][1])

    def test_the_surface_is_read_from_the_peers_settings_line(self):
        line = "bullet test5, step 0.001 s, ...; friction 100 on every shape (test5's never-sliding contacts)"
        self.assertEqual(peer_compare.peer_friction(line), "100")
        self.assertTrue(peer_compare.like_surface("test5", "100"))  # the peers' no-slip, ODE's infinity
        self.assertEqual(peer_compare.peer_friction("bullet test4, step 0.001 s: Bullet's defaults"),
                         "engine default")
        self.assertFalse(peer_compare.like_surface("test4", "engine default"))
        self.assertTrue(peer_compare.like_surface("test9", "engine default"))  # head-on: friction does not act
        self.assertTrue(peer_compare.like_surface("test3", "1"))
        self.assertFalse(peer_compare.like_surface("test3", "100"))


class Timing(unittest.TestCase):
    def test_a_short_run_is_stretched_to_the_minimum_cpu(self):
        # 20 s of test9 in 25 ms: the timed run lasts 0.5 s of CPU or more.
        seconds = timing.timed_seconds(20.0, 0.025)
        self.assertGreaterEqual(seconds * 0.025 / 20.0, timing.MIN_RUN_CPU_SECONDS)
        self.assertEqual(timing.timed_seconds(20.0, 2.0), 20.0)  # long enough already
        self.assertEqual(timing.with_seconds(["--seconds", "20", "--step", "0.01"], 600.0),
                         ["--seconds", 600.0, "--step", "0.01"])
        self.assertEqual(timing.with_seconds(["--step", "0.01"], 600.0), ["--step", "0.01", "--seconds", 600.0])

    def test_five_runs_a_figure_and_ranges(self):
        self.assertGreaterEqual(timing.REPEATS, 5)
        self.assertEqual(timing.spread([3.0, 1.0, 2.0, None]), (2.0, 1.0, 3.0))
        self.assertTrue(timing.overlap(1.0, 2.0, 1.9, 3.0))
        self.assertFalse(timing.overlap(1.0, 2.0, 2.1, 3.0))
        self.assertEqual(timing.ratio_range(0.9, 1.1, 1.0, 1.2), (0.75, 1.1))


class EnginesCell(unittest.TestCase):
    def cell(self, scene, lines, higher_better=True, figure="{v:k2}", step=0.001):
        folder = Path(tempfile.mkdtemp())
        self.addCleanup(shutil.rmtree, folder)
        (folder / "peers.csv").write_text(HEADER + COLUMNS + "".join(line + "\n" for line in lines))
        setting = dict(quantity={"test3": "dominoes fallen", "test4": "heaviest cube held"}.get(scene, "joint error"))
        return first_screen.cell(Sentences(Data(folder)), first_screen.peer_cell(scene, higher_better, figure, step),
                                 setting, "engines read", first_screen.NO_PEERS)

    def test_test3_compares_at_odes_step_and_a_tie_within_the_scatter_says_so(self):
        lines = ["test3,ode,default,0.005,fallen_fraction,1,1,1,,0.09,0.088,0.095",
                 "test3,havok,default,0.005,fallen_fraction,1,1,1,,0.088,0.085,0.093",
                 "test3,bullet,default,0.005,fallen_fraction,1,1,1,,0.089,0.086,0.092",
                 "test3,rapier,default,0.001,fallen_fraction,1,1,1,,0.01,0.01,0.01"]
        self.assertEqual(self.cell("test3", lines, figure="{v:p2}", step=0.005), "[tie (see §5)](#exp-peers)")
        alone = [lines[0], lines[1], "test3,bullet,default,0.005,fallen_fraction,1,1,1,,0.2,0.19,0.21"]
        self.assertEqual(self.cell("test3", alone, figure="{v:p2}", step=0.005),
                         "havok 100% @0.005 mu 1, 0.088 [0.085-0.093]")

    def test_defaults_beside_defaults(self):
        lines = ["test3,havok,best,0.005,fallen_fraction,1,1,1,,0.01,0.01,0.01",
                 "test3,bullet,default,0.005,fallen_fraction,1,1,1,,0.2,0.19,0.21"]
        self.assertTrue(self.cell("test3", lines, figure="{v:p2}", step=0.005).startswith("bullet "))

    def test_another_friction_is_not_compared(self):
        lines = ["test4,ode,default,0.001,heaviest_held_kg,4000,infinite,1,,0.01,0.01,0.01",
                 "test4,bullet,default,0.001,heaviest_held_kg,1000000,engine default,0,,0.02,0.02,0.02"]
        self.assertEqual(self.cell("test4", lines, figure="{v:k2} kg"), "n/a: friction differs")

    def test_zero_by_construction_does_not_win(self):
        made = peer_compare.BY_CONSTRUCTION[("mujoco", "test7")]
        lines = ["test7,mujoco,default,0.001,max_joint_error,3.6e-15,100,1," + made + ",0.008,0.008,0.008",
                 "test7,bullet,default,0.001,max_joint_error,0.03,100,1,,0.0055,0.0054,0.0056"]
        self.assertEqual(self.cell("test7", lines, higher_better=False, figure="{v:k2} m"),
                         "bullet 0.03 m mu 100, 0.0055 [0.0054-0.0056]")


class TuningTies(unittest.TestCase):
    """remedy-test5's descent (timing.keep) and remedy-test4's cost."""

    def test_a_smaller_real_time_margin_inside_the_scatter_keeps_the_value_chosen(self):
        # SOR 1.6 against 1.0 in the committed report: 0.829 against 0.842 from one run each.
        current, other = {"sor": 1.3}, {"sor": 1.6}
        scored = [((0.842, "real time"), current, None), ((0.829, "real time"), other, None)]
        (margin, chosen, _), tied = timing.keep(scored, current, scatter=0.03)
        self.assertIs(chosen, current)
        self.assertEqual(tied, [other])
        (_, chosen, _), tied = timing.keep(scored, current, scatter=0.005)
        self.assertIs(chosen, other)
        self.assertEqual(tied, [])

    def test_a_margin_the_timing_does_not_set_is_compared_as_it_is(self):
        current, other = {"erp": 0.2}, {"erp": 0.4}
        scored = [((0.50, "axis offset"), current, None), ((0.49, "axis offset"), other, None)]
        (_, chosen, _), tied = timing.keep(scored, current, scatter=0.5)
        self.assertIs(chosen, other)
        self.assertEqual(tied, [])

    def test_the_scatter_is_the_range_over_the_median(self):
        self.assertAlmostEqual(timing.scatter_of([0.80, 0.84, 0.82]), 0.04 / 0.82)
        self.assertEqual(timing.scatter_of([0.8]), 0.0)

    def test_remedy_test4_cost_within_the_scatter_is_said_so(self):
        folder = Path(tempfile.mkdtemp())
        self.addCleanup(shutil.rmtree, folder)
        names = [label for label, _, _ in remedy_test4.SETTINGS]
        lines = ["setting,heaviest_held_kg,repeats,cost_relative_to_plain,cost_relative_min,cost_relative_max,"
                 "cost_within_scatter",
                 f'"{names[0]}",28100,5,1,0.97,1.03,1', f'"{names[1]}",1.58e6,5,0.96,0.9,1.02,1',
                 f'"{names[2]}",8.89e5,5,10,9.6,10.5,0']
        (folder / "remedy-test4.csv").write_text(HEADER + "\n".join(lines) + "\n")
        text = Sentences(Data(folder)).say(*remedy_test4.HEADLINE)
        self.assertIn("at the same CPU cost within the timing's scatter (0.90-1.02x over 5 runs each)", text)
        self.assertNotIn("0.96x", text)


class TimingCheck(unittest.TestCase):
    """check_report.py's rule on a report folder (timing_check.py)."""

    def folder(self, files):
        folder = Path(tempfile.mkdtemp())
        self.addCleanup(shutil.rmtree, folder)
        for name, text in files.items():
            (folder / name).write_text("# options: --jobs 2\n" + text)
        return folder

    def test_a_tie_list_from_one_25_ms_run_is_refused(self):
        # the committed speed-test9.csv: points timed once, on runs of 25 ms
        folder = self.folder({"speed-test9.csv": "solver,step_s,wall_per_sim_second,repeats\n"
                                                 "QuickStep 20,0.01,0.0012,1\n"})
        found = timing_check.problems(folder)
        self.assertIn("speed-test9.csv row 1: a cost from 1 timed runs (at least 5: a median and a range)", found)
        self.assertIn("speed-test9.csv row 1: a timed run of unknown CPU s (at least 0.5: long enough to time)",
                      found)

    def test_five_runs_long_enough_pass_and_a_scan_is_timed_as_it_runs(self):
        folder = self.folder({
            "speed-test9.csv": "solver,step_s,wall_per_sim_second,repeats,shortest_run_cpu_seconds\n"
                               "QuickStep 20,0.01,0.0012,5,0.61\n",
            "peers.csv": "scene,engine,cpu_s_per_sim_s,repeats,shortest_run_cpu_seconds\n"
                         "test10,ode,0.001,5,0.03\ntest2,ode,,0,\ntest9,bullet,0.002,5,0.2\n"})
        self.assertEqual(timing_check.problems(folder),
                         ["peers.csv row 3: a timed run of 0.2 CPU s (at least 0.5: long enough to time)"])


if __name__ == "__main__":
    unittest.main()

"""Unit checks of the report's physics scores: test6's fall time against the
analytic inverted pendulum (inverted_pendulum.py, experiments/remedy_test6.py,
the test6 row of the first screen, the engines' test6 figure left unranked);
test2's energy errors against the swing's energy m g d, not E0
(swing_energy.py, and each place the report gives one).
Run: /usr/bin/python3 -m unittest discover -s lab/tests (CTest: lab_executor_units, lab_physics_scores)."""

import collections
import csv
import math
import re
import shutil
import sys
import tempfile
import types
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from odelab_report import first_screen, inverted_pendulum, swing_energy  # noqa: E402
from odelab_report.claims import Data, Sentences  # noqa: E402
from odelab_report.experiments import limit_test10, peers, speed_accuracy, thesis  # noqa: E402
from odelab_report.runner import LabError  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
COMMITTED = ROOT / "doc" / "results"
HEADER = "# ODE: test\n"


def constant(path, name, namespace=None):
    """A `constexpr double NAME = value;` of a C++ header (inside `namespace` when given)."""
    text = (ROOT / path).read_text()
    if namespace:
        text = text[text.index(f"namespace {namespace} {{"):]
        text = text[:text.index(f"}}  // namespace {namespace}")]
    return float(re.search(rf"constexpr double {name} = ([0-9.eE+-]+);", text).group(1))


def row(scene):
    return next(r for r in first_screen.rows() if r[0] == scene)


class AnalyticFall(unittest.TestCase):
    """lambda = sqrt(m g d / I) from the scene's own constants; t = acosh(theta_f / theta_0) / lambda."""

    def test_the_inputs_are_the_scenes_own_constants(self):
        self.assertEqual(inverted_pendulum.BIG_SIDE_M,
                         constant("tests/shared/SceneConstants.h", "BIG_SIDE", "test6"))
        self.assertEqual(inverted_pendulum.FALL_TILT_DEGREES,
                         constant("tests/shared/SceneConstants.h", "UPRIGHT_TILT_DEGREES", "test6"))
        self.assertEqual(inverted_pendulum.GRAVITY_M_S2, constant("utils/WorldSettings.h", "SURFACE_GRAVITY"))

    def test_the_e_fold_time_is_the_one_the_scene_states(self):
        # tests/scenes/test6_axis_system.cpp: "about e-fold every 0.65 s for these sizes".
        source = (ROOT / "tests/scenes/test6_axis_system.cpp").read_text()
        self.assertRegex(source, r"e-fold every\s*(//\s*)?0\.65 s")
        self.assertAlmostEqual(1 / inverted_pendulum.growth_rate(), 0.65, delta=0.005)
        a, g = 5.0, 9.823  # I = m a^2 / 6 + m (a / 2)^2 about the anchor, d = a / 2
        self.assertAlmostEqual(inverted_pendulum.growth_rate(), math.sqrt(g * a / 2 / (a * a / 6 + a * a / 4)))

    def test_the_fall_time_and_its_inverse(self):
        self.assertAlmostEqual(inverted_pendulum.fall_seconds(0.01), math.acosh(100) / inverted_pendulum.growth_rate())
        self.assertAlmostEqual(inverted_pendulum.equivalent_start_tilt(inverted_pendulum.fall_seconds(0.001)), 0.001)
        for bad in (0, -0.1, 1.0, 2.0):
            with self.assertRaises(ValueError):
                inverted_pendulum.fall_seconds(bad)

    def test_the_header_states_the_formula_and_its_inputs(self):
        text = inverted_pendulum.header()
        for words in ("acosh(theta_f / theta_0) / lambda", "sqrt(m g d / I)", "a = 5 m", "g = 9.823",
                      "theta_f = 1 degree", "I = m a^2/6 + m d^2"):
            self.assertIn(words, text)


class Test6Row(unittest.TestCase):
    """The first screen's test6 row scores the fall from a tilt, and the
    engines' untilted "seconds upright" is not put beside it."""

    def folder(self):
        folder = Path(tempfile.mkdtemp())
        self.addCleanup(shutil.rmtree, folder)
        lines = ["setting,step_s,seed,tilt_degrees,seconds,seconds_upright,fell,analytic_fall_s,fall_time_error"]
        for setting, step, error in (("QuickStep 20, step 0.001 (plain)", 0.001, -0.6),
                                     ("dWorldStep, step 0.001 (remedy)", 0.001, -0.0008),
                                     ("QuickStep 20, step 0.0001 (smaller step)", 0.0001, -0.05)):
            for seed in (1, 2, 3):
                lines.append(f'"{setting}",{step},{seed},0.01,7,{3.45 * (1 + error)},1,3.45,{error}')
        (folder / "remedy-test6-tilted.csv").write_text(HEADER + "\n".join(lines) + "\n")
        return folder

    def test_the_figure_is_the_fall_time_error_from_a_tilt(self):
        _, (definition, setting), figure, _, decides, _, _ = row("test6")
        sentences = Sentences(Data(self.folder()))
        self.assertEqual(setting["quantity"], "fall-time error")
        self.assertIn("0.01° tilt", sentences.say(definition))
        self.assertEqual(first_screen.cell(sentences, figure, setting, "ODE reads", "-"), "-60% (median, 3)")
        self.assertEqual(sentences.say(*decides), "the solver: from a 0.01 deg tilt dWorldStep falls -0.08% off "
                                                  "the analytic time, QuickStep 20 -60% (step 0.0001: -5%)")

    def test_the_engines_untilted_seconds_upright_are_not_its_peer_cell(self):
        # The committed peers.csv has Havok "upright all 60 s": not a fall-time error.
        _, (_, setting), _, _, _, _, peer = row("test6")
        self.assertEqual(first_screen.cell(Sentences(Data(COMMITTED)), peer, setting, "engines read", "-"),
                         "n/a: engines read seconds upright")


class EnginesTest6Unranked(unittest.TestCase):
    """No engine is "best" at standing longest on an unstable equilibrium."""

    def test_the_section_says_why_and_gives_no_headline(self):
        out = Path(tempfile.mkdtemp())
        self.addCleanup(shutil.rmtree, out)
        ctx = types.SimpleNamespace(out_dir=out, register_files=lambda *files: None)
        scene = next(s for s in peers.SCENES if s.name == "test6")
        rows = [dict(scene="test6", engine=e, setting="best", step=0.001, value=v, wall_s_per_sim_s=0.01,
                     cpu_s_per_sim_s=0.01, cpu_s_per_sim_s_min=0.009, cpu_s_per_sim_s_max=0.011, repeats=5,
                     engine_s_per_sim_s=0.005, engine_s_per_sim_s_min=0.004, engine_s_per_sim_s_max=0.006,
                     surface="mu infinite", mu="infinite", like_ode_surface=1, by_construction="", exit_status=0,
                     voided=False,
                     capped=False) for e, v in (("ode", 10.98), ("havok", 60.0))]
        text, headline, claims = peers.Peers().scene_part(ctx, scene, rows)
        self.assertEqual(claims, {})
        self.assertEqual(headline, [])
        self.assertIn("Not ranked: standing longer is not better physics", text)
        self.assertNotIn("is best with", text)



class FakeRun:
    """A run's metrics, as runner.RunResult gives them."""

    def __init__(self, metrics, rc=0):
        self.metrics, self.rc = metrics, rc

    def m(self, name):
        return self.metrics.get(name)


E0 = 0.43 * 9.823 * 7.0  # m g H: released horizontal, the potential's zero on the ground
SWING = 0.43 * 9.823 * (0.1 * 1.5 + 0.33 * 3.3) / 0.43  # m g d


class SwingEnergy(unittest.TestCase):
    """test2's relative energy errors divide by m g d, not by E0 (2.4x larger)."""

    def test_the_inputs_are_the_scenes_own_constants(self):
        header = "tests/shared/SceneConstants.h"
        for mine, name in ((swing_energy.HINGE_HEIGHT_M, "ANCHOR_HEIGHT"), (swing_energy.ROD_LENGTH_M, "ROD_LENGTH"),
                           (swing_energy.ROD_MASS_KG, "ROD_MASS"), (swing_energy.BOB_MASS_KG, "BOB_MASS"),
                           (swing_energy.BOB_DISTANCE_M, "BOB_DISTANCE")):
            self.assertEqual(mine, constant(header, name, "test2"), name)
        self.assertEqual(swing_energy.GRAVITY_M_S2, constant("utils/WorldSettings.h", "SURFACE_GRAVITY"))

    def test_m_g_d_and_the_dilution_of_e0(self):
        self.assertAlmostEqual(swing_energy.swing_joules(), SWING)
        self.assertAlmostEqual(swing_energy.start_joules(), E0)
        self.assertAlmostEqual(E0 / SWING, 2.43, delta=0.005)
        # The committed report's test2 run started at m g H: the constants describe the scene that ran.
        with open(ROOT / "doc/results/energy-test2-summary.csv") as f:
            row = next(csv.DictReader(line for line in f if not line.startswith("#")))
        self.assertAlmostEqual(float(row["energy_start_J"]), E0, delta=1e-6 * E0)
        for words in ("m g d = 12.17", "E0 = m g H = 29.567", "m = 0.43 kg", "g = 9.823", "d = 2.8814 m"):
            self.assertIn(words, swing_energy.header())

    def test_a_run_from_another_start_is_refused(self):
        with self.assertRaises(LabError):
            swing_energy.largest_error(E0 * 1.01, E0, E0 * 1.01)
        self.assertAlmostEqual(swing_energy.largest_error(E0, E0 - 0.1, E0 + 0.05), 0.1 / SWING)

    def test_the_speed_sweep_reads_the_error_per_swing_energy(self):
        run = FakeRun({"energy_start_J": E0, "energy_min_J": E0 - 0.2, "energy_max_J": E0 + 0.1})
        self.assertAlmostEqual(speed_accuracy.SpeedTest2().error_of(run), 0.2 / SWING)
        self.assertIn("(m g d)", speed_accuracy.SpeedTest2.error_label)

    def test_every_engines_test2_figure_is_per_swing_energy(self):
        scene = next(s for s in peers.SCENES if s.name == "test2")
        ctx = types.SimpleNamespace(quick=False, runner=types.SimpleNamespace(
            run=lambda spec: FakeRun({"energy_max_deviation": 0.01, "energy_start_J": E0})))
        value, _, _ = peers.Peers().measure(ctx, scene, "bullet", [], 0.001)
        self.assertAlmostEqual(value, 0.01 * E0 / SWING)
        self.assertIn("(m g d)", scene.label)

    def test_the_thesis_rows_value_is_per_swing_energy(self):
        results = collections.defaultdict(lambda: FakeRun({}))
        results["t2"] = FakeRun({"energy_start_J": E0, "energy_min_J": E0 - 0.3, "energy_max_J": E0})
        rows = {r["name"]: r for r in thesis.Thesis.values(results) if r["key"] == "test2"}
        self.assertNotIn("max_deviation", rows)
        self.assertAlmostEqual(rows["max_swing_error"]["value"], 0.3 / SWING)

    def test_the_drift_is_per_swing_energy(self):
        results = collections.defaultdict(lambda: FakeRun({}))
        results["t2_cfm"] = FakeRun({"energy_start_J": E0, "energy_last_J": E0 - 0.2, "energy_drift": -0.2 / E0})
        rows = {r["name"]: r for r in thesis.Thesis.values(results) if r["key"] == "test2_cfm"}
        self.assertAlmostEqual(rows["drift"]["value"], -0.2 / SWING)



class Test10Symbols(unittest.TestCase):
    """test10's symbols mean one thing each: a the cube's half-size, w the
    wall's thickness, h the step (as in test8's F h CFM / ERP)."""

    def test_the_csv_header_defines_them(self):
        for words in ("a the cube's half-size", "w the wall's thickness", "h the step",
                      "geometric_prediction = (a + w) / h", "guaranteed_stop_velocity = (a + w/2) / h"):
            self.assertIn(words, limit_test10.SYMBOLS)

    def test_no_text_uses_h_for_the_half_size(self):
        places = [*sorted((ROOT / "lab/odelab_report").rglob("*.py")),
                  *(ROOT / name for name in ("doc/lab.md", "doc/peers.md", "doc/tests/test10.md"))]
        for path in places:
            text = path.read_text()
            for old in ("h + t", "(h+t)", "2h + t"):
                self.assertNotIn(old, text, f"{path.relative_to(ROOT)} writes {old!r}")

    def test_doc_lab_defines_the_symbols_once(self):
        text = (ROOT / "doc/lab.md").read_text()
        self.assertEqual(text.count("### Symbols"), 1)
        start = text.index("### Symbols")
        section = " ".join(text[start:text.index("\n###", start + 3)].split())
        for words in ("a the cube's half-size", "w the wall's thickness", "h the step", "|E - E0| / (m g d)",
                      "theta_0 the start tilt"):
            self.assertIn(words, section)


if __name__ == "__main__":
    unittest.main()

"""Unit checks that every sentence of RESULTS.md is a rule on its own data:
the engines' (peers) headline findings and verdicts are claims on peers.csv,
a typed peers headline fails the check, and a claim that reads the CSVs
with a rule naming none of its values fails it too.
Run: /usr/bin/python3 -m unittest discover -s lab/tests (CTest: lab_executor_units)."""

import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

import check_report  # noqa: E402
from odelab_report import csvout, peers_headline  # noqa: E402
from odelab_report.claims import HEADLINE, Claim, Data, Sentences, q, read_rows, recheck  # noqa: E402

PEERS = ("# ODE: test\nscene,engine,setting,step,quantity,value,engine_s_per_sim_s,engine_s_per_sim_s_min,"
         "engine_s_per_sim_s_max,like_ode_surface,by_construction,capped\n"
         "test2,ode,default,0.001,e,0.00032,0.003,0.0028,0.0032,1,,0\n"
         "test2,ode,best,0.001,e,1e-9,0.004,0.0038,0.0042,1,,0\n"
         "test2,havok,default,0.001,e,3e-8,0.02,0.019,0.021,1,,0\n"
         "test2,jolt,default,0.001,e,5e-8,0.01,0.009,0.0205,1,,0\n"
         "test2,mujoco,best,0.001,e,2e-14,0.004,0.0039,0.0041,1,,0\n"
         "test4,ode,default,0.001,m,11900,0.01,0.009,0.011,1,,0\n"
         "test4,bullet,default,0.001,m,3e6,0.02,0.019,0.021,0,,0\n"
         "test7,ode,default,0.001,j,0.016,0.01,0.009,0.011,1,,0\n"
         "test7,mujoco,default,0.001,j,3e-15,0.001,0.0009,0.0011,1,zero by construction,0\n"
         "test10,ode,default,0.001,v,250,0.002,0.0019,0.0021,1,,0\n"
         "test10,ode,best,0.001,v,100000,0.003,0.0029,0.0031,1,,1\n"
         "test10,bullet,default,0.001,v,100000,0.004,0.0039,0.0041,1,,0\n")
ROUNDING = (("havok", "jolt", "rapier"), 1e-12, 1e-7)


class PeersHeadline(unittest.TestCase):
    """Defaults beside defaults, like with like, ties within the timing's scatter."""

    def setUp(self):
        self.folder = Path(tempfile.mkdtemp())
        (self.folder / "peers.csv").write_text(PEERS)

    def say(self, scene, label, lower_is_better):
        claims = peers_headline.headline(scene, label, lower_is_better, 0.001, *ROUNDING)
        return Sentences(Data(self.folder)).say(*claims, place=HEADLINE)

    def test_errors_below_rounding_tie_inside_the_scatter(self):
        # havok's and jolt's errors are both below float32 rounding; their
        # engine-time ranges overlap: a tie, the cheapest first; ODE's and MuJoCo's "best"
        # settings take no part beside defaults.
        self.assertEqual(self.say("test2", "energy error", True),
                         "peers test2 (energy error): at step 0.001, defaults beside defaults: a tie within the "
                         "timing's scatter at 5e-08: jolt, havok.")

    def test_a_higher_figure_wins_among_defaults(self):
        text = self.say("test10", "velocity stopped", False)
        self.assertTrue(text.startswith("peers test10 (velocity stopped): at step 0.001, defaults beside defaults: "
                                        "bullet is best with 1e5 at "), text)

    def test_another_surface_takes_no_part(self):
        text = self.say("test4", "heaviest cube held", False)
        self.assertIn(": ode is best with 11900", text)

    def test_a_figure_zero_by_construction_takes_no_part(self):
        text = self.say("test7", "joint error", True)
        self.assertIn(": ode is best with 0.016", text)

    def test_no_figure_at_the_step_is_said_as_such(self):
        rows = [line for line in PEERS.splitlines() if not line.startswith("test10")]
        (self.folder / "peers.csv").write_text("\n".join(rows + ["test10,ode,default,0.001,v,,,,,1,,0"]) + "\n")
        self.assertEqual(self.say("test10", "velocity stopped", False),
                         "peers test10 (velocity stopped): at step 0.001, defaults beside defaults: no engine that "
                         "compares reached a figure.")

    def test_the_rule_fails_when_the_csv_no_longer_backs_the_sentence(self):
        claims = peers_headline.headline("test10", "velocity stopped", False, 0.001, *ROUNDING)
        sentences = Sentences(Data(self.folder))
        self.assertIsNotNone(sentences.say(*claims, place=HEADLINE))
        (self.folder / "peers.csv").write_text(PEERS.replace("test10,ode,default,0.001,v,250,", "test10,ode,default,"
                                                             "0.001,v,200000,"))
        problems = recheck(self.folder, sentences.shown)
        self.assertTrue(any("the CSVs give" in p for p in problems), problems)


class EverySentenceARule(unittest.TestCase):
    def setUp(self):
        self.folder = Path(tempfile.mkdtemp())
        (self.folder / "peers.csv").write_text(PEERS)

    def write(self, found, headline_lines):
        sentences = Sentences(Data(self.folder))
        for claim in found:
            sentences.say(*(claim if isinstance(claim, list) else [claim]), place=HEADLINE)
        csvout.write_csv(self.folder / "claims.csv", [("ODE", "test")], Sentences.COLUMNS, sentences.shown)
        text = "\n".join(["# report", "", "## Headline findings", ""] + [f"- {h}" for h in headline_lines] + [""])
        (self.folder / "RESULTS.md").write_text(text)
        return text

    def test_a_typed_peers_headline_is_no_claim(self):
        typed = "peers test2 (energy error): at step 0.001, defaults beside defaults: havok is best with 0."
        claims = peers_headline.headline("test10", "velocity stopped", False, 0.001, *ROUNDING)
        said = Sentences(Data(self.folder)).say(*claims, place=HEADLINE)
        text = self.write([claims], [said, typed])
        problems = check_report.check_sentences(self.folder, text)
        self.assertTrue(any("peers test2" in p and "no claim" in p for p in problems), problems)

    def test_a_peers_headline_claim_passes(self):
        claims = peers_headline.headline("test2", "energy error", True, 0.001, *ROUNDING)
        said = Sentences(Data(self.folder)).say(*claims, place=HEADLINE)
        text = self.write([claims], [said])
        self.assertEqual(check_report.check_sentences(self.folder, text), [])
        self.assertEqual(recheck(self.folder, read_rows(self.folder / "claims.csv")), [])
        self.assertEqual(check_report.check_rules(self.folder), [])

    def test_a_rule_that_reads_nothing_fails(self):
        blind = Claim("headline.blind", "ODE's error is {v:n}.",
                      {"v": q("peers.csv", "value", scene="test2", engine="ode", setting="default", step=0.001)})
        self.write([blind], ["ODE's error is 0.00032."])
        problems = check_report.check_rules(self.folder)
        self.assertEqual(len(problems), 1, problems)
        self.assertIn("reads none of its values", problems[0])

    def test_a_definition_of_constants_needs_no_rule(self):
        label = Claim("first.test2.definition", "energy, 60 s", {"quantity": "'energy'", "seconds": "60"})
        self.write([label], [])
        self.assertEqual(check_report.check_rules(self.folder), [])


class Percentages(unittest.TestCase):
    def test_a_share_that_rounds_up_to_a_new_digit_is_still_a_plain_percentage(self):
        from odelab_report import markdown as md
        self.assertEqual([md.pct(0.995), md.pct(0.5), md.pct(0.00123), md.pct(123.4)],
                         ["99.5%", "50%", "0.12%", "12340%"])


if __name__ == "__main__":
    unittest.main()

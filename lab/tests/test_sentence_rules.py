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

PEERS = ("# ODE: test\nscene,engine,setting,step,quantity,value,wall_s_per_sim_s,cpu_s_per_sim_s,capped\n"
         "test2,ode,default,0.001,e,0.00032,0.002,0.003,0\n"
         "test2,mujoco,default,0.001,e,2e-14,0.004,0.005,0\n"
         "test2,mujoco,best,0.001,e,3e-14,0.003,0.004,0\n"
         "test2,havok,best,0.001,e,4e-3,0.01,0.02,0\n"
         "test2,ode,default,0.01,e,1e-20,0.0002,0.0003,0\n"
         "test10,ode,default,0.001,v,250,0.001,0.002,0\n"
         "test10,ode,best,0.001,v,100000,0.002,0.003,1\n"
         "test10,bullet,best,0.001,v,,0.003,0.004,0\n")
ROUNDING = (("havok", "jolt", "rapier"), 1e-12, 1e-7)


class PeersHeadline(unittest.TestCase):
    def setUp(self):
        self.folder = Path(tempfile.mkdtemp())
        (self.folder / "peers.csv").write_text(PEERS)

    def say(self, claim):
        return claim.evaluate(Data(self.folder))

    def test_errors_below_rounding_tie_and_the_cheapest_is_named(self):
        text, holds = self.say(peers_headline.headline("test2", "energy error", True, 0.001, *ROUNDING))
        self.assertTrue(holds)
        self.assertEqual(text, "peers test2 (energy error): at step 0.001: mujoco (default), mujoco (best) are exact "
                               "to rounding with 3e-14, the cheapest mujoco (best) at 0.003 wall s per simulated s; "
                               "ODE at its default 0.00032.")

    def test_a_higher_figure_wins_and_a_scan_limit_says_so(self):
        text, holds = self.say(peers_headline.headline("test10", "velocity stopped", False, 0.001, *ROUNDING))
        self.assertTrue(holds)
        self.assertEqual(text, "peers test10 (velocity stopped): at step 0.001: ode (best) is best with 1e5 "
                               "(scan limit) at 0.002 wall s per simulated s; ODE at its default 250.")

    def test_the_rule_fails_when_the_csv_no_longer_backs_the_sentence(self):
        claim = peers_headline.headline("test10", "velocity stopped", False, 0.001, *ROUNDING)
        sentences = Sentences(Data(self.folder))
        self.assertIsNotNone(sentences.say(claim, place=HEADLINE))
        (self.folder / "peers.csv").write_text(PEERS.replace("test10,bullet,best,0.001,v,,", "test10,bullet,best,"
                                                             "0.001,v,200000,"))
        problems = recheck(self.folder, sentences.shown)
        self.assertTrue(any("the CSVs give" in p for p in problems), problems)

    def test_no_figure_at_the_step_is_said_as_such(self):
        (self.folder / "peers.csv").write_text(PEERS.replace("test10,ode,default,0.001,v,250", "test10,ode,default,"
                                                             "0.001,v,").replace("v,100000", "v,"))
        found, none = peers_headline.verdict("test10", False, 0.001, *ROUNDING)
        sentences = Sentences(Data(self.folder))
        self.assertEqual(sentences.say(found, none, place="peers"), "No engine reached a figure at step 0.001.")


class EverySentenceARule(unittest.TestCase):
    def setUp(self):
        self.folder = Path(tempfile.mkdtemp())
        (self.folder / "peers.csv").write_text(PEERS)

    def write(self, found, headline_lines):
        sentences = Sentences(Data(self.folder))
        for claim in found:
            sentences.say(claim, place=HEADLINE)
        csvout.write_csv(self.folder / "claims.csv", [("ODE", "test")], Sentences.COLUMNS, sentences.shown)
        text = "\n".join(["# report", "", "## Headline findings", ""] + [f"- {h}" for h in headline_lines] + [""])
        (self.folder / "RESULTS.md").write_text(text)
        return text

    def test_a_typed_peers_headline_is_no_claim(self):
        typed = "peers test2 (energy error): at step 0.001: havok (best) is best with 0 at 0.001 wall s."
        claim = peers_headline.headline("test10", "velocity stopped", False, 0.001, *ROUNDING)
        text = self.write([claim], [claim.evaluate(Data(self.folder))[0], typed])
        problems = check_report.check_sentences(self.folder, text)
        self.assertTrue(any("peers test2" in p and "no claim" in p for p in problems), problems)

    def test_a_peers_headline_claim_passes(self):
        claim = peers_headline.headline("test2", "energy error", True, 0.001, *ROUNDING)
        text = self.write([claim], [claim.evaluate(Data(self.folder))[0]])
        self.assertEqual(check_report.check_sentences(self.folder, text), [])
        self.assertEqual(recheck(self.folder, read_rows(self.folder / "claims.csv")), [])
        self.assertEqual(check_report.check_rules(self.folder), [])

    def test_a_rule_that_reads_nothing_fails(self):
        blind = Claim("headline.blind", "ODE's error is {v:n}.",
                      {"v": q("peers.csv", "value", scene="test2", engine="ode", step=0.001)})
        self.write([blind], ["ODE's error is 0.00032."])
        problems = check_report.check_rules(self.folder)
        self.assertEqual(len(problems), 1, problems)
        self.assertIn("reads none of its values", problems[0])

    def test_a_definition_of_constants_needs_no_rule(self):
        label = Claim("first.test2.definition", "energy, 60 s", {"quantity": "'energy'", "seconds": "60"})
        self.write([label], [])
        self.assertEqual(check_report.check_rules(self.folder), [])


if __name__ == "__main__":
    unittest.main()

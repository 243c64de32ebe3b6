"""remedy-test4's settings and its headline sentence (experiments/remedy_test4.py
measures them): apart, so that the sentence's rule is checked without the
plotting the experiment needs."""

from .claims import Claim, q

SETTINGS = [
    ("QuickStep 20, step 0.001 (plain)", 1e-3, ["--solver", "quick", "--iterations", 20]),
    ("dWorldStep, step 0.001 (remedy)", 1e-3, ["--solver", "step"]),
    ("QuickStep 20, step 0.0001 (smaller step)", 1e-4, ["--solver", "quick", "--iterations", 20]),
]
COST_MASS = 5000.0


def _setting(column, label):
    return q("remedy-test4.csv", column, setting=label)


_HEADLINE = {"p": _setting("heaviest_held_kg", SETTINGS[0][0]), "s": _setting("heaviest_held_kg", SETTINGS[1][0]),
             "small": _setting("heaviest_held_kg", SETTINGS[2][0]),
             "sr": _setting("cost_relative_to_plain", SETTINGS[1][0]),
             "slo": _setting("cost_relative_min", SETTINGS[1][0]), "shi": _setting("cost_relative_max", SETTINGS[1][0]),
             "tie": _setting("cost_within_scatter", SETTINGS[1][0]), "n": _setting("repeats", SETTINGS[1][0]),
             "smallr": _setting("cost_relative_to_plain", SETTINGS[2][0]),
             "smlo": _setting("cost_relative_min", SETTINGS[2][0]),
             "smhi": _setting("cost_relative_max", SETTINGS[2][0])}
# The cost against the plain setting: the ratio of the medians and its range
# over the runs; where the two settings' ranges overlap, neither is cheaper.
HEADLINE = [Claim("headline.test4.remedy", "test4 remedy: dWorldStep at step 0.001 holds {s:n} kg (QuickStep: "
                  "{p:n} kg) "
                  "at {sr:.2f}x the CPU cost ({slo:.2f}-{shi:.2f}x over {n:.0f} runs each); step 0.0001 holds "
                  "{small:n} kg at {smallr:.1f}x ({smlo:.1f}-{smhi:.1f}x).", _HEADLINE,
                  "s > p and small > p and tie == 0"),
            Claim("headline.test4.remedy.tie", "test4 remedy: dWorldStep at step 0.001 holds {s:n} kg (QuickStep: "
                  "{p:n} kg) at the same CPU cost within the timing's scatter ({slo:.2f}-{shi:.2f}x over {n:.0f} runs "
                  "each); step 0.0001 holds {small:n} kg at {smallr:.1f}x ({smlo:.1f}-{smhi:.1f}x).", _HEADLINE,
                  "s > p and small > p and tie == 1")]

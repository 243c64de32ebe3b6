"""The thesis's figures as the lab uses them, read from the sentences that
write them (lab/reference/thesis-statements.csv, column `figures`) rather
than typed into the experiments: lab/tests/test_thesis_statements.py holds
every quote to the thesis's text and every listed figure to its quote, so a
figure the experiments judge by is held to the thesis too.

Kept free of the experiments' imports (matplotlib), so that the unit test
can read it."""

import csv
import re
from pathlib import Path

STATEMENTS = Path(__file__).resolve().parents[1] / "reference" / "thesis-statements.csv"

# Figures the thesis writes in words; each with the value the lab reads it as
# and why. A figure written in digits is parsed (number_of).
WORDS = {
    "v reálném čase": 1.0,              # "in real time": a real-time factor of 1
    "na šest desetinných míst": 5e-7,   # "to six decimals": half a unit of the sixth decimal
    "polovinu": 0.5,                    # "to half"
    "na nulu": 0.0,                     # "to zero"
    "nad nulou": 0.0,                   # "above zero"
    "desetinásobek": 10.0,              # "tenfold"
    "1000 tun": 1e6,                    # "1000 tonnes", in kg as the scenes take a mass
}


def number_of(token):
    """The value of a figure as the thesis writes it: 0.75%, 29.250, 5000.0,
    10−3 (ten to the minus three), 250 ms−1 (a speed)."""
    if token in WORDS:
        return WORDS[token]
    text = token.replace("\u2212", "-").removesuffix(" ms-1").strip()
    power = re.fullmatch(r"10-(\d+)", text)
    if power:
        return 10.0 ** -int(power.group(1))
    if text.endswith("%"):
        return float(text[:-1]) / 100
    return float(text)


def read(path=STATEMENTS):
    with open(path, newline="", encoding="utf-8") as stream:
        return list(csv.DictReader(stream))


def quoted(target, token, statements=None):
    """The value of `token`, a figure that a quoted statement pointing at
    `target` (thesis.csv:KEY or thesis-havok.csv:TEST) lists in its
    `figures`; a ValueError when none does, so an experiment cannot judge by
    a figure the thesis was not quoted giving."""
    for s in statements if statements is not None else read():
        if target in s["rows"].split() and token in filter(None, s["figures"].split(";")):
            return number_of(token)
    raise ValueError(f"{STATEMENTS.name}: no statement pointing at {target} lists the figure '{token}'")

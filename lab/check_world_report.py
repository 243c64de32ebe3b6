#!/usr/bin/python3
"""Checks a report written by `lab/odelab-report --world FILE` (CTest runs
it after the quick report on checks/worlds/):

- RESULTS.md starts with its title, its only top-level heading, holds no HTML
  element or comment, and has "## At a glance" within its first 15
  lines with the three questions, each answered by at least one sentence;
- every CSV the world report writes is there, starts with the run header and
  has at least one row; world-sweep.csv has exactly one reference row and one
  row of the world's own settings, the reference's agreement with itself
  (ode_max_dev) 0;
- every plot RESULTS.md embeds exists as a valid PNG and its SVG parses;
- every sentence in claims.csv, recomputed from the folder's CSVs, gives the
  same text and its rule holds, and stands in RESULTS.md.

Usage: check_world_report.py REPORT_DIR   (exit 0: all good; 1: problems, listed)"""

import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from check_report import check_png, check_svg  # noqa: E402
from odelab_report.claims import read_rows, recheck  # noqa: E402

CSVS = ("world-sweep.csv", "world-measures.csv", "world-limit.csv", "world-engines.csv", "runs.csv", "claims.csv")
QUESTIONS = ("Which setting keeps it accurate enough at the least cost?", "Where does it break?",
             "Would another engine do better?")
HEADER_KEYS = ("ODE", "compiler", "CPU", "date", "commit")


def check(folder):
    problems = []
    results = folder / "RESULTS.md"
    if not results.is_file():
        return [f"{results}: missing"]
    text = results.read_text()
    lines = text.splitlines()
    if not lines or not lines[0].startswith("# ODE Lab: the world"):
        problems.append("RESULTS.md: does not start with its title")
    # The world's title is the file's text: it must not make a heading, a row or an element of its own.
    headings = [l for l in lines if l.startswith("# ")]
    if len(headings) != 1:
        problems.append(f"RESULTS.md: {len(headings)} top-level headings; the title makes the only one")
    element = re.search(r"<[A-Za-z!/?]", "\n".join(l for l in lines if not l.startswith("    ")))
    if element:
        problems.append(f"RESULTS.md: an HTML element or comment ({element.group(0)}...): given text must be escaped")
    if "## At a glance" not in lines[:15]:
        problems.append("RESULTS.md: no '## At a glance' within its first 15 lines")
    for question in QUESTIONS:
        line = next((l for l in lines if l.startswith(f"**{question}**")), None)
        if line is None or len(line) <= len(question) + 6:
            problems.append(f"RESULTS.md: the question '{question}' has no answer")
    for name in CSVS:
        path = folder / name
        if not path.is_file():
            problems.append(f"{name}: missing")
            continue
        head = path.read_text().splitlines()[:len(HEADER_KEYS) + 4]
        for key in HEADER_KEYS:
            if not any(h.startswith(f"# {key}:") for h in head):
                problems.append(f"{name}: no '# {key}:' line in its run header")
        if not read_rows(path):
            problems.append(f"{name}: no rows")
    if (folder / "world-sweep.csv").is_file():
        rows = read_rows(folder / "world-sweep.csv")
        refs = [r for r in rows if r["reference"] == "1"]
        if len(refs) != 1 or len([r for r in rows if r["own"] == "1"]) != 1:
            problems.append("world-sweep.csv: not exactly one reference row and one row of the world's settings")
        elif float(refs[0]["ode_max_dev"]) != 0.0:
            problems.append(f"world-sweep.csv: the reference deviates from itself by {refs[0]['ode_max_dev']}")
    for stem in sorted(set(re.findall(r"!\[[^\]]*\]\(([\w.-]+)\.png\)", text))):
        for suffix, checker in ((".png", check_png), (".svg", check_svg)):
            path = folder / (stem + suffix)
            problem = checker(path) if path.is_file() else "missing"
            if problem:
                problems.append(f"{path.name}: {problem}")
    if (folder / "claims.csv").is_file():
        claims = read_rows(folder / "claims.csv")
        problems += recheck(folder, claims)
        problems += [f"claim {c['key']}: its text is not in RESULTS.md" for c in claims if c["text"] not in text]
    return problems


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__.split("\n\n")[-1] + "\n")
        return 2
    problems = check(Path(argv[1]))
    for problem in problems:
        print(f"check_world_report: {problem}")
    if not problems:
        print(f"check_world_report: {argv[1]}: every file and sentence checks")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

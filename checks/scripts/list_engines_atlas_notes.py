#!/usr/bin/env python3
"""`PROGRAM --list-engines` prints, under each engine, exactly the rows of
the atlas-notes.csv its tree committed (compiled in by cmake/AtlasNotes.cmake):
every row, in its engine's block, with the same counts and cases; no
engine said to be measured that the CSV does not have.

Usage: list_engines_atlas_notes.py PROGRAM ATLAS_NOTES_CSV   (exit 0 / 1)"""

import csv
import re
import subprocess
import sys

LINE = re.compile(r"^  measured, (\w+) \(accuracy atlas, step (\S+) s\): right on (\d+) of (\d+) cases"
                  r"(?:; not on: (.*))?$")


def printed(text):
    rows, engine = [], None
    for line in text.splitlines():
        opened = re.match(r"^([a-z0-9_]+): (?:available|not available)", line)
        if opened:
            engine = opened.group(1)
            continue
        m = LINE.match(line)
        if m:
            setting, step, right, cases, not_right = m.groups()
            rows.append(dict(engine=engine, setting=setting, step=step, right=right, cases=cases,
                             not_right=not_right or ""))
    return rows


def main(program, notes):
    with open(notes, newline="", encoding="utf-8") as stream:
        wanted = list(csv.DictReader(line for line in stream if not line.startswith("#")))
    have = printed(subprocess.run([program, "--list-engines"], check=True, capture_output=True, text=True).stdout)
    if have != wanted:
        for n in range(max(len(have), len(wanted))):
            a = have[n] if n < len(have) else "(none)"
            b = wanted[n] if n < len(wanted) else "(none)"
            if a != b:
                print(f"list_engines_atlas_notes: row {n + 1}: --list-engines prints {a}\n  {notes} has {b}")
                break
        return 1
    print(f"list_engines_atlas_notes: {len(have)} measured lines, each the CSV's row")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.stderr.write(__doc__)
        sys.exit(2)
    sys.exit(main(sys.argv[1], sys.argv[2]))

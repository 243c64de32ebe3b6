#!/usr/bin/env python3
"""Checks an atlas report (lab/odelab-report --atlas): its ATLAS.md says what
atlas.csv and atlas-engines.csv say, word for word, because the text is made
again here from those CSVs by the rules that made it (atlas_text.py); and
atlas-notes.csv (what odelab --list-engines prints) holds the rows those
rules make from atlas.csv.

    lab/check_atlas_report.py [DIR]   (default doc/atlas-report/)

Exit status: 0 the text matches; 1 it does not (the first differing line is
shown); 2 the folder, a CSV or ATLAS.md is missing or unreadable."""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from odelab_report import atlas_text  # noqa: E402
from odelab_report.csvout import format_value, read_csv  # noqa: E402

FILES = ("atlas.csv", "atlas-engines.csv")
NOTES = "atlas-notes.csv"


def expected_text(folder):
    rows, engine_rows = (read_csv(folder / name)[2] for name in FILES)
    return atlas_text.markdown(rows, engine_rows, list(FILES) + [NOTES])


def notes_problem(folder):
    """None, or the first row of atlas-notes.csv that is not what
    atlas_text.note_rows makes from atlas.csv."""
    _, columns, have = read_csv(folder / NOTES)
    if tuple(columns) != atlas_text.NOTE_COLUMNS:
        return f"its columns are {', '.join(columns)}, not {', '.join(atlas_text.NOTE_COLUMNS)}"
    wanted = [{k: format_value(v) for k, v in row.items()} for row in atlas_text.note_rows(read_csv(folder / FILES[0])[2])]
    for n in range(max(len(have), len(wanted))):
        a = have[n] if n < len(have) else "(no row)"
        b = wanted[n] if n < len(wanted) else "(no row)"
        if a != b:
            return f"row {n + 1} differs from atlas.csv's:\n  {NOTES}: {a}\n  atlas.csv makes: {b}"
    return None


def main(argv):
    folder = Path(argv[1] if len(argv) > 1 else Path(__file__).resolve().parents[1] / "doc" / "atlas-report")
    try:
        wanted = expected_text(folder).strip().splitlines()
        text = (folder / "ATLAS.md").read_text(encoding="utf-8").splitlines()
        notes = notes_problem(folder)
    except (OSError, UnicodeDecodeError, KeyError, StopIteration) as error:
        sys.stderr.write(f"check_atlas_report: error: {folder}: {error}\n")
        return 2
    try:
        start = text.index(wanted[0])
    except ValueError:
        sys.stderr.write(f"check_atlas_report: {folder / 'ATLAS.md'}: the atlas's first line is not there:\n"
                         f"  {wanted[0]}\n")
        return 1
    if notes:
        sys.stderr.write(f"check_atlas_report: {folder / NOTES}: {notes}\n")
        return 1
    for n, line in enumerate(wanted):
        have = text[start + n] if start + n < len(text) else "(the end of the file)"
        if have != line:
            sys.stderr.write(f"check_atlas_report: {folder / 'ATLAS.md'} line {start + n + 1} differs from its "
                             f"CSVs:\n  ATLAS.md: {have}\n  the CSVs: {line}\n")
            return 1
    print(f"check_atlas_report: {folder / 'ATLAS.md'}: {len(wanted)} lines made again from its CSVs, all equal")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

#!/usr/bin/env python3
"""Holds what is written about an engine's behaviour to what the accuracy
atlas measured. A sentence about how an engine behaves (in an adapter's
best-settings text or translation notes, or in doc/peers.md) cites the atlas
cells it rests on in a tag:

    [atlas: bullet default double-pendulum-energy off; bullet best double-pendulum-energy right]

each part ENGINE SETTING CASE MARK, MARK one of the atlas's marks (right,
off, no figure, no run, blew up, ODE error). Every tag found is checked
against atlas.csv at the step the atlas shows (atlas_text.SHOWN_STEP): a
cited case, engine or setting the atlas does not have, or a mark that
differs, fails, naming the file and line. So a note the measurement
contradicts cannot stand; when the atlas is made again and an engine
changes, the note must change with it.

    lab/check_engine_claims.py [ROOT] [--atlas DIR]
    (default ROOT: the project; DIR: ROOT/doc/atlas-report)

Exit status: 0 every tag holds; 1 a tag does not (each listed); 2 the
atlas's CSV is missing or unreadable, or bad usage."""

import argparse
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from odelab_report import atlas_text  # noqa: E402
from odelab_report.csvout import read_csv  # noqa: E402

# Where notes about engines are written by hand.
SOURCES = ("peers/engines/*.cpp", "peers/engines/*.h", "peers/wasm/src/engines/*.js", "utils/world/*.cpp",
           "doc/peers.md")
TAG = re.compile(r"\[atlas: ([^\]]*)\]")
MARKS = ("right", "off", "no figure", "no run", "blew up", "ODE error")
PART = re.compile(r"^\s*([a-z0-9_]+) +(default|best) +([a-z0-9-]+) +(" + "|".join(MARKS) + r")\s*$")


def tags(text):
    """(line number, tag text) of every atlas tag; a tag may run over a line
    break (a C++ string split in two)."""
    joined = re.sub(r'"\s*\n\s*"', "", text)  # "... [atlas: a" \n "b ...]" in a C++ or JS source
    found = []
    for m in TAG.finditer(joined):
        line = joined[:m.start()].count("\n") + 1
        found.append((line, m.group(1)))
    return found


def problems_of(root, atlas_dir):
    rows = read_csv(atlas_dir / "atlas.csv")[2]
    marks = {(r["engine"], r["setting"], r["case"]): r["mark"] for r in rows if r["step"] == atlas_text.SHOWN_STEP}
    problems, count = [], 0
    for pattern in SOURCES:
        for path in sorted(root.glob(pattern)):
            for line, tag in tags(path.read_text(encoding="utf-8")):
                for part in tag.split(";"):
                    count += 1
                    where = f"{path.relative_to(root)}:{line}"
                    m = PART.match(part)
                    if not m:
                        problems.append(f"{where}: '[atlas: {tag}]': '{part.strip()}' is not ENGINE SETTING CASE "
                                        f"MARK (MARK one of {', '.join(MARKS)})")
                        continue
                    engine, setting, case, mark = m.groups()
                    measured = marks.get((engine, setting, case))
                    if measured is None:
                        problems.append(f"{where}: cites {engine} {setting} {case}, which atlas.csv has no row "
                                        f"for at step {atlas_text.SHOWN_STEP} s")
                    elif measured != mark:
                        problems.append(f"{where}: says {engine} {setting} is '{mark}' on {case}; the atlas "
                                        f"measured '{measured}' (atlas.csv, step {atlas_text.SHOWN_STEP} s)")
    return problems, count


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("root", nargs="?", default=str(Path(__file__).resolve().parents[1]))
    parser.add_argument("--atlas", help="the atlas report's folder (default ROOT/doc/atlas-report)")
    args = parser.parse_args(argv)
    root = Path(args.root)
    atlas_dir = Path(args.atlas) if args.atlas else root / "doc" / "atlas-report"
    try:
        problems, count = problems_of(root, atlas_dir)
    except (OSError, UnicodeDecodeError, KeyError) as error:
        sys.stderr.write(f"check_engine_claims: error: {error}\n")
        return 2
    for problem in problems:
        sys.stderr.write(f"check_engine_claims: {problem}\n")
    if problems:
        return 1
    print(f"check_engine_claims: {count} cited atlas cells, each as the atlas measured it")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/python3
"""Checks a report written by lab/odelab-report (CTest runs it after
`odelab-report --quick`):

- RESULTS.md exists and starts with the run header;
- every CSV in the folder starts with the run header and has at least one row;
- every plot RESULTS.md embeds or links (PNG and SVG) exists, and every PNG
  and SVG in the folder is a valid image: a PNG's signature and IHDR chunk
  with a non-zero width and height, an SVG that parses as XML with an <svg>
  root and a size;
- every CSV and plot RESULTS.md names exists;
- thesis.csv, when there, has the ODE 0.11.1 rebuild's column and a
  sensitivity for every row not reproduced.

Usage: check_report.py REPORT_DIR   (exit 0: all good; 1: problems, listed)"""

import re
import struct
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

HEADER_KEYS = ("ODE", "compiler", "CPU", "date", "commit")
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def check_png(path):
    data = path.read_bytes()[:33]
    if not data.startswith(PNG_SIGNATURE):
        return "not a PNG (bad signature)"
    if len(data) < 24 or data[12:16] != b"IHDR":
        return "PNG without an IHDR chunk"
    width, height = struct.unpack(">II", data[16:24])
    if width == 0 or height == 0:
        return f"PNG of {width} x {height} pixels"
    return None


def check_svg(path):
    try:
        root = ElementTree.parse(path).getroot()
    except ElementTree.ParseError as error:
        return f"SVG does not parse as XML: {error}"
    if not root.tag.endswith("svg"):
        return f"root element is <{root.tag}>, not <svg>"
    if not (root.get("viewBox") or (root.get("width") and root.get("height"))):
        return "SVG without a size (no viewBox, width or height)"
    if len(list(root.iter())) < 10:
        return "SVG with almost nothing in it"
    return None


def check_csv(path):
    lines = path.read_text(errors="replace").splitlines()
    comments = [line for line in lines if line.startswith("#")]
    body = [line for line in lines if line.strip() and not line.startswith("#")]
    keys = {line[2:].split(":", 1)[0] for line in comments}
    missing = [k for k in HEADER_KEYS if k not in keys]
    if missing:
        return "run header lacks " + ", ".join(missing)
    if len(body) < 2:
        return "no data rows (only " + ("the column names" if body else "the header") + ")"
    return None


def check_thesis(path):
    """thesis.csv (issue 12): the ODE 0.11.1 rebuild's column, and a
    sensitivity for every row the lab does not reproduce."""
    import csv
    rows = list(csv.DictReader(line for line in path.read_text().splitlines() if not line.startswith("#")))
    if rows and "ode_0_11_1_rebuild" not in rows[0]:
        return ["no ode_0_11_1_rebuild column"]
    return [f"row {i + 1} ({row['test']}, {row['conditions']}) is '{row['verdict']}' with an empty sensitivity"
            for i, row in enumerate(rows)
            if not row["verdict"].startswith("reproduced") and not row.get("sensitivity", "").strip()]


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    folder = Path(argv[1])
    problems = []
    results = folder / "RESULTS.md"
    if not results.exists():
        problems.append(f"{results}: missing")
        text = ""
    else:
        text = results.read_text()
        if not all(f"| {key} |" in text for key in HEADER_KEYS):
            problems.append("RESULTS.md: the run header is incomplete")
    named = set(re.findall(r"\]\(([^)#]+\.(?:png|svg|csv))\)", text))
    for name in sorted(named):
        if not (folder / name).exists():
            problems.append(f"RESULTS.md names {name}, which is missing")
    csvs = sorted(folder.glob("*.csv"))
    pngs = sorted(folder.glob("*.png"))
    svgs = sorted(folder.glob("*.svg"))
    for path in csvs:
        problem = check_csv(path)
        if problem:
            problems.append(f"{path.name}: {problem}")
    if (folder / "thesis.csv").exists():
        problems += [f"thesis.csv: {problem}" for problem in check_thesis(folder / "thesis.csv")]
    for path in pngs:
        problem = check_png(path)
        if problem:
            problems.append(f"{path.name}: {problem}")
        if not path.with_suffix(".svg").exists():
            problems.append(f"{path.name}: no SVG beside it")
    for path in svgs:
        problem = check_svg(path)
        if problem:
            problems.append(f"{path.name}: {problem}")
    embedded = set(re.findall(r"!\[[^\]]*\]\(([^)]+\.png)\)", text))
    for path in pngs:
        if path.name not in embedded:
            problems.append(f"{path.name}: not embedded in RESULTS.md")
    if not csvs or not pngs:
        problems.append(f"{folder}: {len(csvs)} CSV files and {len(pngs)} plots; expected some of each")
    for problem in problems:
        print("check_report: " + problem)
    print(f"check_report: {folder}: {len(csvs)} CSV files, {len(pngs)} PNG and {len(svgs)} SVG plots checked, "
          f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

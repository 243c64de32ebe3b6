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
  sensitivity for every row with a thesis figure not reproduced;
- the table at the top ("At a glance") has its six columns and a row per
  scene, test0 to test10, all within the first 40 lines, no line of the first
  screen over 160 characters and no row over 120 characters of cell text;
  every sentence in claims.csv, recomputed from the folder's CSVs by its
  lookups, gives the same text and its rule holds; each cell but the scene is
  its claim's text or "n/a: <why>"; the verdict is one word; every lookup of
  a row's claims reads the quantity at the setting of the row's definition
  claim (readings.py says what a file reads where its columns do not);
- every other sentence in claims.csv (headline findings, sections'
  conclusions) stands in RESULTS.md where claims.csv says, and every headline
  finding is such a sentence, the engines' (peers) included. A claims.csv
  without the `place` column comes from a report made before sentences
  outside the first table were claims: its claims are all the first table's;
- every claim that reads the CSVs has a rule on what it read: a rule that
  names none of the claim's values (`True`) holds whatever the data say.

Usage: check_report.py REPORT_DIR   (exit 0: all good; 1: problems, listed)"""

import ast
import csv
import json
import re
import struct
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from odelab_report import readings  # noqa: E402 (standard library only)
from odelab_report.claims import Data, _matches, read_rows, recheck  # noqa: E402
from odelab_report import scenes, timing_check  # noqa: E402 (standard library only)

HEADER_KEYS = ("ODE", "compiler", "CPU", "date", "commit")
FIRST_COLUMNS = ["scene", "quantity, setting", "ODE there", "thesis", "cheapest ODE within 1%",
                 "best other engine, step 0.001"]
SCENES = scenes.names()  # tests/scenes/scenes.txt: a row for each
VERDICTS = ("reproduced", "partly", "differs", "untested")
# The first screen: its eleven rows within the first FIRST_SCREEN_LINES lines,
# no line of it longer than LONGEST_LINE, no row's cells longer than
# LONGEST_ROW characters of text (a link counts by its text).
FIRST_SCREEN_LINES, LONGEST_LINE, LONGEST_ROW = 40, 160, 120
FIRST_TABLE, HEADLINE, DECIDES = "first table", "headline", "what decides"
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
    rows = list(csv.DictReader(line for line in path.read_text().splitlines() if not line.startswith("#")))
    if rows and "ode_0_11_1_rebuild" not in rows[0]:
        return ["no ode_0_11_1_rebuild column"]
    return [f"row {i + 1} ({row['test']}, {row['conditions']}) is '{row['verdict']}' with an empty sensitivity"
            for i, row in enumerate(rows)
            if row["verdict"].split(";")[0] in ("partly", "differs") and row.get("thesis_figure")
            and not row.get("sensitivity", "").strip()]


def cells(line):
    """The cells of a markdown table row ('\\|' inside a cell is a '|')."""
    parts = re.split(r"(?<!\\)\|", line.strip())[1:-1]
    return [part.strip().replace("\\|", "|") for part in parts]


def check_first_screen(folder, text):
    """The table under "## At a glance": columns, a row per scene, and every
    sentence recomputed from the CSVs (claims.csv)."""
    lines = text.splitlines()
    try:
        start = lines.index("## At a glance")
    except ValueError:
        return ["RESULTS.md has no '## At a glance' table at the top"]
    table = []
    for line in lines[start + 1:]:
        if line.startswith("|"):
            table.append(line)
        elif table:
            break
    problems = []
    if not table or cells(table[0]) != FIRST_COLUMNS:
        return [f"the first table's columns are {cells(table[0]) if table else 'missing'}, expected {FIRST_COLUMNS}"]
    body = [cells(line) for line in table[2:]]
    if [row[0] for row in body] != SCENES:
        problems.append(f"the first table's rows are {[row[0] for row in body]}, expected {SCENES}")
    problems += check_screen_size(lines, start, table, body)
    claims_path = folder / "claims.csv"
    claims = read_rows(claims_path) if claims_path.exists() else []
    problems += recheck(folder, claims)
    claims = [row for row in claims if row.get("place", FIRST_TABLE) == FIRST_TABLE]
    shown = {row["key"]: row["text"] for row in claims}
    every_cell = {cell for row in body for cell in row}
    for row in claims:
        if row["text"] not in every_cell:
            problems.append(f"claim {row['key']} ('{row['text']}') is in no cell of the first table")
    for row in body:
        for column, name in ((1, "definition"), (2, "figure"), (3, "thesis"), (4, "cheapest"), (5, "peer")):
            made = [v for k, v in shown.items() if k.startswith(f"first.{row[0]}.{name}")
                    or (name == "thesis" and k.startswith(f"first.{row[0]}") and k.endswith(".thesis"))]
            if len(row) > column and not row[column].startswith("n/a: ") and row[column] not in made:
                problems.append(f"{row[0]}: the cell '{row[column]}' ({FIRST_COLUMNS[column]}) is neither a claim "
                                "recomputed from the CSVs nor 'n/a: <why>'")
        if len(row) > 3 and row[3] not in VERDICTS and not row[3].startswith("n/a: "):
            problems.append(f"{row[0]}: the verdict '{row[3]}' is not one of {', '.join(VERDICTS)} "
                            "nor 'n/a: <why>' (a report without the thesis experiment)")
    problems += check_one_reading(folder, claims)
    return problems


def visible(cell):
    """A cell's text as read: a markdown link counts by its text."""
    return re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", cell)


def check_screen_size(lines, start, table, body):
    """The first screen fits a screen: its rows within the first lines, no
    long line, no long row."""
    problems = []
    last_row = start + 1 + lines[start + 1:].index(table[-1]) if table[-1] in lines[start + 1:] else len(lines)
    if last_row + 1 > FIRST_SCREEN_LINES:
        problems.append(f"the first table ends on line {last_row + 1}, after the first {FIRST_SCREEN_LINES}")
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    for number, line in enumerate(lines[:end], 1):
        if len(line) > LONGEST_LINE:
            problems.append(f"line {number} of the first screen has {len(line)} characters (at most {LONGEST_LINE})")
    for row in body:
        size = sum(len(visible(cell)) for cell in row)
        if size > LONGEST_ROW:
            problems.append(f"{row[0]}: {size} characters of cell text (at most {LONGEST_ROW})")
    return problems


def check_one_reading(folder, claims):
    """Each row's cells read the quantity at the setting its definition
    claim (first.<scene>.definition) fixes: every lookup of the row's claims,
    by what its file's columns and readings.py say it reads."""
    data = Data(folder)
    definitions = {}
    for row in claims:
        if row["key"].endswith(".definition"):
            values = json.loads(row["values"])
            definitions[row["key"].split(".")[1]] = {k: ast.literal_eval(v) for k, v in values.items()}
    problems = [f"{scene}: no definition claim (first.{scene}.definition) saying its quantity and setting"
                for scene in SCENES if scene not in definitions]
    for row in claims:
        scene = row["key"].split(".")[1]
        if scene not in definitions:
            continue
        for name, spec in json.loads(row["values"]).items():
            if not isinstance(spec, dict) or spec["file"] in readings.NOT_READINGS:
                continue
            rows = [r for r in data.rows(spec["file"])
                    if all(_matches(r.get(k), v) for k, v in spec.get("where", {}).items())]
            for difference in readings.differences(definitions[scene], readings.facts(spec, rows)):
                problems.append(f"{scene}: claim {row['key']} reads {spec['file']} ({name}): {difference} "
                                "(the row's definition)")
    return problems


def section_of(lines, is_heading):
    """The lines under the first heading for which `is_heading` holds, to the next heading."""
    start = next((i for i, line in enumerate(lines) if is_heading(line)), None)
    if start is None:
        return []
    rest = lines[start + 1:]
    end = next((i for i, line in enumerate(rest) if line.startswith(("## ", "### "))), len(rest))
    return rest[:end]


def headline_lines(lines):
    return section_of(lines, lambda line: line == "## Headline findings")


def experiment_lines(lines, name):
    """The lines of the experiment `name`'s subsection (its heading names `--only name`)."""
    return section_of(lines, lambda line: line.startswith("### ") and f"(`--only {name}`)" in line)


def check_sentences(folder, text):
    """The claims outside the first table: each where claims.csv places it,
    and every headline finding one of them."""
    path = folder / "claims.csv"
    claims = read_rows(path) if path.exists() else []
    if not claims or "place" not in claims[0]:
        return []
    lines = text.splitlines()
    problems = []
    headline = {row["text"] for row in claims if row["place"] == HEADLINE}
    for line in headline_lines(lines):
        finding = line[2:] if line.startswith("- ") else None
        if finding and finding not in headline:
            problems.append(f"headline finding '{finding[:80]}...' is no claim recomputed from the CSVs")
    for row in claims:
        place = row["place"]
        if place == FIRST_TABLE:
            continue
        if place == HEADLINE:
            where = headline_lines(lines)
        elif place == DECIDES:
            where = section_of(lines, lambda line: line == "## What decides each figure")
        else:
            where = experiment_lines(lines, place)
        if row["text"] not in "\n".join(where):
            problems.append(f"claim {row['key']} ('{row['text'][:80]}') is not in RESULTS.md's {place}")
    return problems


def check_rules(folder):
    """Each claim that reads the CSVs has a rule that reads its values: a
    rule naming none of them (`True`) would let any figure through."""
    path = folder / "claims.csv"
    problems = []
    for row in read_rows(path) if path.exists() else []:
        values = json.loads(row["values"])
        if not any(isinstance(spec, dict) for spec in values.values()):
            continue  # a definition: constants only, checked by check_one_reading
        try:
            named = {node.id for node in ast.walk(ast.parse(row["rule"], mode="eval")) if isinstance(node, ast.Name)}
        except SyntaxError:
            problems.append(f"claim {row['key']}: its rule `{row['rule']}` does not parse")
            continue
        if not named & set(values):
            problems.append(f"claim {row['key']}: its rule `{row['rule']}` reads none of its values "
                            f"({', '.join(values)}): it holds whatever the CSVs say")
    return problems


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
    if text:
        problems += [f"first table: {problem}" for problem in check_first_screen(folder, text)]
        problems += check_sentences(folder, text)
        problems += check_rules(folder)
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
    problems += timing_check.problems(folder)
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

#!/usr/bin/python3
"""Fails when a measured figure in the docs does not come from the cell of a
committed CSV that it names, so that no figure outlives its data or was
never measured.

Where a figure may stand. In README.md and every doc/**/*.md (not the lab's
reports: doc/results/, doc/worlds/NAME/ and doc/atlas-report/, which
lab/check_report.py, lab/check_world_report.py and lab/check_atlas_report.py
hold to their own CSVs), a measured figure is
either

- cited: a link whose text holds the figure and whose target is a committed
  CSV, with the row's key and the cell's column after the `#`:
  [11900 kg](results/limit-test4.csv#solver=QuickStep%2020&step_s=0.001&cell=heaviest_held_kg)
  (column=value pairs joined by `&`, URL-encoded: %20 for a space; `cell=`
  names the column read). The key must select exactly one row, and every
  figure of the link's text must be the number in that cell at the precision
  written (0.064 for 0.06403; a percentage also for the fraction: 17% for
  0.1704; a whole number's trailing zeros are not significant: 11900 for
  11892). A median with its range cites one cell per figure, in order:
  [47.7 [44.0-51.2]](measurements/compare-window.csv#scene=test2&engine_count=2&part=ode&cell=fps&cell=fps_min&cell=fps_max)
  (the link's text then holds exactly as many figures as the key names
  cells, and a link's text may hold one level of [brackets]). Or
- generated: inside a block between `<!-- BEGIN GENERATED: NAME -->` and
  `<!-- END GENERATED: NAME -->` that a generator of the lab writes from
  committed CSVs (GENERATORS below); the block must be exactly what the
  generator writes today, so a hand edit or a stale block fails.

A number that is not a measurement (a setting, an option's value, a count of
cores) is written as `code` (`--step 0.001`, `step 0.001`, `2 cores`): code
spans and code blocks are not prose. Any other measured figure in prose
fails.

Which numbers count as measured figures (after code, HTML comments, link
targets and URLs are removed): a decimal (0.064, 1.97e6, 2.8e-9) or a
percentage (17%), or a whole number of at least two digits followed by a
unit of measure (s, ms, us, min, kg, t, m, cm, mm, m/s, J, N, x, plates, fps,
deg, degrees, Hz); both ends of a range (0.24-0.27 s). Not: part of a word or
a name (test10, x86_64), a version (0.16.2; a decimal after ODE, version,
Havok, ...), a section (after chapter, section, thesis, figure, table, issue,
§, or at the start of a heading), a date or a clock time, one side of a size
(1280 x 720).

Pages still quoting uncited figures are listed in
lab/reference/docs-uncited.txt, one `PATH COUNT  # why` a line: the page may
hold exactly COUNT uncited figures, no more (the figures are listed) and no
fewer (the count must then be lowered), so the list only shrinks. A page not
listed may hold none.

Usage: check_docs.py [REPO_ROOT]   (exit 0: every figure cited or generated;
1: the problems, each with its file and line; 2: bad usage)"""

import csv
import math
import re
import subprocess
import sys
from pathlib import Path
from urllib.parse import parse_qsl

sys.path.insert(0, str(Path(__file__).resolve().parent))
from odelab_report import atlas_text, peers_notes  # noqa: E402  (doc/peers.md's generated blocks)
from odelab_report.csvout import read_csv  # noqa: E402

UNITS = r"(?:m/s|ms|us|µs|min|kg|cm|mm|s|t|m|J|N|x|plates|fps|degrees|deg|Hz)"
NAMES_BEFORE_VERSION = ("ode", "version", "v", "havok", "bullet", "mujoco", "python", "cmake", "c++", "gcc", "g++",
                        "debian", "ubuntu", "windows", "gtest", "matplotlib", "jolt", "rapier", "libode", "release")
SECTION_WORDS = ("chapter", "section", "thesis", "thesis's", "figure", "table", "issue", "§", "chapters", "sections")
NUMBER = re.compile(r"(?<![\w./])(-?(?:\d{1,3}(?:,\d{3})+|\d+)(?:\.\d+)?(?:[eE][-+]?\d+)?)(?![\w.]*\d)"
                    r"(\s?%|\s?" + UNITS + r"(?![\w]))?")
# The link's text may hold one level of brackets: [47.7 [44.0-51.2]](...).
CITATION = re.compile(r"\[((?:[^\[\]\n]|\[[^\[\]\n]*\])+)\]\(([^)\s#]+\.csv)#([^)\s]+)\)")
# A block's markers each on a line of their own (a marker quoted in a sentence is none).
BLOCK = re.compile(r"^<!-- BEGIN GENERATED: ([^>]*?) -->\n(.*?)\n?^<!-- END GENERATED: [^>]*?-->$", re.S | re.M)
ALLOWANCE = Path("lab") / "reference" / "docs-uncited.txt"
CELL = "cell"  # the key's pair that names the column read


def _translation_notes(root):
    return peers_notes.markdown(peers_notes.read_rows(root / "doc" / "results" / peers_notes.NOTES_CSV))


def _atlas_per_engine(root):
    """Each engine's measured sentences from the committed atlas (atlas.csv), as ATLAS.md's."""
    rows = read_csv(root / "doc" / "atlas-report" / "atlas.csv")[2]
    engines = list(dict.fromkeys(r["engine"] for r in rows))
    return "\n".join(["What each engine gets right, measured: the accuracy atlas's cases (doc/atlas/, each "
                      "with its analytic answer) on every engine, as [atlas-report/ATLAS.md](atlas-report/ATLAS.md) "
                      "says it from [atlas.csv](atlas-report/atlas.csv). Regenerated by lab/write_doc_blocks.py; "
                      "do not edit by hand.", ""] + [f"- {e}: {atlas_text.engine_sentences(rows, e)}"
                                                     for e in engines])


# A generated block's name (the start of its BEGIN marker's text) and what writes it, from committed CSVs.
GENERATORS = {"translation notes": _translation_notes, "atlas per engine": _atlas_per_engine}


def blanked(text, pattern, flags=0):
    """`text` with each match of `pattern` blanked, its line breaks kept."""
    return re.sub(pattern, lambda m: "\n" * m.group(0).count("\n"), text, flags=flags)


def uncoded(text):
    """The text with generated blocks, code blocks, HTML comments and `code
    spans` blanked (line breaks kept): a citation written as an example is none."""
    text = BLOCK.sub(lambda m: "\n" * m.group(0).count("\n"), text)
    text = blanked(text, r"```.*?```", re.S)
    text = blanked(text, r"<!--.*?-->", re.S)
    # A code span may run over a line break, not over a paragraph's end.
    return re.sub(r"`(?:[^`\n]|\n(?![ \t]*\n))*`", lambda m: " " + "\n" * m.group(0).count("\n"), text)


def citations(text):
    """(line number, link text, CSV path as written, row key) of every
    citation link in a document's text."""
    text = uncoded(text)
    return [(text[:m.start()].count("\n") + 1, m.group(1), m.group(2), m.group(3)) for m in CITATION.finditer(text)]


def without_citations(text):
    """The text with each citation's link blanked (its figures are checked
    against their cells instead)."""
    return CITATION.sub(" ", uncoded(text))


def same(cell, wanted):
    """A cell equals a key's value: as numbers when both are, else as text."""
    try:
        return math.isclose(float(cell), float(wanted), rel_tol=1e-9, abs_tol=1e-15)
    except ValueError:
        return cell.strip() == wanted.strip()


def cited_cells(rows, key):
    """([the text of each cell], None) that `key` (column=value&...&cell=
    COLUMN, one or more cells) names in `rows` (lists of cells, the first the
    column names), or (None, why not)."""
    if not rows:
        return None, "an empty CSV"
    header, pairs = rows[0], parse_qsl(key, keep_blank_values=True)
    columns = [value for name, value in pairs if name == CELL]
    wanted = [(name, value) for name, value in pairs if name != CELL]
    if not columns:
        return None, f"names no cell (add &{CELL}=COLUMN: the column the figure is read from)"
    missing = [c for c in columns if c not in header]
    if missing:
        return None, f"names the cell '{missing[0]}', which is no column of the CSV"
    if not wanted or any(name not in header for name, _ in wanted):
        return None, "selects no row (a column it names is not in the CSV)"
    selected = [row for row in rows[1:] if all(len(row) > header.index(name) and same(row[header.index(name)], value)
                                               for name, value in wanted)]
    if len(selected) != 1:
        return None, f"selects {len(selected)} rows, not one"
    row = selected[0]
    return [row[header.index(c)] if len(row) > header.index(c) else "" for c in columns], None


def check_citations(root, doc, text, tables):
    """Problems with the page's citations: a CSV not committed, a key that
    selects no single row or names no column, a figure not in its cell."""
    problems = []
    committed_paths = {path.resolve(): rows for path, rows in tables.items()}
    name = str(doc.relative_to(root))
    for line, link_text, target, key in citations(text):
        path = (doc.parent / target).resolve()
        if path not in committed_paths:
            problems.append(f"{name}:{line}: cites {target}, which is no committed CSV")
            continue
        cells, why = cited_cells(committed_paths[path], key)
        if why:
            problems.append(f"{name}:{line}: the citation {target}#{key} {why}")
            continue
        written_figures = figures(link_text)
        if len(cells) > 1 and len(written_figures) != len(cells):
            problems.append(f"{name}:{line}: the citation {target}#{key} names {len(cells)} cells for "
                            f"{len(written_figures)} figures (one cell per figure, in order)")
            continue
        for n, (_, written, value, unit) in enumerate(written_figures):
            cell = cells[n] if len(cells) > 1 else cells[0]
            if not is_held(sorted(numbers_in(cell.replace(",", ""))), value, written, unit):
                problems.append(f"{name}:{line}: {shown(written, unit)} is not the cell it cites "
                                f"({target}#{key}: '{cell}')")
    return problems


def check_blocks(root, doc, text):
    """Problems with the page's generated blocks: one no generator writes,
    or one that differs from what its generator writes today."""
    problems, name = [], str(doc.relative_to(root))
    for m in BLOCK.finditer(text):
        line = text[:m.start()].count("\n") + 1
        generator = next((g for prefix, g in GENERATORS.items() if m.group(1).startswith(prefix)), None)
        if generator is None:
            problems.append(f"{name}:{line}: a generated block '{m.group(1)}' that no generator of the lab writes")
        elif generator(root).strip("\n") != m.group(2).strip("\n"):
            problems.append(f"{name}:{line}: the generated block '{m.group(1)}' is not what its generator writes "
                            "from the committed CSVs (edited by hand, or stale: lab/write_doc_blocks.py)")
    return problems


def prose(text):
    """The text with what is not prose blanked (so line numbers stay)."""
    text = uncoded(text)
    text = re.sub(r"\]\([^)]*\)", "]", text)
    text = re.sub(r"https?://\S+", " ", text)
    text = re.sub(r"\b\d{4}-\d{2}-\d{2}\b", " ", text)
    text = re.sub(r"\b\d+:\d{2}(?::\d{2})?\b", " ", text)
    text = re.sub(r"\b\d+(?:\.\d+){2,}\b", " ", text)  # versions
    text = re.sub(r"\d+(?:\.\d+)?(?:\s?x\s?\d+(?:\.\d+)?)+", lambda m: " " if re.search(r"x\s?\d", m.group(0))
                  and not re.fullmatch(r"\d+(?:\.\d+)?\s?x", m.group(0)) else m.group(0), text)
    return text


def figures(text):
    """(line number, the number as written, its value, its unit or '%') for
    every measured figure in a document's text."""
    found = []
    for number, line in enumerate(prose(text).splitlines(), 1):
        heading = line.lstrip().startswith("#")
        for match in NUMBER.finditer(line):
            written, unit = match.group(1), (match.group(2) or "").strip()
            before = line[:match.start()].rstrip().split()
            previous = before[-1].lower().strip("(,;:*") if before else ""
            if heading and not line[:match.start()].strip("# "):
                continue
            if previous in SECTION_WORDS or previous.endswith("§"):
                continue
            decimal = "." in written or "e" in written.lower()
            if decimal and previous in NAMES_BEFORE_VERSION:
                continue
            if not (decimal or unit == "%" or (unit and len(written.replace(",", "").lstrip("-")) >= 2)):
                continue
            value = float(written.replace(",", ""))
            if math.isfinite(value) and (value == 0 or 1e-300 < abs(value) < 1e300):
                found.append((number, written + (unit if unit == "%" else ""), value, unit))
    return found


def shown(written, unit):
    return f"{written}{'' if unit in ('', '%') else ' ' + unit}"


TOKEN = re.compile(r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")


def numbers_in(text):
    return {abs(float(t)) for t in TOKEN.findall(text) if math.isfinite(float(t))}


def committed(root, *patterns):
    """The files git tracks under `root` matching `patterns`; outside a git
    checkout (an unpacked source archive, a test's copy), every such file but
    build output."""
    listed = subprocess.run(["git", "-C", str(root), "ls-files", *patterns], capture_output=True, text=True)
    if listed.returncode == 0 and (root / ".git").exists():
        return [root / name for name in listed.stdout.split() if (root / name).exists()]
    return [p for pattern in patterns for p in root.rglob(pattern)
            if not any(part.startswith("build") or part.startswith(".") for part in p.relative_to(root).parts)]


def csv_rows(root):
    """{committed CSV path: its rows (lists of cells)}."""
    tables = {}
    for path in committed(root, "*.csv"):
        with open(path, newline="", errors="replace") as stream:
            tables[path] = list(csv.reader(line for line in stream if not line.startswith("#")))
    return tables


def significant_digits(written):
    """1 for 5, 0.2, 500 or 5e-3; 2 for 35, 0.064 or 4.4%; 3 for 11900."""
    mantissa = written.replace(",", "").lstrip("-").lower().rstrip("%").strip().partition("e")[0]
    digits = mantissa.replace(".", "").lstrip("0")
    return len(digits if "." in mantissa else digits.rstrip("0")) or 1


def half_unit(written):
    """Half a unit of the last significant digit written (0.064 -> 0.0005;
    1.97e6 -> 5e3; 11900 -> 50)."""
    mantissa, _, exponent = written.replace(",", "").lstrip("-").lower().partition("e")
    # A whole number's trailing zeros are not significant (11900 for 11892).
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else -(len(mantissa) - len(mantissa.rstrip("0")))
    if mantissa.strip("0") == "":
        decimals = 0
    return 0.5 * 10.0 ** max(-320, min(300, -decimals + (int(exponent) if exponent else 0)))


def held(values, target, tolerance):
    return any(abs(v - target) <= tolerance for v in values)


def is_held(values, value, written, unit):
    tolerance = half_unit(written.rstrip("%").strip())
    return held(values, abs(value), tolerance) or (unit == "%" and held(values, abs(value) / 100, tolerance / 100))


def allowances(root):
    """{page: the uncited figures it may hold} from docs-uncited.txt."""
    path, found = root / ALLOWANCE, {}
    if path.exists():
        for number, line in enumerate(path.read_text().splitlines(), 1):
            entry = line.split("#")[0].split()
            if not entry:
                continue
            if len(entry) != 2 or not entry[1].isdigit():
                raise ValueError(f"{ALLOWANCE}:{number}: not 'PATH COUNT  # why': {line}")
            found[entry[0]] = int(entry[1])
    return found


def _is_report(root, page):
    """A lab report's page (doc/results/, a world's report in
    doc/worlds/NAME/, the atlas in doc/atlas-report/): lab/check_report.py,
    lab/check_world_report.py and lab/check_atlas_report.py hold its
    figures to its own CSVs."""
    parts = page.relative_to(root / "doc").parts
    return "results" in parts or parts[0] == "atlas-report" or (len(parts) == 3 and parts[0] == "worlds")


def pages(root):
    return [root / "README.md"] + sorted(p for p in (root / "doc").rglob("*.md") if not _is_report(root, p))


def check(root):
    """(problems, measured figures counted, pages, uncited figures allowed)."""
    tables, allowed = csv_rows(root), allowances(root)
    problems, counted, docs = [], 0, [p for p in pages(root) if p.exists()]
    for doc in docs:
        text = doc.read_text(errors="replace")
        name = str(doc.relative_to(root))
        problems += check_blocks(root, doc, text)
        problems += check_citations(root, doc, text, tables)
        counted += sum(len(figures(link_text)) for _, link_text, _, _ in citations(text))
        uncited = figures(without_citations(text))
        counted += len(uncited)
        may = allowed.pop(name, 0)
        if len(uncited) > may:
            problems += [f"{name}:{line}: {shown(written, unit)} is neither cited to its CSV cell nor generated "
                         f"(a setting: write it as `code`)" for line, written, _, unit in uncited]
            problems.append(f"{name}: {len(uncited)} uncited figures, {may} allowed ({ALLOWANCE})")
        elif len(uncited) < may:
            problems.append(f"{name}: {len(uncited)} uncited figures, fewer than the {may} allowed: lower its "
                            f"line in {ALLOWANCE} to {len(uncited)}")
    problems += [f"{ALLOWANCE}: {name} is no page the check reads" for name in allowed]
    return problems, counted, len(docs), sum(allowances(root).values())


def main(argv):
    if len(argv) > 2 or (len(argv) == 2 and argv[1] in ("-h", "--help")):
        sys.stderr.write(__doc__)
        return 2
    root = Path(argv[1] if len(argv) == 2 else Path(__file__).resolve().parents[1])
    if not (root / "doc").is_dir():
        sys.stderr.write(f"check_docs: {root} is not the project's root (no doc/ folder)\n")
        return 2
    try:
        problems, counted, files, allowed = check(root)
    except ValueError as error:
        sys.stderr.write(f"check_docs: {error}\n")
        return 2
    for problem in problems:
        print("check_docs: " + problem)
    print(f"check_docs: {counted} measured figures in {files} documents, {allowed} of them allowed uncited "
          f"({ALLOWANCE}), {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

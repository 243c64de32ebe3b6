#!/usr/bin/python3
"""Fails when a measured figure in the docs is held by no committed CSV, so
that a figure copied from an older run cannot outlive the data.

Which numbers count as measured figures. In README.md and every doc/**/*.md
(not the lab's reports: doc/results/ and doc/worlds/NAME/, which
lab/check_report.py and lab/check_world_report.py check against their own CSVs),
after removing code blocks, `code spans` (option values, commands, exit
statuses, file names), link targets, URLs and HTML comments, a number is a
measured figure when it is

- a decimal (a point, or an exponent: 0.064, 1.97e6, 2.8e-9) or a
  percentage (17%), or
- a whole number of at least two digits directly followed by a unit of
  measure: s, ms, us, min, kg, t, m, cm, mm, m/s, J, N, x (a ratio),
  plates, fps, deg, degrees, Hz;

both ends of a range count (0.24-0.27 s: 0.24 and 0.27); and it is not

- part of a word or a name (test10, x86_64, H100, libode8, 0x1f),
- a version (two points or more: 0.16.2; or a decimal after ODE, version,
  v, Havok, Bullet, MuJoCo, Python, CMake, C++, GCC, g++, Debian, Ubuntu,
  Windows, gtest, matplotlib, Jolt, Rapier),
- a section of the thesis or a document (after chapter, section, thesis,
  figure, table, issue, §, or at the start of a heading),
- a date or a clock time (2026-11-24, 6:16),
- one side of a size or a count pair with an x between whole numbers
  (1280 x 720, 10 x 0.2 x 10 is a size: the x between numbers marks it).

A figure is held by a CSV when some number in a cell of a committed CSV
(any `git ls-files '*.csv'`, numbers inside text cells included) rounds to
it at the precision the doc writes (a whole number's trailing zeros are
not significant: 11900 is held by 11892). A short figure, of one or two significant digits (5, 0.2, 35 s, 4.4%),
is matched by coincidence in some CSV more often than not, so it must be held
by the page's own data: the CSVs the page names (a link, or a mention of
`name.csv`) and, on a scene's page doc/tests/testN.md, the CSVs whose name
holds testN and the rows of any CSV that name testN in a cell. A number written as a literal in the
programs' committed C++ sources (`*.cpp`, `*.h`: gravity 9.823, a wall
0.05 m thick) is a setting the code states, not a measurement, and passes
the same way. Rounding: 0.064 is held by 0.06403 (|v - d| is at
most half a unit of the last digit shown), and a percentage also by the
fraction (17% by 0.1704). Signs are ignored.

A quoted figure cites the CSV row it comes from: a link whose text holds
the figure and whose target is the committed CSV with the row's key after
the `#`, as column=value pairs joined by `&` (URL-encoded: %20 for a space):
[11900 kg](results/limit-test4.csv#solver=QuickStep%2020&step_s=0.001).
Every figure in such a link's text must be in the rows the key selects (at
the precision written, as above), not merely in some CSV; a key that selects
no row, or names a CSV that is not committed, fails. On a page not marked
`uncited` (below), every measured figure but the C++ literals must be so
cited.

Documents named in lab/reference/docs-pending.txt (one path a line, each
with its reason after a #) are still checked and their figures listed, but
do not fail the check: a page whose owner has not yet moved its figures into
a CSV. A line `PATH uncited` lets the page quote figures without citing
their rows (they must still be held as above). A line `PATH short` holds back only the page's short figures from the
page's own data (they must still be held by some CSV); a line `PATH "FIGURE"`
(as written, with its unit: "366 s") exempts that one figure, a measurement
too long to redo. The list is meant to shrink to nothing.

Usage: check_docs.py [REPO_ROOT]   (exit 0: every figure held; 1: the
figures held by no CSV, each with its file and line; 2: bad usage)"""

import bisect
import csv
import math
import re
import subprocess
import sys
from pathlib import Path
from urllib.parse import parse_qsl

UNITS = r"(?:m/s|ms|us|µs|min|kg|cm|mm|s|t|m|J|N|x|plates|fps|degrees|deg|Hz)"
NAMES_BEFORE_VERSION = ("ode", "version", "v", "havok", "bullet", "mujoco", "python", "cmake", "c++", "gcc", "g++",
                        "debian", "ubuntu", "windows", "gtest", "matplotlib", "jolt", "rapier", "libode", "release")
SECTION_WORDS = ("chapter", "section", "thesis", "thesis's", "figure", "table", "issue", "§", "chapters", "sections")
NUMBER = re.compile(r"(?<![\w./])(-?(?:\d{1,3}(?:,\d{3})+|\d+)(?:\.\d+)?(?:[eE][-+]?\d+)?)(?![\w.]*\d)"
                    r"(\s?%|\s?" + UNITS + r"(?![\w]))?")


CITATION = re.compile(r"\[([^\]\n]+)\]\(([^)\s#]+\.csv)#([^)\s]+)\)")


def uncoded(text):
    """The text with code blocks, HTML comments and `code spans` blanked (line
    breaks kept): a citation written as an example is none."""
    text = re.sub(r"```.*?```", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    text = re.sub(r"<!--.*?-->", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"`[^`\n]*`", " ", text)


def citations(text):
    """(line number, link text, CSV path as written, row key) of every
    citation link in a document's text."""
    text = uncoded(text)
    return [(text[:m.start()].count("\n") + 1, m.group(1), m.group(2), m.group(3)) for m in CITATION.finditer(text)]


def without_citations(text):
    """The text with each citation's link blanked (its figures are checked
    against their rows instead)."""
    return CITATION.sub(" ", uncoded(text))


def cited_rows(rows, key):
    """The rows (lists of cells, the first the column names) that `key`
    (column=value&...) selects: None when it names a column the CSV lacks."""
    if not rows:
        return None
    header, wanted = rows[0], parse_qsl(key, keep_blank_values=True)
    if not wanted or any(column not in header for column, _ in wanted):
        return None
    return [row for row in rows[1:] if all(len(row) > header.index(column) and same(row[header.index(column)], value)
                                           for column, value in wanted)]


def same(cell, wanted):
    """A cell equals a key's value: as numbers when both are, else as text."""
    try:
        return math.isclose(float(cell), float(wanted), rel_tol=1e-9, abs_tol=1e-15)
    except ValueError:
        return cell.strip() == wanted.strip()


def check_citations(root, doc, text, tables):
    """Problems with the page's citations: a CSV not committed, a key that
    selects no row, a figure of the link's text not in the rows selected."""
    problems = []
    committed_paths = {path.resolve(): rows for path, rows in tables.items()}
    name = str(doc.relative_to(root))
    for line, link_text, target, key in citations(text):
        path = (doc.parent / target).resolve()
        if path not in committed_paths:
            problems.append(f"{name}:{line}: cites {target}, which is no committed CSV")
            continue
        rows = cited_rows(committed_paths[path], key)
        if not rows:
            problems.append(f"{name}:{line}: cites row '{key}' of {target}, which selects no row"
                            + (" (a column it names is not in the CSV)" if rows is None else ""))
            continue
        values = sorted(row_numbers(rows, set()))
        for _, written, value, unit in figures(link_text):
            if not is_held(values, value, written, unit):
                problems.append(f"{name}:{line}: {written}{'' if unit in ('', '%') else ' ' + unit} is not in the "
                                f"row '{key}' of {target} it cites")
    return problems


def prose(text):
    """The text with what is not prose blanked (so line numbers stay)."""
    text = re.sub(r"```.*?```", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    text = re.sub(r"<!--.*?-->", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    text = re.sub(r"`[^`\n]*`", " ", text)
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


TOKEN = re.compile(r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")


def committed(root, *patterns):
    """The files git tracks under `root` matching `patterns`; outside a git
    checkout (an unpacked source archive), every such file but build output."""
    listed = subprocess.run(["git", "-C", str(root), "ls-files", *patterns], capture_output=True, text=True)
    if listed.returncode == 0:
        return [root / name for name in listed.stdout.split() if (root / name).exists()]
    return [p for pattern in patterns for p in root.rglob(pattern)
            if not any(part.startswith("build") or part.startswith(".") for part in p.relative_to(root).parts)]


def numbers_in(text, values):
    for t in TOKEN.findall(text):
        value = abs(float(t))
        if math.isfinite(value):
            values.add(value)


def csv_rows(root):
    """{committed CSV path: its rows (lists of cells)}."""
    tables = {}
    for path in committed(root, "*.csv"):
        with open(path, newline="", errors="replace") as stream:
            tables[path] = list(csv.reader(line for line in stream if not line.startswith("#")))
    return tables


def code_numbers(root):
    """Every literal of the committed C++ sources (settings the code states)."""
    values = set()
    for path in committed(root, "*.cpp", "*.h", "*.hpp"):
        numbers_in(re.sub(r"(?<=\d)[fF]\b", "", path.read_text(errors="replace")), values)
    return values


def row_numbers(rows, values):
    for row in rows:
        for cell in row:
            numbers_in(cell.replace(",", ""), values)
    return values


def held_numbers(root, tables=None, code=None):
    """Every number in a cell of a committed CSV, and every literal of the
    committed C++ sources, as sorted absolute values."""
    values = set(code_numbers(root) if code is None else code)
    for rows in (csv_rows(root) if tables is None else tables).values():
        row_numbers(rows, values)
    return sorted(values)


def significant_digits(written):
    """1 for 5, 0.2, 500 or 5e-3; 2 for 35, 0.064 or 4.4%; 3 for 11900."""
    mantissa = written.replace(",", "").lstrip("-").lower().rstrip("%").strip().partition("e")[0]
    digits = mantissa.replace(".", "").lstrip("0")
    return len(digits if "." in mantissa else digits.rstrip("0")) or 1


SHORT = 2  # significant digits at most: a short figure, held by the page's own data only


def own_numbers(doc, text, tables, code):
    """The numbers a page's short figures may come from: the CSVs it names,
    its scene's CSVs and rows (doc/tests/testN.md), the C++ literals."""
    values = set(code)
    named = set(re.findall(r"([\w.-]+\.csv)\b", text))
    scene = re.fullmatch(r"(test\d+)\.md", doc.name) if doc.parent.name == "tests" else None
    mention = re.compile(rf"(?<![a-z0-9]){scene.group(1)}(?![0-9])") if scene else None
    for path, rows in tables.items():
        if path.name in named or (mention and mention.search(path.stem)):
            row_numbers(rows, values)
        elif mention:
            row_numbers([row for row in rows if any(mention.search(cell) for cell in row)], values)
    return sorted(values)


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
    i = bisect.bisect_left(values, target - tolerance)
    return i < len(values) and values[i] <= target + tolerance


def pending(root):
    """{path: what of it is pending}: "page" (the whole page), "short" (its
    short figures' scope), or a set of figures as written ("366 s")."""
    path = root / "lab" / "reference" / "docs-pending.txt"
    waiting = {}
    if not path.exists():
        return waiting
    for line in path.read_text().splitlines():
        entry = line.split("#")[0].strip()
        if not entry:
            continue
        name, _, rest = entry.partition(" ")
        rest = rest.strip()
        if not rest:
            waiting[name] = "page"
        elif rest in ("short", "uncited"):
            waiting.setdefault(name, set()).add(rest)
        else:
            waiting.setdefault(name, set()).add(rest.strip('"'))
    return waiting


def is_held(values, value, written, unit):
    tolerance = half_unit(written.rstrip("%").strip())
    return held(values, abs(value), tolerance) or (unit == "%" and held(values, abs(value) / 100, tolerance / 100))


def _is_report(root, page):
    """A lab report's page (doc/results/, or a world's report in
    doc/worlds/NAME/): lab/check_report.py and lab/check_world_report.py
    hold its figures to its own CSVs."""
    parts = page.relative_to(root / "doc").parts
    return "results" in parts or (len(parts) == 3 and parts[0] == "worlds")


def check(root):
    tables, code = csv_rows(root), code_numbers(root)
    values = held_numbers(root, tables, code)
    waiting = pending(root)
    code_values = sorted(code)
    docs = [root / "README.md"] + sorted(p for p in (root / "doc").rglob("*.md") if not _is_report(root, p))
    problems, counted = [], 0
    for doc in docs:
        if not doc.exists():
            continue
        text = doc.read_text(errors="replace")
        name = str(doc.relative_to(root))
        exempt = waiting.get(name, set())
        own = None
        for problem in check_citations(root, doc, text, tables):
            problems.append((exempt == "page", problem))
        counted += sum(len(figures(link_text)) for _, link_text, _, _ in citations(text))
        cited = exempt == "page" or "uncited" not in exempt
        for line, written, value, unit in figures(without_citations(text)):
            counted += 1
            shown = f"{written}{'' if unit in ('', '%') else ' ' + unit}"
            if cited and not is_held(code_values, value, written, unit):
                problems.append((exempt == "page" or shown in exempt,
                                 f"{name}:{line}: {shown} cites no CSV row (a link [{shown}](path.csv#column=value))"))
                continue
            if not is_held(values, value, written, unit):
                problems.append((exempt == "page" or shown in exempt, f"{name}:{line}: {shown} is held by no committed CSV"))
                continue
            if significant_digits(written) > SHORT:
                continue
            own = own_numbers(doc, text, tables, code) if own is None else own
            if not is_held(own, value, written, unit):
                problems.append((exempt == "page" or "short" in exempt or shown in exempt,
                                 f"{name}:{line}: {shown} (short) is held by no CSV of this page "
                                 f"(named in it, or of its scene), only by others'"))
    return problems, counted, len(docs)


def main(argv):
    if len(argv) > 2 or (len(argv) == 2 and argv[1] in ("-h", "--help")):
        sys.stderr.write(__doc__)
        return 2
    root = Path(argv[1] if len(argv) == 2 else Path(__file__).resolve().parents[1])
    if not (root / ".git").exists() and not (root / "doc").is_dir():
        sys.stderr.write(f"check_docs: {root} is not the project's root (no doc/ folder)\n")
        return 2
    problems, counted, files = check(root)
    for waiting, problem in problems:
        print("check_docs: " + ("(pending, lab/reference/docs-pending.txt) " if waiting else "") + problem)
    failing = sum(not waiting for waiting, _ in problems)
    print(f"check_docs: {counted} measured figures in {files} documents, {len(problems)} not cited or not held by "
          f"a committed CSV ({len(problems) - failing} in pending documents)")
    return 1 if failing else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

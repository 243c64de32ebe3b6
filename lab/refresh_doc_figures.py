#!/usr/bin/python3
"""After a report is regenerated, brings the docs' quoted figures to the new
measurements, citing the row each comes from.

A cited figure ([figure](path.csv#column=value&...), lab/check_docs.py)
whose row now holds another value in the column it was read from is
rewritten with that value, at the precision it was written.

An uncited figure that today's CSVs no longer hold (lab/check_docs.py's
figures, less the literals of the C++ sources: settings, not
measurements) is looked up in the page's own CSVs as they were at REV, the
commit whose report the docs quote: those it names and, on
doc/tests/testN.md, its scene's CSVs and the rows of any CSV that name the
scene. A figure with a unit is looked up only in a column, or a row, whose
name fits it (seconds in a time, kilograms in a mass), and not where the
column holds other values within ten roundings of it (a time series: a
match there may be chance). A figure held there by exactly one cell is
found again in today's CSV (the row by the columns that name it: those
whose values are found again, the swept settings and the names) and
written as a citation of that row with today's value. With --cite, the
figures today's CSVs still hold are cited the same way (not the short
ones, of one or two significant digits: their cell cannot be told); read
each before committing it.

A figure that cannot be placed is listed for a person; nothing is written
unless --write is given (without it the changes are printed).

It also regenerates doc/peers.md's generated block (between the markers of
odelab_report/peers_notes.py, at the end of the page): the engines'
translation notes per engine and scene, from the committed
doc/results/peers-notes.csv; the page's text outside the markers is left as
it is.

Usage: refresh_doc_figures.py --from REV [--write] [--cite] [--only PAGE ...] [--root DIR]
(exit 0: every failing figure placed; 1: some left for a person; 2: bad usage)"""

import argparse
import csv
import io
import math
import os
import re
import subprocess
import sys
from pathlib import Path
from urllib.parse import quote

sys.path.insert(0, str(Path(__file__).resolve().parent))
import check_docs  # noqa: E402  (the same figures, the same rules)
from odelab_report import files  # noqa: E402  (the one writer)
from odelab_report import peers_notes  # noqa: E402  (doc/peers.md's generated block)

NOTES_PAGE = Path("doc") / "peers.md"


def old_tables(root, rev, paths):
    """{path: rows} of the CSVs as committed at `rev` (absent ones left out)."""
    tables = {}
    for path in paths:
        name = str(path.relative_to(root))
        shown = subprocess.run(["git", "-C", str(root), "show", f"{rev}:{name}"], capture_output=True, text=True)
        if shown.returncode == 0:
            tables[path] = list(csv.reader(io.StringIO("".join(
                line for line in shown.stdout.splitlines(keepends=True) if not line.startswith("#")))))
    return tables


def identity_columns(old, new):
    """The columns (by name) that name a row rather than measure it: those
    in both tables whose values at REV are (nearly all) found again today
    (the swept settings, the names), where a measured column's values change."""
    if not old or not new:
        return []
    identity = []
    for c, name in enumerate(old[0]):
        if name not in new[0]:
            continue
        n = new[0].index(name)
        before = {r[c] for r in old[1:] if len(r) > c}
        after = {r[n] for r in new[1:] if len(r) > n}
        if before and len(before & after) >= 0.8 * len(before):
            identity.append(name)
    return identity


def row_key(header, rows, row, names):
    """The shortest run of identity columns (`names`, in the CSV's order)
    that selects `row` alone among `rows`: [(column name, value)], or None."""
    chosen = []
    for name in names:
        chosen.append(header.index(name))
        matching = [r for r in rows[1:] if all(len(r) > k and r[k] == row[k] for k in chosen)]
        if len(matching) == 1:
            return [(header[k], row[k]) for k in chosen]
    return None


def cells_holding(rows, value, written, unit):
    """(row index, column) of every cell that holds the figure at the
    precision written (a percentage also as a fraction)."""
    found = []
    for i, row in enumerate(rows[1:], 1):
        for c, cell in enumerate(row):
            try:
                number = float(cell)
            except ValueError:
                continue
            if not math.isfinite(number):
                continue
            if check_docs.is_held([abs(number)], value, written, unit):
                found.append((i, c))
    return found


def formatted(new, written, unit, old_cell):
    """`new` written as `written` was: the same significant digits, the same
    notation; a percentage from a fraction when the cell held a fraction."""
    bare = written.rstrip("%").replace(",", "")
    if unit == "%" and abs(float(old_cell)) < abs(float(bare)) / 50:
        new *= 100
    digits = check_docs.significant_digits(written)
    negative = bare.startswith("-")
    new = abs(new) if not negative else -abs(new)
    if "e" in bare.lower():
        mantissa, exponent = f"{new:.{digits - 1}e}".split("e")
        text = f"{mantissa}e{int(exponent)}"
    elif "." in bare:
        decimals = len(bare.split(".")[1])
        text = f"{new:.{decimals}f}"
    else:
        text = f"{float(f'{new:.{digits}g}'):.0f}" if new != 0 else "0"
    if "," in written:
        whole, _, frac = text.partition(".")
        text = f"{int(whole):,}" + (f".{frac}" if frac else "")
    return text + ("%" if written.endswith("%") else "")


def scope(doc, text, old):
    """{path: row indexes} a page's figures may come from: the CSVs it
    names and, on doc/tests/testN.md, its scene's CSVs and the rows of any
    CSV that name the scene."""
    named = set(re.findall(r"([\w.-]+\.csv)\b", text))
    scene = re.fullmatch(r"(test\d+)\.md", doc.name) if doc.parent.name == "tests" else None
    mention = re.compile(rf"(?<![a-z0-9]){scene.group(1)}(?![0-9])") if scene else None
    rows = {}
    for path, table in old.items():
        if path.name in named or (mention and mention.search(path.stem)):
            rows[path] = range(1, len(table))
        elif mention:
            rows[path] = [i for i, row in enumerate(table[1:], 1) if any(mention.search(cell) for cell in row)]
    return rows


# A figure with one of these units comes from a column, or a row's metric,
# whose name holds one of the words: a wall time is not read from an energy.
UNIT_WORDS = {"s": ("second", "_s", "time", "wall", "cpu", "held", "upright"), "ms": ("ms", "second", "wall", "cpu"),
              "J": ("_j", "energy"), "kg": ("kg", "mass"), "m/s": ("velocity", "m_s", "speed")}


def fits_unit(table, i, c, unit):
    words = UNIT_WORDS.get(unit)
    if not words:
        return True
    names = [table[0][c].lower()] + [cell.lower() for cell in table[i] if not check_docs.TOKEN.fullmatch(cell)]
    return any(word in name for name in names for word in words)


def crowded(table, i, c, value, written):
    """Whether the figure's column holds other values within ten times the
    figure's rounding of its cell (a time series, a sweep's fine steps):
    there a match to the digits written may be chance, not its source."""
    cell = abs(float(table[i][c]))
    reach = 10 * check_docs.half_unit(written.rstrip("%").strip()) * (cell / abs(value) if value else 1.0)
    near = 0
    for row in table[1:]:
        try:
            near += len(row) > c and abs(abs(float(row[c])) - cell) <= reach
        except ValueError:
            continue
    return near > 1


def locate(value, written, unit, rows, old):
    """The one (path, row index, column) among `rows` ({path: row indexes})
    holding the figure at REV in a column fit for its unit and not crowded
    about it, or None."""
    found = [(path, i, c) for path, indexes in rows.items() for i, c in cells_holding(old[path], value, written, unit)
             if i in indexes and fits_unit(old[path], i, c, unit)]
    if len(found) != 1:
        return None
    path, i, c = found[0]
    return None if crowded(old[path], i, c, value, written) else found[0]


def link(text, path, doc, key):
    return f"[{text}]({os.path.relpath(path, doc.parent)}#" + "&".join(f"{k}={quote(v, safe='.-_')}" for k, v in key) + ")"


def shown(written, unit):
    return f"{written}{'' if unit in ('', '%') else ' ' + unit}"


def refresh_citations(doc, text, lines, tables, old, rel):
    """Rewrites, in `lines`, the figures of citation links whose row now
    holds another value in the same column; returns (changes, left)."""
    changes, left = [], []
    for line, link_text, target, key in check_docs.citations(text):
        path = (doc.parent / target).resolve()
        if path not in old or path not in tables:
            continue
        new_rows, old_rows = check_docs.cited_rows(tables[path], key), check_docs.cited_rows(old[path], key)
        new_text = link_text
        for _, written, value, unit in check_docs.figures(link_text):
            if new_rows and check_docs.is_held(sorted(check_docs.row_numbers(new_rows, set())), value, written, unit):
                continue
            columns = {c for _, c in cells_holding([[], old_rows[0]], value, written, unit)} if old_rows else set()
            if not new_rows or len(new_rows) != 1 or len(old_rows) != 1 or len(columns) != 1:
                left.append(f"{rel(doc)}:{line}: {shown(written, unit)} cites '{key}' of {target}, "
                            "which does not name one row and column at --from and today")
                continue
            c = columns.pop()
            new_written = formatted(float(new_rows[0][c]), written, unit, old_rows[0][c])
            new_text = re.sub(rf"(?<![\w.]){re.escape(written)}(?![\w]*\d)", new_written, new_text, count=1)
        if new_text != link_text:
            old_link, new_link = f"[{link_text}]({target}#{key})", f"[{new_text}]({target}#{key})"
            if lines[line - 1].count(old_link) != 1:
                left.append(f"{rel(doc)}:{line}: {old_link} -> {new_text}: place it by hand")
                continue
            lines[line - 1] = lines[line - 1].replace(old_link, new_link)
            changes.append(f"{rel(doc)}:{line}: {old_link} -> {new_link}")
    return changes, left


def refresh_page(root, doc, tables, old, held_now, code, rel, cite=False):
    """(new text, changes, left): the page with its cited figures brought
    to today's rows, its uncited figures cited and brought to today's
    values where their cell is known; `left` lists what a person must
    place."""
    text = doc.read_text()
    lines = text.split("\n")
    changes, left = refresh_citations(doc, text, lines, tables, old, rel)
    own = scope(doc, text, old)
    for line, written, value, unit in check_docs.figures(check_docs.without_citations(text)):
        if check_docs.is_held(code, value, written, unit):
            continue  # a setting the code states
        still_held = check_docs.is_held(held_now, value, written, unit)
        if still_held and (not cite or check_docs.significant_digits(written) <= check_docs.SHORT):
            continue  # still held: left as it is (a short one's cell cannot be told)
        place = locate(value, written, unit, own, old)
        if place is None:
            if not still_held:
                left.append(f"{rel(doc)}:{line}: {shown(written, unit)} is held by no single cell of the page's "
                            "CSVs at --from")
            continue
        path, i, c = place
        header, old_row, new_rows = old[path][0], old[path][i], tables[path]
        column = header[c]
        key = row_key(header, old[path], old_row, [k for k in identity_columns(old[path], new_rows) if k != column])
        new_header = new_rows[0] if new_rows else []
        matching = ([r for r in new_rows[1:] if all(len(r) > new_header.index(k) and r[new_header.index(k)] == v
                                                    for k, v in key)] if key and column in new_header else [])
        if len(matching) != 1 or len(matching[0]) <= new_header.index(column):
            if not still_held:
                left.append(f"{rel(doc)}:{line}: {shown(written, unit)} came from {path.name} row {i}, which "
                            "today's CSV has not")
            continue
        try:
            new_value = float(matching[0][new_header.index(column)])
        except ValueError:
            left.append(f"{rel(doc)}:{line}: {shown(written, unit)} came from {path.name}'s {header[c]}, empty today")
            continue
        new_written = formatted(new_value, written, unit, old_row[c])
        cited = link(shown(new_written, unit), path, doc, key)
        pattern = re.compile(rf"(?<![\w.\[]){re.escape(written)}(?:\s?{re.escape(unit)})?(?![\w.\]]*\d)"
                             if unit and unit != "%" else rf"(?<![\w.\[]){re.escape(written)}(?![\w.\]]*\d)")
        source = lines[line - 1]
        hits = [m for m in pattern.finditer(source) if "](" not in source[m.end():m.end() + 2]]
        if len(hits) != 1:
            left.append(f"{rel(doc)}:{line}: {shown(written, unit)} -> {new_written}: written {len(hits)} times on "
                        f"its line; place it by hand ({path.name}, {header[c]} of the row "
                        f"{'&'.join(f'{k}={v}' for k, v in key)})")
            continue
        lines[line - 1] = source[:hits[0].start()] + cited + source[hits[0].end():]
        changes.append(f"{rel(doc)}:{line}: {shown(written, unit)} -> {cited}")
    return "\n".join(lines), changes, left


def notes_block(root):
    """(doc/peers.md's text with its generated block made from
    doc/results/peers-notes.csv, whether that changes the page); (None,
    False) when the page, its markers or the CSV are not there."""
    page, source = root / NOTES_PAGE, root / "doc" / "results" / peers_notes.NOTES_CSV
    if not page.exists() or not source.exists():
        return None, False
    text = page.read_text()
    new = peers_notes.with_block(text, peers_notes.markdown(peers_notes.read_rows(source)))
    return new, new is not None and new != text


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--from", dest="rev", required=True, help="the commit whose report the docs quote")
    parser.add_argument("--write", action="store_true", help="rewrite the pages (default: print the changes)")
    parser.add_argument("--cite", action="store_true",
                        help="also cite the figures today's CSVs still hold, where their cell is known "
                             "(read each before committing it)")
    parser.add_argument("--only", action="append", default=[], help="only this page (repeatable)")
    parser.add_argument("--root", type=Path, default=Path(__file__).resolve().parents[1],
                        help="the checkout (default: this one)")
    args = parser.parse_args(argv)
    root = args.root.resolve()
    if subprocess.run(["git", "-C", str(root), "rev-parse", "--verify", "-q", args.rev + "^{commit}"],
                      capture_output=True).returncode:
        parser.error(f"--from {args.rev}: no such commit")
    tables, code = check_docs.csv_rows(root), check_docs.code_numbers(root)
    old = old_tables(root, args.rev, list(tables))
    held_now, code = check_docs.held_numbers(root, tables, code), sorted(code)
    docs = [root / "README.md"] + sorted(p for p in (root / "doc").rglob("*.md") if "results" not in p.parts)
    if args.only:
        wanted = {(root / p).resolve() for p in args.only}
        docs = [d for d in docs if d.resolve() in wanted]
    def rel(path):
        return str(path.relative_to(root))
    all_left = []
    for doc in docs:
        text, changes, left = refresh_page(root, doc, tables, old, held_now, code, rel, args.cite)
        for change in changes:
            print(change)
        all_left += left
        if changes and args.write:
            files.write_atomically(doc, text)
    if not args.only or (root / NOTES_PAGE).resolve() in {d.resolve() for d in docs}:
        text, changed = notes_block(root)
        if changed:
            print(f"{NOTES_PAGE}: the translation notes block regenerated from "
                  f"doc/results/{peers_notes.NOTES_CSV}")
            if args.write:
                files.write_atomically(root / NOTES_PAGE, text)
    for item in all_left:
        print("left: " + item)
    return 1 if all_left else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

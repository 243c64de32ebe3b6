"""Compares two lab reports (folders written by lab/odelab-report) column by
column, leaving out what is a timing or says where a run ran: every CSV of
the first must be in the second with the same columns, and the same rows in
every other column (runs.csv in any order: runs finish in any order).

Usage: compare_reports.py REPORT_A REPORT_B; status 0 same, 1 different."""

import csv
import re
import sys
from pathlib import Path

# Columns that measure time, or name the host: they differ between any two runs.
TIMING = re.compile(r"wall|cpu_|per_step|per_sim|real_time|^host$")
UNORDERED = {"runs.csv"}


def read(path):
    lines = [line for line in path.read_text().splitlines() if not line.startswith("#")]
    rows = list(csv.reader(lines))
    return rows[0], rows[1:]


def compare(a_dir, b_dir):
    problems = []
    names = sorted(p.name for p in a_dir.glob("*.csv"))
    if not names:
        problems.append(f"{a_dir} holds no CSV")
    for name in names:
        if not (b_dir / name).is_file():
            problems.append(f"{name}: only in {a_dir}")
            continue
        (columns_a, rows_a), (columns_b, rows_b) = read(a_dir / name), read(b_dir / name)
        if columns_a != columns_b:
            problems.append(f"{name}: columns differ: {columns_a} against {columns_b}")
            continue
        kept = [i for i, c in enumerate(columns_a) if not TIMING.search(c)]
        project = lambda rows: [[row[i] for i in kept] for row in rows]  # noqa: E731
        a, b = project(rows_a), project(rows_b)
        if name in UNORDERED:
            a, b = sorted(a), sorted(b)
        if a != b:
            first = next((i for i, (x, y) in enumerate(zip(a, b)) if x != y), min(len(a), len(b)))
            problems.append(f"{name}: {len(a)} against {len(b)} rows; first difference at row {first + 1}: "
                            f"{a[first] if first < len(a) else None} against {b[first] if first < len(b) else None}")
        else:
            print(f"{name}: {len(a)} rows same in {len(kept)} non-timing columns "
                  f"(left out: {', '.join(c for c in columns_a if TIMING.search(c)) or 'none'})")
    extra = sorted(p.name for p in b_dir.glob("*.csv") if not (a_dir / p.name).is_file())
    problems += [f"{name}: only in {b_dir}" for name in extra]
    return problems


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    found = compare(Path(sys.argv[1]), Path(sys.argv[2]))
    for problem in found:
        print("DIFFERENT: " + problem)
    sys.exit(1 if found else 0)

#!/usr/bin/python3
"""Gathers what the web checks compared (each check's comparison.json,
written by scripts/web/check-scene.sh) into one CSV: scene, metric, the
browser's value, the desktop's, their difference and the tolerance.

Usage: comparison-table.py CHECKS_DIR CSV   (CHECKS_DIR: build/checks)"""

import csv
import json
import sys
from pathlib import Path


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    checks, target = Path(sys.argv[1]), Path(sys.argv[2])
    rows = [json.loads(path.read_text()) for path in checks.glob("web_test*/comparison.json")]
    if not rows:
        sys.exit(f"error: no web_test*/comparison.json under {checks}; run ctest -L web first")
    rows.sort(key=lambda row: int(row["scene"][4:]))
    with target.open("w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(["scene", "metric", "web", "native", "difference", "tolerance"])
        for row in rows:
            writer.writerow([row[key] for key in ("scene", "metric", "web", "native", "difference", "tolerance")])


if __name__ == "__main__":
    main()

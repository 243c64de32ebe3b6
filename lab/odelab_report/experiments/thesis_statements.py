"""The thesis's checkable statements (lab/reference/thesis-statements.csv):
each quoted in Czech with its section, and either the report rows that judge
it or the reason it has none. thesis.py gives each of its rows its quotes,
and writes the statements with the verdicts of the rows they point at;
lab/tests/test_thesis_statements.py holds the quotes to the thesis's text and
the thesis's figures to the quotes."""

import csv
from pathlib import Path

STATEMENTS = Path(__file__).resolve().parents[2] / "reference" / "thesis-statements.csv"
COLUMNS = ["section", "quote", "claim", "rows", "verdicts", "reason"]


def read():
    with open(STATEMENTS, newline="", encoding="utf-8") as stream:
        return list(csv.DictReader(stream))


def quotes_for(key, statements=None):
    """'§5.9: "..."' for each statement that thesis.csv's row key judges."""
    return " | ".join(f'§{s["section"]}: "{s["quote"]}"' for s in statements or read()
                      if f"thesis.csv:{key}" in s["rows"].split())


def report_rows(thesis_rows):
    """Every statement with the verdicts of the thesis.csv rows it points at
    (thesis-havok.csv's rows are named: that experiment writes them)."""
    verdict = {row["key"]: row["verdict"] for row in thesis_rows}
    found = []
    for s in read():
        verdicts = []
        for target in s["rows"].split():
            name, key = target.split(":")
            verdicts.append(f"{key}: {verdict[key]}" if name == "thesis.csv" else f"see {target}")
        found.append(dict(section=s["section"], quote=s["quote"], claim=s["claim"], rows=s["rows"],
                          verdicts="; ".join(verdicts), reason=s["reason"]))
    return found

"""CSV files with the run header: `# key: value` lines, then the column
names, then one row per measurement. Readers skip the `#` lines
(pandas: comment='#'; Python's csv: filter them out first)."""

import csv
import math

from .files import replacing


def format_value(value):
    if value is None:
        return ""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return format(value, ".10g")
    return str(value)


def write_csv(path, header, columns, rows, notes=()):
    """`header`: (key, value) pairs; `rows`: dicts keyed by column name.
    Written whole, and only over a regular file (files.py)."""
    with replacing(path, newline="") as stream:
        for key, value in header:
            stream.write(f"# {key}: {value}\n")
        for note in notes:
            stream.write(f"# {note}\n")
        writer = csv.writer(stream, lineterminator="\n")
        writer.writerow(columns)
        for row in rows:
            writer.writerow([format_value(row.get(column)) for column in columns])


def read_csv(path):
    """(comment lines, columns, rows as dicts of strings)."""
    with open(path, newline="") as stream:
        lines = stream.read().splitlines()
    comments = [line for line in lines if line.startswith("#")]
    body = [line for line in lines if not line.startswith("#")]
    reader = csv.reader(body)
    columns = next(reader, [])
    return comments, columns, [dict(zip(columns, row)) for row in reader]

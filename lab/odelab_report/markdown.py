"""Small markdown helpers shared by the experiments and RESULTS.md."""

import html
import math
import re


def num(value, digits=3, unit=""):
    """A number for a table: `digits` significant digits, '-' for nothing;
    11900 rather than 1.19e+04, 1.97e6 rather than 1.97e+06."""
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return "-"
    if isinstance(value, float) and math.isinf(value):
        return "inf"
    magnitude = abs(value)
    whole_digits = int(math.floor(math.log10(magnitude))) + 1 if magnitude else 1
    if magnitude >= 1e5:
        mantissa, exponent = f"{value:.{digits - 1}e}".split("e")
        text = f"{float(mantissa):g}e{int(exponent)}"
    elif float(value).is_integer():
        text = str(int(value))
    elif magnitude >= 1 and whole_digits >= digits:
        text = str(int(round(value, digits - whole_digits)))
    else:
        text = f"{value:.{digits}g}"
    return text + (" " + unit if unit else "")


def short(value, digits=2):
    """A number in few characters, for the first table: `digits`
    significant digits, 9.3e-5 rather than 9.3e-05."""
    text = num(value, digits)
    if "e" in text:
        mantissa, exponent = text.split("e")
        text = f"{mantissa}e{int(exponent)}"
    return text


def pct(fraction, digits=2):
    """A fraction as a percentage with `digits` significant digits (at least
    every digit before the point: 100%, not 1e+02%)."""
    if fraction is None:
        return "-"
    value = 100 * fraction
    if value == 0:
        return "0%"
    whole = int(math.floor(math.log10(abs(value)))) + 1
    text = f"{value:.{max(digits, whole)}g}"
    if "e" in text:  # rounding carried into a new digit (99.5 -> 1e+02): one more digit
        text = f"{value:.{max(digits, whole + 1)}g}"
    return text + "%"


def table(columns, rows):
    """`rows`: lists of cells (already text)."""
    lines = ["| " + " | ".join(columns) + " |", "|" + "---|" * len(columns)]
    for row in rows:
        lines.append("| " + " | ".join(str(cell).replace("|", "\\|") for cell in row) + " |")
    return "\n".join(lines)


def figure(stem, caption):
    """An embedded PNG with a link to the SVG."""
    return f"![{caption}]({stem}.png)\n\n*{caption}* ([SVG]({stem}.svg))"


def files_line(names):
    return "Data: " + ", ".join(f"[{n}]({n})" for n in names)


# Markdown's marks that can start structure or emphasis inside a line.
_MARKS = re.compile(r"([\\`*_\[\]#!|~])")


def text(value):
    """User- or engine-given text (a world's title, a file name, an engine's
    message) as Markdown that shows it and makes nothing: one line (every
    control character a space), HTML's <, > and & as entities (no element, no
    comment) and each Markdown mark backslash-escaped (no heading, table cell,
    link or emphasis). The one escaping function for the lab's Markdown."""
    one_line = "".join(" " if ord(c) < 0x20 or ord(c) == 0x7f else c for c in str(value))
    return _MARKS.sub(r"\\\1", html.escape(one_line, quote=False))

"""The scenes' list, tests/scenes/scenes.txt (the scenes' registration,
which the builds read too): each line a program's name, its source and its
title."""

import re
from pathlib import Path

LIST = Path(__file__).resolve().parents[2] / "tests" / "scenes" / "scenes.txt"
LINE = re.compile(r"([a-z][a-z0-9_]*)\s+(\S+\.cpp)\s+(\S.*?)\s*")


def entries(path=LIST):
    """[(name, source, title)] in the list's order; ValueError naming the
    line for one that is not NAME SOURCE.cpp TITLE."""
    found = []
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip() or line.lstrip().startswith("#"):
            continue
        match = LINE.fullmatch(line)
        if not match:
            raise ValueError(f"{path}:{number}: {line!r} is not NAME SOURCE.cpp TITLE")
        found.append(match.groups())
    return found


def names(path=LIST):
    """The programs' names, test0 first, as the builds list them."""
    return [name for name, _, _ in entries(path)]

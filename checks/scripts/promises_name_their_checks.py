#!/usr/bin/env python3
"""Every promise of doc/hardening.md names checks this build has.

usage: promises_name_their_checks.py HARDENING_MD CTEST BUILD_DIR

The section "## What you can rely on" is a list of promises, each written
  - **Promise.** text *Checks:* `name`, `name` (a note), `name`.
("*Check:*" for one). Every promise must name at least one check, and every
name must be a test that `CTEST -N` lists in BUILD_DIR. Names in backticks
inside parentheses are notes (options, file names), not checks. Two
shorthands are read:
  `test2/test8_rest`  test2_rest and test8_rest (each alternative before a
                      "/" is as many words long as the last one's prefix:
                      `bullet_lab/mujoco_lab_rest`);
  `BlowUp.*`, `test0_refuses_bad_<option>`  a pattern: * and <...> stand for
                      any text, and at least one listed test must match.
A bullet whose promise starts "Not promised" lists what is not held, and
names no check.
"""
import re
import subprocess
import sys

SECTION = "## What you can rely on"


def promises(markdown):
    """[(promise title, its text)] from the section's top-level bullets."""
    start = markdown.find("\n" + SECTION + "\n")
    if start < 0:
        raise SystemExit(f"FAIL: no section {SECTION!r}")
    body = markdown[start + len(SECTION) + 2:]
    end = body.find("\n## ")
    body = body if end < 0 else body[:end]
    items, current = [], None
    for line in body.splitlines():
        if line.startswith("- "):
            current = [line[2:]]
            items.append(current)
        elif current is not None and line.startswith("  "):
            current.append(line.strip())
        elif line.strip():
            current = None  # a paragraph of the section, no promise
    result = []
    for lines in items:
        text = " ".join(lines)
        title = re.match(r"\*\*(.+?)\*\*", text)
        result.append((title.group(1) if title else text[:60], text))
    return result


def named_checks(text):
    """The backticked names after "*Checks:*", leaving out those inside parentheses."""
    marker = re.search(r"\*Checks?:\*", text)
    if not marker:
        return None
    names, depth, i, tail = [], 0, 0, text[marker.end():]
    while i < len(tail):
        c = tail[i]
        if c == "`":
            close = tail.index("`", i + 1)
            if depth == 0:
                names.append(tail[i + 1:close])
            i = close + 1
            continue
        depth += c == "("
        depth -= c == ")" and depth > 0
        i += 1
    return names


def expand(name):
    """The names a shorthand stands for (test2/test8_rest: two)."""
    if "/" not in name:
        return [name]
    parts = name.split("/")
    words = parts[0].count("_") + 1
    last = parts[-1].split("_")
    rest = "_".join(last[words:])
    return [f"{prefix}_{rest}" for prefix in parts[:-1] + ["_".join(last[:words])]]


def pattern(name):
    """A regular expression for a name with * or <...>, else None."""
    if "*" not in name and "<" not in name:
        return None
    pieces = re.split(r"\*|<[^>]*>", name)
    return re.compile("^" + ".+".join(re.escape(piece) for piece in pieces) + "$")


def listed_tests(ctest, build_dir):
    done = subprocess.run([ctest, "-N"], cwd=build_dir, capture_output=True, text=True, timeout=120)
    if done.returncode != 0:
        raise SystemExit(f"FAIL: ctest -N in {build_dir}: status {done.returncode}: {done.stderr.strip()}")
    # A parametrized GoogleTest is listed with its parameter after its name
    # ("Suite/Test.Name/case  # GetParam() = ..."): the name is the first word.
    return {line.split()[0] for line in re.findall(r"^\s*Test\s+#\d+: (.+)$", done.stdout, re.MULTILINE)}


def main():
    if len(sys.argv) != 4:
        print(__doc__, file=sys.stderr)
        return 2
    with open(sys.argv[1], encoding="utf-8") as file:
        markdown = file.read()
    tests = listed_tests(sys.argv[2], sys.argv[3])
    failures, held = [], 0
    for title, text in promises(markdown):
        if title.startswith("Not promised"):
            continue
        names = named_checks(text)
        if not names:
            failures.append(f"{title!r} names no check (no *Checks:* with a backticked name)")
            continue
        held += 1
        for name in names:
            # A name that is itself a test or a pattern of tests (GoogleTest's
            # "Suite/Test.Name/case" has slashes of its own) is no shorthand.
            whole = pattern(name)
            if (any(whole.match(test) for test in tests) if whole else name in tests):
                continue
            for expanded in expand(name):
                match = pattern(expanded)
                found = any(match.match(test) for test in tests) if match else expanded in tests
                if not found:
                    failures.append(f"{title!r}: `{name}`: no test {expanded!r} in ctest -N")
    for failure in failures:
        print("FAIL", failure)
    print(f"{held} promises with checks, {len(tests)} tests listed, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

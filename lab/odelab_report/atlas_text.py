"""The atlas's words, made from atlas.csv's rows alone (as read back from the
file, every cell a string): the experiment writes the CSV, reads it back and
calls markdown(); lab/check_atlas_report.py calls it again on the committed
CSV and compares. Every figure and every sentence is a rule on those rows."""

import re

from . import markdown as md

# The step each family's tables are shown at: the middle of the full grid,
# and the only step of --quick.
SHOWN_STEP = "1/240"


def family_stem(family):
    return "atlas-" + re.sub(r"[^a-z0-9]+", "-", family.lower()).strip("-")


def _number(cell):
    try:
        return float(cell)
    except (TypeError, ValueError):
        return None


def cell_text(row):
    """A cell: the mark (with the worst probe's error in tolerances) and the
    engine's own cost per simulated second, median [range]."""
    mark = row["mark"]
    worst = _number(row["worst_tolerances"])
    if mark == "right":
        text = f"right ({md.num(worst, 2)} tol)" if worst is not None else "right"
    elif mark == "off":
        text = f"**off** {md.num(worst, 2)} tol ({row['worst_probe']})" if worst is not None else "**off**"
    else:
        text = f"**{mark}**" + (f" ({row['worst_probe']})" if mark == "no figure" else "")
    cost = _number(row["engine_s_per_sim_s"])
    if cost is not None:
        low, high = _number(row["engine_s_per_sim_s_min"]), _number(row["engine_s_per_sim_s_max"])
        text += f"; {md.num(cost, 2)}" + (f" [{md.num(low, 2)}-{md.num(high, 2)}]" if low != high else "")
    return text


def _engines(rows):
    return list(dict.fromkeys(r["engine"] for r in rows))


def family_table(rows, setting, step):
    mine = [r for r in rows if r["setting"] == setting and r["step"] == step]
    engines = _engines(mine)
    cases = list(dict.fromkeys(r["case"] for r in mine))
    by = {(r["case"], r["engine"]): r for r in mine}
    titles = {r["case"]: r["title"] for r in mine}
    return md.table(["case"] + [f"{e} ({setting})" for e in engines],
                    [[f"{md.text(titles[c])} (`{c}`)"] + [cell_text(by[(c, e)]) if (c, e) in by else "-"
                                                          for e in engines] for c in cases])


def counts_table(rows):
    """Right answers per engine and setting at each step: "n of N"."""
    steps = list(dict.fromkeys(r["step"] for r in rows))
    out = []
    for engine in _engines(rows):
        for setting in dict.fromkeys(r["setting"] for r in rows):
            cells = []
            for step in steps:
                mine = [r for r in rows if r["engine"] == engine and r["setting"] == setting and r["step"] == step]
                cells.append(f"{sum(r['mark'] == 'right' for r in mine)} of {len(mine)}")
            out.append([engine, setting] + cells)
    return md.table(["engine", "setting"] + [f"right at step {s} s" for s in steps], out)


def engine_sentences(rows, engine):
    """What follows from an engine's row: at the shown step, per setting,
    how many cases it gets right, which it does not (with the worst), and
    where its best setting is worse than its default."""
    out = []
    at = [r for r in rows if r["engine"] == engine and r["step"] == SHOWN_STEP]
    for setting in dict.fromkeys(r["setting"] for r in at):
        mine = [r for r in at if r["setting"] == setting]
        right = [r for r in mine if r["mark"] == "right"]
        wrong = [r for r in mine if r["mark"] != "right"]
        sentence = f"At step {SHOWN_STEP} s, {setting}: right on {len(right)} of {len(mine)} cases"
        if wrong:
            sentence += "; not on " + ", ".join(
                f"`{r['case']}` ({r['mark']}" + (f" {md.num(_number(r['worst_tolerances']), 2)} tol"
                                                 if r["mark"] == "off" and _number(r["worst_tolerances"]) is not None
                                                 else "") + ")" for r in wrong)
        out.append(sentence + ".")
    default = {r["case"]: r for r in at if r["setting"] == "default"}
    worse = [r["case"] for r in at if r["setting"] == "best" and r["mark"] != "right"
             and default.get(r["case"], {}).get("mark") == "right"]
    if worse:
        out.append(f"Its best setting is worse than its default on {', '.join(f'`{c}`' for c in worse)}.")
    return " ".join(out)


NOTE_COLUMNS = ("engine", "setting", "step", "right", "cases", "not_right")


def _not_right_text(row):
    """"bounce-v1-e0p25 off 3 tol": a case and how it ended, with no comma,
    so a program can read atlas-notes.csv by splitting its lines."""
    worst = _number(row["worst_tolerances"])
    text = f"{row['case']} {row['mark']}"
    if row["mark"] == "off" and worst is not None:
        text += f" {md.num(worst, 2)} tol"
    elif row["mark"] == "no figure" and row["worst_probe"]:
        text += f" ({row['worst_probe']})"
    if "," in text:
        raise ValueError(f"atlas-notes.csv: a comma in '{text}' (case and probe names have none)")
    return text


def note_rows(rows):
    """atlas-notes.csv: per engine and setting at the shown step, how many
    cases it gets right and which it does not. Programs compile it in and
    print it with --list-engines (cmake/AtlasNotes.cmake), so what an engine
    is said to do comes from its measurement."""
    out = []
    at = [r for r in rows if r["step"] == SHOWN_STEP]
    for engine in _engines(at):
        for setting in dict.fromkeys(r["setting"] for r in at if r["engine"] == engine):
            mine = [r for r in at if r["engine"] == engine and r["setting"] == setting]
            out.append(dict(engine=engine, setting=setting, step=SHOWN_STEP,
                            right=sum(r["mark"] == "right" for r in mine), cases=len(mine),
                            not_right="; ".join(_not_right_text(r) for r in mine if r["mark"] != "right")))
    return out


def markdown(rows, engine_rows, files):
    """The atlas's part of the report from atlas.csv's rows and
    atlas-engines.csv's (which engines ran here, and why not)."""
    missing = {r["engine"]: r["missing"] for r in engine_rows if r["available"] != "1"}
    families = list(dict.fromkeys(r["family"] for r in rows))
    steps = list(dict.fromkeys(r["step"] for r in rows))
    repeats = max((int(r["repeats"]) for r in rows if r["repeats"]), default=0)
    parts = [f"Every case of doc/atlas/ on every engine here at its default and best settings, at step "
             f"{', '.join(steps)} s, at most {repeats} timed run{'s' if repeats != 1 else ''} a cell. A cell: **right** "
             "when every probe of the case is within the tolerance the case states (with the worst probe's "
             "error in tolerances), **off** when one is not, **no figure** when a probe got no reading, or how "
             "the run ended; then the engine's own collision and step calls in seconds per simulated second, "
             "median [range] of the timed runs (the link and the whole run's CPU are in the CSV beside it, "
             "never added). Each case's answer is analytic or a conservation law, written in the case; no "
             "engine is the reference for another.", "", counts_table(rows), ""]
    if missing:
        parts += ["Not run here: " + "; ".join(f"{e} ({md.text(why)})" for e, why in missing.items()) + ".", ""]
    for family in families:
        mine = [r for r in rows if r["family"] == family]
        parts += [f"### {md.text(family)}", ""]
        for setting in dict.fromkeys(r["setting"] for r in mine):
            parts += [f"At step {SHOWN_STEP} s, {setting} settings:", "", family_table(mine, setting, SHOWN_STEP), ""]
        stem = family_stem(family)
        parts += [md.figure(stem, f"{family}: worst probe error in tolerances, every engine and setting at each "
                                  f"step"), ""]
    parts += ["### Each engine", ""]
    for engine in _engines(rows):
        parts += [f"- {engine}: {engine_sentences(rows, engine)}"]
    parts += ["", md.files_line(files)]
    return "\n".join(parts)

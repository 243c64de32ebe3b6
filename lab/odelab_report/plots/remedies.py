"""Plots of section 4, the remedies: accuracy and cost side by side."""

import textwrap

from ..markdown import num
from .common import new_figure, save, serialized

PLAIN, REMEDY, OTHER = "#606060", "#2ca02c", "#1f77b4"


def _colour(label):
    if "plain" in label or "thesis" in label:
        return PLAIN
    if "remedy" in label or "ccd" in label:
        return REMEDY
    return OTHER


def _wrap(labels, width=22):
    return ["\n".join(textwrap.wrap(label, width)) for label in labels]


@serialized
def bars_pair(out_dir, stem, title, labels, left_values, left_upper, left_label, right_values, right_label,
              log_left=False, spread=None):
    """Accuracy (left) and cost (right) per setting, as bars (grey: plain,
    green: the remedy, blue: the alternative)."""
    fig, (left, right) = new_figure(ncols=2, width=12.0, height=5.4)
    fig.suptitle(title)
    positions = list(range(len(labels)))
    colours = [_colour(label) for label in labels]
    left.bar(positions, [v or 0 for v in left_values], color=colours)
    if left_upper:
        for x, low, high in zip(positions, left_values, left_upper):
            if low and high:
                left.plot([x, x], [low, high], color="black", linewidth=1)
                left.plot([x], [high], marker="_", markersize=14, color="black")
        left.plot([], [], color="black", marker="_", label="bar to the lightest that failed")
        left.legend(loc="upper left", fontsize=8)
    if spread:
        for x, (low, high) in zip(positions, spread):
            left.plot([x, x], [low, high], color="black", linewidth=1.2, marker="_", markersize=12)
    for x, v in zip(positions, left_values):
        if v:
            left.annotate(num(v), (x, v), ha="left", va="bottom", fontsize=8, xytext=(6, 2),
                          textcoords="offset points")
    if log_left:
        left.set_yscale("log")
    left.set_xticks(positions, _wrap(labels), fontsize=8)
    left.set_ylabel(left_label)
    left.set_title("what it buys")
    left.set_ylim(top=left.get_ylim()[1] * (3 if log_left else 1.08))
    right.bar(positions, right_values, color=colours)
    for x, v in zip(positions, right_values):
        right.annotate(num(v), (x, v), ha="center", va="bottom", fontsize=8)
    right.set_xticks(positions, _wrap(labels), fontsize=8)
    right.set_ylabel(right_label)
    right.set_title("what it costs (this machine)")
    right.set_ylim(top=right.get_ylim()[1] * 1.08)
    return save(fig, out_dir, stem)


CASE_MARKERS = ("o", "s", "D", "^")


@serialized
def ccd(out_dir, stem, rows, scan_limit, target):
    fig, (left, right) = new_figure(ncols=2, width=12.0, height=5.6)
    scans = [r for r in rows if r["kind"] == "scan"]
    cases = list(dict.fromkeys(r["case"] for r in scans))
    for setting, colour, style in (("plain", PLAIN, "--"), ("--ccd", REMEDY, "-")):
        for case, marker in zip(cases, CASE_MARKERS):
            mine = sorted((r["step_s"], r["max_velocity"], r["first_failure_velocity"]) for r in scans
                          if r["setting"] == setting and r["case"] == case)
            if not mine:
                continue
            left.plot([s for s, _, _ in mine], [v for _, v, _ in mine], marker=marker, color=colour, linestyle=style,
                      fillstyle="full" if setting == "--ccd" else "none", label=f"{setting}: {case}")
            capped = [(s, v) for s, v, f in mine if not f]
            if capped:  # nothing passed up to the scan limit: the true limit is above
                left.plot([s for s, _ in capped], [v * 1.25 for _, v in capped], linestyle="none", marker="^",
                          markersize=7, color=colour)
    left.plot([], [], linestyle="none", marker="^", color="black", label="nothing passed up to the scan limit")
    left.axhline(scan_limit, color="grey", linestyle=":", linewidth=1, label=f"scan limit {scan_limit:g} m/s")
    left.axhline(target, color="red", linestyle="--", linewidth=0.8, label=f"goal: {target:g} m/s")
    left.set_xscale("log")
    left.set_yscale("log")
    left.set_xlabel("step (s)")
    left.set_ylabel("highest launch velocity with every launch stopped (m/s)")
    left.set_title("what it buys")
    left.legend(loc="lower left", fontsize=6.5)
    costs = [r for r in rows if r["kind"] == "cost"]
    labels = [f"{r['setting']}\n{r['launch_velocity']:g} m/s" for r in costs]
    values = [r["us_per_launch"] for r in costs]
    right.bar(range(len(costs)), values, color=[_colour(r["setting"]) for r in costs])
    for x, r in enumerate(costs):
        right.plot([x, x], [r["us_per_launch_min"], r["us_per_launch_max"]], color="black", linewidth=1.2,
                   marker="_", markersize=12, label="spread of the runs" if x == 0 else None)
    right.legend(loc="upper right", fontsize=8)
    for x, v in enumerate(values):
        right.annotate(num(v), (x, v), ha="left", va="bottom", fontsize=8, xytext=(6, 2),
                       textcoords="offset points")
    right.set_xticks(range(len(costs)), labels, fontsize=8)
    right.set_ylabel("wall time per launch (microseconds)")
    right.set_title("what it costs: launches at step 0.001 (this machine)")
    fig.suptitle("test10: continuous collision for fast bodies (--ccd) against the plain setting")
    return save(fig, out_dir, stem)


@serialized
def stack_settings(out_dir, stem, rows):
    fig, ax = new_figure(width=10.0, height=5.4)
    labels = [r["setting"] for r in rows]
    values = [r["tallest_plates"] or 0 for r in rows]
    colours = [PLAIN if r["thesis_default"] else OTHER for r in rows]
    best = max(values) if values else 0
    colours = [REMEDY if v == best and not r["thesis_default"] else c for v, c, r in zip(values, colours, rows)]
    ax.barh(range(len(rows)), values, color=colours)
    for y, (v, r) in enumerate(zip(values, rows)):
        text = f"{v} plates" + (f", {r['tallest_height_m']:.2f} m" if r["tallest_height_m"] else "")
        if r["failure"]:
            text += "; limited by " + ("real time" if "ms per step" in r["failure"] else "alignment")
        elif r.get("first_failing_plates") is None:
            text += " (search cap)"
        ax.annotate(text, (v, y), ha="left", va="center", fontsize=8, xytext=(3, 0), textcoords="offset points")
    ax.set_yticks(range(len(rows)), labels, fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel("tallest aligned stack that runs in real time (plates of 0.05 m)")
    ax.set_title("test5: settings against the thesis's default (grey); best in green")
    ax.set_xlim(0, best * 1.45 if best else 1)
    return save(fig, out_dir, stem)

"""Plots of the world report (lab/odelab-report --world) that the thesis
scenes' plots do not cover: the deviation along the step (where the world
breaks) and against ERP and CFM."""

import math

from .common import new_figure, save, serialized

FLOOR = 1e-16  # a deviation of exactly 0 (the reference itself) is drawn here


def _y(value):
    return max(value, FLOOR)


@serialized
def step_limit(out_dir, stem, sweep_rows, limit_rows, solver, bound):
    """Largest deviation from the reference against the step, one curve per
    solver of the sweep, the step search's probes at the world's solver as
    crosses (a blow-up drawn at the top), the bound as a line."""
    fig, ax = new_figure(width=10.0, height=5.6)
    finite = [r["max_dev"] for r in sweep_rows + limit_rows if r.get("max_dev") is not None
              and math.isfinite(r["max_dev"])]
    top = max([bound * 10] + [10 * v for v in finite])
    for name in dict.fromkeys(r["solver"] for r in sweep_rows if "step" in r["groups"]):
        mine = sorted((r["step_s"], r["max_dev"]) for r in sweep_rows
                      if r["solver"] == name and "step" in r["groups"] and r.get("max_dev") is not None
                      and math.isfinite(r["max_dev"]))
        if mine:
            ax.plot([s for s, _ in mine], [_y(d) for _, d in mine], marker="o", markersize=4, linewidth=1.2,
                    label=name)
    probes = sorted({(r["step_s"], r["exit_status"], r["max_dev"]) for r in limit_rows},
                    key=lambda p: p[0])
    ran = [(s, d) for s, x, d in probes if x == 0 and d is not None and math.isfinite(d)]
    blown = [s for s, x, _ in probes if x != 0]
    if ran:
        ax.plot([s for s, _ in ran], [_y(d) for _, d in ran], "x", color="black", markersize=7,
                label=f"step search ({solver})")
    if blown:
        ax.plot(blown, [top] * len(blown), "X", color="#d62728", markersize=9, linestyle="none",
                label="blew up (status 3), drawn at the top")
    ax.axhline(bound, color="#8c564b", linestyle=":", linewidth=1.2, label=f"bound {bound:g}")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("step (s)")
    ax.set_ylabel("largest deviation from the reference (every measurement)")
    ax.set_title("where the world breaks: deviation against the step", fontsize=10)
    ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)
    return save(fig, out_dir, stem)


@serialized
def erp_cfm(out_dir, stem, sweep_rows):
    """Largest deviation against ERP (left) and CFM (right) at the world's step and solver."""
    fig, (left, right) = new_figure(ncols=2, width=11.0, height=4.6)
    for ax, group, column, label in ((left, "erp", "erp", "ERP"), (right, "cfm", "cfm", "CFM")):
        mine = sorted((r[column], r["max_dev"], r["exit_status"]) for r in sweep_rows if group in r["groups"])
        ok = [(x, d) for x, d, s in mine if s == 0 and d is not None and math.isfinite(d)]
        if ok:
            ax.plot([x for x, _ in ok], [_y(d) for _, d in ok], marker="o", linewidth=1.2)
        for x, d, s in mine:
            if s != 0:
                ax.annotate("blew up", (x, FLOOR), fontsize=7, color="#d62728")
        if column == "cfm":
            ax.set_xscale("symlog", linthresh=1e-10)
        ax.set_yscale("log")
        ax.set_xlabel(label)
        ax.set_ylabel("largest deviation from the reference")
        ax.set_title(f"{label} at the world's step and solver", fontsize=10)
    return save(fig, out_dir, stem)

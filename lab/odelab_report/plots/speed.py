"""Plots of section 3, speed against accuracy."""

from .common import SOLVER_COLOURS, SOLVER_MARKERS, new_figure, save, serialized

THRESHOLD_COLOURS = {1e-2: "#e377c2", 1e-3: "#8c564b", 1e-4: "#17becf"}
THRESHOLD_LABELS = {1e-2: "1%", 1e-3: "0.1%", 1e-4: "0.01%"}


@serialized
def speed_accuracy(out_dir, stem, rows, cheapest, ylabel, title, zero_floor, xlabel=None, subtitle=None):
    """`xlabel`, `subtitle`: the cost's name and the steps' range where they differ from the scenes' sweep."""
    fig, ax = new_figure(width=11.5, height=6.0)
    for solver in dict.fromkeys(r["solver"] for r in rows):
        mine = sorted(((r["wall_per_sim_second"], r["error"], r["step_s"]) for r in rows
                       if r["solver"] == solver and r["error"] is not None), key=lambda p: -p[2])
        ax.plot([x for x, _, _ in mine], [max(e, zero_floor) for _, e, _ in mine], marker=SOLVER_MARKERS[solver],
                color=SOLVER_COLOURS[solver], markersize=5, linewidth=1.2, label=solver)
    for threshold, colour in THRESHOLD_COLOURS.items():
        ax.axhline(threshold, color=colour, linestyle=":", linewidth=1, label=f"{THRESHOLD_LABELS[threshold]} error")
    for threshold, best in cheapest:
        if best is None:
            continue
        colour = THRESHOLD_COLOURS[threshold]
        ax.plot([best["wall_per_sim_second"]], [max(best["error"], zero_floor)], marker="o", markersize=16,
                fillstyle="none", markeredgewidth=2, color=colour, linestyle="none",
                label=f"cheapest reaching {THRESHOLD_LABELS[threshold]}: {best['solver']}, step {best['step_s']:g}")
    if any(r["error"] == 0 for r in rows):
        ax.axhline(zero_floor, color="grey", linewidth=0.8)
        ax.text(0.01, zero_floor, "exactly 0 (drawn at 1e-16)", va="bottom", fontsize=7.5, color="grey",
                transform=ax.get_yaxis_transform())  # x in axes fractions, y in data
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel(xlabel or "cost: wall seconds per simulated second (this machine)")
    ax.set_ylabel(ylabel)
    ax.set_title(title + "\n" + (subtitle or "one curve per solver setting, steps 1e-2 (left) to 1e-4 (right)"),
                 fontsize=10)
    ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)
    return save(fig, out_dir, stem)

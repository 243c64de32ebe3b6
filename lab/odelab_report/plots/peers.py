"""Plots of the peers section: one speed-accuracy plot per scene, one curve
per engine and setting."""

from .common import HAVOK_STYLE, new_figure, save, serialized

ENGINE_COLOURS = {"ode": "#2ca02c", "bullet": "#d62728", "mujoco": "#1f77b4", "havok": "#ff7f0e", "jolt": "#9467bd",
                  "rapier": "#8c564b", "physx": "#17becf"}
SETTING_STYLES = {"default": dict(linestyle="--", marker="o"), "best": dict(linestyle="-", marker="s")}


@serialized
def peers_speed_accuracy(out_dir, stem, rows, label, lower_is_better, havok, zero_floor):
    """`rows`: the scene's rows of peers.csv (cost: the engine's own seconds
    per simulated second, engine_s_per_sim_s, median and range of its timed runs); `havok`: the thesis's quoted
    Havok figure (a horizontal line) or None; errors below `zero_floor` are
    drawn at it."""
    fig, ax = new_figure(width=10.0, height=5.6)
    pointless = []  # curves with no figure at any step (e.g. no 20th bounce): named under the plot
    for (engine, setting) in dict.fromkeys((r["engine"], r["setting"]) for r in rows):
        mine = [r for r in rows if r["engine"] == engine and r["setting"] == setting and r["value"] is not None
                and r.get("engine_s_per_sim_s")]
        points = sorted(((r["engine_s_per_sim_s"], r["value"], r["step"]) for r in mine), key=lambda p: -p[2])
        if not points:
            pointless.append(f"{engine} {setting}")
            continue
        ys = [max(v, zero_floor) if lower_is_better else v for _, v, _ in points]
        ax.plot([x for x, _, _ in points], ys, color=ENGINE_COLOURS[engine], markersize=5, linewidth=1.3,
                label=f"{engine} {setting}", **SETTING_STYLES[setting])
        # the range of the timed runs, a horizontal bar through each point
        spans = {r["step"]: (r["engine_s_per_sim_s_min"], r["engine_s_per_sim_s_max"]) for r in mine}
        for (x, _, step), y in zip(points, ys):
            low, high = spans[step]
            if low is not None and high is not None:
                ax.plot([low, high], [y, y], color=ENGINE_COLOURS[engine], linewidth=2.5, alpha=0.5)
        for (x, _, step), y in zip(points, ys):
            ax.annotate(f"{step:g}", (x, y), textcoords="offset points", xytext=(4, 3), fontsize=6.5,
                        color=ENGINE_COLOURS[engine])
    if havok is not None:
        ax.axhline(havok, color=HAVOK_STYLE["color"], linestyle="-.", linewidth=1.5,
                   label="Havok 6.5, quoted by the thesis (not measured)")
    if lower_is_better and any(r["value"] is not None and r["value"] < zero_floor for r in rows):
        ax.axhline(zero_floor, color="grey", linewidth=0.8)
        ax.text(0.01, zero_floor, f"exact to rounding (drawn at {zero_floor:g})", va="bottom", fontsize=7.5,
                color="grey", transform=ax.get_yaxis_transform())
    if pointless:
        ax.text(0.0, -0.14, "no figure at any step (see the table): " + ", ".join(pointless), fontsize=8,
                color="grey", transform=ax.transAxes)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("cost: engine seconds (its own collision and step calls) per simulated second, median of the "
                  "timed runs, bars their range (this machine)")
    ax.set_ylabel(label + (" (lower is better)" if lower_is_better else " (higher is better)"))
    engines = ", ".join(dict.fromkeys(r["engine"] for r in rows))
    ax.set_title(f"{stem.replace('peers-', '')}: {engines} at the same steps\n"
                 "dashed: the engine's defaults; solid: its best settings; labels: the step (s)", fontsize=10)
    ax.legend(loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=8)
    return save(fig, out_dir, stem)

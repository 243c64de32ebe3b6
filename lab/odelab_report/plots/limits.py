"""Plots of section 2, the stability limits."""

import math

from .common import HAVOK_STYLE, SOLVER_COLOURS, SOLVER_MARKERS, THESIS_STYLE, new_figure, save, serialized


@serialized
def apex_error(out_dir, stem, series, failure, resolution):
    fig, ax = new_figure()
    colours = ["#000000", "#1f77b4", "#2ca02c", "#ff7f0e", "#d62728"]
    for (cfm, points), colour in zip(sorted(series.items()), colours):
        points = [(n, e) for n, e in points if e and e > 0]
        if not points:
            continue
        label = f"CFM {cfm:g}"
        ax.plot([n for n, _ in points], [e for _, e in points], marker="o", markersize=4, color=colour, label=label)
    ax.axhline(failure, color="red", linestyle="--", linewidth=1, label=f"failure rule: {failure:.0%} of the drop")
    if resolution:  # the resolution of the figures, when they are not full precision
        ax.axhline(resolution, color="grey", linestyle=":", linewidth=1,
                   label=f"six-decimal print resolution ({resolution:.1g})")
    ax.set_yscale("log")
    ax.set_xlabel("bounce count (apex after the n-th bounce)")
    ax.set_ylabel("relative apex error |apex - start| / drop height")
    ax.set_title("test9: apex error of a perfect bounce (ERP 0.2, step 0.001, QuickStep 20)")
    ax.legend(loc="lower right")
    return save(fig, out_dir, stem)


@serialized
def elongation(out_dir, stem, rows, failure):
    fig, (left, right) = new_figure(ncols=2)
    for erp, colour in ((0.4, "#1f77b4"), (1.0, "#d62728")):
        mine = sorted((r["cfm"], r["max_relative_elongation"], r["estimate_F_h_CFM_over_ERP"]) for r in rows
                      if r["sweep"] == "cfm" and r["erp"] == erp)
        soft = [(c, e, m) for c, e, m in mine if c > 0 and e]
        left.plot([c for c, _, _ in soft], [e for _, e, _ in soft], marker="o", color=colour,
                  label=f"measured, ERP {erp:g}")
        left.plot([c for c, _, _ in soft], [m for _, _, m in soft], linestyle="--", color=colour, alpha=0.7,
                  label=f"estimate F h CFM / (ERP l0), ERP {erp:g}")
        rigid = [e for c, e, _ in mine if c == 0 and e]
        if rigid:
            left.axhline(rigid[0], color=colour, linestyle=":", linewidth=1.2,
                         label=f"CFM 0, ERP {erp:g}: {rigid[0]:.2g} (solver floor)")
    left.axhline(failure, color="red", linestyle="-.", linewidth=1, label=f"failure rule: {failure:.0%}")
    left.plot([1e-4, 1e-4], [1e-3, 1e-3], **THESIS_STYLE, label="thesis: about 1e-3 at CFM 1e-4, ERP 0.4")
    left.set_xscale("log")
    left.set_yscale("log")
    left.set_xlabel("CFM (global, dimensionless)")
    left.set_ylabel("largest relative elongation |l - l0| / l0")
    left.set_title("5000 kg bob, step 0.001: against CFM")
    left.legend(loc="upper left", fontsize=7.5)
    for cfm, colour in ((1e-4, "#1f77b4"), (0.0, "#2ca02c")):
        mine = sorted((r["bob_mass_kg"], r["max_relative_elongation"], r["estimate_F_h_CFM_over_ERP"]) for r in rows
                      if r["sweep"] == "mass" and r["cfm"] == cfm)
        right.plot([m for m, _, _ in mine], [e for _, e, _ in mine], marker="o", color=colour,
                   label=f"measured, CFM {cfm:g}")
        if cfm > 0:
            right.plot([m for m, _, _ in mine], [x for _, _, x in mine], linestyle="--", color=colour, alpha=0.7,
                       label=f"estimate F h CFM / (ERP l0), CFM {cfm:g}")
    right.axhline(failure, color="red", linestyle="-.", linewidth=1, label=f"failure rule: {failure:.0%}")
    right.set_xscale("log")
    right.set_yscale("log")
    right.set_xlabel("bob mass (kg)")
    right.set_ylabel("largest relative elongation |l - l0| / l0")
    right.set_title("ERP 0.4, step 0.001: against the bob's mass")
    right.legend(loc="upper left", fontsize=7.5)
    return save(fig, out_dir, stem)


@serialized
def energy_curves(out_dir, stem, rows, thesis_range, failure):
    """test2's energies (top, the thesis's least and largest total as a band:
    joules like for like) and the total's deviation from its start as a share
    of the swing's energy m g d (bottom, the failure rule's unit)."""
    fig, (top, bottom) = new_figure(nrows=2, width=9.0, height=7.5, sharex=True,
                                    gridspec_kw={"height_ratios": [2, 1.2]})
    t = [r["time_s"] for r in rows]
    top.plot(t, [r["potential_J"] for r in rows], color="#1f77b4", linewidth=0.9, label="potential")
    top.plot(t, [r["kinetic_J"] for r in rows], color="#d62728", linewidth=0.9, label="kinetic")
    top.plot(t, [r["total_J"] for r in rows], color="black", linewidth=1.4, label="total")
    low, high = thesis_range
    top.axhspan(low, high, color="#b8860b", alpha=0.25, label=f"thesis's total, {low}-{high} J")
    top.set_ylabel("energy (J)")
    top.set_title("test2: pendulum energies, ERP 0.4, CFM 0, step 0.001 (thesis figure 4)")
    top.legend(loc="center right")
    bottom.plot(t, [100 * r["swing_relative_deviation"] for r in rows], color="black", linewidth=0.9,
                label="total, this build")
    bottom.axhline(-100 * failure, color="red", linestyle="--", linewidth=1, label=f"failure rule: {failure:.0%}")
    bottom.set_ylim(-100 * failure * 1.1, 100 * failure * 0.3)
    bottom.set_xlabel("simulated time (s)")
    bottom.set_ylabel("total - E0 (% of m g d)")
    bottom.legend(loc="lower right", fontsize=7.5)
    return save(fig, out_dir, stem)


@serialized
def velocity_limit(out_dir, stem, rows):
    fig, ax = new_figure()
    steps = [r["step_s"] for r in rows]
    half_size, wall = rows[0]["cube_half_size_m"], rows[0]["wall_thickness_m"]  # as test10 reports them
    fine = [10 ** (math.log10(min(steps)) + i * (math.log10(max(steps)) - math.log10(min(steps))) / 50)
            for i in range(51)]
    ax.plot(fine, [(half_size + wall) / s for s in fine], color="grey", linestyle="--",
            label="geometric prediction (a + w) / h")
    ax.plot(fine, [(half_size + wall / 2) / s for s in fine], color="grey", linestyle=":",
            label="every phase stopped below (a + w/2) / h")
    ax.plot(steps, [r["max_velocity"] for r in rows], marker="o", color="#1f77b4", label="measured limit")
    banded = [r for r in rows if r["velocities_stopped_in_band"]]
    for i, r in enumerate(banded):
        ax.plot([r["step_s"]] * 2, [r["first_failure_velocity"], r["highest_stopped_velocity_in_band"]],
                color="#ff7f0e", linewidth=5, alpha=0.5, solid_capstyle="butt",
                label="band: some velocities above the first failure stopped again" if i == 0 else None)
    ax.plot([1e-3], [250], **THESIS_STYLE, label="thesis (ODE 0.11.1): 250 m/s, about 3630 m/s")
    ax.plot([1e-4], [3630], **THESIS_STYLE)
    ax.plot([1e-3], [350], **HAVOK_STYLE, label="Havok 6.5 (quoted): 350 m/s")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("step h (s)")
    ax.set_ylabel("highest launch velocity with every launch stopped (m/s)")
    ax.set_title(f"test10: cube (half-size a = {half_size:g} m) against a wall (w = {wall:g} m), ERP 0.3, CFM 0")
    ax.legend(loc="upper right")
    return save(fig, out_dir, stem)


@serialized
def heaviest_mass(out_dir, stem, limits):
    fig, ax = new_figure()
    for solver in ("QuickStep 20", "dWorldStep"):
        mine = sorted((x["step_s"], x["heaviest_held_kg"], x["lightest_failed_kg"]) for x in limits
                      if x["solver"] == solver)
        colour, marker = SOLVER_COLOURS[solver], SOLVER_MARKERS[solver]
        held = [(s, h) for s, h, _ in mine if h]
        ax.plot([s for s, _ in held], [h for _, h in held], marker=marker, color=colour,
                label=f"{solver}: heaviest held")
        failed = [(s, f) for s, _, f in mine if f]
        ax.plot([s for s, _ in failed], [f for _, f in failed], marker=marker, color=colour, linestyle="none",
                fillstyle="none", markersize=8, label=f"{solver}: lightest failed")
        for s, h, f in mine:
            if h and f:
                ax.plot([s, s], [h, f], color=colour, linewidth=4, alpha=0.25)
    ax.plot([1e-3], [5000], **THESIS_STYLE, label="thesis: fails at 5000 kg (0.001), holds 15 t (0.0001)")
    ax.plot([1e-4], [15000], **THESIS_STYLE)
    ax.plot([1e-4], [75000], marker="*", markersize=11, color="none", markeredgecolor="#b8860b", linestyle="none",
            label="thesis: 75 t with hopping (0.0001)")
    ax.plot([1e-3], [4000], **HAVOK_STYLE, label="Havok 6.5 (quoted): 4000 kg")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("step (s)")
    ax.set_ylabel("big cube's mass (kg) on a 5 kg cube")
    ax.set_title("test4: heaviest cube held (ERP 0.2, CFM 1e-6)")
    ax.legend(loc="best", fontsize=8)
    return save(fig, out_dir, stem)


@serialized
def stack_cost(out_dir, stem, probes, budget_ms):
    fig, ax = new_figure()
    colours = {"simple": "#1f77b4", "hash": "#d62728", "sap": "#2ca02c", "quadtree": "#9467bd"}
    for setting in dict.fromkeys(p["setting"] for p in probes):
        mine = sorted((p["plates"], p["ms_per_step"], p["passed"], p["space"], p["iterations"]) for p in probes
                      if p["setting"] == setting and p["ms_per_step"] is not None)
        if not mine:
            continue
        space, iterations = mine[0][3], mine[0][4]
        style = "-" if iterations == 20 else "--"
        ax.plot([n for n, *_ in mine], [c for _, c, *_ in mine], linestyle=style, marker="o", markersize=4,
                color=colours.get(space, "black"), label=setting)
        bad = [(n, c) for n, c, passed, *_ in mine if not passed]
        ax.plot([n for n, _ in bad], [c for _, c in bad], linestyle="none", marker="x", markersize=8,
                color=colours.get(space, "black"))
    ax.axhline(budget_ms, color="red", linestyle="-.", linewidth=1, label="real-time budget: the step, 1 ms")
    ax.plot([], [], linestyle="none", marker="x", color="black", label="failed the rule (x)")
    ax.set_xlabel("plates in the stack")
    ax.set_ylabel("cost per step (ms of the program's CPU time)")
    ax.set_ylim(bottom=0)
    ax.set_title("test5: cost of a step against the stack (step 0.001, ERP 0.2, CFM 0)")
    ax.legend(loc="upper left", fontsize=8, ncol=2)
    return save(fig, out_dir, stem)

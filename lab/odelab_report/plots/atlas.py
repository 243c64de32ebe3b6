"""The atlas's heat map per family: cases down, every engine and setting at
each step across, each square the worst probe's error in tolerances (log
scale; 1 is the tolerance), a cross where the run gave no figure."""

import math

from .common import new_figure, save, serialized

FLOOR, CEILING = 1e-3, 1e3  # tolerances: below and above are drawn at the ends of the scale


def _number(cell):
    try:
        value = float(cell)
    except (TypeError, ValueError):
        return None
    return value if math.isfinite(value) else None


@serialized
def heat_map(out_dir, stem, family, rows):
    import matplotlib.colors as colors

    cases = list(dict.fromkeys(r["case"] for r in rows))
    columns = list(dict.fromkeys((r["engine"], r["setting"], r["step"]) for r in rows))
    by = {(r["case"], r["engine"], r["setting"], r["step"]): r for r in rows}
    grid, crosses = [], []
    for i, case in enumerate(cases):
        line = []
        for j, column in enumerate(columns):
            row = by.get((case, *column))
            value = _number(row["worst_tolerances"]) if row and row["mark"] in ("right", "off") else None
            if value is None:
                crosses.append((j, i))
                line.append(math.nan)
            else:
                line.append(min(max(value, FLOOR), CEILING))
        grid.append(line)
    fig, ax = new_figure(width=max(8.0, 0.32 * len(columns) + 4), height=max(3.0, 0.45 * len(cases) + 2.2))
    # Bins with the tolerance as an edge: greens within it, oranges and reds past it.
    edges = [FLOOR, 0.1, 0.5, 1.0, 2.0, 10.0, 100.0, CEILING]
    palette = colors.ListedColormap(["#1a9850", "#66bd63", "#a6d96a", "#fdae61", "#f46d43", "#d73027", "#a50026"])
    image = ax.imshow(grid, cmap=palette, norm=colors.BoundaryNorm(edges, palette.N), aspect="auto")
    for j, i in crosses:
        ax.plot(j, i, "x", color="black", markersize=8)
    ax.set_yticks(range(len(cases)), cases, fontsize=8)
    ax.set_xticks(range(len(columns)), [f"{e} {s[0]} {h}" for e, s, h in columns], rotation=90, fontsize=7)
    ax.set_title(f"{family}: worst probe error in tolerances (x: no figure; d default, b best; step in s)")
    fig.colorbar(image, ax=ax, label="|error| / tolerance (1: the tolerance)", format="%g")
    return save(fig, out_dir, stem)

"""Shared look of every plot, and saving as PNG + SVG."""

import functools
import io
import threading
import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from ..files import write_atomically  # noqa: E402

plt.rcParams.update({
    "figure.figsize": (8.0, 5.2),
    "figure.dpi": 120,
    "savefig.dpi": 120,
    "font.size": 10,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "grid.linestyle": ":",
    "axes.titlesize": 11,
    "legend.fontsize": 8.5,
    "legend.framealpha": 0.85,
    "svg.hashsalt": "odelab-report",  # stable ids: the same data gives the same SVG
    "svg.fonttype": "path",
})

# One colour per solver setting, the same in every plot.
SOLVER_COLOURS = {
    "dWorldStep": "#000000",
    "QuickStep 5": "#d62728",
    "QuickStep 10": "#ff7f0e",
    "QuickStep 20": "#2ca02c",
    "QuickStep 50": "#1f77b4",
    "QuickStep 100": "#9467bd",
}
SOLVER_MARKERS = {
    "dWorldStep": "s", "QuickStep 5": "v", "QuickStep 10": "<", "QuickStep 20": "o",
    "QuickStep 50": ">", "QuickStep 100": "^",
}
THESIS_STYLE = dict(marker="*", markersize=13, color="#b8860b", linestyle="none", markeredgecolor="black",
                    markeredgewidth=0.6)
HAVOK_STYLE = dict(marker="P", markersize=10, color="#17becf", linestyle="none", markeredgecolor="black",
                   markeredgewidth=0.6)


_LOCK = threading.RLock()


def serialized(plot):
    """Matplotlib is not thread-safe and experiments run in threads: one
    plot is drawn at a time."""
    @functools.wraps(plot)
    def locked(*args, **kwargs):
        with _LOCK:
            return plot(*args, **kwargs)
    return locked


def new_figure(ncols=1, nrows=1, width=None, height=None, **kwargs):
    size = (width or (8.0 if ncols == 1 else 12.0), height or 5.2 * (1 if nrows == 1 else 0.75 * nrows))
    return plt.subplots(nrows, ncols, figsize=size, **kwargs)


def save(fig, out_dir, stem):
    """Writes stem.png and stem.svg; returns their names."""
    with warnings.catch_warnings():  # a legend outside the axes: tight_layout may give up; bbox below copes
        warnings.simplefilter("ignore", UserWarning)
        fig.tight_layout()
    names = [stem + ".png", stem + ".svg"]
    # bbox "tight": a legend placed outside the axes is kept in the picture.
    # Drawn in memory, then written by the file rule's writer (files.py):
    # savefig given a path would open it through a link or a FIFO.
    for name, metadata in ((names[0], {"Software": None}), (names[1], {"Date": None, "Creator": None})):
        drawn = io.BytesIO()
        fig.savefig(drawn, format=name.rsplit(".", 1)[1], metadata=metadata, bbox_inches="tight", pad_inches=0.15)
        write_atomically(out_dir / name, drawn.getvalue())
    plt.close(fig)
    return names

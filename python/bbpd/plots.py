# SPDX-License-Identifier: GPL-2.0-or-later
"""Plot helpers (PNG, Agg backend): a figure saved and closed in one place, and the K(t) plots of
the DSIF benchmarks of section 4.2."""
from contextlib import contextmanager

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (backend must be set first)

DPI = 150


@contextmanager
def figure(path, *args, dpi=DPI, **kwargs):
    """(fig, axes) of plt.subplots(*args, **kwargs) for the block; on leaving it the figure is
    laid out tight and saved to path; closed either way"""
    fig, axes = plt.subplots(*args, **kwargs)
    try:
        yield fig, axes
        fig.tight_layout()
        fig.savefig(path, dpi=dpi)
    finally:
        plt.close(fig)


def plot_k(path, series, refs, window, title, xlabel, ylabel):
    """K(t) figure: measured series (solid, colour), references (black/grey, dashed), and the
    validity window of the comparison (dotted lines).
    series: [(label, t, K, colour)]; refs: [(label, t, K, linestyle, colour)];
    window: (start, end) in the units of t."""
    if not series and not refs:
        raise ValueError("nothing to plot")
    with figure(path, figsize=(7.0, 4.4)) as (fig, ax):
        for label, t, k, color in series:
            ax.plot(t, k, "-", color=color, linewidth=1.4, label=label)
        for label, t, k, style, color in refs:
            ax.plot(t, k, linestyle=style, color=color, linewidth=1.6, label=label)
        for n, x in enumerate(x for x in window if x > 0):
            ax.axvline(x, color="grey", linestyle=":", linewidth=1.0,
                       label="window of the comparison" if n == 0 else None)
        ax.set(xlabel=xlabel, ylabel=ylabel)
        ax.set_title(title, fontsize=10)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
    return path

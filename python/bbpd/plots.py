# SPDX-License-Identifier: GPL-2.0-or-later
"""Plot helpers (PNG, Agg backend): a figure saved and closed in one place, and the K(t) plots of
the DSIF benchmarks of section 4.2."""
from contextlib import contextmanager

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (backend must be set first)

FIGSIZE = (6.4, 4.2)
DPI = 150
ANALYTIC_STYLE = {"color": "black", "linestyle": "--", "linewidth": 1.5}
SERIES_LINEWIDTH = 1.2
WINDOW_STYLE = {"color": "grey", "linestyle": ":", "linewidth": 1.0}


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


def plot_k_histories(path, series, analytic=None, xlabel="t (s)",
                     ylabel="normalised K", title=None, window_end=None):
    """Plot several K(t) series and an optional analytic curve to a PNG.

    series:     mapping label -> (t, K)
    analytic:   (label, t, K) or None
    window_end: optional time marked with a vertical line (end of validity).
    Returns the path written.
    """
    if not series and analytic is None:
        raise ValueError("nothing to plot")
    fig, ax = plt.subplots(figsize=FIGSIZE)
    try:
        for label, (t, k) in series.items():
            ax.plot(t, k, label=label, linewidth=SERIES_LINEWIDTH)
        if analytic is not None:
            label, t, k = analytic
            ax.plot(t, k, label=label, **ANALYTIC_STYLE)
        if window_end is not None:
            ax.axvline(window_end, label="end of validity", **WINDOW_STYLE)
        ax.set_xlabel(xlabel)
        ax.set_ylabel(ylabel)
        if title:
            ax.set_title(title)
        ax.grid(True, alpha=0.3)
        ax.legend()
        fig.tight_layout()
        fig.savefig(path, dpi=DPI)
    finally:
        plt.close(fig)
    return path

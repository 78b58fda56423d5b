# SPDX-License-Identifier: GPL-2.0-or-later
"""The report's figures (PNG beside REPORT.md): K(t) against the references, and the
benchmark modules' own plots; a figure that fails is noted in the report, not fatal."""
from pathlib import Path

import numpy as np

from bbpd.benchmarks import mode2
from bbpd.kernels import COLORS
from bbpd.plots import plot_k


def _figures(make, what, notes):
    """The names of the figures make() draws (it returns their paths), or [] with a note in the
    report: a failure does not stop it."""
    try:
        return [Path(p).name for p in make()]
    except Exception as exc:  # the report must still be written
        notes.append(f"{what} not made: {type(exc).__name__}: {exc}")
        return []


def _figure(make, path, notes):
    """[the name of the figure make() draws at path], or [] with a note in the report"""
    return _figures(lambda: (make(), [path])[1], f"figure {Path(path).name}", notes)


def mode2_figures(ok, figdir, notes):
    """Fig. 12 per dx: K_II(t) of the three kernels, from the extrapolation and from J."""
    figs = []
    win = mode2.window()
    tt = np.linspace(0.0, mode2.T_END, 600)
    refs = [("semi-infinite crack loaded by 2 tau", tt * 1e6,
             mode2.normalise(mode2.reference()(tt)), "--", "black")]
    # the extrapolation's figure and the J-integral's: (file, K_II column, label, title)
    kinds = (("kernels", "k_ii", lambda r: f"(L2 {r['l2']:.1f} %)",
              "Fig. 12: Mode-II K_II(t), dx = {} mm, m = 5, three kernels"),
             ("jintegral", "k_ii_j", lambda r: f"from J (peak {r['jintegral']['peak']:.1f} %)",
              "Mode-II K_II(t) from the J-integral, dx = {} mm, three kernels"))
    window = (win.t_start * 1e6, win.t_end_ignoring_corners * 1e6)
    for dx in sorted({dx for _, dx in ok}, reverse=True):
        for name, col, label, title in kinds:
            series = [(f"{k} {label(r)}", r["t"] * 1e6, mode2.normalise(r[col]), COLORS[k])
                      for (k, d), r in ok.items() if d == dx and col in r]
            if series:
                path = figdir / f"fig12_{name}_dx{dx * 1e3:g}mm.png"
                figs += _figure(lambda: plot_k(path, series, refs, window,
                                               title.format(f"{dx * 1e3:g}"), "t (us)",
                                               r"$K_{II}/(\tau\sqrt{\pi a})$"), path, notes)
    return figs

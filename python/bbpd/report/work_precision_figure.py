# SPDX-License-Identifier: GPL-2.0-or-later
"""The work-precision figure of REPORT.md (bbpd.report.work_precision): per benchmark, error
against run time on log-log axes, one line per kernel and K extraction method."""
import math

from bbpd.benchmarks.kalthoff_winkler import PAPER_INITIATION_US
from bbpd.kernels import COLORS, KERNELS

METHOD_LABEL = {"dsif": "displacement extrapolation", "jintegral": "J-integral",
                "ridge": "FFT ridge", "damage": "damage map", "relax": "fix bbpd/relax bisection",
                "dynamic": "dynamic ramp"}
METHOD_STYLE = {"dsif": "-", "jintegral": "--", "ridge": "-", "damage": "-", "relax": "-",
                "dynamic": "--"}
PANELS = {"mode1": ("L2 (%)", "peak (%)"), "mode2": ("L2 (%)",),
          "dispersion": ("|c/c_29 - 1|",),
          "kalthoff_winkler": ("|angle - finest| (deg)", "|angle - 70 deg| (deg)",
                               "initiation time (us)"),
          "quasi_static": ("|sigma_c/LEFM - 1| (%)", "|sigma_c/relaxed - 1| (%)")}
PLAIN_TICKS_SPAN = 30.0    # label the minor ticks of log axes spanning less than this factor
MINOR_LABELS = (2.0, 3.0, 5.0)
LABEL_ALL_SPAN = 3.0       # ... and every minor tick of those spanning less than this factor


def _plain_log_ticks(ax, which):
    """Plain numbers (0.3, 2, 20) on a log axis that spans little more than a decade, where
    matplotlib would print mantissa x 10^e labels or none at all."""
    from matplotlib.ticker import FuncFormatter, NullFormatter
    lo, hi = ax.get_xlim() if which == "x" else ax.get_ylim()
    axis = ax.xaxis if which == "x" else ax.yaxis
    plain = FuncFormatter(lambda v, _: f"{v:g}")

    def sparse(v, _):    # minor ticks: 2, 3 and 5 times a power of ten only
        mantissa = round(v / 10.0 ** math.floor(math.log10(v) + 1e-9), 6) if v > 0 else 0
        return f"{v:g}" if mantissa in MINOR_LABELS or hi / lo < LABEL_ALL_SPAN else ""
    axis.set_major_formatter(plain)
    axis.set_minor_formatter(FuncFormatter(sparse) if hi / lo < PLAIN_TICKS_SPAN
                             else NullFormatter())


def plot(path, table, benchmark, title, resolution):
    """One log-log panel per metric of PANELS[benchmark]: error against run time, one line per
    kernel and method through its resolutions, each point labelled resolution(dx)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = PANELS[benchmark]
    width = max(8.0, 5.0 * len(panels))
    fig, axes = plt.subplots(1, len(panels), figsize=(width, 5.0), squeeze=False)
    handles = {}
    try:
        for ax, metric in zip(axes[0], panels):
            mine = [r for r in table if r["benchmark"] == benchmark and r["error_metric"] == metric]
            lines = sorted({(r["kernel"], r["method"]) for r in mine},
                           key=lambda x: (KERNELS.index(x[0]) if x[0] in KERNELS else 99, x[1]))
            for kernel, method in lines:
                pts = sorted((r["wall_s"], r["error"], r["resolution"]) for r in mine
                             if r["kernel"] == kernel and r["method"] == method)
                t, e, dx = zip(*pts)
                y = [100 * v for v in e] if metric.startswith("|c/") else e
                label = kernel + ("" if method in ("ridge", "damage")
                                  else f", {METHOD_LABEL[method]}")
                (h,) = ax.plot(t, y, METHOD_STYLE.get(method, "-"),
                               color=COLORS.get(kernel, "black"),
                               marker="s" if method in ("jintegral", "relax") else "o", markersize=4,
                               label=label)
                handles.setdefault(label, h)
                for ti, yi, di in zip(t, y, dx):
                    ax.annotate(resolution(di).replace("dx = ", ""), (ti, yi),
                                fontsize=6, textcoords="offset points", xytext=(3, 3),
                                color="dimgrey")
            ax.set_xscale("log")
            if metric == "initiation time (us)":
                for kernel, t0 in PAPER_INITIATION_US.items():
                    ax.axhline(t0, color=COLORS[kernel], linestyle=":", linewidth=0.9)
                ax.set_ylabel("initiation time (us); dotted: the paper's")
            else:
                if any(r["error"] > 0 for r in mine):
                    ax.set_yscale("log")
                    _plain_log_ticks(ax, "y")
                ax.set_ylabel("|c/c_29 - 1| (%)" if metric.startswith("|c/") else metric)
            if mine:
                _plain_log_ticks(ax, "x")
            ax.set_xlabel("run time: LAMMPS loop, 1 rank (s)")
            ax.grid(True, which="both", alpha=0.3)
        fig.suptitle(title, fontsize=10)
        fig.legend(list(handles.values()), list(handles), loc="lower center", fontsize=7.5,
                   ncol=3, frameon=False)
        rows_of_legend = (len(handles) + 2) // 3
        fig.tight_layout(rect=(0.0, 0.04 + 0.045 * rows_of_legend, 1.0, 1.0))
        fig.savefig(path, dpi=150)
    finally:
        plt.close(fig)
    return path

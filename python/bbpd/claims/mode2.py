# SPDX-License-Identifier: GPL-2.0-or-later
"""Blocks of examples/mode2-central-crack/README.md and the Mode-II sentence of
doc/compute_bbpd_jintegral.rst, from examples/mode2-central-crack/results/mode2.csv."""
from bbpd.kernels import KERNELS

from .text import f, md_table, mm, run_note, span

NAME = "mode2"
WINDOW_END_US = 9.77    # t_start + 2a/c_d (README, "Reference")


def _rows(data):
    return sorted(data.rows(NAME), key=lambda r: (-r["dx_m"], KERNELS.index(r["kernel"])))


def table(data):
    header = ["kernel", "dx (mm)", "atoms", "peak (%)", "L2 (%)",
              f"K_II/(tau sqrt(pi a)) at {WINDOW_END_US} us, ours / reference",
              "run time (s)"]
    rows = [[r["kernel"], mm(r["dx_m"]), f"{r['atoms']:,.0f}", f(r["peak"]), f(r["l2"]),
             f"{r['k_end']:.3f} / {r['k_end_exact']:.3f}", f(r["run_time_s"], ".1f")]
            for r in _rows(data)]
    return md_table(header, rows) + "\n\n" + run_note(data, NAME)


def jtable(data):
    header = ["kernel", "dx (mm)", "extrapolation: peak / L2 (%)",
              f"extrapolation: ratio at {WINDOW_END_US} us", "J: peak / L2 (%)",
              f"J: ratio at {WINDOW_END_US} us", "run time (s)"]
    rows = [[r["kernel"], mm(r["dx_m"]), f"{r['peak']:.2f} / {r['l2']:.2f}",
             f"{r['ratio_end']:.3f}", f"{r['j_peak']:.2f} / {r['j_l2']:.2f}",
             f"{r['j_ratio_end']:.3f}", f(r["run_time_s"], ".1f")] for r in _rows(data)]
    return md_table(header, rows) + "\n\n" + run_note(data, NAME)


def excess(data):
    """'11.9–28.9 %' of the extrapolation at the window end, over every run."""
    return span([100 * (r["ratio_end"] - 1) for r in data.rows(NAME)], ".0f", " %")



# SPDX-License-Identifier: GPL-2.0-or-later
"""Blocks of examples/kalthoff-winkler/README.md, from
examples/kalthoff-winkler/results/kalthoff_winkler.csv."""
from bbpd.benchmarks import kalthoff_winkler as kw_bench

from .text import by_kernel, f, md_table, mm

NAME = "kalthoff_winkler"


def _consts():
    return kw_bench.PAPER_INITIATION_US, kw_bench.EXPERIMENT_ANGLE_DEG


def _gauss(data):
    return [r for r in by_kernel(data.rows(NAME)) if r["kernel"] == "gaussian"]


def table(data):
    paper, exp = _consts()
    header = ["kernel", "dx (mm)", "atoms", "first bond (us)", "damage band (us)", "paper (us)",
              "angle (deg)", "exp. (deg)", "speed (m/s)", "tip mirror mismatch (mm)",
              "far-edge crack from (us)", "other far damage (atoms)", "run time (s)"]
    rows = [[r["kernel"], mm(r["dx_m"]), f"{r['atoms']:.0f}", f(r["first_bond_us"], ".1f"),
             f(r["damage_band_us"], ".1f"), f"{paper[r['kernel']]:.1f}", f(r["angle_deg"], ".1f"),
             f"{exp:.0f}", f(r["speed_m_s"], ".0f"), f(r["symmetry_tip_mm"], ".1e"),
             "none" if r["far_edge_crack_us"] is None else f"{r['far_edge_crack_us']:.0f}",
             f(r["far_damage_other_atoms"], ".0f"), f(r["run_time_s"], ".1f")]
            for r in by_kernel(data.rows(NAME))]
    return md_table(header, rows) + (
        f"\n\nFrom {data.source(NAME)}. Run time: one single-rank run, two at a time on "
        f"{data.cpu(NAME)} (cores shared with other jobs). Every other number is deterministic.")



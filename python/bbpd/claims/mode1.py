# SPDX-License-Identifier: GPL-2.0-or-later
"""Blocks of examples/mode1-semi-infinite/README.md, from
examples/mode1-semi-infinite/results/mode1.csv and the tolerances of
tests/regression/test_mode1.py."""

from bbpd import csvfile
from bbpd.benchmarks import mode1 as mode1_bench
from bbpd.benchmarks import mode1_lps

from .text import md_table, run_note

NAME = "mode1"
TABLE3_DX = mode1_bench.TABLE3_DX


def paper():
    return mode1_bench.PAPER_TABLE2, mode1_bench.PAPER_TABLE3


def _gauss(data):
    return sorted((r for r in data.rows(NAME) if r["kernel"] == "gaussian"),
                  key=lambda r: -r["dx_m"])


def _pair(r, a, b):
    return f"{r[a]:.2f} / {r[b]:.2f}"


def table2(data):
    return mode1_bench.table2(data.rows(NAME)) + "\n\n" + run_note(data, NAME)


def table3(data):
    return mode1_bench.table3(data.rows(NAME)) + "\n\n" + run_note(data, NAME)


def jtable(data):
    return mode1_bench.jtable(data.rows(NAME)) + "\n\n" + run_note(data, NAME)


TIPS = "mode1_tips"


def tips_table(data):
    def where(x):
        return {0.5: "+0.5 dx", -0.5: "-0.5 dx", 0.0: "0"}.get(x, f"{x:+g} dx")
    header = ["tip x - a", "r1, r2 (dx)", "face nodes at x - a", "K_max / K_max,exact (consistent)",
              "consistent peak / L2", "paper peak / L2"]
    rows = [[where(r["tipshift_dx"]) + (" (default, paper Fig. 7)" if i == 0 else ""),
             f"{r['r1_dx']:g}, {r['r2_dx']:g}",
             f"{r['tipshift_dx'] - r['r1_dx']:g}, {r['tipshift_dx'] - r['r2_dx']:g} dx",
             f"{r['kmax_ratio']:.3f}", _pair(r, "consistent_peak", "consistent_l2"),
             _pair(r, "paper_peak", "paper_l2")] for i, r in enumerate(data.rows(TIPS))]
    return md_table(header, rows) + f"\n\nFrom {data.source(TIPS)}."


def _lps_rows():
    made = [ln.split(": ", 1)[1] for ln in csvfile.provenance(mode1_lps.CSV)]
    return mode1_lps.read_rows(), made


def lps_table(data):
    rows, made = _lps_rows()
    return mode1_lps.table(rows, data.rows(NAME), made[0] if made else None)



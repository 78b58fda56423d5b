# SPDX-License-Identifier: GPL-2.0-or-later
"""Blocks of examples/mode2-central-crack/README.md, from
examples/mode2-central-crack/results/mode2.csv."""
from bbpd.benchmarks import mode2 as mode2_bench

from .text import run_note, span

NAME = "mode2"


def table(data):
    return mode2_bench.table(data.rows(NAME)) + "\n\n" + run_note(data, NAME)


def jtable(data):
    return mode2_bench.jtable(data.rows(NAME)) + "\n\n" + run_note(data, NAME)


def excess(data):
    """'11.9–28.9 %' of the extrapolation at the window end, over every run."""
    return span([100 * (r["ratio_end"] - 1) for r in data.rows(NAME)], ".0f", " %")

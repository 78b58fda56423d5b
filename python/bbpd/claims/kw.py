# SPDX-License-Identifier: GPL-2.0-or-later
"""Blocks of examples/kalthoff-winkler/README.md, from
examples/kalthoff-winkler/results/kalthoff_winkler.csv."""
from bbpd.benchmarks import kalthoff_winkler as kw_bench

from .text import by_kernel

NAME = "kalthoff_winkler"


def _consts():
    return kw_bench.PAPER_INITIATION_US, kw_bench.EXPERIMENT_ANGLE_DEG


def _gauss(data):
    return [r for r in by_kernel(data.rows(NAME)) if r["kernel"] == "gaussian"]


def table(data):
    return kw_bench.table(data.rows(NAME)) + (
        f"\n\nFrom {data.source(NAME)}. Run time: one single-rank run, two at a time on "
        f"{data.cpu(NAME)} (cores shared with other jobs). Every other number is deterministic.")

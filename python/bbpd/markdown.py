# SPDX-License-Identifier: GPL-2.0-or-later
"""Markdown tables of the READMEs, the docs and REPORT.md: one cell format for a value that may
be missing, one table layout."""
import math


def cell(v, spec=".2f"):
    """v formatted by spec (a number written as text is read first); '-' where it is missing
    (None, an empty CSV cell, NaN)"""
    if v is None or v == "":
        return "-"
    v = float(v) if isinstance(v, str) else v
    return "-" if isinstance(v, float) and math.isnan(v) else format(v, spec)


def table(header, rows):
    """a pipe table: the header, its rule, then one line per row of cells"""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)

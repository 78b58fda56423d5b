# SPDX-License-Identifier: GPL-2.0-or-later
"""Markdown tables of the READMEs, the docs and REPORT.md: one cell format for a value that may
be missing, one table layout."""
import math


def cell(v, spec=".2f"):
    """v formatted by spec (a number written as text is read first); '-' where it is missing
    (None, an empty CSV cell, NaN); a value that rounds to zero without its sign (a straight
    crack measured at -1e-15 deg is 0.0, not -0.0)"""
    if v is None or v == "":
        return "-"
    v = float(v) if isinstance(v, str) else v
    text = "-" if isinstance(v, float) and math.isnan(v) else format(v, spec)
    return text[1:] if text[:1] == "-" and text[1:] and not text[1:].strip("0.") else text


def made_by(commands):
    """'Made by `a`. Rows added by `b`. ...': the commands that wrote a CSV and added to it"""
    return " ".join(f"{'Made by' if k == 0 else 'Rows added by'} `{c}`."
                    for k, c in enumerate(commands))


def table(header, rows):
    """a pipe table: the header, its rule, then one line per row of cells"""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(str(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def columns(rows, spec):
    """table() of rows, one column per entry of spec: (header, key) takes the row's value as it
    is, (header, key, format) through cell(), (header, function of the row) what it returns"""
    def value(r, key, fmt=None):
        return key(r) if callable(key) else r[key] if fmt is None else cell(r[key], fmt)
    return table([s[0] for s in spec], [[value(r, *s[1:]) for s in spec] for r in rows])

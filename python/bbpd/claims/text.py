# SPDX-License-Identifier: GPL-2.0-or-later
"""Number formats of the generated text: ranges, rankings, tables."""
from bbpd.kernels import KERNELS
from bbpd.markdown import cell as f
from bbpd.markdown import table as md_table

DASH = "–"


def span(values, spec=".1f", unit=""):
    """'a–b' over the values (rounded first), or 'a' when they round alike."""
    vals = [v for v in values if v is not None]
    lo, hi = format(min(vals), spec), format(max(vals), spec)
    return (lo if lo == hi else f"{lo}{DASH}{hi}") + unit


def sci(v):
    """6e-06 -> 6e-6"""
    mant, exp = f"{v:.0e}".split("e")
    return f"{mant}e{int(exp)}"


def by_kernel(rows):
    return sorted(rows, key=lambda r: (KERNELS.index(r["kernel"]), -r["dx_m"]))


def mm(dx):
    return f"{dx * 1e3:g}"

# SPDX-License-Identifier: GPL-2.0-or-later
"""The paper's three kernels, in one place: names (pair styles bbpd/<name>) and plot colours."""

KERNELS = ("constant", "triangular", "gaussian")
COLORS = {"constant": "tab:blue", "triangular": "tab:orange", "gaussian": "tab:green"}

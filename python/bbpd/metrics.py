# SPDX-License-Identifier: GPL-2.0-or-later
"""Error metrics of section 4.2.1 of the paper.

eq. 44  peak relative error   |max K_PD - max K_exact| / max K_exact
eq. 45  L2 relative error     sqrt(sum (K_PD - K_exact)^2 / sum K_exact^2)

Both compare a numerical series K_PD(t_n) with the exact solution sampled at
the same times t_n, restricted to a closed time window [t_min, t_max] (e.g.
t <= 3 t_c for eq. 42).  Non-finite input raises ValueError instead of
silently producing NaN.
"""

import numpy as np


def _prepare(t, k_num, k_exact, window):
    t = np.asarray(t, dtype=float)
    k_num = np.asarray(k_num, dtype=float)
    if t.ndim != 1 or k_num.shape != t.shape:
        raise ValueError(f"t and k_num must be 1-D of equal length, got {t.shape} and {k_num.shape}")
    exact = k_exact(t) if callable(k_exact) else k_exact
    exact = np.asarray(exact, dtype=float)
    if exact.shape != t.shape:
        raise ValueError(f"exact values have shape {exact.shape}, expected {t.shape}")
    for name, arr in (("t", t), ("k_num", k_num), ("k_exact", exact)):
        if not np.all(np.isfinite(arr)):
            raise ValueError(f"{name} contains NaN or inf")
    if window is not None:
        t_min, t_max = window
        if not t_min <= t_max:
            raise ValueError(f"window must satisfy t_min <= t_max, got {window!r}")
        mask = (t >= t_min) & (t <= t_max)
        t, k_num, exact = t[mask], k_num[mask], exact[mask]
    if t.size == 0:
        raise ValueError("no samples inside the time window")
    return k_num, exact


def peak_relative_error(t, k_num, k_exact, window=None):
    """Eq. 44.  k_exact is an array sampled at t or a callable f(t)."""
    k_num, exact = _prepare(t, k_num, k_exact, window)
    peak_exact = exact.max()
    if peak_exact <= 0.0:
        raise ValueError("maximum of the exact solution must be > 0 in the window")
    return float(abs(k_num.max() - peak_exact) / peak_exact)


def l2_relative_error(t, k_num, k_exact, window=None):
    """Eq. 45.  k_exact is an array sampled at t or a callable f(t)."""
    k_num, exact = _prepare(t, k_num, k_exact, window)
    denominator = np.sum(exact ** 2)
    if denominator == 0.0:
        raise ValueError("exact solution is identically zero in the window")
    return float(np.sqrt(np.sum((k_num - exact) ** 2) / denominator))

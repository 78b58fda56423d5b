# SPDX-License-Identifier: GPL-2.0-or-later
"""Displacement extrapolation of DSIFs, paper eqs. 39-40 (reference for the
LAMMPS compute).

Tip at the origin, crack along theta = +-pi (behind the tip), points B and D on
the faces at r1 < r2.  The two-point method assumes u/sqrt(r) is linear in r
and extrapolates it to r = 0:

    K = 2 mu sqrt(2 pi) / (kappa + 1) * (u(r1) r2/sqrt(r1) - u(r2) r1/sqrt(r2)) / (r2 - r1)

with u the displacement of ONE face (u2 for K_I, u1 for K_II; eq. 39 with its
brackets restored).  With the face jumps (upper minus lower face), which are
twice the single-face values for a pure mode, the prefactor is halved:
:func:`k_from_face_jump`.  Both are exact for the Williams field
u = (K/(2 mu)) sqrt(r/(2 pi)) (kappa + 1) on theta = pi and remain exact if an
r^(3/2) term is added.  The jumps are unchanged by rotating the local frame
by pi, so the same formula applies to the left tip of a central crack.
"""

import numpy as np

from .freund import PLANE_STRAIN, PLANE_STRESS, _check_poisson, _check_positive

FACE_JUMP_FACTOR = 2.0  # jump = upper - lower = 2 x single-face value


def shear_modulus(E, nu):
    """mu = E / (2 (1 + nu))."""
    _check_positive(E=E)
    _check_poisson(nu)
    return E / (2.0 * (1.0 + nu))


def kolosov_constant(nu, condition):
    """Eq. 40: kappa = 3 - 4 nu (plane strain), (3 - nu)/(1 + nu) (plane stress)."""
    _check_poisson(nu)
    if condition == PLANE_STRAIN:
        return 3.0 - 4.0 * nu
    if condition == PLANE_STRESS:
        return (3.0 - nu) / (1.0 + nu)
    raise ValueError(f"condition must be {PLANE_STRAIN!r} or {PLANE_STRESS!r}, got {condition!r}")


def _extrapolate(u_r1, u_r2, r1, r2):
    _check_positive(r1=r1, r2=r2)
    if r2 <= r1:
        raise ValueError(f"need r2 > r1, got r1={r1}, r2={r2}")
    u_r1 = np.asarray(u_r1, dtype=float)
    u_r2 = np.asarray(u_r2, dtype=float)
    if u_r1.shape != u_r2.shape:
        raise ValueError("displacement series at r1 and r2 must have the same shape")
    if not (np.all(np.isfinite(u_r1)) and np.all(np.isfinite(u_r2))):
        raise ValueError("displacements contain NaN or inf")
    return (u_r1 * r2 / np.sqrt(r1) - u_r2 * r1 / np.sqrt(r2)) / (r2 - r1)


def k_from_face_displacement(u_r1, u_r2, r1, r2, mu, kappa):
    """Eq. 39 with single-face displacements (upper face, theta = pi)."""
    _check_positive(mu=mu, kappa=kappa)
    value = 2.0 * mu * np.sqrt(2.0 * np.pi) / (kappa + 1.0) * _extrapolate(u_r1, u_r2, r1, r2)
    return float(value) if np.ndim(value) == 0 else value


def k_from_face_jump(jump_r1, jump_r2, r1, r2, mu, kappa):
    """Eq. 39 with face jumps: opening u2(+) - u2(-) gives K_I, sliding
    u1(+) - u1(-) gives K_II.  Accepts scalars or time series."""
    _check_positive(mu=mu, kappa=kappa)
    value = (2.0 * mu * np.sqrt(2.0 * np.pi) / ((kappa + 1.0) * FACE_JUMP_FACTOR)
             * _extrapolate(jump_r1, jump_r2, r1, r2))
    return float(value) if np.ndim(value) == 0 else value


def williams_displacement(k_i, k_ii, r, theta, mu, kappa):
    """Leading (sqrt r) term of the near-tip displacement (u1, u2) in the tip
    frame (x1 ahead of the tip, crack on theta = +-pi)."""
    r = np.asarray(r, dtype=float)
    theta = np.asarray(theta, dtype=float)
    amp = np.sqrt(r / (2.0 * np.pi)) / (2.0 * mu)
    c, s = np.cos(theta / 2.0), np.sin(theta / 2.0)
    u1 = amp * (k_i * c * (kappa - 1.0 + 2.0 * s * s)
                + k_ii * s * (kappa + 1.0 + 2.0 * c * c))
    u2 = amp * (k_i * s * (kappa + 1.0 - 2.0 * c * c)
                - k_ii * c * (kappa - 1.0 - 2.0 * s * s))
    return u1, u2

# SPDX-License-Identifier: GPL-2.0-or-later
"""Independent NumPy forms of kernel-weighted bond-based peridynamics: the kernels, c0, s0,
the partial volume, and the grid's dispersion relation.

Written from the paper (Bouaraquia & Mabssout 2026), not from the C++ plugin, so the tests can
compare the two (the bond model itself, forces, energy and damage, is tests/lammps/refmodel.py):

  micromodulus   c(xi) = c0 W(xi/delta)                                 eq. 9
  volume factor  C_v = 1, (delta + dx/2 - xi)/dx, 0                     eq. 19

c0 and s0 are the closed forms of Table 1 and eqs. 14-16 written with the
kernel moments M_n = int_0^1 W(r) r^n dr, which are integrated numerically
here (scipy quadrature), so a wrong closed form on either side shows up:

  1D            c0 = E / (A delta^2 M1)          G_c = A c0 s0^2 delta^3 M2 / 2
  plane stress  c0 = 3 E / (pi h delta^3 M2)     G_c = h c0 s0^2 delta^4 M3
  plane strain  c0 = 16 E / (5 pi h delta^3 M2)  G_c = h c0 s0^2 delta^4 M3
  3D            c0 = 3 E / (pi delta^4 M3)       G_c = pi c0 s0^2 delta^5 M4 / 2
"""

import math

import numpy as np
from scipy import integrate

from bbpd.readers import read_dump, thermo_tables  # noqa: F401  (the tests' names for them)

KERNELS = {
    "constant": lambda r: np.ones_like(np.asarray(r, dtype=float)),
    "triangular": lambda r: np.clip(1.0 - np.asarray(r, dtype=float), 0.0, None),
    "gaussian": lambda r: np.exp(-((2.0 * np.asarray(r, dtype=float)) ** 2)),
}

# Poisson's ratio implied by bond-based PD (paper section 2.1; Silling 2000)
POISSON = {"1d": 0.0, "plane/stress": 1.0 / 3.0, "plane/strain": 0.25, "3d": 0.25}
DIMENSION = {"1d": 1, "plane/stress": 2, "plane/strain": 2, "3d": 3}


def kernel(name):
    """W(r), r = xi/delta in [0, 1]."""
    try:
        return KERNELS[name]
    except KeyError:
        raise ValueError(f"unknown kernel {name!r}; use one of {sorted(KERNELS)}") from None


def moment(name, n):
    """M_n = int_0^1 W(r) r^n dr by adaptive quadrature."""
    w = kernel(name)
    value, _ = integrate.quad(lambda r: float(w(r)) * r**n, 0.0, 1.0, epsabs=0.0, epsrel=1e-13)
    return value


def micromodulus(name, model, E, delta, geom=1.0):
    """c0 from strain-energy equivalence under isotropic expansion; geom = A (1d), h (2D)."""
    if model == "1d":
        return E / (geom * delta**2 * moment(name, 1))
    if model == "plane/stress":
        return 3.0 * E / (math.pi * geom * delta**3 * moment(name, 2))
    if model == "plane/strain":
        return 16.0 * E / (5.0 * math.pi * geom * delta**3 * moment(name, 2))
    if model == "3d":
        return 3.0 * E / (math.pi * delta**4 * moment(name, 3))
    raise ValueError(f"unknown model {model!r}")


def critical_stretch(name, model, c0, Gc, delta, geom=1.0):
    """s0 such that breaking every bond across a unit crack area costs G_c."""
    if model == "1d":
        return math.sqrt(2.0 * Gc / (geom * c0 * delta**3 * moment(name, 2)))
    if model in ("plane/stress", "plane/strain"):
        return math.sqrt(Gc / (geom * c0 * delta**4 * moment(name, 3)))
    if model == "3d":
        return math.sqrt(2.0 * Gc / (math.pi * c0 * delta**5 * moment(name, 4)))
    raise ValueError(f"unknown model {model!r}")


def partial_volume(xi, delta, dx):
    """C_v of eq. 19, vectorised over xi."""
    xi = np.asarray(xi, dtype=float)
    cv = np.clip((delta + 0.5 * dx - xi) / dx, 0.0, 1.0)
    return np.where(xi <= delta - 0.5 * dx, 1.0, cv)


def grid_family(m, dim=2):
    """The bond vectors of one atom's family on a square (dim 2) or cubic (dim 3) grid of unit
    spacing with horizon m (|xi| < m + 1/2, as the pair styles build it), N x 3."""
    n = int(math.ceil(m + 0.5))
    axes = [np.arange(-n, n + 1)] * dim + [np.zeros(1)] * (3 - dim)
    g = np.stack([a.ravel() for a in np.meshgrid(*axes, indexing="ij")], axis=1).astype(float)
    r = np.linalg.norm(g, axis=1)
    return g[(r > 0.0) & (r < m + 0.5)]


def dynamic_matrix(name, model, E, m, dx, k):
    """rho omega^2 of the plane waves u = U exp(i k.x) on the unbounded grid: the eigenvalues of
    D(k) = sum_j c(xi) C_v V_j / |xi| (1 - cos k.xi) e e^T (e = xi/|xi|), the linearised force
    density of the bonds (eqs. 20-21) summed over the family exactly as the pair style builds
    it (3 x 3; k a 3-vector in 1/m). In 2D c0 V_j does not depend on the thickness."""
    dim = DIMENSION[model]
    delta = m * dx
    xi_vec = grid_family(m, dim) * dx
    xi = np.linalg.norm(xi_vec, axis=1)
    e = xi_vec / xi[:, None]
    c = micromodulus(name, model, E, delta) * kernel(name)(xi / delta)
    weight = c * partial_volume(xi, delta, dx) * dx**dim / xi
    # 1 - cos x written as 2 sin^2(x/2): no cancellation at long wavelengths
    phase = 2.0 * np.sin(0.5 * (xi_vec @ np.asarray(k, dtype=float))) ** 2
    return np.einsum("b,bp,bq->pq", weight * phase, e, e)


# a wavelength this many horizons long is in the long-wave limit to round-off (k delta ~ 1e-3)
LONG_WAVE_HORIZONS = 6.0e3


def grid_wave_speeds(name, model, E, rho, m, dx, direction=(1.0, 0.0, 0.0),
                     wavelength=None):
    """Phase speeds (c_d, c_s) of the longitudinal and in-plane transverse waves travelling
    along direction on the grid (wavelength in m; default: the long-wave limit). They differ
    from the continuum's where the lattice sum differs from the horizon integral (the
    calibration tests' table) and by the grid's anisotropy."""
    n = np.asarray(direction, dtype=float)
    n = n / np.linalg.norm(n)
    lam = LONG_WAVE_HORIZONS * m * dx if wavelength is None else wavelength
    kk = 2.0 * math.pi / lam
    d = dynamic_matrix(name, model, E, m, dx, kk * n)
    t = np.array([-n[1], n[0], 0.0])    # in-plane transverse polarisation
    return (math.sqrt(float(n @ d @ n) / rho) / kk, math.sqrt(float(t @ d @ t) / rho) / kk)


def lame_moduli(model, E, nu):
    """(lambda, G) of linear elasticity at any Poisson ratio nu; plane stress takes the
    in-plane lambda' = E nu / (1 - nu^2), plane strain and 3d the classical lambda."""
    G = E / (2.0 * (1.0 + nu))
    if model == "plane/stress":
        return E * nu / (1.0 - nu**2), G
    return E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), G


def classical_energy_density(model, E, strain):
    """Strain-energy density of linear elasticity with the model's Poisson ratio.

    plane/stress: eq. 13 with the in-plane 2x2 strain; plane/strain (2x2
    strain, epsilon_33 = 0) and 3d (3x3): W = lambda/2 (tr eps)^2 + mu eps:eps.
    """
    eps = np.asarray(strain, dtype=float)
    nu = POISSON[model]
    if model == "plane/stress":
        e11, e22, e12 = eps[0, 0], eps[1, 1], eps[0, 1]
        return E / (2.0 * (1.0 - nu**2)) * (e11**2 + e22**2 + 2.0 * nu * e11 * e22
                                             + 2.0 * (1.0 - nu) * e12**2)
    lam, mu = lame_moduli(model, E, nu)
    return 0.5 * lam * np.trace(eps) ** 2 + mu * np.sum(eps * eps)

# SPDX-License-Identifier: GPL-2.0-or-later
"""Independent NumPy implementation of kernel-weighted bond-based peridynamics.

Written from the paper (Bouaraquia & Mabssout 2026), not from the C++ plugin,
so the LAMMPS-level tests can compare the two:

  micromodulus   c(xi) = c0 W(xi/delta)                                 eq. 9
  stretch        s = (|y_j - y_i| - xi) / xi                            eq. 22
  force density  f_i = sum_j c s C_v V_j (y_j - y_i)/|y_j - y_i|        eqs. 20-21
  energy density W_i = 1/2 sum_j (1/2 c s^2 xi) C_v V_j                 eqs. 6, 12
  volume factor  C_v = 1, (delta + dx/2 - xi)/dx, 0                     eq. 19

c0 and s0 are the closed forms of Table 1 and eqs. 14-16 written with the
kernel moments M_n = int_0^1 W(r) r^n dr, which are integrated numerically
here (scipy quadrature), so a wrong closed form on either side shows up:

  1D            c0 = E / (A delta^2 M1)          G_c = A c0 s0^2 delta^3 M2 / 2
  plane stress  c0 = 3 E / (pi h delta^3 M2)     G_c = h c0 s0^2 delta^4 M3
  plane strain  c0 = 16 E / (5 pi h delta^3 M2)  G_c = h c0 s0^2 delta^4 M3
  3D            c0 = 3 E / (pi delta^4 M3)       G_c = pi c0 s0^2 delta^5 M4 / 2

A bond family holds every pair with reference distance < delta + dx/2.
"""

import math

import numpy as np
from scipy import integrate
from scipy.spatial import cKDTree

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
    lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    mu = E / (2.0 * (1.0 + nu))
    return 0.5 * lam * np.trace(eps) ** 2 + mu * np.sum(eps * eps)


class Bonds:
    """Bond families of a set of reference positions x0 (N x 3).

    Pairs are stored once (i < j); broken bonds are kept with intact = False.
    No periodic images: the tests use free surfaces.
    """

    def __init__(self, x0, volume, kernel_name, c0, delta, dx):
        self.x0 = np.asarray(x0, dtype=float)
        self.volume = np.broadcast_to(np.asarray(volume, dtype=float), (len(self.x0),)).copy()
        rcut = delta + 0.5 * dx
        pairs = cKDTree(self.x0).query_pairs(rcut, output_type="ndarray")
        xi = np.linalg.norm(self.x0[pairs[:, 1]] - self.x0[pairs[:, 0]], axis=1)
        keep = xi < rcut    # family: strictly inside delta + dx/2
        self.i, self.j = pairs[keep, 0], pairs[keep, 1]
        self.xi = xi[keep]
        self.cv = partial_volume(self.xi, delta, dx)
        self.c = c0 * kernel(kernel_name)(self.xi / delta)
        self.intact = np.ones(len(self.i), dtype=bool)

    def crossing(self, crosses):
        """Mask of the bonds for which crosses(xa, xb) holds at the reference positions."""
        return crosses(self.x0[self.i], self.x0[self.j])

    def cut(self, crosses):
        """Break every bond crossing a notch (see segment_crossing); returns how many."""
        hit = self.crossing(crosses)
        self.intact &= ~hit
        return int(np.count_nonzero(hit))

    def stretch(self, y):
        y = np.asarray(y, dtype=float)
        d = y[self.j] - y[self.i]
        r = np.sqrt(d[:, 0] * d[:, 0] + d[:, 1] * d[:, 1] + d[:, 2] * d[:, 2])
        return d, r, (r - self.xi) / self.xi

    def force_density(self, y):
        """f_i = sum_j c s C_v V_j e_ij over intact bonds (N x 3)."""
        d, r, s = self.stretch(y)
        n = len(self.x0)
        f = np.zeros((n, 3))
        a = self.intact
        # force on i from j, per unit volume of i: c s C_v V_j (y_j - y_i)/r; on j: the opposite
        g = self.c[a] * s[a] * self.cv[a] / r[a]
        gi = (g * self.volume[self.j[a]])[:, None] * d[a]
        gj = (g * self.volume[self.i[a]])[:, None] * d[a]
        for k in range(3):
            f[:, k] += np.bincount(self.i[a], gi[:, k], minlength=n)
            f[:, k] -= np.bincount(self.j[a], gj[:, k], minlength=n)
        return f

    def virial_density(self, y):
        """Per-atom virial W_i = 1/2 sum_j (y_i - y_j) (x) f_ij (N x 6: xx yy zz xy xz yz),
        the half of each bond's virial that LAMMPS tallies on atom i (per unit volume of i)."""
        d, r, s = self.stretch(y)
        n = len(self.x0)
        a = self.intact
        g = self.c[a] * s[a] * self.cv[a] / r[a]
        w = np.zeros((n, 6))
        for col, (p, q) in enumerate(((0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2))):
            dd = -0.5 * g * d[a, p] * d[a, q]    # (y_i - y_j)_p (f_i)_q with f_i = g V_j d
            w[:, col] += np.bincount(self.i[a], dd * self.volume[self.j[a]], minlength=n)
            w[:, col] += np.bincount(self.j[a], dd * self.volume[self.i[a]], minlength=n)
        return w

    def energy_density(self, y):
        """W_i = 1/2 sum_j (1/2 c s^2 xi) C_v V_j over intact bonds (per unit volume of i)."""
        _, _, s = self.stretch(y)
        n = len(self.x0)
        a = self.intact
        w = 0.25 * self.c[a] * s[a] ** 2 * self.xi[a] * self.cv[a]
        return (np.bincount(self.i[a], w * self.volume[self.j[a]], minlength=n)
                + np.bincount(self.j[a], w * self.volume[self.i[a]], minlength=n))

    def damage(self):
        """phi_i = 1 - sum_intact C_v V_j / sum_all C_v V_j over the family of i (eq. 17)."""
        n = len(self.x0)
        w_i = self.cv * self.volume[self.j]    # bond weight seen from end i
        w_j = self.cv * self.volume[self.i]    # and from end j
        a = self.intact
        total = np.bincount(self.i, w_i, minlength=n) + np.bincount(self.j, w_j, minlength=n)
        intact = (np.bincount(self.i[a], w_i[a], minlength=n)
                  + np.bincount(self.j[a], w_j[a], minlength=n))
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(total > 0.0, 1.0 - intact / total, 0.0)

    def breaking_energy(self, s0, mask=None):
        """sum over bonds (in mask) of the work to break them: 1/2 c s0^2 xi C_v V_i V_j."""
        m = self.intact if mask is None else (self.intact & mask)
        return float(np.sum(0.5 * self.c[m] * s0**2 * self.xi[m] * self.cv[m]
                            * self.volume[self.i[m]] * self.volume[self.j[m]]))


def segment_crossing(p1, p2):
    """crosses(xa, xb) for a 2D notch segment p1-p2.

    The bond crosses when its ends lie on opposite sides of the segment's line,
    an end exactly on the line counting as the side of the normal (-a_y, a_x),
    a = p2 - p1, and the intersection lies on the segment (ends included).
    """
    p1 = np.asarray(p1, dtype=float)
    a = np.asarray(p2, dtype=float) - p1
    n = np.array([-a[1], a[0]])

    def crosses(xa, xb):
        sa = (xa[:, :2] - p1) @ n
        sb = (xb[:, :2] - p1) @ n
        opposite = (sa >= 0.0) != (sb >= 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            u = np.where(opposite, sa / (sa - sb), 0.0)
        hit = xa[:, :2] + u[:, None] * (xb[:, :2] - xa[:, :2]) - p1
        t = hit @ a / (a @ a)
        return opposite & (t >= 0.0) & (t <= 1.0)

    return crosses


def rectangle_crossing(corner, ea, eb):
    """crosses(xa, xb) for a 3D notch rectangle corner + t ea + w eb, t, w in [0, 1].

    Same side rule as segment_crossing with the normal ea x eb.
    """
    p = np.asarray(corner, dtype=float)
    ea = np.asarray(ea, dtype=float)
    eb = np.asarray(eb, dtype=float)
    n = np.cross(ea, eb)
    gram = np.array([[ea @ ea, ea @ eb], [ea @ eb, eb @ eb]])

    def crosses(xa, xb):
        sa = (xa - p) @ n
        sb = (xb - p) @ n
        opposite = (sa >= 0.0) != (sb >= 0.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            u = np.where(opposite, sa / (sa - sb), 0.0)
        hit = xa + u[:, None] * (xb - xa) - p
        tw = np.linalg.solve(gram, np.stack([hit @ ea, hit @ eb]))
        t, w = tw[0], tw[1]
        return opposite & (t >= 0) & (t <= 1) & (w >= 0) & (w <= 1)

    return crosses


# ---------------------------------------------------------------------------
# lattices and LAMMPS text files, so a test can feed LAMMPS exactly the
# positions the reference uses (%.17g round-trips a double)

def square_lattice(shape, dx, origin=(0.0, 0.0, 0.0)):
    """Points of a simple square (2 entries in shape) or cubic (3) lattice, N x 3, id order."""
    axes = [origin[k] + dx * np.arange(n) for k, n in enumerate(shape)]
    grids = np.meshgrid(*axes, indexing="ij")
    x = np.zeros((grids[0].size, 3))
    for k, g in enumerate(grids):
        x[:, k] = g.ravel()
    return x


def write_data(path, x, volume, density, box, types=None):
    """LAMMPS data file for atom_style peri, ids 1..N; box = [(lo, hi)] * 3.

    volume: one value or one per atom; types default to 1.
    """
    types = np.ones(len(x), dtype=int) if types is None else np.asarray(types, dtype=int)
    volume = np.broadcast_to(np.asarray(volume, dtype=float), (len(x),))
    lines = ["BBPD reference lattice", "", f"{len(x)} atoms", f"{types.max()} atom types", ""]
    for (lo, hi), ax in zip(box, "xyz"):
        lines.append(f"{lo:.17g} {hi:.17g} {ax}lo {ax}hi")
    lines += ["", "Atoms # peri", ""]
    lines += [f"{k + 1} {t} {v:.17g} {density:.17g} {p[0]:.17g} {p[1]:.17g} {p[2]:.17g}"
              for k, (t, v, p) in enumerate(zip(types, volume, x))]
    path.write_text("\n".join(lines) + "\n")


def write_positions(path, x, box, step=0):
    """Dump-format file 'id x y z' for 'read_dump FILE step x y z box no replace yes'."""
    lines = ["ITEM: TIMESTEP", str(step), "ITEM: NUMBER OF ATOMS", str(len(x)),
             "ITEM: BOX BOUNDS ff ff ff"]
    lines += [f"{lo:.17g} {hi:.17g}" for lo, hi in box]
    lines.append("ITEM: ATOMS id x y z")
    lines += [f"{k + 1} {p[0]:.17g} {p[1]:.17g} {p[2]:.17g}" for k, p in enumerate(x)]
    path.write_text("\n".join(lines) + "\n")

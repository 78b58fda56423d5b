"""The reference bond model the LAMMPS tests hold the plugin against, and the files that give
LAMMPS exactly the positions it uses (%.17g round-trips a double). Written from the paper, not
from the C++ plugin (bbpd.reference has the kernels, c0, s0 and C_v it builds on):

  stretch        s = (|y_j - y_i| - xi) / xi                            eq. 22
  force density  f_i = sum_j c s C_v V_j (y_j - y_i)/|y_j - y_i|        eqs. 20-21
  energy density W_i = 1/2 sum_j (1/2 c s^2 xi) C_v V_j                 eqs. 6, 12

A bond family holds every pair with reference distance < delta + dx/2. Imported by name
(pytest.ini puts tests/lammps on the path): `import refmodel`.
"""
import numpy as np
from scipy.spatial import cKDTree

from bbpd.reference import kernel, partial_volume


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

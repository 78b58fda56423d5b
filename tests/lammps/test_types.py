"""Several materials in one body: pair_coeff per type pair (E, G_c or s0, horizon).

The NumPy reference (python/bbpd/reference.py) is extended here to type pairs: every bond
takes c0, horizon (family cutoff, W(xi/delta), C_v) and s0 of the pair of its end types, from
the reference formulas. Checked: forces and energies of a perturbed two-type lattice, the
critical stretch of each type pair (a uniform stretch breaks exactly the bonds whose stretch
passes their pair's s0), momentum over a dynamic run with two densities and breaking bonds.
"""
import numpy as np

from bbpd import reference as ref
import refmodel
from scenes import assert_forces_match, peri_preamble

DX = 1.0e-3
THICKNESS = 1.0e-3
VOLUME = THICKNESS * DX**2
SEED = 20261201
FORCE_RTOL = 1.0e-12    # of the largest force: summation order only
MODEL = "plane/strain"
KERNEL = "gaussian"

# type pair -> (E, horizon in dx, s0); no lattice distance sits on a C_v breakpoint
# (delta +- dx/2 avoids 1, sqrt 2, 2, sqrt 5, sqrt 8, 3, sqrt 10, sqrt 13)
MATERIALS = {(1, 1): (190.0e9, 3.05, 0.020),
             (2, 2): (70.0e9, 2.55, 0.030),
             (1, 2): (120.0e9, 2.80, 0.015)}
DENSITY = {1: 7800.0, 2: 2700.0}


def pair_of(ti, tj):
    return (min(ti, tj), max(ti, tj))


def gc_for(E, delta, s0):
    """G_c that gives critical stretch s0 (reference closed form, so s0 comes back exactly
    up to round-off; the test compares s0 through its effect, not its digits)."""
    c0 = ref.micromodulus(KERNEL, MODEL, E, delta, THICKNESS)
    per_gc = ref.critical_stretch(KERNEL, MODEL, c0, 1.0, delta, THICKNESS) ** 2
    return s0**2 / per_gc


class TypedBonds(refmodel.Bonds):
    """refmodel.Bonds with per-type-pair c0, horizon and s0."""

    def __init__(self, x0, types, volume):
        deltas = {p: m * DX for p, (_, m, _) in MATERIALS.items()}
        super().__init__(x0, volume, KERNEL, 1.0, max(deltas.values()), DX)
        ti, tj = types[self.i], types[self.j]
        lo, hi = np.minimum(ti, tj), np.maximum(ti, tj)
        delta = np.zeros(len(self.i))
        c0 = np.zeros(len(self.i))
        s0 = np.zeros(len(self.i))
        for (a, b), (E, m, s) in MATERIALS.items():
            sel = (lo == a) & (hi == b)
            delta[sel] = m * DX
            c0[sel] = ref.micromodulus(KERNEL, MODEL, E, m * DX, THICKNESS)
            s0[sel] = s
        keep = self.xi < delta + 0.5 * DX    # each pair's own family cutoff
        for name in ("i", "j", "xi", "intact"):
            setattr(self, name, getattr(self, name)[keep])
        delta, c0, s0 = delta[keep], c0[keep], s0[keep]
        self.cv = ref.partial_volume(self.xi, delta, DX)
        self.c = c0 * ref.kernel(KERNEL)(self.xi / delta)
        self.s0 = s0
        self.mixed = types[self.i] != types[self.j]


def two_type_lattice():
    """14 x 12 lattice, left half type 1, right half type 2 (an interface of mixed bonds)."""
    x0 = refmodel.square_lattice((14, 12), DX)
    types = np.where(x0[:, 0] < 6.5 * DX, 1, 2)
    pad = 5 * DX
    box = [(x0[:, 0].min() - pad, x0[:, 0].max() + pad),
           (x0[:, 1].min() - pad, x0[:, 1].max() + pad), (-0.5 * DX, 0.5 * DX)]
    return x0, types, box


def header(datafile, stretch=None):
    """Input lines up to pair_coeff; stretch: type pair -> s0 given by critical_stretch."""
    lines = [peri_preamble(2, data=datafile).rstrip("\n"),
             f"pair_style bbpd/{KERNEL} {MODEL} thickness {THICKNESS!r}"]
    for (a, b), (E, m, s0) in MATERIALS.items():
        gc = gc_for(E, m * DX, s0)
        tail = f" critical_stretch {stretch[(a, b)]!r}" if stretch else ""
        lines.append(f"pair_coeff {a} {b} {E!r} {gc!r} {m * DX!r}{tail}")
    return "\n".join(lines) + "\n"


def write_data(path, x0, types, volume, box):
    """Data file with per-type densities (refmodel.write_data has one density)."""
    volume = np.broadcast_to(np.asarray(volume, dtype=float), (len(x0),))
    lines = ["BBPD two-type lattice", "", f"{len(x0)} atoms", "2 atom types", ""]
    lines += [f"{lo!r} {hi!r} {a}lo {a}hi" for (lo, hi), a in zip(box, "xyz")]
    lines += ["", "Atoms # peri", ""]
    lines += [f"{k + 1} {t} {v!r} {DENSITY[t]!r} {p[0]!r} {p[1]!r} {p[2]!r}"
              for k, (t, v, p) in enumerate(zip(types, volume, x0))]
    path.write_text("\n".join(lines) + "\n")


def test_two_types_forces_match_reference(lmp, tmp_path):
    """Forces and energy of a perturbed two-type lattice: each bond uses the c0, horizon and
    C_v of its own type pair (a mixed bond with the c0 or horizon of one end type fails)."""
    rng = np.random.default_rng(SEED)
    x0, types, box = two_type_lattice()
    y = x0 + 1.0e-3 * DX * rng.uniform(-1.0, 1.0, x0.shape)
    y[:, 2] = 0.0
    write_data(tmp_path / "body.data", x0, types, VOLUME, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    bonds = TypedBonds(x0, types, VOLUME)
    assert np.count_nonzero(bonds.mixed) > 100
    script = (header("body.data")
              + "compute pea all pe/atom\n"
              "thermo_style custom step pe\nthermo_modify format float %.17g\n"
              "run 0\n"
              "read_dump current.dump 0 x y box no replace yes\n"
              "run 0\n"
              "write_dump all custom forces.dump id fx fy fz c_pea modify format float %.17g\n")
    out = lmp(script).output
    assert f"total bonds {len(bonds.i)} (0 broken)" in out
    assert_forces_match(tmp_path / "forces.dump", bonds, y, FORCE_RTOL)


STRAIN = 0.0175    # between s0 of the mixed pair (0.015) and of type 1 (0.020)


def test_each_type_pair_breaks_at_its_own_critical_stretch(lmp, tmp_path):
    """A uniform strain e_xx = 0.0175 breaks the bonds whose stretch passes their own pair's
    s0: mixed bonds (s0 = 0.015) along x break, type-1 (0.020) and type-2 (0.030) bonds do not
    break at all. The damage of every atom is eq. 17 of the bonds the reference breaks."""
    x0, types, box = two_type_lattice()
    y = x0.copy()
    y[:, 0] *= 1.0 + STRAIN
    write_data(tmp_path / "body.data", x0, types, VOLUME, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    bonds = TypedBonds(x0, types, VOLUME)
    _, _, s = bonds.stretch(y)
    breaks = s > bonds.s0
    assert np.min(np.abs(s - bonds.s0)) > 1e-6    # no bond near its threshold
    assert np.count_nonzero(breaks) > 20 and np.all(bonds.mixed[breaks])
    assert np.any(s[~bonds.mixed] > 0.015)    # same-type bonds that a wrong s0 would break
    script = (header("body.data")
              + "compute d all bbpd/damage/atom\n"
              "run 0\n"
              "read_dump current.dump 0 x y box no replace yes\n"
              "run 0\n"
              "write_dump all custom damage.dump id c_d modify format float %.17g\n"
              "run 0\n")
    out = lmp(script).output
    assert f"total bonds {len(bonds.i)} ({np.count_nonzero(breaks)} broken)" in out
    bonds.intact &= ~breaks
    got = ref.read_dump(tmp_path / "damage.dump")
    np.testing.assert_allclose(got["c_d"], bonds.damage(), rtol=0, atol=1e-14)


STEPS = 100
RUN_STRETCH = {(1, 1): 0.002, (2, 2): 0.003, (1, 2): 0.0015}    # low, so bonds break
MOMENTUM_RTOL = 1.0e-12


def test_two_types_conserve_momentum(lmp, tmp_path):
    """sum_i rho_i V_i v_i is constant over a run of two types (densities 7800 and 2700,
    unequal volumes, random velocities, s0 per type pair) while bonds break."""
    rng = np.random.default_rng(SEED + 1)
    x0, types, box = two_type_lattice()
    volume = VOLUME * rng.uniform(0.9, 1.1, len(x0))
    write_data(tmp_path / "body.data", x0, types, volume, box)
    v = 20.0 * rng.uniform(-1.0, 1.0, x0.shape)    # m/s: bonds break within 100 steps
    for k, a in enumerate("xy"):
        (tmp_path / f"v{a}.txt").write_text(
            f"{len(x0)}\n" + "".join(f"{i + 1} {v[i, k]!r}\n" for i in range(len(x0))))
    script = (header("body.data", RUN_STRETCH)
              + "".join(f"variable v{a} atomfile v{a}.txt\nset group all v{a} v_v{a}\n"
                        for a in "xy")
              + "fix nve all nve\nfix 2d all enforce2d\n"
              "compute vol all property/atom vfrac\n"
              "compute damage all bbpd/damage/atom\ncompute dsum all reduce sum c_damage\n"
              + "".join(f"variable p{a} atom c_vol*mass*v{a}\n"
                        f"variable a{a} atom abs(c_vol*mass*v{a})\n" for a in "xy")
              + "compute p all reduce sum v_px v_py\ncompute pabs all reduce sum v_ax v_ay\n"
              "compute dtb all pair bbpd/gaussian\n"
              "run 0\n"
              "variable dt equal 0.5*c_dtb[1]\ntimestep ${dt}\n"
              "thermo_style custom step c_p[1] c_p[2] c_pabs[1] c_pabs[2] c_dsum\n"
              f"thermo_modify format float %.17g\nthermo 10\nrun {STEPS}\n")
    out = lmp(script).output
    for s0 in RUN_STRETCH.values():
        assert f"critical_stretch s0 = {s0:g} (given)" in out
    table = ref.thermo_tables(out)[-1]
    assert len(table["Step"]) == STEPS // 10 + 1
    assert table["c_dsum"][-1] > table["c_dsum"][0], "no bond broke: raise the velocities"
    scale = max(table["c_pabs[1]"][0], table["c_pabs[2]"][0])
    for k in (1, 2):
        p = table[f"c_p[{k}]"]
        drift = np.abs(p - p[0]).max()
        assert drift < MOMENTUM_RTOL * scale, f"momentum {k} drifts by {drift:.3g} of {scale:.3g}"

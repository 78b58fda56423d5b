"""Forces and energies of the bbpd/* pair styles against an independent NumPy
implementation (python/bbpd/reference.py), and momentum conservation.

The reference positions are a lattice written to a data file with %.17g, so
LAMMPS and NumPy start from the same doubles; the current positions (lattice
plus a random perturbation of 1e-3 dx) are read with read_dump. Bonds at the
horizon get partial volumes (eq. 19) and notches pre-break some bonds; the
reference breaks the bonds crossing the same segments/rectangles.
"""
import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from scenes import assert_forces_match, peri_preamble

KERNELS = ("constant", "triangular", "gaussian")
MODELS = ("plane/stress", "plane/strain", "3d")
DX = 1.0e-3
THICKNESS = 1.0e-3
YOUNGS = 200.0e9
DENSITY = 8000.0
HORIZON_RATIO = 3.05    # m = delta/dx: no lattice distance sits on a C_v breakpoint
PERTURBATION = 1.0e-3    # of dx: bond stretches below 4e-3
CRITICAL_STRETCH = 0.02    # G_c is chosen to give this s0, so no bond breaks under the perturbation
FORCE_RTOL = 1.0e-12    # of the largest force: different summation order only
SEED = 20260704


def lattice_shape(dim):
    return (12, 12) if dim == 2 else (7, 7, 7)


def notches(dim):
    """Notch commands and the reference's crossing tests; the cuts avoid atom rows."""
    if dim == 2:
        segs = [((-1.0 * DX, 5.5 * DX), (5.3 * DX, 5.5 * DX)),    # edge crack between rows
                ((7.2 * DX, 2.3 * DX), (9.7 * DX, 8.1 * DX))]      # inclined interior crack
        cmd = " ".join(f"segment {a[0]!r} {a[1]!r} {b[0]!r} {b[1]!r}" for a, b in segs)
        return cmd, [refmodel.segment_crossing(a, b) for a, b in segs]
    rects = [((-1.0 * DX, -1.0 * DX, 3.5 * DX), (4.3 * DX, 0.0, 0.0), (0.0, 8.0 * DX, 0.0)),
             ((4.6 * DX, 1.2 * DX, 0.3 * DX), (0.0, 3.1 * DX, 1.7 * DX),
              (0.0, -1.4 * DX, 4.2 * DX))]
    cmd = " ".join("rectangle " + " ".join(repr(v) for v in (*c, *a, *b)) for c, a, b in rects)
    return cmd, [refmodel.rectangle_crossing(c, a, b) for c, a, b in rects]


def material(kernel, model):
    """Horizon, c0 and a G_c that gives CRITICAL_STRETCH, from the reference formulas."""
    dim = ref.DIMENSION[model]
    delta = HORIZON_RATIO * DX
    geom = THICKNESS if dim == 2 else 1.0
    c0 = ref.micromodulus(kernel, model, YOUNGS, delta, geom)
    gc_unit = ref.critical_stretch(kernel, model, c0, 1.0, delta, geom) ** 2    # s0^2 per unit G_c
    return delta, c0, CRITICAL_STRETCH**2 / gc_unit


def header(kernel, model, datafile, gc, delta, extra=""):
    dim = ref.DIMENSION[model]
    thick = f" thickness {THICKNESS!r}" if dim == 2 else ""
    return (peri_preamble(dim, data=datafile, plugin=False) +
            f"pair_style bbpd/{kernel} {model}{thick}\n"
            f"pair_coeff * * {YOUNGS!r} {gc!r} {delta!r}{extra}\n")


def lattice_body(dim):
    """Lattice positions and a box with room around them."""
    x0 = refmodel.square_lattice(lattice_shape(dim), DX)
    pad = 5 * DX
    box = [(x0[:, k].min() - pad, x0[:, k].max() + pad) for k in range(3)]
    if dim == 2:
        box[2] = (-0.5 * DX, 0.5 * DX)
    return x0, box


# every kernel and model serially, and one case split over 2 MPI ranks (ghost partners,
# notch cuts decided per rank)
FORCE_CASES = [(k, m, 1) for k in KERNELS for m in MODELS] + [("gaussian", "plane/stress", 2)]


@pytest.mark.parametrize("model", ["plane/strain", "3d"])
def test_virial_matches_reference(lmp, tmp_path, model):
    """Per-atom virial (compute stress/atom ... virial = -W_i) against the reference, under a
    uniform stretch: the stress must be tensile (positive) in the stretched direction."""
    dim = ref.DIMENSION[model]
    x0, box = lattice_body(dim)
    y = x0.copy()
    y[:, 0] *= 1.0 + 1.0e-4
    volume = THICKNESS * DX**2 if dim == 2 else DX**3
    delta, c0, _ = material("gaussian", model)
    refmodel.write_data(tmp_path / "body.data", x0, volume, DENSITY, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    coords = "x y z" if dim == 3 else "x y"
    script = ("plugin load bbpdplugin.so\n" + header("gaussian", model, "body.data", "none", delta)
              + "compute s all stress/atom NULL virial\n"
              "run 0\n"
              f"read_dump current.dump 0 {coords} box no replace yes\n"
              "run 0\n"
              "write_dump all custom virial.dump id c_s[1] c_s[2] c_s[3] c_s[4] c_s[5] c_s[6] "
              "modify format float %.17g\n")
    lmp(script)
    got = ref.read_dump(tmp_path / "virial.dump")
    stress = np.stack([got[f"c_s[{k}]"] for k in range(1, 7)], axis=1)
    bonds = refmodel.Bonds(x0, volume, "gaussian", c0, delta, DX)
    expected = -bonds.virial_density(y)
    scale = np.abs(expected).max()
    assert np.abs(stress - expected).max() < FORCE_RTOL * scale
    assert stress[:, 0].min() > 0.0    # tension


@pytest.mark.parametrize("kernel,model,nprocs", FORCE_CASES)
def test_forces_match_reference(lmp, tmp_path, kernel, model, nprocs):
    dim = ref.DIMENSION[model]
    rng = np.random.default_rng(SEED)
    x0, box = lattice_body(dim)
    y = x0 + PERTURBATION * DX * rng.uniform(-1.0, 1.0, x0.shape)
    if dim == 2:
        y[:, 2] = 0.0
    volume = THICKNESS * DX**2 if dim == 2 else DX**3
    delta, c0, gc = material(kernel, model)
    refmodel.write_data(tmp_path / "body.data", x0, volume, DENSITY, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    notch_cmd, crossings = notches(dim)

    bonds = refmodel.Bonds(x0, volume, kernel, c0, delta, DX)
    ncut = sum(bonds.cut(c) for c in crossings)
    partial = np.count_nonzero(bonds.cv < 1.0)
    assert ncut > 50 and partial > 50    # the test exercises notches and partial volumes

    coords = "x y z" if dim == 3 else "x y"
    script = ("plugin load bbpdplugin.so\n" + header(kernel, model, "body.data", gc, delta)
              + f"fix notch all bbpd/notch {notch_cmd}\n"
              "compute pea all pe/atom\n"
              "thermo_style custom step pe\nthermo_modify format float %.17g\n"
              "run 0\n"
              f"read_dump current.dump 0 {coords} box no replace yes\n"
              "run 0\n"
              "write_dump all custom forces.dump id x y z fx fy fz c_pea "
              "modify format float %.17g\n"
              "run 0\n")    # a third setup reports the bond count after the forces were computed
    out = lmp(script, nprocs=nprocs).output

    assert f"{ncut} bonds cut by 2 notches" in out
    # no bond broke under the perturbation: only the notched ones are broken
    assert out.count(f"total bonds {len(bonds.i)} ({ncut} broken)") == 3

    got, w_ref = assert_forces_match(tmp_path / "forces.dump", bonds, y, FORCE_RTOL)
    np.testing.assert_array_equal(np.stack([got["x"], got["y"], got["z"]], axis=1), y)
    pe = ref.thermo_tables(out)[1]["PotEng"][-1]
    assert pe == pytest.approx(w_ref.sum(), rel=FORCE_RTOL)


def test_notch_cuts_bonds_across_periodic_boundary(lmp, tmp_path):
    """A notch next to a periodic boundary also cuts the bonds that wrap around it."""
    nx, ny = 12, 10
    length = nx * DX
    x0 = refmodel.square_lattice((nx, ny), DX, origin=(0.5 * DX, 0.5 * DX, 0.0))
    box = [(0.0, length), (-DX, (ny + 1) * DX), (-0.5 * DX, 0.5 * DX)]
    refmodel.write_data(tmp_path / "strip.data", x0, THICKNESS * DX**2, DENSITY, box)
    line_y = 0.5 * ny * DX    # between two rows
    a, b = (length - 1.3 * DX, line_y), (length - 0.2 * DX, line_y)
    delta, _, gc = material("constant", "plane/stress")
    periodic_x = header("constant", "plane/stress", "strip.data", gc, delta).replace(
        "boundary s s p", "boundary p s p")
    out = lmp("plugin load bbpdplugin.so\n" + periodic_x
              + f"fix notch all bbpd/notch segment {a[0]!r} {a[1]!r} {b[0]!r} {b[1]!r}\n"
              "run 0\n").output
    # reference: minimum-image bonds; one crosses if either of its two images does
    i, j = np.triu_indices(len(x0), 1)
    d = x0[j] - x0[i]
    d[:, 0] -= length * np.round(d[:, 0] / length)
    family = np.linalg.norm(d, axis=1) < delta + 0.5 * DX
    i, j, d = i[family], j[family], d[family]
    crosses = refmodel.segment_crossing(a, b)
    ncut = np.count_nonzero(crosses(x0[i], x0[i] + d) | crosses(x0[j] - d, x0[j]))
    assert f" {ncut} bonds cut by 1 notch" in out


# ---------------------------------------------------------------------------

STEPS = 100
VELOCITY = 5.0    # m/s, uniform random per component: breaks bonds within 100 steps
MOMENTUM_STRETCH = 2.0e-3    # critical stretch of this run, low so bonds break
DT_FRACTION = 0.5    # of the stable (velocity-Verlet) time step
MOMENTUM_RTOL = 1.0e-12    # of sum_i |m_i v_i|: round-off of 100 velocity updates


@pytest.mark.parametrize("kernel,model,nprocs", [("gaussian", "plane/stress", 2),
                                                  ("constant", "3d", 1)])
def test_momentum_conserved(lmp, tmp_path, kernel, model, nprocs):
    """sum_i rho V_i v_i is constant over a dynamic run with random velocities,
    unequal volumes (so V_i f_ij = -V_j f_ji is what is tested) and breaking bonds."""
    dim = ref.DIMENSION[model]
    rng = np.random.default_rng(SEED + 1)
    x0, box = lattice_body(dim)
    delta, c0, gc = material(kernel, model)
    vol0 = THICKNESS * DX**2 if dim == 2 else DX**3
    volume = vol0 * rng.uniform(0.9, 1.1, len(x0))
    refmodel.write_data(tmp_path / "body.data", x0, volume, DENSITY, box)
    v = VELOCITY * rng.uniform(-1.0, 1.0, x0.shape)
    for k, a in enumerate("xyz"):    # an atomfile variable holds one column
        (tmp_path / f"v{a}.txt").write_text(
            f"{len(x0)}\n" + "\n".join(f"{i + 1} {v[i, k]!r}" for i in range(len(x0))) + "\n")
    # stable step sqrt(2 rho / sum_j c C_v V_j / xi) from the reference bonds; the spacing
    # for C_v is the largest implied by a volume, as in the pair style
    spacing = np.sqrt(volume.max() / THICKNESS) if dim == 2 else np.cbrt(volume.max())
    bonds = refmodel.Bonds(x0, volume, kernel, c0, delta, spacing)
    stiff = bonds.c * bonds.cv / bonds.xi
    sums = (np.bincount(bonds.i, stiff * volume[bonds.j], minlength=len(x0))
            + np.bincount(bonds.j, stiff * volume[bonds.i], minlength=len(x0)))
    dt = DT_FRACTION * np.sqrt(2.0 * DENSITY / sums.max())
    notch_cmd, _ = notches(dim)

    axes = "xyz"[:dim]
    script = ("plugin load bbpdplugin.so\n"
              + header(kernel, model, "body.data", gc, delta,
                       f" critical_stretch {MOMENTUM_STRETCH!r}")
              + f"fix notch all bbpd/notch {notch_cmd}\n"
              + "".join(f"variable v{a} atomfile v{a}.txt\nset group all v{a} v_v{a}\n"
                        for a in axes)
              + "fix nve all nve\n" + ("fix 2d all enforce2d\n" if dim == 2 else "")
              + "compute vol all property/atom vfrac\n"
              "compute damage all bbpd/damage/atom\ncompute dsum all reduce sum c_damage\n"
              + "".join(f"variable p{a} atom c_vol*mass*v{a}\n"
                        f"variable a{a} atom abs(c_vol*mass*v{a})\n" for a in axes)
              + "compute p all reduce sum " + " ".join(f"v_p{a}" for a in axes) + "\n"
              + "compute pabs all reduce sum " + " ".join(f"v_a{a}" for a in axes) + "\n"
              + f"timestep {dt!r}\n"
              + "thermo_style custom step " + " ".join(f"c_p[{k + 1}]" for k in range(dim))
              + " " + " ".join(f"c_pabs[{k + 1}]" for k in range(dim)) + " c_dsum\n"
              "thermo_modify format float %.17g\nthermo 10\n"
              f"run {STEPS}\n")
    out = lmp(script, nprocs=nprocs).output
    assert "exceeds" not in out    # no stability warning from the pair style
    table = ref.thermo_tables(out)[0]
    assert len(table["Step"]) == STEPS // 10 + 1
    damage = table["c_dsum"]
    print(f"{model}: summed damage {damage[0]:.4g} (notches) -> {damage[-1]:.4g}")
    assert damage[-1] > damage[0], "no bond broke during the run: raise VELOCITY"
    scale = max(table[f"c_pabs[{k + 1}]"][0] for k in range(dim))
    for k in range(dim):
        p = table[f"c_p[{k + 1}]"]
        drift = np.abs(p - p[0]).max()
        print(f"{model} momentum {k}: start {p[0]:.6g}, max drift {drift:.3g} (scale {scale:.3g})")
        assert drift < MOMENTUM_RTOL * scale, f"momentum {k} drifts by {drift:.3g} of {scale:.3g}"

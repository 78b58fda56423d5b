"""Bond failure of the bbpd/* pair styles: the critical stretch s0 (paper
eqs. 14-16 and their plane-strain/3D analogues) and the fracture energy it
implies.

1. Threshold: a two-atom body whose single bond is stretched to 0.999 s0
   keeps it and to 1.001 s0 loses it, with s0 from the critical_stretch
   keyword and from G_c (the printed c0 and s0 are compared with
   python/bbpd/reference.py, which integrates the kernel moments numerically).
2. Fracture-energy audit: the work to break every bond crossing a straight
   line of length L in a plane-stress strip, sum 1/2 c s0^2 xi C_v V_i V_j,
   against G_c h L. It is measured in LAMMPS: under an isotropic expansion e
   every bond has stretch e exactly, so the energy of the bonds a notch
   removes is the difference of the body's energy with and without them,
   and scaling it by (s0/e)^2 gives their breaking work. Two edge notches
   whose tips differ by K lattice columns isolate K dx of straight crack: the
   tip and strip-end contributions are translates of each other and cancel.
"""
import re

import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from scenes import peri_preamble

KERNELS = ("constant", "triangular", "gaussian")
MODELS = ("plane/stress", "plane/strain", "3d")
DX = 1.0e-3
THICKNESS = 1.0e-3
YOUNGS = 190.0e9         # Kalthoff-Winkler steel (paper section 4.2.3)
FRACTURE_ENERGY = 6.9e4  # J/m^2, same source
DENSITY = 7800.0
PRINT_RTOL = 2.0e-7      # the report prints c0 and s0 with 8 significant digits
REPORT = re.compile(r"micromodulus c0 = (\S+)\s+critical_stretch s0 = (\S+)( \(given\))?")


def constants_printed(output):
    return [(float(a), float(b), bool(c)) for a, b, c in REPORT.findall(output)]


def volume_of(dim):
    return THICKNESS * DX**2 if dim == 2 else DX**3


def section(kernel, model, datafile, coeff_tail, extra=""):
    dim = ref.DIMENSION[model]
    thick = f" thickness {THICKNESS!r}" if dim == 2 else ""
    return (peri_preamble(dim, "f f p" if dim == 2 else "f f f", data=datafile, plugin=False,
                          clear=True) +
            f"pair_style bbpd/{kernel} {model}{thick}\npair_coeff * * {YOUNGS!r} {coeff_tail}\n"
            + extra)


# ---------------------------------------------------------------------------
# 1. threshold

HORIZON = 3.0 * DX
BOND = np.array([1.0, 2.0, 1.0]) * DX    # |xi| = sqrt(6) dx < delta - dx/2: C_v = 1
GIVEN_STRETCH = 0.0123
ELASTIC_STRETCH = 0.2    # far beyond any s0: must not break without a failure criterion
FACTORS = (0.999, 1.001)


@pytest.mark.parametrize("model", MODELS)
def test_bond_breaks_at_critical_stretch(lmp, tmp_path, model):
    dim = ref.DIMENSION[model]
    bond = BOND.copy()
    if dim == 2:
        bond[2] = 0.0
    x0 = np.array([[0.0, 0.0, 0.0], bond])
    box = [(-3.0 * HORIZON, 3.0 * HORIZON)] * 3
    if dim == 2:
        box[2] = (-0.5 * DX, 0.5 * DX)
    refmodel.write_data(tmp_path / "two.data", x0, volume_of(dim), DENSITY, box)
    coords = "x y z" if dim == 3 else "x y"

    def stretched(name, s):
        refmodel.write_positions(tmp_path / f"{name}.dump", np.array([x0[0], (1.0 + s) * bond]),
                                 box)
        return f"read_dump {name}.dump 0 {coords} box no replace yes\nrun 0\n"

    geom = THICKNESS if dim == 2 else 1.0
    probes = "compute damage all bbpd/damage/atom\ncompute dmax all reduce max c_damage\n" \
             "thermo_style custom step pe c_dmax\nrun 0\n"
    cases = []    # (kernel, s0 expected, tail of pair_coeff)
    for kernel in KERNELS:
        c0 = ref.micromodulus(kernel, model, YOUNGS, HORIZON, geom)
        s0 = ref.critical_stretch(kernel, model, c0, FRACTURE_ENERGY, HORIZON, geom)
        cases.append((kernel, c0, s0, f"{FRACTURE_ENERGY!r} {HORIZON!r}", False))
        cases.append((kernel, c0, GIVEN_STRETCH,
                      f"none {HORIZON!r} critical_stretch {GIVEN_STRETCH!r}", True))
    script = "plugin load bbpdplugin.so\n"
    for n, (kernel, c0, s0, tail, given) in enumerate(cases):
        script += section(kernel, model, "two.data", tail, probes)
        script += "".join(stretched(f"c{n}_{f}", f * s0) for f in FACTORS) + "run 0\n"
    # an elastic body (G_c = none) has no failure criterion
    script += section("gaussian", model, "two.data", f"none {HORIZON!r}", probes)
    script += stretched("elastic", ELASTIC_STRETCH)
    out = lmp(script).output

    printed = constants_printed(out)
    tables = ref.thermo_tables(out)
    runs_per_case = 2 + len(FACTORS)
    for n, (kernel, c0, s0, _, given) in enumerate(cases):
        c0_lmp, s0_lmp, given_lmp = printed[n * runs_per_case]
        assert c0_lmp == pytest.approx(c0, rel=PRINT_RTOL), f"{kernel} {model} c0"
        assert s0_lmp == pytest.approx(s0, rel=PRINT_RTOL), f"{kernel} {model} s0"
        assert given_lmp == given
        t = tables[n * runs_per_case:(n + 1) * runs_per_case]
        damage = [tab["c_dmax"][-1] for tab in t]
        assert damage == [0.0, 0.0, 1.0, 1.0], f"{kernel} {model} s0={s0:.6g}: damage {damage}"
    assert "fracture: off" in out
    assert tables[-1]["c_dmax"][-1] == 0.0
    # the report of the last run of every breaking case counts the broken bond
    assert out.count("total bonds 1 (1 broken)") == len(cases)


# ---------------------------------------------------------------------------
# 2. fracture-energy audit (plane stress)

AUDIT_M = (3, 5)
EXPANSION = 1.0e-4       # isotropic strain, well below s0 (~1e-2): no bond breaks
COLUMNS = 10             # K: crack length difference in lattice spacings
TIP_OFFSET = 0.2718      # tip x in dx past a column: no bond crosses the line exactly there
LATTICE_RTOL = 1.0e-8    # LAMMPS energy difference against the NumPy lattice sum
# |ratio - 1| of a lattice sum is a quadrature error of the horizon integral,
# O(dx/delta); measured 0.034, 0.150, 0.058 (constant, triangular, gaussian)
# at m = 3 and 0.024, 0.051, 0.018 at m = 5: C/m with C = 0.5 bounds all six
# with a margin of 10-80%, and the error must shrink from m = 3 to m = 5.
AUDIT_TOLERANCE_C = 0.5


def strip(m):
    """Lattice strip with a horizontal crack line between rows and room around the tips."""
    nx = 2 * (m + 2) + COLUMNS + 2
    ny = 2 * (m + 2)
    x0 = refmodel.square_lattice((nx, ny), DX)
    line_y = (ny // 2 - 0.5) * DX
    tip1 = (m + 2 + TIP_OFFSET) * DX
    return x0, line_y, tip1, tip1 + COLUMNS * DX


def lattice_breaking_energy(kernel, m, x0, segment_short, segment_long, s0):
    """Python: breaking work of the bonds cut by the long notch and not by the short one."""
    delta = m * DX
    c0 = ref.micromodulus(kernel, "plane/stress", YOUNGS, delta, THICKNESS)
    bonds = refmodel.Bonds(x0, volume_of(2), kernel, c0, delta, DX)
    extra = (bonds.crossing(refmodel.segment_crossing(*segment_long))
             & ~bonds.crossing(refmodel.segment_crossing(*segment_short)))
    return bonds.breaking_energy(s0, extra)


def test_fracture_energy_of_straight_crack(lmp, tmp_path):
    script = "plugin load bbpdplugin.so\n"
    cases = []
    for m in AUDIT_M:
        x0, line_y, tip1, tip2 = strip(m)
        box = [(x0[:, k].min() - DX, x0[:, k].max() + DX) for k in (0, 1)]
        box.append((-0.5 * DX, 0.5 * DX))
        refmodel.write_data(tmp_path / f"strip{m}.data", x0, volume_of(2), DENSITY, box)
        refmodel.write_positions(tmp_path / f"strip{m}_expanded.dump", (1.0 + EXPANSION) * x0, box)
        start = (x0[:, 0].min() - 2.0 * DX, line_y)    # edge notches: they start outside the strip
        segments = [(start, (tip, line_y)) for tip in (tip1, tip2)]
        for kernel in KERNELS:
            for seg in segments:
                notch = f"fix notch all bbpd/notch segment {seg[0][0]!r} {seg[0][1]!r} " \
                        f"{seg[1][0]!r} {seg[1][1]!r}\n"
                script += section(kernel, "plane/stress", f"strip{m}.data",
                                  f"{FRACTURE_ENERGY!r} {m * DX!r}", notch)
                script += ("thermo_style custom step pe\nthermo_modify format float %.17g\nrun 0\n"
                           f"read_dump strip{m}_expanded.dump 0 x y box no replace yes\nrun 0\n")
            cases.append((kernel, m, x0, segments))
    out = lmp(script).output
    tables = ref.thermo_tables(out)
    printed = constants_printed(out)
    assert len(tables) == 4 * len(cases)
    assert "broken)" in out and "fracture: on" in out

    ratios, lines = {}, []
    for n, (kernel, m, x0, segments) in enumerate(cases):
        delta = m * DX
        c0 = ref.micromodulus(kernel, "plane/stress", YOUNGS, delta, THICKNESS)
        s0 = ref.critical_stretch(kernel, "plane/stress", c0, FRACTURE_ENERGY, delta, THICKNESS)
        assert printed[4 * n][1] == pytest.approx(s0, rel=PRINT_RTOL)
        pe_short, pe_long = tables[4 * n + 1]["PotEng"][-1], tables[4 * n + 3]["PotEng"][-1]
        # pe sums energy densities: times the atom volume gives joules
        work = (pe_short - pe_long) * volume_of(2) * (s0 / EXPANSION) ** 2
        expected = lattice_breaking_energy(kernel, m, x0, segments[0], segments[1], s0)
        assert work == pytest.approx(expected, rel=LATTICE_RTOL)
        ratios[kernel, m] = work / (FRACTURE_ENERGY * THICKNESS * COLUMNS * DX)
        lines.append(f"{kernel:10s} m={m}: breaking work / (G_c h L) = {ratios[kernel, m]:.4f}")
    print("\n" + "\n".join(lines))

    for kernel in KERNELS:
        err = [abs(ratios[kernel, m] - 1.0) for m in AUDIT_M]
        for m, e in zip(AUDIT_M, err):
            assert e < AUDIT_TOLERANCE_C / m, f"{kernel} m={m}: ratio {ratios[kernel, m]:.4f}"
        assert err[1] < err[0], f"{kernel}: error {err} does not shrink with m"


@pytest.mark.parametrize("kernel", KERNELS)
def test_lattice_fracture_energy_converges(kernel):
    """The same lattice sum (NumPy only) tends to G_c as m grows: s0's closed form is right."""
    m = 20
    delta = m * DX
    c0 = ref.micromodulus(kernel, "plane/stress", YOUNGS, delta, THICKNESS)
    s0 = ref.critical_stretch(kernel, "plane/stress", c0, FRACTURE_ENERGY, delta, THICKNESS)
    # bonds from one column of atoms below the line y = 0 to every atom above it
    reach = m + 1
    rows = DX * (np.arange(reach) + 0.5)
    below = np.stack([np.zeros(reach), -rows], axis=1)
    cols = DX * np.arange(-reach, reach + 1)
    above = np.stack(np.meshgrid(cols, rows, indexing="ij"), -1).reshape(-1, 2)
    xi = np.linalg.norm(above[None, :, :] - below[:, None, :], axis=2).ravel()
    xi = xi[xi < delta + 0.5 * DX]
    c = c0 * ref.kernel(kernel)(xi / delta)
    work = np.sum(0.5 * c * s0**2 * xi * ref.partial_volume(xi, delta, DX)) * volume_of(2) ** 2
    ratio = work / (FRACTURE_ENERGY * THICKNESS * DX)
    assert abs(ratio - 1.0) < 0.005, f"{kernel}: lattice / G_c h L = {ratio:.5f} at m = {m}"

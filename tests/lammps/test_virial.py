"""Global virial and pressure of the bbpd/* pair styles against the NumPy reference.

compute pressure NULL virial gives P_ab = sum_i W_i,ab / V_box (area in 2D), with W_i the
per-atom virial 1/2 sum_j (y_i - y_j) (x) f_ij of python/bbpd/reference.py. Under a uniform
stretch every bond pulls: the pressure is negative (tension) in the stretched direction, so a
sign flip, a missing factor 1/2 or a virial of one bond end only fails. Each force-loop variant
tallies the virial on its own: the SIMD kernel (default storage), the portable loop (compact
storage) and the per-type-pair s0 loop (two types), on 1 and 2 ranks.
"""
import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from scenes import peri_preamble

DX = 1.0e-3
THICKNESS = 1.0e-3
DELTA = 3.05 * DX
STRETCH = (1.0e-4, -0.4e-4, 0.7e-4)    # strain along x, y, z
SHEAR = 0.3e-4                         # y += SHEAR x
RTOL = 1.0e-11                         # of the largest component: summation order only


def body(dim):
    shape = (12, 10) if dim == 2 else (7, 6, 5)
    x0 = refmodel.square_lattice(shape, DX)
    pad = 4 * DX
    box = [(x0[:, k].min() - pad, x0[:, k].max() + pad) for k in range(3)]
    if dim == 2:
        box[2] = (-0.5 * DX, 0.5 * DX)
    y = x0.copy()
    for k in range(dim):
        y[:, k] *= 1.0 + STRETCH[k]
    y[:, 1] += SHEAR * x0[:, 0]
    return x0, y, box


@pytest.mark.parametrize("model,variant,nprocs", [
    ("plane/strain", "fast", 1), ("plane/strain", "compact", 1),
    ("plane/strain", "types", 1), ("plane/strain", "fast", 2), ("3d", "fast", 1),
    ("3d", "types", 2)])
def test_pressure_matches_reference(lmp, tmp_path, model, variant, nprocs):
    dim = ref.DIMENSION[model]
    x0, y, box = body(dim)
    volume = THICKNESS * DX**2 if dim == 2 else DX**3
    types = np.ones(len(x0), dtype=int)
    if variant == "types":
        types[x0[:, 0] > 4.5 * DX] = 2
    refmodel.write_data(tmp_path / "body.data", x0, volume, 8000.0, box, types=types)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    thick = f" thickness {THICKNESS!r}" if dim == 2 else ""
    storage = " bond/storage compact" if variant == "compact" else ""
    coeffs = f"pair_coeff * * 200e9 none {DELTA!r}\n"
    if variant == "types":
        # same material, a different (never reached) s0 per pair: the per-pair-s0 loop
        coeffs = "".join(f"pair_coeff {a} {b} 200e9 none {DELTA!r} critical_stretch {s!r}\n"
                         for a, b, s in ((1, 1, 0.1), (1, 2, 0.2), (2, 2, 0.3)))
    coords = "x y z" if dim == 3 else "x y"
    boundary = "f f p" if dim == 2 else "f f f"    # fixed: the box volume is known
    script = (peri_preamble(dim, boundary, data="body.data") +
              f"pair_style bbpd/gaussian {model}{thick}{storage}\n" + coeffs
              + "compute p all pressure NULL virial\n"
              "thermo_style custom step press c_p[1] c_p[2] c_p[3] c_p[4] c_p[5] c_p[6]\n"
              "thermo_modify format float %.17g\n"
              "run 0\n"
              f"read_dump current.dump 0 {coords} box no replace yes\n"
              "run 0\n")
    out = lmp(script, nprocs=nprocs).output
    c0 = ref.micromodulus("gaussian", model, 200e9, DELTA, THICKNESS if dim == 2 else 1.0)
    bonds = refmodel.Bonds(x0, volume, "gaussian", c0, DELTA, DX)
    virial = bonds.virial_density(y).sum(axis=0)
    size = 1.0
    for k in range(dim):
        size *= box[k][1] - box[k][0]
    expected = virial / size
    table = ref.thermo_tables(out)[-1]
    got = np.array([table[f"c_p[{k}]"][-1] for k in range(1, 7)])
    scale = np.abs(expected).max()
    np.testing.assert_allclose(got, expected, rtol=0, atol=RTOL * scale)
    assert table["Press"][-1] == pytest.approx(expected[:dim].sum() / dim, rel=1e-10,
                                               abs=RTOL * scale)
    assert expected[0] < 0.0    # tension along the largest stretch
    assert abs(expected[3]) > 1e-3 * scale    # the shear component is tested too

"""Short-range contact of the bbpd/* pair styles (pair_style ... contact yes).

Written here from the contact model of LAMMPS peri/pmb (Parks et al. 2008; Silling, EMU
manual): two atoms closer than d_c = f dx (f = 0.9 by default, contact/distance) that share no
intact bond repel each other with the force density

    f_i = k_i (d_c - r) (x_i - x_j)/r,   k_i = 15 c0 V_j / delta,

whose potential is 1/2 K (d_c - r)^2, K = 15 c0 V_i V_j / delta, tallied half per atom as an
energy density e_i = 1/4 k_i (d_c - r)^2, with the virial W_i = 1/2 (x_i - x_j) (x) f_i per
atom (LAMMPS stress/atom = -W_i, pressure = sum_i W_i / area in 2D). Bonded pairs feel their
bond only; a pair whose bond a notch cut feels contact.
"""
import math

import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from scenes import peri_preamble

DX = 1.0e-3
THICKNESS = 1.0e-3
VOLUME = THICKNESS * DX**2
DELTA = 3.0 * DX
YOUNGS = 190.0e9
DENSITY = 7800.0
CONTACT_STIFFNESS = 15.0    # x c0 / delta, as in peri/pmb
RTOL = 1.0e-12
BOX = [(-20 * DX, 40 * DX), (-20 * DX, 20 * DX), (-0.5 * DX, 0.5 * DX)]
C0 = ref.micromodulus("gaussian", "plane/stress", YOUNGS, DELTA, THICKNESS)
GAP = 0.5 * DX                              # distance of each pressed pair
DIRECTION = np.array([0.6, 0.8, 0.0])       # from the first atom of a pair to the second

# two pairs, far apart (> horizon): (1, 2) bonded, (3, 4) with the bond cut by a notch;
# the second atom of each pair has 0.7 of the volume, so k_1 != k_2
X0 = np.array([[0.0, 0.0, 0.0], DX * DIRECTION,
               [20 * DX, 0.0, 0.0], [20 * DX, 0.0, 0.0] + DX * DIRECTION])
VOLUMES = VOLUME * np.array([1.0, 0.7, 1.0, 0.7])
NOTCH = "segment {!r} {!r} {!r} {!r}".format(19 * DX, 0.4 * DX, 22 * DX, 0.4 * DX)


def pressed():
    y = X0.copy()
    y[1] = y[0] + GAP * DIRECTION
    y[3] = y[2] + GAP * DIRECTION
    return y


def run_pair(lmp, tmp_path, distance_keyword="", two_bodies=""):
    refmodel.write_data(tmp_path / "atoms.data", X0, VOLUMES, DENSITY, BOX)
    refmodel.write_positions(tmp_path / "pressed.dump", pressed(), BOX)
    data = "atoms.data extra/atom/types 1" if two_bodies else "atoms.data"
    script = peri_preamble(2, "f f p", data=data) + f"""\
{"set atom 2 type 2" if two_bodies else ""}
pair_style bbpd/gaussian plane/stress thickness {THICKNESS!r} contact yes{distance_keyword}
pair_coeff * * {YOUNGS!r} none {DELTA!r}
{two_bodies}
fix notch all bbpd/notch {NOTCH}
compute pea all pe/atom
compute sa all stress/atom NULL virial
compute p all pressure NULL virial
thermo_style custom step pe c_p c_p[1] c_p[2] c_p[3] c_p[4] c_p[5] c_p[6]
thermo_modify format float %.17g
run 0
read_dump pressed.dump 0 x y box no replace yes
run 0
write_dump all custom f.dump id fx fy fz c_pea c_sa[1] c_sa[2] c_sa[3] c_sa[4] c_sa[5] c_sa[6] modify format float %.17g
"""
    out = lmp(script).output
    return out, ref.read_dump(tmp_path / "f.dump")


def contact_expected(factor):
    """force density, energy density and virial (xx yy zz xy xz yz) of atoms 3 and 4."""
    y = pressed()
    dc = factor * DX    # spacing from the largest volume: DX
    f, e, w = np.zeros((2, 3)), np.zeros(2), np.zeros((2, 6))
    for n, (i, j) in enumerate(((2, 3), (3, 2))):
        d = y[i] - y[j]
        r = np.linalg.norm(d)
        k = CONTACT_STIFFNESS * C0 * VOLUMES[j] / DELTA
        f[n] = k * (dc - r) / r * d
        e[n] = 0.25 * k * (dc - r) ** 2
        w[n] = 0.5 * np.array([d[0] * f[n][0], d[1] * f[n][1], d[2] * f[n][2],
                               d[0] * f[n][1], d[0] * f[n][2], d[1] * f[n][2]])
    return f, e, w


def test_bonds_no_makes_two_bodies_that_touch_by_contact(lmp, tmp_path):
    """Atom 2 of type 2, 'pair_coeff 1 2 ... bonds no' with twice the plate's E: the pair
    (1, 2), bonded with one type, now feels the contact force only, with c0 of the pair 1 2."""
    out, got = run_pair(lmp, tmp_path, two_bodies=f"pair_coeff 1 2 {2 * YOUNGS!r} none "
                                                  f"{DELTA!r} bonds no")
    assert "types 1 2: no bonds (separate bodies)" in out
    assert "total bonds 1 (1 broken)" in out        # only the notched pair (3, 4) was bonded
    force = np.stack([got["fx"], got["fy"], got["fz"]], axis=1)
    f_c, _, _ = contact_expected(0.9)               # the pair (3, 4), types 1 1
    np.testing.assert_allclose(force[2:], f_c, rtol=0, atol=RTOL * np.abs(f_c).max())
    y = pressed()
    for n, (i, j) in enumerate(((0, 1), (1, 0))):
        d = y[i] - y[j]
        r = np.linalg.norm(d)
        k = CONTACT_STIFFNESS * 2 * C0 * VOLUMES[j] / DELTA      # c0 is proportional to E
        np.testing.assert_allclose(force[i], k * (0.9 * DX - r) / r * d, rtol=0,
                                   atol=RTOL * np.abs(f_c).max())


def bond_expected():
    """force density and energy density of atoms 1 and 2: their bond only (eqs. 9, 19, 21)."""
    y = pressed()
    xi0 = DX
    coef_i = C0 * math.exp(-4.0 * (xi0 / DELTA) ** 2) / xi0    # C_v = 1: xi0 < delta - dx/2
    f, e = np.zeros((2, 3)), np.zeros(2)
    for n, (i, j) in enumerate(((0, 1), (1, 0))):
        d = y[j] - y[i]
        r = np.linalg.norm(d)
        f[n] = coef_i * VOLUMES[j] * (r - xi0) / r * d
        e[n] = 0.25 * coef_i * VOLUMES[j] * (r - xi0) ** 2
    return f, e


@pytest.mark.parametrize("factor", [0.9, 0.6])
def test_contact_force_energy_and_virial(lmp, tmp_path, factor):
    keyword = "" if factor == 0.9 else f" contact/distance {factor!r}"
    out, got = run_pair(lmp, tmp_path, keyword)
    assert "1 bonds cut by 1 notch" in out
    assert f"contact: on, distance {factor * DX:g}" in out
    force = np.stack([got["fx"], got["fy"], got["fz"]], axis=1)
    f_c, e_c, w_c = contact_expected(factor)
    f_b, e_b = bond_expected()
    scale = np.abs(f_c).max()
    # the notched pair: contact only; the bonded pair: its bond only, no contact
    np.testing.assert_allclose(force[2:], f_c, rtol=0, atol=RTOL * scale)
    np.testing.assert_allclose(force[:2], f_b, rtol=0, atol=RTOL * np.abs(f_b).max())
    np.testing.assert_allclose(got["c_pea"][2:], e_c, rtol=RTOL)
    np.testing.assert_allclose(got["c_pea"][:2], e_b, rtol=RTOL)
    stress = np.stack([got[f"c_sa[{k}]"] for k in range(1, 7)], axis=1)
    np.testing.assert_allclose(stress[2:], -w_c, rtol=0, atol=RTOL * np.abs(w_c).max())
    # global: energy and pressure include the contact; contact pushes apart: pressure > 0
    table = ref.thermo_tables(out)[-1]
    assert table["PotEng"][-1] == pytest.approx(e_c.sum() + e_b.sum(), rel=RTOL)
    area = (BOX[0][1] - BOX[0][0]) * (BOX[1][1] - BOX[1][0])
    w_b = bond_virial()
    virial = w_c.sum(axis=0) + w_b.sum(axis=0)
    for k in range(6):
        assert table[f"c_p[{k + 1}]"][-1] == pytest.approx(virial[k] / area, rel=1e-11,
                                                           abs=1e-12 * abs(virial).max() / area)
    assert table["c_p"][-1] == pytest.approx(0.5 * (virial[0] + virial[1]) / area, rel=1e-11)
    assert w_c[:, 0].sum() > 0.0 and w_c[:, 1].sum() > 0.0


def bond_virial():
    y = pressed()
    f_b, _ = bond_expected()
    w = np.zeros((2, 6))
    for n, (i, j) in enumerate(((0, 1), (1, 0))):
        d = y[i] - y[j]
        w[n] = 0.5 * np.array([d[0] * f_b[n][0], d[1] * f_b[n][1], d[2] * f_b[n][2],
                               d[0] * f_b[n][1], d[0] * f_b[n][2], d[1] * f_b[n][2]])
    return w


def test_no_contact_beyond_the_contact_distance(lmp, tmp_path):
    """contact/distance 0.4: the pressed pair at 0.5 dx is outside it, no force at all."""
    out, got = run_pair(lmp, tmp_path, " contact/distance 0.4")
    assert np.all(got["fx"][2:] == 0.0) and np.all(got["fy"][2:] == 0.0)
    assert np.all(got["c_pea"][2:] == 0.0)

"""compute bbpd/damage/atom: fractional damage of eq. 17,

    phi_i = 1 - sum_{j intact} C_v V_j / sum_{j in family} C_v V_j,

against the NumPy reference (python/bbpd/reference.py, Bonds.damage) on a lattice with
unequal atom volumes, bonds at the horizon with partial volumes (eq. 19), notches and bonds
broken during a run. A count of bonds (1 - n_intact/n) or weights without C_v or V_j differ
from eq. 17 on this body by far more than the tolerance.
"""
import numpy as np

from bbpd import reference as ref
import refmodel
from scenes import peri_preamble

DX = 1.0e-3
THICKNESS = 1.0e-3
DENSITY = 8000.0
DELTA = 3.05 * DX
SEED = 77
ATOL = 1.0e-14    # damage is a ratio of sums of O(1) terms


def body(tmp_path, rng):
    x0 = refmodel.square_lattice((14, 14), DX)
    volume = THICKNESS * DX**2 * rng.uniform(0.8, 1.0, len(x0))
    box = [(-5 * DX, 19 * DX), (-5 * DX, 19 * DX), (-0.5 * DX, 0.5 * DX)]
    refmodel.write_data(tmp_path / "body.data", x0, volume, DENSITY, box)
    # the pair style's spacing for C_v: the largest implied by an atom's volume
    spacing = np.sqrt(volume.max() / THICKNESS)
    return x0, volume, box, spacing


SEGMENTS = [((-1.0 * DX, 6.5 * DX), (7.3 * DX, 6.5 * DX)),
            ((9.27 * DX, 2.18 * DX), (11.64 * DX, 10.37 * DX))]


def script(extra=""):
    notch = " ".join(f"segment {a[0]!r} {a[1]!r} {b[0]!r} {b[1]!r}" for a, b in SEGMENTS)
    return (peri_preamble(2, data="body.data") +
            f"pair_style bbpd/gaussian plane/stress thickness {THICKNESS!r}\n"
            f"pair_coeff * * 190e9 none {DELTA!r} critical_stretch 0.004\n"
            f"fix notch all bbpd/notch {notch}\n"
            "compute d all bbpd/damage/atom\n" + extra)


def scaled(segment, factor):
    (ax, ay), (bx, by) = segment
    return (ax, ay), (ax + factor * (bx - ax), ay + factor * (by - ay))


def reference_bonds(x0, volume, spacing):
    c0 = ref.micromodulus("gaussian", "plane/stress", 190e9, DELTA, THICKNESS)
    bonds = refmodel.Bonds(x0, volume, "gaussian", c0, DELTA, spacing)
    # no bond passes within round-off of a notch end (where the plugin's tolerance decides)
    for seg in SEGMENTS:
        for flip in (False, True):
            seg_ = seg[::-1] if flip else seg
            near, far = (refmodel.segment_crossing(*scaled(seg_, f)) for f in (1 - 1e-6, 1 + 1e-6))
            assert np.array_equal(bonds.crossing(near), bonds.crossing(far))
    for a, b in SEGMENTS:
        bonds.cut(refmodel.segment_crossing(a, b))
    return bonds


def count_damage(bonds):
    n = len(bonds.x0)
    total = np.bincount(bonds.i, minlength=n) + np.bincount(bonds.j, minlength=n)
    a = bonds.intact
    intact = np.bincount(bonds.i[a], minlength=n) + np.bincount(bonds.j[a], minlength=n)
    return 1.0 - intact / total


def test_notch_damage_is_eq17(lmp, tmp_path):
    rng = np.random.default_rng(SEED)
    x0, volume, _, spacing = body(tmp_path, rng)
    lmp(script("run 0\nwrite_dump all custom d.dump id c_d modify format float %.17g\n"))
    got = ref.read_dump(tmp_path / "d.dump")["c_d"]
    bonds = reference_bonds(x0, volume, spacing)
    expected = bonds.damage()
    assert np.count_nonzero(expected) > 40 and np.count_nonzero(bonds.cv < 1.0) > 100
    # the body tells eq. 17 from a bond count
    assert np.abs(count_damage(bonds) - expected).max() > 1e-2
    np.testing.assert_allclose(got, expected, rtol=0, atol=ATOL)


def test_damage_after_bonds_break_in_a_run(lmp, tmp_path):
    """A stretch applied after the families exist breaks bonds during 'run 0' (s0 = 0.004,
    stretch up to 0.006 in a band): the damage is eq. 17 of the bonds that passed s0."""
    rng = np.random.default_rng(SEED + 1)
    x0, volume, box, spacing = body(tmp_path, rng)
    # current positions: x stretched by 0.006 in the band 3 dx < y < 9 dx
    y = x0.copy()
    band = (x0[:, 1] > 3 * DX) & (x0[:, 1] < 9 * DX)
    y[band, 0] *= 1.006
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    out = lmp(script("run 0\nread_dump current.dump 0 x y box no replace yes\nrun 0\n"
                     "write_dump all custom d.dump id c_d modify format float %.17g\nrun 0\n")
              ).output
    bonds = reference_bonds(x0, volume, spacing)
    notched = np.count_nonzero(~bonds.intact)
    _, _, s = bonds.stretch(y)
    assert np.min(np.abs(s - 0.004)) > 1e-7
    bonds.intact &= ~(s > 0.004)
    broken = np.count_nonzero(~bonds.intact)
    assert broken > notched + 20
    assert f"total bonds {len(bonds.i)} ({broken} broken)" in out
    got = ref.read_dump(tmp_path / "d.dump")["c_d"]
    np.testing.assert_allclose(got, bonds.damage(), rtol=0, atol=ATOL)

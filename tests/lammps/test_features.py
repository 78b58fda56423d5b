"""Input features checked by their effect, against python/bbpd/reference.py:

- model 1d: a bond breaks at s0 of the 1D closed form (two-atom bar);
- the spacing keyword: C_v (eq. 19) and the family cutoff use the given spacing;
- the material-file route of pair_coeff gives the same bits as E and G_c typed in;
- fix bbpd/notch limited to a group cuts the bonds with at least one end in the group;
- an atom exactly on a notch line lies on the positive side (normal (-a_y, a_x)), as
  doc/fix_bbpd_notch.rst states;
- compute bbpd/dsif options offset and tolerance, and how it resolves ties.
"""
import re

import numpy as np
import pytest

from bbpd import reference as ref
import refmodel
from bbpd.runner import LammpsError
from scenes import peri_preamble, sibling

DX = 1.0e-3
THICKNESS = 1.0e-3
VOLUME = THICKNESS * DX**2
DENSITY = 7800.0
YOUNGS = 190.0e9
GC = 6.9e4
RTOL = 1.0e-12
REPORT = re.compile(r"micromodulus c0 = (\S+)\s+critical_stretch s0 = (\S+)")


def preamble(dim=2, boundary=None, datafile="body.data"):
    return peri_preamble(dim, boundary, data=datafile)


def plate(nx=12, ny=12):
    x0 = refmodel.square_lattice((nx, ny), DX)
    box = [(-5 * DX, (nx + 5) * DX), (-5 * DX, (ny + 5) * DX), (-0.5 * DX, 0.5 * DX)]
    return x0, box


# --------------------------------------------------------------------------- model 1d

AREA = 2.0e-6
BAR_HORIZON = 3.0 * DX
BAR_BOND = 2.0 * DX    # < delta - dx/2: C_v = 1


@pytest.mark.parametrize("kernel", ["constant", "gaussian"])
def test_bond_breaks_at_critical_stretch_in_1d(lmp, tmp_path, kernel):
    """Two atoms of a bar (area A, volume A dx): c0 and s0 of the 1D closed forms, the bond
    survives 0.999 s0 and breaks at 1.001 s0."""
    x0 = np.array([[0.0, 0.0, 0.0], [BAR_BOND, 0.0, 0.0]])
    box = [(-10 * DX, 10 * DX)] * 3
    refmodel.write_data(tmp_path / "bar.data", x0, AREA * DX, DENSITY, box)
    c0 = ref.micromodulus(kernel, "1d", YOUNGS, BAR_HORIZON, AREA)
    s0 = ref.critical_stretch(kernel, "1d", c0, GC, BAR_HORIZON, AREA)
    script = (preamble(3, "f f f", "bar.data")
              + f"pair_style bbpd/{kernel} 1d area {AREA!r}\n"
              f"pair_coeff * * {YOUNGS!r} {GC!r} {BAR_HORIZON!r}\n"
              "compute d all bbpd/damage/atom\ncompute dmax all reduce max c_d\n"
              "thermo_style custom step c_dmax\nrun 0\n")
    for n, factor in enumerate((0.999, 1.001)):
        y = x0.copy()
        y[1, 0] = BAR_BOND * (1.0 + factor * s0)
        refmodel.write_positions(tmp_path / f"p{n}.dump", y, box)
        script += f"read_dump p{n}.dump 0 x y z box no replace yes\nrun 0\n"
    out = lmp(script + "run 0\n").output
    c0_lmp, s0_lmp = (float(v) for v in REPORT.search(out).groups())
    assert c0_lmp == pytest.approx(c0, rel=2e-7) and s0_lmp == pytest.approx(s0, rel=2e-7)
    damage = [t["c_dmax"][-1] for t in ref.thermo_tables(out)]
    assert damage == [0.0, 0.0, 1.0, 1.0]
    assert "total bonds 1 (1 broken)" in out


# --------------------------------------------------------------------------- spacing

def forces_script(coeff, style_extra="", model="plane/stress", kernel="gaussian"):
    return (preamble()
            + f"pair_style bbpd/{kernel} {model} thickness {THICKNESS!r}{style_extra}\n"
            + coeff + "run 0\nread_dump current.dump 0 x y box no replace yes\nrun 0\n"
            "write_dump all custom f.dump id fx fy fz modify format float %.17g\n")


def perturbed(tmp_path, seed=3):
    x0, box = plate()
    rng = np.random.default_rng(seed)
    y = x0 + 1e-3 * DX * rng.uniform(-1.0, 1.0, x0.shape)
    y[:, 2] = 0.0
    refmodel.write_data(tmp_path / "body.data", x0, VOLUME, DENSITY, box)
    refmodel.write_positions(tmp_path / "current.dump", y, box)
    return x0, y


def read_forces(path):
    got = ref.read_dump(path)
    return np.stack([got["fx"], got["fy"], got["fz"]], axis=1)


def test_spacing_keyword_sets_the_volume_correction(lmp, tmp_path):
    """spacing 1.2 dx (the volumes imply dx): C_v = (delta + 0.6 dx - xi)/(1.2 dx) and bonds
    up to delta + 0.6 dx; the forces match the reference with that spacing, not with dx."""
    delta, given = 3.05 * DX, 1.2 * DX
    x0, y = perturbed(tmp_path)
    out = lmp(forces_script(f"pair_coeff * * {YOUNGS!r} none {delta!r}\n",
                            f" spacing {given!r}")).output
    assert f"grid spacing for the volume correction = {given:g} (given)" in out
    c0 = ref.micromodulus("gaussian", "plane/stress", YOUNGS, delta, THICKNESS)
    bonds = refmodel.Bonds(x0, VOLUME, "gaussian", c0, delta, given)
    assert f"total bonds {len(bonds.i)} (0 broken)" in out
    f_ref = bonds.force_density(y)
    wrong = refmodel.Bonds(x0, VOLUME, "gaussian", c0, delta, DX).force_density(y)
    scale = np.abs(f_ref).max()
    assert np.abs(wrong - f_ref).max() > 1e-4 * scale    # the keyword matters here
    np.testing.assert_allclose(read_forces(tmp_path / "f.dump"), f_ref, rtol=0,
                               atol=RTOL * scale)


# --------------------------------------------------------------------------- material file

def test_material_file_gives_the_typed_in_material(lmp, tmp_path):
    """pair_coeff * * kalthoff_winkler_steel.bbpd maraging_steel delta: the E and G_c of the
    file (190e9, 6.9e4), bit for bit the run of the typed-in numbers."""
    delta = 3.05 * DX
    perturbed(tmp_path)
    typed = lmp(forces_script(f"pair_coeff * * 190.0e9 6.9e4 {delta!r}\n")).output
    f_typed = read_forces(tmp_path / "f.dump")
    filed = lmp(forces_script(f"pair_coeff * * kalthoff_winkler_steel.bbpd maraging_steel "
                              f"{delta!r}\n")).output
    f_file = read_forces(tmp_path / "f.dump")
    c0 = ref.micromodulus("gaussian", "plane/stress", 190.0e9, delta, THICKNESS)
    s0 = ref.critical_stretch("gaussian", "plane/stress", c0, 6.9e4, delta, THICKNESS)
    assert "E = 1.9e+11  Gc = 69000" in filed
    c0_lmp, s0_lmp = (float(v) for v in REPORT.search(filed).groups())
    assert c0_lmp == pytest.approx(c0, rel=2e-7) and s0_lmp == pytest.approx(s0, rel=2e-7)
    assert REPORT.search(filed).group(0) == REPORT.search(typed).group(0)
    np.testing.assert_array_equal(f_file, f_typed)
    assert np.abs(f_file).max() > 0.0
    # a material with Gc = none in its file: elastic
    out = lmp(forces_script(f"pair_coeff * * mode1_steel.bbpd mode1_steel {delta!r}\n")).output
    assert "E = 2.1e+11  Gc = inf" in out and "fracture: off" in out


# --------------------------------------------------------------------------- notch in a group

def notch_count(lmp, tmp_path, segment, group_cmd="", group="all"):
    out = lmp(preamble()
              + f"pair_style bbpd/gaussian plane/stress thickness {THICKNESS!r}\n"
              f"pair_coeff * * {YOUNGS!r} {GC!r} {3.05 * DX!r}\n" + group_cmd
              + "fix notch {} bbpd/notch segment {!r} {!r} {!r} {!r}\n".format(group, *segment[0],
                                                                            *segment[1])
              + "compute d all bbpd/damage/atom\n"
              "run 0\nwrite_dump all custom d.dump id c_d modify format float %.17g\n").output
    m = re.search(r"(\d+) bonds cut by 1 notch", out)
    return (int(m.group(1)) if m else 0), ref.read_dump(tmp_path / "d.dump")["c_d"]


def test_notch_limited_to_a_group(lmp, tmp_path):
    """fix ID left bbpd/notch: a bond crossing the segment is cut if at least one of its
    atoms is in the group (doc/fix_bbpd_notch.rst)."""
    x0, box = plate()
    refmodel.write_data(tmp_path / "body.data", x0, VOLUME, DENSITY, box)
    segment = ((-1.0 * DX, 5.5 * DX), (13.0 * DX, 5.5 * DX))
    c0 = ref.micromodulus("gaussian", "plane/stress", YOUNGS, 3.05 * DX, THICKNESS)
    bonds = refmodel.Bonds(x0, VOLUME, "gaussian", c0, 3.05 * DX, DX)
    cross = bonds.crossing(refmodel.segment_crossing(*segment))
    in_group = x0[:, 0] < 4.5 * DX
    either = cross & (in_group[bonds.i] | in_group[bonds.j])
    both = cross & in_group[bonds.i] & in_group[bonds.j]
    assert np.count_nonzero(both) < np.count_nonzero(either) < np.count_nonzero(cross)
    n, damage = notch_count(lmp, tmp_path, segment,
                            "region left block INF 0.0045 INF INF INF INF units box\n"
                            "group left region left\n", "left")
    assert n == np.count_nonzero(either)
    bonds.intact &= ~either
    np.testing.assert_allclose(damage, bonds.damage(), rtol=0, atol=1e-14)


# --------------------------------------------------------------------------- atoms on the line

@pytest.mark.parametrize("direction", [1, -1])
def test_atom_on_the_notch_line_is_on_the_positive_side(lmp, tmp_path, direction):
    """A segment along the atom row y = 5 dx: with the segment running in +x the row lies on
    the side of the normal (0, +1), keeps its bonds to the rows above and loses those to the
    rows below; reversed, the other way round. The damage map is the reference's with that
    rule, and the rows at y = 4 dx and 6 dx differ accordingly."""
    x0, box = plate()
    refmodel.write_data(tmp_path / "body.data", x0, VOLUME, DENSITY, box)
    a, b = (-1.0 * DX, 5.0 * DX), (13.0 * DX, 5.0 * DX)
    segment = (a, b) if direction == 1 else (b, a)
    n, damage = notch_count(lmp, tmp_path, segment)
    c0 = ref.micromodulus("gaussian", "plane/stress", YOUNGS, 3.05 * DX, THICKNESS)
    bonds = refmodel.Bonds(x0, VOLUME, "gaussian", c0, 3.05 * DX, DX)
    cut = bonds.crossing(refmodel.segment_crossing(*segment))
    assert n == np.count_nonzero(cut)
    # explicitly: no bond from the row on the line to the positive side is cut
    row = np.isclose(x0[:, 1], 5.0 * DX)
    pos_side = direction * (x0[:, 1] - 5.0 * DX) > 0.5 * DX
    to_pos = (row[bonds.i] & pos_side[bonds.j]) | (row[bonds.j] & pos_side[bonds.i])
    neg_side = direction * (x0[:, 1] - 5.0 * DX) < -0.5 * DX
    to_neg = (row[bonds.i] & neg_side[bonds.j]) | (row[bonds.j] & neg_side[bonds.i])
    assert not np.any(cut & to_pos) and np.all(cut[to_neg])
    bonds.intact &= ~cut
    expected = bonds.damage()
    np.testing.assert_allclose(damage, expected, rtol=0, atol=1e-14)
    interior = (x0[:, 0] > 3.5 * DX) & (x0[:, 0] < 7.5 * DX)
    below = expected[interior & np.isclose(x0[:, 1], 4.0 * DX)]
    above = expected[interior & np.isclose(x0[:, 1], 6.0 * DX)]
    # the row off the line on the negative side loses its bonds to the row on the line too
    assert (below.min() > above.max()) == (direction == 1)


# --------------------------------------------------------------------------- dsif options

TD = sibling("test_dsif")    # its plate, exact crack-face field and runner


def run_k(lmp, body, args, nprocs=1):
    return TD.run_k(lmp, body, args, nprocs=nprocs)


def test_dsif_offset_selects_the_face_rows(lmp):
    """An extra opening that grows with the distance from the crack line, sgn(q) A sqrt(r)
    (|q| - 1/2) with A the field's opening amplitude: zero on the rows at |q| = 1/2, so the
    default offset (dx/2) still gives K_I; 'offset 1.5' reads the rows at |q| = 3/2, where the
    opening per sqrt(r) is twice the field's, and must give 2 K_I (K_II unchanged)."""
    _, a2 = TD.face_amplitudes(TD.YOUNGS, TD.IMPLIED_NU["plane/stress"], "stress")
    q, s = "f_ref[2]", "(f_ref[1]-0.5)"
    r = f"(({s}<0)*abs({s}))"
    body = TD.field_script() + (
        f"variable uy2 atom ({q}/abs({q}))*{a2!r}*sqrt({r})*(abs({q})-0.5)\n"
        "displace_atoms all move 0.0 v_uy2 0.0 units box\n")
    assert run_k(lmp, body, "tip 0.5 0.0") == pytest.approx((TD.K_I, TD.K_II), rel=TD.RTOL)
    ki, kii = run_k(lmp, body, "tip 0.5 0.0 offset 1.5")
    assert (ki, kii) == pytest.approx((2.0 * TD.K_I, TD.K_II), rel=TD.RTOL)


def test_dsif_tolerance(lmp):
    """r1 = 1.3 dx puts the r1 face points 0.3 dx from the nearest node: 'tolerance 0.25' is
    an ERROR naming the point, 'tolerance 0.35' reads that node (K exact for the field)."""
    with pytest.raises(LammpsError) as err:
        run_k(lmp, TD.field_script(), "tip 0.5 0.0 r1 1.3 r2 3.0 tolerance 0.25")
    assert "within tolerance 0.25 of the upper-face r1 face point" in err.value.message
    ki, kii = run_k(lmp, TD.field_script(), "tip 0.5 0.0 r1 1.3 r2 3.0 tolerance 0.35")
    assert (ki, kii) == pytest.approx((TD.K_I, TD.K_II), rel=TD.RTOL)


@pytest.mark.parametrize("nprocs", [1, 2])
def test_dsif_ties_go_to_the_smaller_atom_id(lmp, nprocs):
    """A face point midway between two nodes (tip at x = 1.5, r1 = 1.5: the nodes at x = -0.5
    and 0.5, on different ranks with 'processors 2 1 1') takes the one with the smaller atom
    ID, x = -0.5 (create_atoms numbers a row left to right, and rank 0 first), so K is that
    of r1 = 2. An extra opening linear in r makes the extrapolation depend on which node
    is read (r1 = 1 gives another K)."""
    body = TD.field_script(tip=(1.5, 0.0))
    if nprocs == 2:
        body = body.replace("lattice", "processors 2 1 1\nlattice", 1)
    q, s = "f_ref[2]", "(f_ref[1]-1.5)"
    r = f"(({s}<0)*abs({s}))"
    body += (f"variable uy2 atom ({q}/abs({q}))*1.0e-6*{r}\n"
             "displace_atoms all move 0.0 v_uy2 0.0 units box\n")
    tie = run_k(lmp, body, "tip 1.5 0.0 r1 1.5 r2 3.0 tolerance 0.6", nprocs=nprocs)
    far = run_k(lmp, body, "tip 1.5 0.0 r1 2.0 r2 3.0", nprocs=nprocs)
    near = run_k(lmp, body, "tip 1.5 0.0 r1 1.0 r2 3.0", nprocs=nprocs)
    assert tie == pytest.approx(far, rel=1e-14)
    assert abs(near[0] - far[0]) > 1e-3 * abs(far[0])

"""Kalthoff-Winkler struck by the experiment's projectile (examples/kalthoff-winkler, -var
loading projectile; README "Projectile").

At dx = 2 mm (default suite): the total momentum of projectile + plate is conserved to
round-off while they touch; the interface speed and the time the contact opens against the 1D
two-bar estimate (impedance ratio 4.36, 2 Lp / c), with the measured differences; the two
cracks are mirror images; no bond joins the bodies (the bond count is the plate's plus the
projectile's own, and 'bonds yes' would add the pairs across the gap); 1 and 2 ranks give the
same bits; and the default prescribed loading gives the bits of the script before the
projectile existed (digests of a run made with main at 1b2c9fb).
"""
import hashlib
import re

import numpy as np
import pytest
from scipy.spatial import cKDTree

from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import kalthoff_winkler_projectile as kwp
from bbpd.runner import run_lammps
from scenes import kw_run

DX = 2.0e-3
TEND = "85e-6"        # past the contact's opening (71 us at 2 mm), before it touches again

# tips.dat, damage.dump and final.dump of 'tools/lmp -in in.kalthoff_winkler -var dx 2.0e-3'
# (default variables: Gaussian, prescribed loading, 70 us) with the script and plugin of main
# at commit 1b2c9fb, before the projectile was added
MAIN_DIGESTS = {
    "tips.dat": "a35044397661e8e1e68eef334b6a1b3674317a4e7654e2e8612228fd4138b443",
    "damage.dump": "2f852cfa97d0dcfb82db55400d368afca746fa4c1d074c0ef17ee6a14c15bfbf",
    "final.dump": "de97c220f3e6f93042fa33088fe8fb4520d0e0a2bd2fb9f8d60cf39d128f00e2",
}


def run(work, nprocs=1, script=None, **variables):
    return kw_run(work, DX, nprocs, script, **variables)


def total_bonds(work):
    return int(re.search(r"total bonds (\d+)", (work / "log.lammps").read_text())[1])


@pytest.fixture(scope="module")
def projectile(tmp_path_factory):
    base = tmp_path_factory.mktemp("kw-projectile")
    one = run(base / "np1", loading="projectile", tend=TEND)
    two = run(base / "np2", nprocs=2, loading="projectile", tend=TEND)
    return one, two, kwp.analyse(one)


@pytest.fixture(scope="module")
def prescribed(tmp_path_factory):
    return run(tmp_path_factory.mktemp("kw-prescribed") / "default")


def test_default_prescribed_loading_has_the_bits_of_main(prescribed):
    for name, digest in MAIN_DIGESTS.items():
        assert hashlib.sha256((prescribed / name).read_bytes()).hexdigest() == digest, name


def test_momentum_is_conserved_to_round_off(projectile):
    """No external force acts on the two bodies: the x momentum stays at the projectile's
    m v0 (measured drift 1.5e-14 of it), while the plate takes about half of it."""
    _, _, r = projectile
    assert r["momentum_drift"] < 1e-13
    assert r["momentum_y"] < 1e-14
    # not trivially conserved: the contact moved ~half the momentum into the plate
    assert 0.4 < r["px_plate_end"] < 0.7


def test_interface_speed_is_the_two_bar_estimate(projectile):
    """Mean speed of the faces in contact over 2-18.5 us: 25.92 m/s measured against
    v0 r / (r + 1) = 26.03 m/s (-0.4 %); not v0 / 2 = 16 m/s (equal impedances), not v0."""
    _, _, r = projectile
    assert kwp.V_INTERFACE == pytest.approx(26.03, abs=0.01)
    assert abs(r["v_interface"] / kwp.V_INTERFACE - 1.0) < 0.02
    # both faces move at that speed (they do not come apart nor run into each other)
    assert abs(r["v_plate_face"] - r["v_proj_face"]) < 1.0


def test_contact_opens_later_than_two_l_over_c(projectile):
    """The 1D bars of equal length separate at 2 Lp / c = 37.0 us (plane wave) or 39.2 us
    (plane-strain strip).  Measured at 2 mm: the contact force falls to half its early mean
    at 48.2 us and the contact opens at 71.0 us, 1.8x the strip's 2 Lp / c: the plate is no
    bar (its struck strip widens past the notch tips)."""
    _, _, r = projectile
    two_l_c_plane, two_l_c_strip = r["two_l_over_c_us"]
    assert two_l_c_plane == pytest.approx(37.0, abs=0.1)
    assert two_l_c_plane < r["t_drop_us"] < r["t_open_us"]
    assert r["t_open_us"] / two_l_c_strip == pytest.approx(1.81, abs=0.05)
    assert r["t_retouch_us"] is None          # open until the end of the run
    d = kwp.read_projectile(projectile[0] / "projectile.dat")
    gap = d["x_plate"][-1] - d["x_proj"][-1]
    assert gap > 0.9 * DX                     # the faces moved apart: nothing holds them


def test_cracks_are_mirror_images(projectile):
    _, _, r = projectile
    assert r["length_end_mm"] > 20.0          # there are cracks to compare
    assert r["symmetry_tip_mm"] < 1e-12
    assert r["symmetry_phi"] < 1e-12


def projectile_own_bonds(ncol, nrow):
    """Bonds of an ncol x nrow grid with horizon 5 dx: pairs closer than 5.5 dx (eq. 19)."""
    p = np.array([(i, j) for i in range(ncol) for j in range(nrow)], dtype=float)
    return len(cKDTree(p).query_pairs(5.5 - 1e-9))


def test_no_bond_joins_the_bodies(projectile, prescribed, tmp_path):
    """Total bonds = the plate's (the prescribed run) + the projectile's own; with 'bonds yes'
    the pairs across the 0.9 dx gap would be bonds too (negative control)."""
    one, _, r = projectile
    nrow = round((r["yhi"] - r["ylo"]) / DX)
    own = projectile_own_bonds(r["ncol"], nrow)
    assert total_bonds(one) == total_bonds(prescribed) + own
    text = kw.EXAMPLE.read_text()
    cut = "${delta} bonds no"
    assert text.count(cut) == 1
    joined = run(tmp_path / "joined", script=text.replace(cut, "${delta} bonds yes"),
                 loading="projectile", tend="1e-7")
    # in grid spacings: the plate's cells centred at (i + 1/2, j + 1/2), the projectile's front
    # column at x = -0.4 and its rows between the notch lines
    j0 = round(r["ylo"] / DX)
    xp = np.array([(-0.4 - i, j0 + 0.5 + j) for i in range(r["ncol"]) for j in range(nrow)])
    xs = np.array([(0.5 + i, 0.5 + j) for i in range(round(r["Lx"] / DX))
                   for j in range(round(r["Ly"] / DX))])
    across = sum(len(n) for n in cKDTree(xs).query_ball_point(xp, 5.5 - 1e-9))
    assert across > 0
    assert total_bonds(joined) == total_bonds(one) + across


def test_one_and_two_ranks_give_the_same_bits(projectile):
    """Every atom's position and damage is the same bits on 1 and 2 ranks; the monitors are
    sums over atoms (compute reduce), whose order follows the ranks: equal to round-off."""
    one, two, _ = projectile
    for name in ("damage.dump", "final.dump"):
        assert (one / name).read_bytes() == (two / name).read_bytes(), name
    for name in ("projectile.dat", "tips.dat"):
        a, b = (np.loadtxt(w / name, comments="#") for w in (one, two))
        assert a.shape == b.shape
        scale = np.abs(a).max(axis=0)
        if name == "projectile.dat":
            scale[4] = scale[3]          # y momentum: round-off of the x momentum's size
        assert np.all(np.abs(a - b) <= 1e-12 * scale), name


@pytest.mark.slow
def test_3d_plate_conserves_momentum_and_is_mirror_symmetric(tmp_path):
    """in.kalthoff_winkler_3d at dx = 3 mm (three layers, 8,118 atoms), 40 us: momentum to
    round-off, and the damage the same in mirror atoms about the mid-line and the mid-plane."""
    from bbpd import readers
    work = tmp_path / "3d"
    run_lammps(str(kwp.EXAMPLE_3D), work, vars={"dx": "3.0e-3", "tend": "40e-6"})
    r = kwp.analyse(work)
    assert r["setup"] == "3d" and r["loading"] == "projectile"
    assert r["momentum_drift"] < 1e-13
    assert abs(r["v_interface"] / kwp.V_INTERFACE - 1.0) < 0.03
    _, d = readers.dump_snapshots(work / "final3d.dump")[-1]
    x, y, z, phi = d["f_ref[1]"], d["f_ref[2]"], d["f_ref[3]"], d["c_dmg"]
    assert phi.max() > 0.3                                # cracks have started
    key = {(round(a / 1.5e-3), round(b / 1.5e-3), round(c / 1.5e-3)): p
           for a, b, c, p in zip(x, y, z, phi)}
    Ly, Lz = 0.198, 0.009
    for a, b, c, p in zip(x, y, z, phi):
        assert abs(p - key[(round(a / 1.5e-3), round((Ly - b) / 1.5e-3), round(c / 1.5e-3))]) < 1e-12
        assert abs(p - key[(round(a / 1.5e-3), round(b / 1.5e-3), round((Lz - c) / 1.5e-3))]) < 1e-12

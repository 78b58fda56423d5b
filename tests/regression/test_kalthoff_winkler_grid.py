"""Kalthoff-Winkler on perturbed and rotated grids (examples/kalthoff-winkler, -var grid; README
"The grid's pull").

At dx = 2 mm (default suite): `-var grid square` gives the default's bits; the perturbed grid's points move by at most
perturb x dx, by different amounts, the same on 1 and 2 ranks, and become the reference
configuration (no point far from the impact moves in the first steps: with stale reference
positions every bond would start stretched); the rotated grid's rows run at gridangle; on both
grids no notch face touches the other at t = 0 under contact, and the perturbed grid's
reference positions are the moved points (negative control: without the data-file round trip
they are not); and one grid-pull case reproduces its committed CSV row. The pull
arithmetic is checked on made-up rows.
"""
import math

import numpy as np
import pytest
from scipy.spatial import cKDTree

from bbpd import csvfile, readers
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import kalthoff_winkler_grid as kwg
from scenes import kw_run

DX = 2.0e-3
A, YLO, YHI = 0.050, 0.074, 0.126          # notch tip x and notch lines at 2 mm
DT = 8.7e-8 * DX / 1.0e-3                   # the script's time step at 2 mm
SHORT = repr(1.999 * DT)                    # two steps


def run(work, nprocs=1, script=None, **variables):
    return kw_run(work, DX, nprocs, script, **variables)


def snapshots(work):
    snaps = readers.dump_snapshots(work / "final.dump")
    return snaps[0][1], snaps[-1][1]


def reference(work):
    d, _ = snapshots(work)
    return d["f_ref[1]"], d["f_ref[2]"]


def notch_distance(x, y):
    """Distance of each point from the nearer notch segment (x <= A on y = YLO or YHI)."""
    return np.minimum(*(np.hypot(np.maximum(x - A, 0.0), y - yn) for yn in (YLO, YHI)))


def moved_beyond_the_wave(work):
    """How far the points beyond two horizons from the struck edge (x > 20 mm) have moved (m)
    in the two steps of the run: 0 unless a force acted there at t = 0 (the projectile touches
    the plate with zero force then; a bond reaches one horizon per step)."""
    _, d = snapshots(work)
    far = d["f_ref[1]"] > 0.020
    assert far.sum() > 3000
    moved = np.hypot(d["x"][far] - d["f_ref[1]"][far], d["y"][far] - d["f_ref[2]"][far])
    return moved.max()


def test_grid_square_is_the_default_bit_for_bit(tmp_path):
    """-var grid square gives the default's bits; the default's are those of the script before
    the grids and the projectile existed (test_kalthoff_winkler_projectile.py,
    test_default_prescribed_loading_has_the_bits_of_main, checks them against main's digests)."""
    default = run(tmp_path / "default", tend="30e-6")
    square = run(tmp_path / "square", tend="30e-6", grid="square")
    for f in ("tips.dat", "damage.dump", "final.dump"):
        ref = (default / f).read_bytes()
        assert len(ref) > 1000 and (square / f).read_bytes() == ref, f
    perturbed = run(tmp_path / "perturbed", tend="30e-6", grid="perturbed")
    assert (perturbed / "tips.dat").read_bytes() != (default / "tips.dat").read_bytes()


@pytest.fixture(scope="module")
def perturbed(tmp_path_factory):
    base = tmp_path_factory.mktemp("kw-perturbed")
    return (run(base / "square", tend=SHORT, loading="projectile"),
            run(base / "np1", tend=SHORT, loading="projectile", grid="perturbed"),
            run(base / "np2", nprocs=2, tend=SHORT, loading="projectile", grid="perturbed"))


def test_perturbed_grid_moves_the_points_as_documented(perturbed):
    square, one, two = perturbed
    xs, ys = reference(square)
    xp, yp = reference(one)
    ux, uy = (xp - xs) / DX, (yp - ys) / DX
    # uniform in [-0.2, 0.2]: |u| <= 0.2, its mean |u| 0.1, and not one value for all points
    assert np.abs(ux).max() <= 0.2 + 1e-9 and np.abs(uy).max() <= 0.2 + 1e-9
    bulk = (xs > DX) & (notch_distance(xs, ys) > 1.01 * DX)
    assert np.abs(ux[bulk]).mean() == pytest.approx(0.1, abs=0.01)
    assert np.abs(uy[bulk]).mean() == pytest.approx(0.1, abs=0.01)
    assert np.abs(ux[bulk]).max() > 0.19
    # the struck edge's column stays; near the notches the points move along them only
    edge = xs < DX
    assert np.all(ux[edge] == 0.0) and np.all(uy[edge] == 0.0)
    near = ~edge & (notch_distance(xs, ys) < DX)
    assert near.sum() == 100 and np.all(uy[near] == 0.0) and np.abs(ux[near]).max() > 0.1
    # the same points on 2 ranks (the offsets are seeded by the point's position)
    x2, y2 = reference(two)
    assert np.array_equal(x2, xp) and np.array_equal(y2, yp)


def test_perturbed_grid_is_the_reference_configuration(perturbed):
    """Nothing moves ahead of the wave: the moved points are the bonds' reference positions,
    and no notch face pushes the other (contact is on with the projectile)."""
    _, one, two = perturbed
    assert moved_beyond_the_wave(one) == 0.0
    assert moved_beyond_the_wave(two) == 0.0


def test_rotated_grid_rows_run_at_the_angle(tmp_path):
    work = run(tmp_path / "rotated", tend=SHORT, loading="projectile", grid="rotated",
               gridangle=30)
    x, y = reference(work)
    p = np.column_stack([x, y])
    bulk = x > 5 * DX
    _, idx = cKDTree(p).query(p[bulk], k=2)
    d = p[idx[:, 1]] - p[bulk]
    assert np.hypot(d[:, 0], d[:, 1]) == pytest.approx(DX, rel=1e-6)
    ang = np.degrees(np.arctan2(d[:, 1], d[:, 0])) % 90.0
    assert ang == pytest.approx(30.0, abs=1e-5)
    assert (np.abs(x - 0.5 * DX) < 1e-9).sum() == 100          # the square grid's edge column
    assert len(x) == pytest.approx(5000, rel=0.01)              # the plate's area / dx^2
    # no two points closer than the contact distance on opposite sides of a notch
    for yn in (YLO, YHI):
        below, above = p[(y < yn) & (x < A + DX)], p[(y > yn) & (x < A + DX)]
        assert cKDTree(below).query(above)[0].min() >= 0.9 * DX
    assert moved_beyond_the_wave(work) == 0.0


def test_without_the_round_trip_the_perturbed_bonds_start_stretched(tmp_path):
    """Negative control of test_perturbed_grid_is_the_reference_configuration: without the
    write_data / read_data round trip the reference positions stay on the square grid, every
    bond of a moved point starts stretched, and points move everywhere at once."""
    text = kw.EXAMPLE.read_text()
    trip = ("write_data      perturbed_grid.data nocoeff\ndelete_atoms    group all\n"
            "read_data       perturbed_grid.data add append\n")
    assert trip in text
    script = tmp_path / "in.stale"
    script.write_text(text.replace(trip, ""))
    work = run(tmp_path / "stale", script=str(script), tend=SHORT, loading="projectile",
               grid="perturbed")
    assert moved_beyond_the_wave(work) > 1e-9


def test_perturbed_projectile_touches_at_the_smaller_contact_distance(perturbed):
    """The perturbed grid's contact distance is 0.9 (1 - 2 perturb) dx = 0.54 dx (its points
    can be 0.6 dx apart), and the projectile's front column starts that far from the plate."""
    square, one, _ = perturbed
    for work, dc in ((square, 0.9), (one, 0.54)):
        assert f"contact: on, distance {dc * DX:g}" in (work / "log.lammps").read_text()
        d = np.loadtxt(work / "projectile.dat")
        assert d[0, 8] - d[0, 9] == pytest.approx(dc * DX, rel=1e-9)     # plate face - front
        assert abs(d[0, 5]) < 1e-9 * abs(d[1, 5])                         # no force at t = 0


CASES = [pytest.param("rotated-30", "prescribed", 2.0e-3, id="rotated-30-prescribed-2mm"),
         pytest.param("perturbed-1", "projectile", 1.0e-3, id="perturbed-1-projectile-1mm",
                      marks=pytest.mark.slow)]


@pytest.mark.parametrize("grid,loading,dx", CASES)
def test_a_grid_pull_case_gives_its_committed_row(tmp_path, grid, loading, dx):
    """A grid-pull case (Gaussian, to 100 us; the 2 mm one a few seconds, the 1 mm one about a
    minute of CPU) gives the committed CSV's angles to its printed precision (the runs are
    deterministic); its two cracks differ, which on the square grid they cannot (mirror
    images); and the damage stays in crack bands (with the projectile and a contact distance
    above the perturbed grid's closest spacing the plate shattered)."""
    _, rows = csvfile.read_csv(kwg.CSV)

    def find(g):
        return next(r for r in rows if r["grid"] == g and r["loading"] == loading
                    and r["kernel"] == "gaussian" and r["dx_mm"] == dx * 1e3)
    ref, square = find(grid), find("square")
    work = tmp_path / grid
    got = kwg.row(kwg.run_case(work, "gaussian", dx, loading, grid), grid)
    for d in kwg.ANGLES:
        for s in kwg.SIDES:
            assert got[f"{d}_{s}_deg"] == pytest.approx(ref[f"{d}_{s}_deg"], abs=1e-3), (d, s)
        assert square[f"{d}_lo_deg"] == pytest.approx(square[f"{d}_hi_deg"], abs=1e-9)
    assert abs(got["fit_lo_deg"] - got["fit_hi_deg"]) > 0.5
    assert got["first_bond_us"] == pytest.approx(ref["first_bond_us"], abs=1e-3)
    _, end = snapshots(work)
    assert (end["c_dmg"] >= kw.PHI_CRACK).mean() < 0.1


def made_up_row(grid, lo, hi, kernel="gaussian", loading="prescribed"):
    r = {"grid": grid, "loading": loading, "kernel": kernel, "dx_mm": 2.0}
    for d in kwg.ANGLES:
        r[f"{d}_lo_deg"], r[f"{d}_hi_deg"] = lo, hi
    return r


def test_pull_is_square_minus_the_off_grid_mean():
    rows = [made_up_row("square", 60.0, 60.0), made_up_row("perturbed-1", 62.0, 64.0),
            made_up_row("rotated-30", 66.0, None)]
    p = kwg.pull(rows)[("prescribed", "gaussian", 2.0, "fit")]
    assert p["square"] == 60.0 and p["n"] == 3 and p["mean"] == pytest.approx(64.0)
    assert p["pull"] == pytest.approx(-4.0)
    assert p["sd"] == pytest.approx(2.0) and p["se"] == pytest.approx(2.0 / math.sqrt(3))
    table = kwg.pull_table(rows)
    assert "| gaussian | initial | 60.0 | 64.0 (3) | -4.0 ± 1.2 | yes |" in table
    assert sum(kwg.significant(q) for q in kwg.pull(rows).values()) == 3
    # no off-grid crack long enough: no pull
    assert kwg.pull([made_up_row("square", 60.0, 60.0), made_up_row("rotated-30", None, None)]) == {}

"""Kalthoff-Winkler impact benchmark (paper sec. 4.2.3, examples/kalthoff-winkler).

Default suite: the Gaussian kernel at dx = 2 mm (5,000 atoms, 403 steps, a few seconds on
2 ranks).  Slow: all three kernels at the paper's dx = 1 mm.

The cracks must start at the notch tips (the first bond that breaks anywhere in the plate is
within a horizon of a tip, and not before the impact wave can have reached it), run outward
at the angle of the convergence table, mirror each other about y = 100 mm, and nothing else may
break apart from the far-edge crack that the reflected wave opens (README, "far-edge crack").
"""
import math

import pytest

from bbpd.benchmarks import kalthoff_winkler as kw
from scenes import drawn_kw_cracks

# What each run must reproduce: the values measured with this code (table of
# examples/kalthoff-winkler/README.md), per kernel and grid spacing (mm):
# (first broken bond at a tip (us), damage band leaves the tip (us), crack angle (deg)).
# These are regression values of our own model, not the experiment (70 deg) or the paper
# (initiation 20.0 / 20.8 / 21.7 us): the guard is that they do not move.  The margins are a
# few time steps (dt = 0.17 us at 2 mm, 0.087 us at 1 mm) and 1.5 deg, below the angle's
# change with the grid (Gaussian 58.8 / 61.1 / 62.3 deg at 2 / 1 / 0.5 mm), so a crack that
# does not kink, kinks the wrong way or runs at 45 or 90 deg fails, and so does an initiation
# that comes late (the upper bound) or before the wave can arrive (the lower bound).
MEASURED = {("constant", 2.0): (10.8, 20.2, 56.9), ("constant", 1.0): (11.3, 18.1, 60.0),
            ("triangular", 2.0): (12.0, 21.9, 57.3), ("triangular", 1.0): (11.8, 18.9, 61.1),
            ("gaussian", 2.0): (12.0, 23.0, 58.8), ("gaussian", 1.0): (12.4, 20.0, 61.1),
            ("gaussian", 0.5): (12.3, 17.4, 62.3)}
INIT_MARGIN_US = 0.5
BAND_MARGIN_US = 1.0
ANGLE_MARGIN_DEG = 1.5

# plane-strain P-wave speed for nu = 1/4 (lambda = mu): c_p = sqrt(3 mu / rho)
E, NU, RHO = 190.0e9, 0.25, 7800.0
C_P = math.sqrt(3.0 * E / (2.0 * (1.0 + NU)) / RHO)


def check_run(res):
    dx, delta = res["dx"], res["delta"]

    # initiation at the notch tips, both at the same step, after the wave can arrive there:
    # the tip is a - delta from the impacted layer and bonds reach delta + dx/2
    assert res["first_break_at_tip"], (res["t_first_break_us"], res["t_init_us"])
    assert res["t_init_lo_us"] == pytest.approx(res["t_init_hi_us"], abs=1e-9)
    t_arrival_us = (res["a"] - 2.0 * delta - dx) / C_P * 1e6
    assert res["t_init_us"] > t_arrival_us
    t_init, t_band, angle = MEASURED[(res["kernel"], round(dx * 1e3, 3))]
    assert res["t_init_us"] == pytest.approx(t_init, abs=INIT_MARGIN_US)
    # the crack band leaves the tips later and the cracks grow past the fitting range
    assert res["t_band_us"] is not None and res["t_band_us"] > res["t_init_us"]
    assert res["t_band_us"] == pytest.approx(t_band, abs=BAND_MARGIN_US)
    for side in ("lo", "hi"):
        assert res[f"length_{side}_mm"] > kw.FIT_RANGE[1] * 1e3

    # angle from the notch direction towards the outer side
    for side in ("lo", "hi"):
        assert res[f"angle_{side}_deg"] == pytest.approx(angle, abs=ANGLE_MARGIN_DEG)

    # mirror symmetry about y = 100 mm: crack tips within one grid spacing at every snapshot,
    # and the damage fields alike to within a few bonds per atom
    assert res["symmetry_tip_mm"] <= dx * 1e3
    assert res["symmetry_phi"] < 0.05

    # no damage away from the notches and the two cracks, except the far-edge crack
    assert res["far_damage_other"] == 0, res["far_damage"]


@pytest.mark.parametrize("angle_deg", [45.0, 65.0, 80.0])
def test_path_measures_on_a_drawn_crack(angle_deg):
    """The post-processing alone: on a grid with two notches and two mirror cracks drawn at a
    known angle from the tips (crack rows at damage 0.44, as next to a cut), it finds the
    drawn tips and angle, and reports no far damage except a drawn far-edge spot."""
    L = 40.0e-3
    x, y, phi, g = drawn_kw_cracks(angle_deg, L)
    dx, th = g["dx"], math.radians(angle_deg)
    phi0 = phi.copy()                 # the run's damage at t = 0 would show the notches only
    phi0[~((x < g["a"]) & ((abs(y - g["ylo"]) < dx) | (abs(y - g["yhi"]) < dx)))] = 0.0
    phi[(x > 0.098) & (abs(y - 0.1) < 2 * dx)] = 0.2          # a far-edge spot
    phi[(abs(x - 0.020) < dx) & (abs(y - 0.1) < dx)] = 0.01    # one inside the impacted strip
    cr = kw.notch_cracks(x, y, phi, g)
    for side, yn, sign in (("lo", g["ylo"], -1.0), ("hi", g["yhi"], 1.0)):
        (xt, yt), length = kw.tip_of(x, y, cr[side], (g["a"], yn), dx)
        assert length == pytest.approx(L, abs=1.5 * dx)
        assert xt == pytest.approx(g["a"] + L * math.cos(th), abs=1.5 * dx)
        assert yt == pytest.approx(yn + sign * L * math.sin(th), abs=1.5 * dx)
        angle = kw.crack_angle(x, y, cr[side], (g["a"], yn), sign, fit_range=(5e-3, L))
        assert angle == pytest.approx(angle_deg, abs=1.0)
    far = kw.far_damage(x, y, phi, phi0, cr, g)
    assert sorted((c["far_edge"], c["atoms"]) for c in far) == [(False, 4), (True, 8)]


def test_gaussian_dx2mm(lmp, tmp_path):
    lmp(kw.EXAMPLE.read_text(), nprocs=2, vars={"kernel": "gaussian", "dx": "2.0e-3"})
    res = kw.analyse(tmp_path)
    check_run(res)


@pytest.fixture(scope="module")
def runs_dx1mm(tmp_path_factory):
    work = tmp_path_factory.mktemp("kalthoff-winkler")
    return {k: kw.run(k, 1.0e-3, work / k, nprocs=2) for k in kw.KERNELS}


@pytest.mark.slow
@pytest.mark.parametrize("kernel", ["triangular", "gaussian"])
def test_kernels_dx1mm(runs_dx1mm, kernel):
    check_run(runs_dx1mm[kernel])


@pytest.mark.slow
def test_constant_dx1mm(runs_dx1mm):
    """The constant kernel breaks a few bonds at the inner face of the impact layer
    (damage <= 0.02, about one bond per atom): allowed there, and only there."""
    res = runs_dx1mm["constant"]
    other = [c for c in res["far_damage"] if c["x_mm"][1] <= (res["Lx"] - res["delta"]) * 1e3]
    for c in other:
        assert c["x_mm"][1] <= (res["delta"] + res["dx"]) * 1e3 and c["max_phi"] < 0.02, c
    res = dict(res, far_damage=[c for c in res["far_damage"] if c not in other],
               far_damage_other=0)
    check_run(res)


@pytest.mark.slow
def test_initiation_order_dx1mm(runs_dx1mm):
    """Paper: the crack leaves the tip first with the constant kernel, then the triangular,
    then the Gaussian (20.0, 20.8, 21.7 us); the damage-band time orders the same way."""
    t = [runs_dx1mm[k]["t_band_us"] for k in ("constant", "triangular", "gaussian")]
    assert t[0] < t[1] < t[2]
    for k in kw.KERNELS:
        assert runs_dx1mm[k]["t_band_us"] == pytest.approx(kw.PAPER_INITIATION_US[k], abs=3.0)

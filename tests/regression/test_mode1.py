"""Stationary Mode-I semi-infinite crack (paper sec. 4.2.1, examples/mode1-semi-infinite)
against Freund's solution (eq. 42) with the error metrics of eqs. 44-45.

Default suite: Gaussian kernel at dx = 0.05 m (16,000 atoms, 240 steps) and
a check that the top-row body force carries the edge traction into the plate.
Slow: the resolution sweep (Table 2) and the three kernels (Table 3).

Measured errors (%, consistent convention: the BBPD model's own nu and wave speed),
README.md of the example:
    Gaussian  dx = 0.1: peak 1.19 L2 4.39   0.05: 1.70 2.33   0.025: 0.83 1.57
    dx = 0.05 constant 14.43 13.41, triangular 5.93 6.32
Tolerances at dx = 0.05: the measured value plus a margin of 0.5 points (peak 2.2, L2 2.8),
less than the change from 0.05 to 0.025 m (0.9 peak, 0.8 L2), so the measured values are what
is guarded.  A micromodulus 10 % too stiff (E x 1.1 in pair_coeff, the analytic solution and
the DSIF keep E) gives peak 4.72 L2 3.71 and fails both: test_stiffer_micromodulus_fails.
The paper convention (nu = 0.3, C_d = 5944 m/s instead of the model's 5434 m/s) has a 9 %
earlier arrival in the reference, which dominates its L2 (6.4-6.9 % at all three grids).

K_I from the J-integral (compute bbpd/jintegral, annulus 0.5-1.5 m, consistent convention),
measured peak / L2:
    Gaussian  dx = 0.1: 0.14 0.67   0.05: 0.30 0.27   0.025: 0.30 0.14
    triangular 0.51 1.14 / 0.49 0.64 / 0.39 0.51; constant 0.49 1.63 / 1.55 1.00 / 1.40 0.87
Tolerances: Gaussian at 0.05 m 1.0 / 1.0 %; every kernel and grid 2.5 / 2.5 %.
"""
import re

import pytest

from bbpd.benchmarks import mode1
from scenes import peri_preamble

PEAK_TOL = 2.2        # % (consistent convention; measured 1.70)
L2_TOL = 2.8          # % (measured 2.33)
PAPER_PEAK_TOL = 3.0  # % (paper convention: measured 0.8-2.2)
PAPER_L2_TOL = 7.5    # % (measured 6.4-6.9)
KII_TOL = 0.01        # K_II / K_I inside the window: zero by symmetry (measured 2e-3)
J_PEAK_TOL = 1.0      # % K_I from J, Gaussian at dx = 0.05 (measured 0.30)
J_L2_TOL = 1.0        # % (measured 0.27)
J_SWEEP_TOL = 2.5     # % peak and L2 of K_I from J, any kernel and grid (measured <= 1.63)
J_KII_TOL = 0.02      # K_II / K_I from the interaction integral (measured 2e-3 to 7e-3)


def test_gaussian_dx005_matches_freund(tmp_path):
    res = mode1.run(tmp_path, "gaussian", 0.05)
    c, p = res["consistent"], res["paper"]
    print(f"consistent peak {c['peak']:.2f} L2 {c['l2']:.2f}; paper peak {p['peak']:.2f} "
          f"L2 {p['l2']:.2f}; wall {res['wall_time']:.1f} s")
    assert c["peak"] < PEAK_TOL and c["l2"] < L2_TOL
    assert p["peak"] < PAPER_PEAK_TOL and p["l2"] < PAPER_L2_TOL
    assert res["kii_over_ki"] < KII_TOL
    j = res["jintegral"]["consistent"]
    print(f"K_I from J: peak {j['peak']:.2f} L2 {j['l2']:.2f}")
    assert j["peak"] < J_PEAK_TOL and j["l2"] < J_L2_TOL
    check_j_mode_mixity(res)
    # the paper's dt = 5e-6 s is well inside the stable bound at this grid; the setup line
    # that reports it must be there (a changed line would drop the check silently)
    assert res["dt_fraction_of_limit"] is not None, "no 'timestep = ... of the limit' line"
    assert 0.0 < res["dt_fraction_of_limit"] < 0.8


def test_stiffer_micromodulus_fails(tmp_path):
    """The negative control of the tolerances: E x 1.1 in pair_coeff only (the analytic
    solution and the DSIF keep E) must fail them (measured peak 4.72, L2 3.71)."""
    res = mode1.run(tmp_path, "gaussian", 0.05, efactor=1.1)
    c = res["consistent"]
    print(f"E x 1.1: consistent peak {c['peak']:.2f} L2 {c['l2']:.2f}")
    assert c["peak"] > PEAK_TOL and c["l2"] > L2_TOL


def check_j_mode_mixity(res):
    """Mode I by symmetry: K_II of the interaction integral vanishes inside the window."""
    exact, t_c = mode1.reference("consistent")
    w = res["t"] <= 3.0 * t_c
    assert abs(res["kii_j"][w]).max() < J_KII_TOL * abs(res["k_j"][w]).max()


FAR_FIELD = peri_preamble(2, lattice="sq {dx} origin 0.5 0.5 0.0") + """\
region plate block 0.0 10.0 -2.0 2.0 -0.5 0.5 units box
create_box 1 plate
create_atoms 1 region plate
set group all density 8000
set group all volume {vol}
pair_style bbpd/gaussian {model} thickness {dx}
pair_coeff * * 210e9 none {delta}
region top block INF INF {ytop} INF INF INF units box
group top region top
region ra block 3 7 {ya0} {ya1} INF INF units box
region rb block 3 7 {yb0} {yb1} INF INF units box
group ra region ra
group rb region rb
variable sigma equal {sigma0}*(time/{td}*(time<{td})+(time>={td}))
variable bload equal v_sigma/{dx}
fix load top addforce 0.0 v_bload 0.0
fix integrate all nve
fix 2d all enforce2d
variable gap0 equal $(xcm(ra,y)-xcm(rb,y))
variable strain equal (xcm(ra,y)-xcm(rb,y)-v_gap0)/v_gap0
fix avg all ave/time 1 31 160 v_strain
timestep 5e-6
thermo_style custom step f_avg
thermo_modify format float %.12g
run 160
"""


@pytest.mark.parametrize("model,modulus", [("plane/stress", 9.0 / 8.0),   # E/(1-nu^2), nu = 1/3
                                           ("plane/strain", 6.0 / 5.0)])  # E(1-nu)/((1+nu)(1-2nu))
def test_top_row_force_density_is_the_edge_traction(lmp, model, modulus):
    """sigma/dx on the top row of atoms = traction sigma on the edge: after the ramp has passed
    two rows 0.5 and 1.5 m below the top (t >= 6.5e-4 s, before any reflection or edge wave),
    the strain between them is sigma0/M, M the P-wave modulus of the BBPD model."""
    dx, sigma0 = 0.1, 1.0e6
    script = FAR_FIELD.format(dx=dx, vol=dx**3, model=model, delta=5 * dx, ytop=2.0 - dx,
                              ya0=1.5 - dx / 2, ya1=1.5 + dx / 2, yb0=0.5 - dx / 2,
                              yb1=0.5 + dx / 2, sigma0=sigma0, td=mode1.T_D)
    out = lmp(script).output
    # average of steps 130-160 (t = 6.5e-4 ... 8e-4 s) printed at step 160
    strain = float(re.findall(r"^\s*160\s+(\S+)", out, re.M)[-1])
    expect = sigma0 / (modulus * 210e9)
    # measured within 0.2 %; 1 % leaves room for the dispersive ripple of the ramp
    assert strain == pytest.approx(expect, rel=0.01)


@pytest.mark.slow
def test_resolution_sweep_converges(tmp_path):
    """Table 2: the L2 error falls with dx and the finest grid meets the tolerances."""
    l2 = []
    for dx in (0.1, 0.05, 0.025):
        res = mode1.run(tmp_path / f"dx{dx}", "gaussian", dx)
        l2.append(res["consistent"]["l2"])
        j = res["jintegral"]["consistent"]
        assert j["peak"] < J_SWEEP_TOL and j["l2"] < J_SWEEP_TOL
        check_j_mode_mixity(res)
        print(dx, res["consistent"], res["paper"], f"{res['wall_time']:.1f} s")
    assert l2[0] > l2[1] > l2[2]
    assert res["consistent"]["peak"] < PEAK_TOL and res["consistent"]["l2"] < L2_TOL


@pytest.mark.slow
def test_kernel_ranking(tmp_path):
    """Table 3: at dx = 0.05 the Gaussian kernel has the smallest errors, then the
    triangular, then the constant kernel (paper: 0.21/2.86, 5.99/6.56, 14.20/15.48)."""
    errs = {}
    for kernel in mode1.KERNELS:
        res = mode1.run(tmp_path / kernel, kernel, 0.05)
        errs[kernel] = res["consistent"]
        j = res["jintegral"]["consistent"]
        assert j["peak"] < J_SWEEP_TOL and j["l2"] < J_SWEEP_TOL, kernel
        print(kernel, res["consistent"], res["paper"], f"{res['wall_time']:.1f} s")
    for m in ("peak", "l2"):
        assert errs["gaussian"][m] < errs["triangular"][m] < errs["constant"][m]
    # measured triangular 5.93/6.32 and constant 14.43/13.41: within 2 points of the paper
    for kernel, (peak, l2) in mode1.PAPER_TABLE3.items():
        if kernel != "gaussian":
            assert errs[kernel]["peak"] == pytest.approx(peak, abs=2.0)
            assert errs[kernel]["l2"] == pytest.approx(l2, abs=2.5)


# The state-based style at the paper's nu = 0.3 (bbpd.benchmarks.mode1_lps,
# results/mode1_lps.csv): plane strain, where the paper's convention is the model's own.
# Measured, Gaussian at dx = 0.05 m: K_I from J peak 0.39 L2 0.54 %, DSIF L2 5.69 %.
LPS_J_TOL = 1.0       # % peak and L2 of K_I from J (measured 0.39 / 0.54)
LPS_L2_TOL = 6.2      # % DSIF L2 (measured 5.69: the margin of the bond-based test, 0.5)


def test_lps_nu03_matches_freund(tmp_path):
    res = mode1.run(tmp_path, "gaussian", 0.05, "plane/strain", family="lps", nu=0.3)
    j, c = res["jintegral"]["consistent"], res["consistent"]
    print(f"LPS nu 0.3: K_I from J peak {j['peak']:.2f} L2 {j['l2']:.2f}; DSIF L2 {c['l2']:.2f}")
    assert j["peak"] < LPS_J_TOL and j["l2"] < LPS_J_TOL
    assert c["l2"] < LPS_L2_TOL
    # the same K_I(t) against Freund's curve of nu = 1/4 (the bond-based plane-strain solid:
    # slower waves, another amplitude) misses: the test sees the Poisson's ratio
    wrong = mode1.errors(res["t"], res["k_j"], res["k_j"], "plane/strain", nu=0.25)["consistent"]
    assert wrong["l2"] > 2.0 * LPS_J_TOL

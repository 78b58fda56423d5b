"""Mode-II central crack under uniform shear (paper sec. 4.2.2, examples/mode2-central-crack).

Reference: the early-time analytic K_II of a semi-infinite crack whose faces see the shear 2 tau
of the two incident plane shear waves (python/bbpd/freund.py), valid from their arrival
(5.77 us) to the arrival of the P wave diffracted at the other tip (9.77 us).

1. The reference itself is checked against an independent classical solution of the same
   plate (explicit plane-strain finite elements, mode2.classical_fe): at h = 0.25 mm the peak
   error is 1.1 % (mode I, against Freund's eq.) and 0.9 % (mode II); 2.9/3.3 % at 0.5 mm and
   0.35/0.40 % at 0.125 mm, so it converges to the reference.  Tolerance 2 %.
2. BBPD with the paper's extraction (tip on the first intact column, r1 = dx, r2 = 2 dx)
   overestimates K_II: measured peak/L2 errors (%) 14-29 / 24-29 for the three kernels at
   dx = 1 and 0.5 mm (README of the example), the same at 0.25 mm; the plate's far-field
   shear strain is tau/mu within 5 %, so the excess is the near-tip sliding profile of the
   peridynamic crack.  The checks below are a regression guard around those numbers, not
   a verification: each run's peak and L2 errors must lie within MARGIN points of the value
   measured for that kernel and grid (README of the example, Results), on either side, so a
   change that moves K_II by more than ~1.5 % of the reference shows up.  A load on one edge
   only (half the amplitude) or a wrong wave speed fails.  The slow three-kernel run at
   0.5 mm reproduces its table row to the printed digits.
3. K_II from the J-integral (compute bbpd/jintegral, annulus 5-12.5 mm), which reads the field
   away from the tip, is on the reference: measured peak / L2 (%) and K_II/K_II,ref at the
   window end: dx = 1 mm constant 7.49 / 12.42 / 0.925, triangular 5.22 / 12.01 / 0.948,
   Gaussian 2.21 / 11.30 / 0.978; dx = 0.5 mm 4.74 / 7.48 / 0.953, 0.46 / 7.94 / 1.005,
   1.85 / 7.62 / 1.018; dx = 0.25 mm 2.58 / 4.44 / 0.974, 0.53 / 5.64 / 1.005,
   0.37 / 5.55 / 1.004 (the L2 error is the first microsecond, where K is small).  The
   extrapolation's excess is therefore in the near-tip reading, not in the field: asserted as
   |K_J/K_ref - 1| < 1/2 |K_dsif/K_ref - 1| at the window end.
"""
import re

import numpy as np
import pytest

from bbpd import metrics
from bbpd.benchmarks import mode2
from scenes import peri_preamble

FE_PEAK_TOL = 2.0     # % (measured 1.1 and 0.9 at h = 0.25 mm)
# measured (peak %, L2 %) per (kernel, dx), README of examples/mode2-central-crack
MEASURED = {("constant", 1.0e-3): (18.67, 28.57), ("triangular", 1.0e-3): (13.90, 25.11),
            ("gaussian", 1.0e-3): (20.47, 24.69), ("constant", 0.5e-3): (20.38, 24.52),
            ("triangular", 0.5e-3): (25.25, 23.60), ("gaussian", 0.5e-3): (28.85, 24.79)}
MARGIN = 1.5          # percentage points either side of the measured value
SYMMETRY_TOL = 1e-8   # left tip vs right tip (measured 2e-10)
KI_TOL = 1e-3         # K_I/K_II (measured 1e-4)
# K_II from J, measured (peak %, L2 %, K_II/K_II,ref at the window end) per (kernel, dx)
MEASURED_J = {("constant", 1.0e-3): (7.49, 12.42, 0.925), ("triangular", 1.0e-3): (5.22, 12.01, 0.948),
              ("gaussian", 1.0e-3): (2.21, 11.30, 0.978), ("constant", 0.5e-3): (4.74, 7.48, 0.953),
              ("triangular", 0.5e-3): (0.46, 7.94, 1.005), ("gaussian", 0.5e-3): (1.85, 7.62, 1.018)}
J_END_MARGIN = 0.01   # on K_II/K_II,ref at the window end


@pytest.mark.parametrize("mode", [1, 2])
def test_reference_matches_classical_fe(mode):
    t, k = mode2.classical_fe(mode, h=0.25e-3)
    win = mode2.classical_window(mode)
    peak = 100 * metrics.peak_relative_error(t, k, mode2.classical_reference(mode), win)
    assert peak < FE_PEAK_TOL


SHEAR_FAR_FIELD = peri_preamble(2, lattice="sq {dx} origin 0.5 0.5 0.0") + """\
region plate block -0.052 0.052 -0.02 0.02 -0.5 0.5 units box
create_box 1 plate
create_atoms 1 region plate
set group all density {rho}
set group all volume {vol}
pair_style bbpd/gaussian plane/strain thickness {dx}
pair_coeff * * {E} none {delta}
region top block INF INF {ytop} INF INF INF units box
region bottom block INF INF INF {ybot} INF INF units box
group top region top
group bottom region bottom
fix loadtop top addforce {btop} 0.0 0.0
fix loadbot bottom addforce {bbot} 0.0 0.0
region ra block -0.01 0.01 0.0140 0.0150 INF INF units box
region rb block -0.01 0.01 0.0040 0.0050 INF INF units box
group ra region ra
group rb region rb
fix integrate all nve
fix 2d all enforce2d
variable gamma equal (xcm(ra,x)-xcm(rb,x))/0.010
fix avg all ave/time 1 15 69 v_gamma
timestep {dt}
thermo_style custom step f_avg
thermo_modify format float %.12g
run 69
"""


def test_edge_rows_carry_the_shear_traction(lmp):
    """+-tau/dx on the edge rows = shear traction tau: once the top wave has passed rows at
    y = 14.5 and 4.5 mm (t = 5.5-6.9 us, before the bottom wave and the side-edge waves), the
    shear strain between them is tau/mu (measured 1.047 at dx = 1 mm, 1.02-1.04 at 0.5 mm:
    the ripple of a step on a dispersive lattice; 7 % tolerance)."""
    dx, dt = 1.0e-3, 1.0e-7
    script = SHEAR_FAR_FIELD.format(dx=dx, rho=mode2.RHO, vol=dx**3, E=mode2.E, delta=5 * dx,
                                    ytop=0.02 - dx, ybot=-0.02 + dx, btop=mode2.TAU / dx,
                                    bbot=-mode2.TAU / dx, dt=dt)
    gamma = float(re.findall(r"^\s*69\s+(\S+)", lmp(script).output, re.M)[-1])
    mu = mode2.E / (2 * (1 + mode2.NU))
    assert gamma == pytest.approx(mode2.TAU / mu, rel=0.07)


def check(res):
    print(f"{res['kernel']} dx {res['dx']}: peak {res['peak']:.2f} L2 {res['l2']:.2f} "
          f"K_end {res['k_end']:.3f}/{res['k_end_exact']:.3f} wall {res['wall_time']:.1f} s")
    peak, l2 = MEASURED[(res["kernel"], res["dx"])]
    assert res["peak"] == pytest.approx(peak, abs=MARGIN)
    assert res["l2"] == pytest.approx(l2, abs=MARGIN)
    assert res["left_right"] < SYMMETRY_TOL
    assert res["ki_over_kii"] < KI_TOL
    j = res["jintegral"]
    ratio_j, ratio_d = j["k_end"] / res["k_end_exact"], res["k_end"] / res["k_end_exact"]
    print(f"  from J: peak {j['peak']:.2f} L2 {j['l2']:.2f} K_end/ref {ratio_j:.3f}")
    j_peak, j_l2, j_end = MEASURED_J[(res["kernel"], res["dx"])]
    assert j["peak"] == pytest.approx(j_peak, abs=MARGIN)
    assert j["l2"] == pytest.approx(j_l2, abs=MARGIN)
    assert ratio_j == pytest.approx(j_end, abs=J_END_MARGIN)
    assert abs(ratio_j - 1.0) < 0.5 * abs(ratio_d - 1.0)
    assert np.max(np.abs(res["k_i_j"][(res["t"] >= res["window"][0])])) < KI_TOL * np.max(
        np.abs(res["k_ii_j"]))
    # nothing reaches the tip before the shear waves (less a horizon of nonlocal reach)
    t, k = res["t"], res["k_ii"]
    early = t < res["window"][0] - 2.0 * 5 * res["dx"] / mode2.wave_speeds()[0]
    assert np.max(np.abs(k[early])) < 0.05 * np.max(np.abs(k))


def test_gaussian_dx1mm(tmp_path):
    check(mode2.run(tmp_path, "gaussian", 1.0e-3))


@pytest.mark.slow
@pytest.mark.parametrize("kernel", mode2.KERNELS)
def test_kernels_dx05mm(tmp_path, kernel):
    check(mode2.run(tmp_path, kernel, 0.5e-3))

"""examples/quasi-static: the stress concentration at a circular hole (d/W = 0.3) in a plate
under uniaxial tension, relaxed by fix bbpd/relax, against Kirsch with Heywood's finite-width
correction K_tg = [2 + (1 - d/W)^3] / (1 - d/W) = 3.347 (bbpd.benchmarks.plate_hole says how K is measured).

Default suite: the Gaussian kernel at m = 4 on the two coarse grids, delta = 2 and 1 mm (4,688
and 18,752 atoms, well under a minute): the load step converges, K is above the infinite-plate
3 and within ERROR_TOL of Heywood, and the error falls with delta (measured: +14.0 % and +6.2 %; the
committed results, examples/quasi-static/results/plate_hole.csv, hold every kernel: the constant kernel's
error rises as delta falls, README.md gives the measured cause). The finest grid is not run yet.

And the centre-cracked plate (bbpd.benchmarks.center_crack): the initiation stress of the Gaussian kernel at
delta = 2 mm, m = 4 (3,200 atoms, 7 one-load-step trials) within INITIATION_TOL of LEFM.
"""
from bbpd.benchmarks import center_crack, plate_hole

# measured at delta = 2 mm, m = 4 (results/plate_hole.csv): +14 %; the admitted error is the
# coarse grid's, the test asks that it falls with delta (it does not for the constant kernel)
ERROR_TOL = 0.2


def test_gaussian_error_falls_from_2_to_1_mm(tmp_path):
    coarse = plate_hole.run_case("gaussian", 2.0e-3, 4, tmp_path)
    fine = plate_hole.run_case("gaussian", 1.0e-3, 4, tmp_path)
    for r in (coarse, fine):
        assert r["K"] > 3.0 and abs(r["error"]) < ERROR_TOL, r
    assert abs(fine["error"]) < abs(coarse["error"])


# centre-cracked plate (bbpd.benchmarks.center_crack): the far-field stress at which the pre-crack starts to
# grow against LEFM, sqrt(E Gc) / (sqrt(pi a) F(a/b)) with Tada's finite-width factor. Measured,
# Gaussian, delta = 2 mm, m = 4 (results/center_crack_gaussian.csv): -2.0 %, bracketed to 0.6 %.
# A Gc off by a factor 2 moves the initiation stress by sqrt(2) (+41 %), far outside.
# The agreement is m = 4's (README.md: m = 3 / 5 at this delta give +10.3 / -11.9 %): the test
# guards the load steps, the bisection and the calibration of the critical stretch, not a
# convergence to LEFM.
INITIATION_TOL = 0.05


def test_gaussian_crack_initiation_against_lefm(tmp_path):
    r = center_crack.initiation("gaussian", 2.0e-3, 4, tmp_path)
    assert r["u_hi"] / r["u_lo"] - 1.0 <= center_crack.REL_RES, r
    assert abs(r["error"]) < INITIATION_TOL, r
    assert r["broken_at_hi"] > 0, r

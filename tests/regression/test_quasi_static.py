"""examples/quasi-static: the stress concentration at a circular hole (d/W = 0.3) in a plate
under uniaxial tension, relaxed by fix bbpd/relax, against Kirsch with Heywood's finite-width
correction K_tg = [2 + (1 - d/W)^3] / (1 - d/W) = 3.347 (plate_hole.py says how K is measured).

Default suite: the Gaussian kernel at m = 4 on the two coarse grids, delta = 2 and 1 mm (4,688
and 18,752 atoms, well under a minute): the load step converges, K is above the infinite-plate
3 and within ERROR_TOL of Heywood, and the error falls with delta (measured: +14.0 % and +6.2 %; the
committed results, examples/quasi-static/results/plate_hole.csv, hold every kernel: the constant kernel's
error rises as delta falls, README.md gives the measured cause). The finest grid is not run yet.
"""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "examples" / "quasi-static"))
import plate_hole    # noqa: E402

# measured at delta = 2 mm, m = 4 (results/plate_hole.csv): +14 %; the admitted error is the
# coarse grid's, the test asks that it falls with delta (it does not for the constant kernel)
ERROR_TOL = 0.2


def test_gaussian_error_falls_from_2_to_1_mm(tmp_path):
    coarse = plate_hole.run_case("gaussian", 2.0e-3, 4, tmp_path)
    fine = plate_hole.run_case("gaussian", 1.0e-3, 4, tmp_path)
    for r in (coarse, fine):
        assert r["K"] > 3.0 and abs(r["error"]) < ERROR_TOL, r
    assert abs(fine["error"]) < abs(coarse["error"])

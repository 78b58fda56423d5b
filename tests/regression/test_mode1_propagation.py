"""Mode-I crack growth under a stress wave (examples/mode1-propagation) against Freund's
equation of motion (bbpd.crack_motion).

Default suite: the three kernels at dx = 0.1 m (4,000 atoms, 240 steps) and the negative
control, 16 s of CPU in all (AMD EPYC Zen 3, AVX2).  Slow: the Gaussian kernel at dx = 0.05 m.

Measured (examples/mode1-propagation/results/mode1_propagation.csv; G_c = 2 J/m^2 at
sigma0 = 1 MPa; theory t_i = 0.6269 ms, t_i - t_c = 0.259 ms; t_i errors in % of t_i - t_c):
MEASURED below, at dx = 0.1 m.  The first broken bond comes 5-14 % early (J = 0.56-0.82
G_c), the tip's first step of one grid spacing 17-24 % late (J = 1.05-1.17 G_c): LEFM's t_i
lies between the two.
Tolerances: the first-bond time is a multiple of dt = 5e-6 s = 1.9 % of t_i - t_c, so
T_I_TOL = 2.5 points admits one step; the tip is read every 1e-5 s = 3.9 %, TIP_TOL = 4.5
points.  Negative control: G_c x 1.5 (K_Ic x 1.22, K* ~ t^1.5 inside the ramp) delays the
theory's t_i by 14.5 % of t_i - t_c; measured: the Gaussian first bond at +10.9 % of the
nominal theory instead of -4.6 %, 15.5 points away, far outside T_I_TOL.
"""
import pytest

from bbpd.benchmarks import mode1_propagation as mp

DX_COARSE = 0.1
# kernel -> t_i error (%) and J/G_c at the first broken bond, the same when the tip has
# moved, L2 error (%) of l(t) against the energy and the K_Ic forms, at dx = 0.1 m
MEASURED = {"constant": (-14.3, 0.561, 16.7, 1.050, 18.0, 49.4),
            "triangular": (-8.5, 0.731, 20.5, 1.145, 6.8, 35.3),
            "gaussian": (-4.6, 0.820, 24.4, 1.171, 5.2, 28.5)}
T_I_TOL = 2.5           # points of %, on the first-bond t_i error (one time step: 1.9)
TIP_TOL = 4.5           # points of %, on the tip-moved t_i error (one tip output: 3.9)
J_TOL = 0.07            # on J/G_c: one time step changes J by ~6 % (J ~ t^3 in the ramp)
L2_TOL = 3.0            # points of %, on the L2 errors of l(t)
NEGATIVE_GC_FACTOR = 1.5


@pytest.fixture(scope="module")
def coarse(tmp_path_factory):
    work = tmp_path_factory.mktemp("mode1_propagation")
    return {k: mp.run(work / k, k, DX_COARSE) for k in MEASURED}


@pytest.mark.parametrize("kernel", list(MEASURED))
def test_initiation_time_and_energy_at_initiation(coarse, kernel):
    res = coarse[kernel]
    ti_err, j_ratio, tip_err, j_tip, _, _ = MEASURED[kernel]
    print(f"{kernel}: first bond {res['ti_err_pct']:+.1f} %, J/G_c "
          f"{res['J_at_ti_over_Gc']:.3f}; tip moved {res['ti_tip_err_pct']:+.1f} %, J/G_c "
          f"{res['J_at_ti_tip_over_Gc']:.3f}; Python tip - compute tip {res['tip_check_dx']} dx")
    assert res["ti_err_pct"] == pytest.approx(ti_err, abs=T_I_TOL)
    assert res["J_at_ti_over_Gc"] == pytest.approx(j_ratio, abs=J_TOL)
    assert res["ti_tip_err_pct"] == pytest.approx(tip_err, abs=TIP_TOL)
    assert res["J_at_ti_tip_over_Gc"] == pytest.approx(j_tip, abs=J_TOL)
    # LEFM's initiation lies between the first broken bond and the tip's first step
    assert res["J_at_ti_over_Gc"] < 1.0 < res["J_at_ti_tip_over_Gc"] + J_TOL
    # the compute and the Python reading of the same definition agree (measured: 2e-4 dx,
    # current against reference positions)
    assert res["tip_check_dx"] <= 1.0


@pytest.mark.parametrize("kernel", list(MEASURED))
def test_crack_path_against_freund(coarse, kernel):
    res = coarse[kernel]
    print(f"{kernel}: extension {res['ext_pd_3tc']:.2f} m, L2 {res['l2_toughness_pct']:.1f} "
          f"(K_Ic form) / {res['l2_energy_pct']:.1f} % (energy form)")
    assert res["l2_energy_pct"] == pytest.approx(MEASURED[kernel][4], abs=L2_TOL)
    assert res["l2_toughness_pct"] == pytest.approx(MEASURED[kernel][5], abs=L2_TOL)
    assert 0.0 < res["ext_pd_3tc"] < res["c_r"] * (3.0 * res["t_c"] - res["ti_theory"])


def test_ranking_gaussian_closest_initiation(coarse):
    errs = {k: abs(coarse[k]["ti_err_pct"]) for k in MEASURED}
    assert errs["gaussian"] < errs["triangular"] < errs["constant"]


def test_tougher_material_fails_the_tolerance(tmp_path):
    """Negative control: G_c x 1.5 in the model, the theory keeps G_c."""
    res = mp.run(tmp_path, "gaussian", DX_COARSE, G_c=NEGATIVE_GC_FACTOR * mp.G_C)
    prob = mp.problem(mp.G_C)
    err = 100.0 * (res["ti_pd"] - prob.initiation_time()) / (prob.initiation_time() - prob.t_c)
    print(f"G_c x {NEGATIVE_GC_FACTOR}: t_i error {err:+.1f} % against the nominal G_c")
    assert abs(err - MEASURED["gaussian"][0]) > T_I_TOL


@pytest.mark.slow
def test_gaussian_finer_grid_converges(tmp_path):
    res = mp.run(tmp_path, "gaussian", 0.05)
    assert abs(res["ti_err_pct"]) < abs(MEASURED["gaussian"][0])

"""The steady crack of examples/strip-steady-crack against its committed results and energy.

Default suite: the Gaussian kernel on the short strip of the sweeps (m = 4, H = 10 horizons,
12,800 atoms), at Delta = U'/G_c = 2, and the negative control Delta = 0.9: below 1 the strip
cannot feed a crack at any speed (U' < G_c), so the crack must arrest; and Delta = 3, at which
the committed run's crack branched: the run must stop once the tip leaves the plane by more
than a horizon, well before its time limit. About a minute of CPU.

Measured (examples/strip-steady-crack/results/strip.csv, the same run): the steady speed, the
energy the bonds take and the closure Gamma + Phi = U'. Tolerances: the tip moves in grid
steps and the speed is a slope over about 4 H of run, SPEED_TOL = 0.01 c_R admits a change of
the fit by a few grid steps but not of the law (the Delta = 1.5 and 2 runs differ by 0.09 c_R);
GAMMA_TOL = 0.05 G_c (Gamma at Delta = 1.5 and 2 differ by 0.3 G_c); the closure within 2 %
(the issue's criterion) and the energy balance within 1 % of the broken-bond energy.
"""
import numpy as np
import pytest

from bbpd.benchmarks import strip

CASE = dict(kernel="gaussian", m=4.0, H_over_delta=10.0, Delta=2.0)
SPEED_TOL = 0.01        # c_R
GAMMA_TOL = 0.05        # G_c
CLOSURE_TOL_PCT = 2.0
BALANCE_TOL_PCT = 1.0
BELOW_THRESHOLD = 0.9   # Delta < 1: no steady crack at any speed
BRANCHING = 3.0         # the committed Gaussian m = 4, H/delta = 10 run branched at this load


def committed(case):
    for r in strip.read_rows(strip.ROOT / "examples" / "strip-steady-crack" / "results" / "strip.csv"):
        if all(r[k] == v for k, v in case.items()):
            return r
    raise LookupError(f"no committed run {case}")


def run(tmp_path, **case):
    return strip.run(tmp_path, case["kernel"], case["Delta"], strip.DX * strip.M / case["m"],
                     case["m"], case["H_over_delta"])


def test_steady_speed_and_energies(tmp_path):
    ref = committed(CASE)
    res = run(tmp_path, **CASE)
    print(f"v_ss/c_R {res['v_ss_over_cR']:.4f} (committed {ref['v_ss_over_cR']:.4f}), Gamma/G_c "
          f"{res['Gamma_over_Gc']:.4f}, Phi/G_c {res['Phi_over_Gc']:.4f}, closure "
          f"{res['closure_pct']:.2f} %, balance {res['balance_pct']:.3f} %")
    assert res["state"] == "crossed"
    assert res["v_ss_over_cR"] == pytest.approx(ref["v_ss_over_cR"], abs=SPEED_TOL)
    assert res["Gamma_over_Gc"] == pytest.approx(ref["Gamma_over_Gc"], abs=GAMMA_TOL)
    assert abs(res["closure_pct"]) <= CLOSURE_TOL_PCT
    assert res["balance_pct"] <= BALANCE_TOL_PCT
    # the crack takes more than G_c per unit area: the bonds' energy rises with speed
    assert 1.0 < res["Gamma_over_Gc"] < res["Delta_model"]


def test_crack_arrests_below_the_energy_threshold(tmp_path):
    res = run(tmp_path, **dict(CASE, Delta=BELOW_THRESHOLD))
    assert res["state"] == "arrested"
    assert res["Delta_model"] < 1.0


def test_run_stops_once_the_crack_leaves_its_plane(tmp_path):
    case = dict(CASE, Delta=BRANCHING)
    assert committed(case)["state"] == "branched"
    res = run(tmp_path, **case)
    assert res["state"] == "branched"
    log = (tmp_path / "log.lammps").read_text()
    maxsteps = int(log.split("maxsteps ")[-1].split()[0])
    # stopped by fix halt at the first output past a horizon off y = 0, not at the time limit
    assert "Fix halt condition" in log
    assert res["steps"] < 0.75 * maxsteps
    y = np.abs(np.loadtxt(tmp_path / "strip.dat", ndmin=2)[:, 3])
    delta = strip.OFF_PLANE_HORIZONS * strip.DX * strip.M     # the horizon: dx m = DX M
    assert y[-1] > delta and np.count_nonzero(y > delta) == 1
    x = np.loadtxt(tmp_path / "strip.dat", ndmin=2)[-1, 2]
    g = strip.geometry(H_over_delta=CASE["H_over_delta"])
    assert res["left_plane_over_H"] == pytest.approx((x - g["a"]) / g["H"])

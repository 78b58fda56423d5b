# SPDX-License-Identifier: GPL-2.0-or-later
"""The closure's height sensitivity and verdict (bbpd.benchmarks.strip_closure): the factor a
taller strip moves the law by and what it does to the gap, from synthetic rows and the committed
closure.csv (no run)."""
import math

from bbpd.benchmarks import strip_closure as sc


def row(kernel, h, delta, v, crossed=True, m=sc.M_MODE1):
    return {"kernel": kernel, "m": m, "H_over_delta": h, "Delta": delta, "v_ss_over_cR": v,
            "crossed": crossed}


def test_taller_shift_is_the_speed_ratio_at_the_shift_load():
    rows = [row("gaussian", 10.0, sc.SHIFT_DELTA, 0.60), row("gaussian", 20.0, sc.SHIFT_DELTA, 0.66),
            row("gaussian", 20.0, 2.5, 0.99)]
    assert math.isclose(sc.taller_shift(rows, "gaussian"), 1.1)


def test_taller_shift_is_none_without_both_heights_or_when_a_run_did_not_cross():
    assert sc.taller_shift([row("gaussian", 10.0, sc.SHIFT_DELTA, 0.6)], "gaussian") is None
    rows = [row("gaussian", 10.0, sc.SHIFT_DELTA, 0.6), row("gaussian", 20.0, sc.SHIFT_DELTA, 0.7, False)]
    assert sc.taller_shift(rows, "gaussian") is None
    rows = [row("gaussian", 10.0, sc.SHIFT_DELTA, 0.6), row("gaussian", 20.0, sc.SHIFT_DELTA, 0.7, m=4.0)]
    assert sc.taller_shift(rows, "gaussian") is None


def closure(l2, l2_taller, shift=1.05):
    return {"kernel": "constant", "dx": 0.025, "law_points": 4, "law_u_min": 0.5, "law_u_max": 0.8,
            "inside_law_pct": 70.0, "below_law_pct": 25.0, "above_law_pct": 5.0,
            "l2_kinetic_pct": l2, "l2_toughness_pct": 13.0,
            "l2_energy_pct": 12.0, "ext_pd_3tc": 0.83, "ext_kinetic_3tc": 0.74,
            "ext_energy_3tc": 0.98, "law_shift_taller": shift, "l2_kinetic_taller_pct": l2_taller}


def test_the_height_effect_says_whether_it_can_close_the_gap():
    assert sc.height_effect(closure(19.6, 17.6)) == "less"
    assert sc.height_effect(closure(19.6, 4.0)) == "can"
    # on a grid where the closure already meets the goal there is no gap to account for
    assert sc.height_effect(closure(3.9, 3.8)) == "met"
    assert sc.height_effect(closure(19.6, float("nan"), float("nan"))) is None
    assert "| - |" in sc.table_markdown([closure(19.6, float("nan"), float("nan"))])


def test_the_verdict_follows_the_rows():
    v = sc.verdict([closure(19.6, 17.6), dict(closure(30.0, 25.0), dx=0.05)])["constant"]
    assert v["dx"] == [0.05, 0.025] and v["l2"] == [30.0, 19.6] and v["falls"]
    assert not v["meets"] and v["best_constant"] == 12.0 and v["height"] == "less"


def test_the_committed_closure_gives_the_readme_verdict():
    """examples/strip-steady-crack/README.md states by hand: the L2 error falls as dx halves for
    every kernel; below the 5 % goal at dx = 0.00625 m for the Gaussian and triangular kernels,
    not for the constant one"""
    rows = sc.read_rows(sc.ROOT / "examples" / "strip-steady-crack" / "results" / "closure.csv")
    v = sc.verdict(rows)
    assert all(x["falls"] for x in v.values())
    assert {k: x["meets"] for k, x in v.items()} == {"constant": False, "gaussian": True, "triangular": True}
    assert all(x["dx"][-1] == 0.00625 for x in v.values())
    assert {k: round(x["l2"][-1], 1) for k, x in v.items()} == {"constant": 7.9, "gaussian": 3.9, "triangular": 3.5}
    assert round(v["constant"]["best_constant"], 1) == 3.8
    assert {k: x["height"] for k, x in v.items()} == {"constant": "less", "gaussian": "met", "triangular": "met"}
    fine = [r for r in rows if r["dx"] == 0.00625]
    assert all(65.0 <= r["inside_law_pct"] <= 75.5 and r["above_law_pct"] == 0.0 for r in fine)
    const = next(r for r in fine if r["kernel"] == "constant")
    assert round(const["l2_kinetic_pct"] - const["l2_kinetic_taller_pct"], 1) == 1.2

# SPDX-License-Identifier: GPL-2.0-or-later
"""The closure's height sensitivity: the factor a taller strip moves the law by, and the verdict
sentence it adds, computed from rows (synthetic here, so the test needs no run)."""
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


def test_the_sentence_says_whether_the_height_can_close_the_gap():
    assert "accounts for less than the gap" in sc.verdict([closure(19.6, 17.6)])
    assert "can account for the gap" in sc.verdict([closure(19.6, 4.0)])
    # on a grid where the closure already meets the goal there is no gap to account for
    met = sc.verdict([closure(3.9, 3.8)])
    assert "the goal is met with the law of either height" in met and "gap" not in met.split("goal (")[1]
    assert "taller" not in sc.verdict([closure(19.6, float("nan"), float("nan"))])
    assert "| - |" in sc.table_markdown([closure(19.6, float("nan"), float("nan"))])


def test_the_sentence_splits_the_speeds_outside_the_law():
    text = sc.verdict([closure(19.6, 17.6)])
    assert ("at such speeds in 70 % of the window, slower in 25 % (the law interpolated from rest) "
            "and faster in 5 % (held at its fastest value)") in text

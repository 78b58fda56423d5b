# SPDX-License-Identifier: GPL-2.0-or-later
"""The strip results CSV: every row names the ranks and CPU that timed it (rows appended on
another machine, or on more ranks, say so), a CSV from before that column takes its timing
line, and the README's tables say which runs each timing covers (synthetic rows, no run)."""
import math

import numpy as np
import pytest

from bbpd.benchmarks import strip


def row(kernel, m, hd, timing="1 rank, CPU A", v=0.6):
    r = {c: 1.0 for c in strip.CSV_COLUMNS}
    r.update(kernel=kernel, m=m, H_over_delta=hd, Delta=2.0, crossed=True, state="crossed",
             v_ss_over_cR=v, timing=timing)
    return r


def test_timing_column_round_trips_and_names_the_other_runs(tmp_path):
    path = tmp_path / "strip.csv"
    rows = [row("gaussian", 4.0, 10.0), row("gaussian", 4.0, 20.0),
            row("gaussian", 6.0, 40.0, timing="2 ranks, CPU B")]
    strip.write_csv(path, rows, "first")
    back = strip.read_rows(path)
    assert [r["timing"] for r in back] == ["1 rank, CPU A", "1 rank, CPU A", "2 ranks, CPU B"]
    note = strip.timing_markdown(back)
    assert "| 1 rank, CPU A | every other run |" in note
    assert "| 2 ranks, CPU B | gaussian m = 6, H/delta = 40, Delta = 2 |" in note
    assert "| 1 rank, CPU A | all |" in strip.timing_markdown(back[:2])
    assert note in strip.table_markdown(back)


def test_a_small_change_that_does_not_shrink_is_not_converged():
    small_steady = strip.height_convergence([(10, 0.648), (20, 0.629), (40, 0.610)])
    assert small_steady["within"] and not small_steady["shrinks"] and not small_steady["converged"]
    shrinking = strip.height_convergence([(10, 0.660), (20, 0.640), (40, 0.634)])
    assert shrinking["shrinks"] and shrinking["converged"] and not shrinking["alternate"]
    flip = strip.height_convergence([(10, 0.653), (20, 0.661), (40, 0.648)])
    assert flip["alternate"] and not flip["shrinks"] and not flip["converged"]
    assert strip.height_convergence([(10, 0.633), (20, 0.665), (40, 0.660)])["alternate"]
    two = strip.height_convergence([(20, 0.598), (40, 0.571)])
    assert two["last"] == pytest.approx(-0.027) and not two["within"] and two["before"] is None
    assert strip.height_convergence([(20, 0.598)]) is None


def test_the_height_change_is_followed_across_m():
    rows = [row("gaussian", 4.0, 10.0, v=0.619), row("gaussian", 4.0, 20.0, v=0.598),
            row("gaussian", 5.0, 10.0, v=0.647), row("gaussian", 5.0, 20.0, v=0.629),
            row("gaussian", 8.0, 10.0, v=0.658), row("gaussian", 8.0, 20.0, v=0.655),
            row("gaussian", 6.0, 20.0, v=0.653)]      # one height: left out
    c = strip.height_change_against_m(rows, "gaussian")
    assert [m for m, _ in c["steps"]] == [4.0, 5.0, 8.0] and c["shrinks"]
    assert [round(d, 4) for _, d in c["steps"]] == [-0.021, -0.018, -0.003]
    rows[5]["v_ss_over_cR"] = 0.690
    assert not strip.height_change_against_m(rows, "gaussian")["shrinks"]
    # a run that did not cross, or a single m, says nothing
    rows[5].update(crossed=False, state="branched")
    assert strip.height_change_against_m(rows[:2] + rows[4:], "gaussian") is None


def test_a_crack_that_leaves_its_plane_is_branched_where_it_left(tmp_path):
    g = strip.geometry()
    delta, H, a = g["delta"], g["H"], g["a"]
    n = 40
    rows = np.zeros((n, 15))
    rows[:, 1] = np.linspace(0.0, 1e-4, n)
    rows[:, 2] = a + np.linspace(0.0, 3.0 * H, n)        # tip x
    rows[:, 3] = -0.5 * strip.DX                          # on the plane, between two rows
    rows[30:, 3] = -2.0 * delta                           # off it from the 31st output on
    res = strip.measure(rows, 1.0, g, strip.DX)
    assert res["state"] == "branched" and not res["crossed"]
    assert res["left_plane_over_H"] == pytest.approx((rows[30, 2] - a) / H)
    rows[:, 3] = -0.5 * strip.DX
    assert math.isnan(strip.measure(rows, 1.0, g, strip.DX)["left_plane_over_H"])
    # the CSV keeps it, the run table and the law table say it
    r = {c: 1.0 for c in strip.CSV_COLUMNS}
    r.update(kernel="gaussian", m=4.0, H_over_delta=80.0, Delta=2.0, crossed=False,
             state="branched", timing="1 rank, CPU A", left_plane_over_H=1.4925)
    strip.write_csv(tmp_path / "s.csv", [r], "x")
    back = strip.read_rows(tmp_path / "s.csv")[0]
    assert back["left_plane_over_H"] == pytest.approx(1.4925)
    assert "no (branched at a + 1.49 H)" in strip.table_markdown([back])
    assert "| 80 branched, off the plane at a + 1.49 H |" in strip.law_table([back])
    back["left_plane_over_H"] = float("nan")    # a branched run that did not measure it
    assert "no (branched) |" in strip.table_markdown([back])


def test_the_energy_closure_names_the_largest_drift_of_all_runs():
    rows = [row("gaussian", 4.0, 10.0), row("gaussian", 4.0, 20.0), row("gaussian", 3.0, 20.0)]
    for r, drift, closure in zip(rows, (0.2, 0.3, 1.24), (0.5, -1.7, 0.0)):
        r.update(balance_pct=drift, closure_pct=closure)
    c = strip.energy_closure(rows)
    assert c["n"] == 3 and c["drift"] == 1.24 and c["worst"] is rows[1]
    rows[2].update(crossed=False, state="branched")
    c = strip.energy_closure(rows)
    assert c["n"] == 2 and c["drift"] == 0.3 and c["drift_all"] is rows[2]
    assert strip.energy_closure([rows[2]]) is None


def test_the_committed_runs_give_the_readme_findings():
    """examples/strip-steady-crack/README.md, by hand: the Gaussian steady speed still falls by
    0.03 c_R from 20 to 40 horizons at m = 4 (not converged in the height) and the crack
    branches at 80; for the smooth kernels the first doubling of H moves the speed less at every
    step in m; the energy split closes within 2 % in every steady run"""
    rows = strip.read_rows(strip.ROOT / "examples" / "strip-steady-crack" / "results" / "strip.csv")
    hd = [(h, strip.speed_at(rows, "gaussian", 4.0, h, 2.0)) for h in (20.0, 40.0)]
    c = strip.height_convergence(hd)
    assert round(c["last"], 2) == -0.03 and not c["within"]
    tall = [r for r in rows if (r["kernel"], r["m"], r["H_over_delta"], r["Delta"]) == ("gaussian", 4.0, 80.0, 2.0)]
    assert tall and tall[0]["state"] == "branched"
    for k in ("gaussian", "triangular"):
        assert strip.height_change_against_m(rows, k)["shrinks"]
    assert round(abs(strip.energy_closure(rows)["worst"]["closure_pct"]), 1) == 1.7
    table = strip.law_table(rows)
    assert "| gaussian | 4 | 1.25 / 1.5 | 0.619, 0.598, 0.571 | -0.0277, no | 80 branched" in table

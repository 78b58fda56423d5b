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
    assert note == ("Loop times: 1 rank, CPU A (every run but these); 2 ranks, CPU B "
                    "(gaussian m = 6, H/delta = 40, Delta = 2).")
    assert strip.timing_markdown(back[:2]) == "Loop times: 1 rank, CPU A."
    assert note in strip.table_markdown(back)


def test_a_csv_without_the_timing_column_takes_its_timing_line(tmp_path):
    path = tmp_path / "old.csv"
    cols = [c for c in strip.CSV_COLUMNS if c != "timing"]
    cells = {"kernel": "gaussian", "state": "crossed", "crossed": "True"}
    path.write_text("# made by: x\n# timing: LAMMPS loop time, 1 rank, AMD EPYC, AVX2\n"
                    + ",".join(cols) + "\n" + ",".join(cells.get(c, "1") for c in cols) + "\n")
    assert strip.read_rows(path)[0]["timing"] == "1 rank, AMD EPYC, AVX2"


def testheight_verdict_calls_a_small_change_that_does_not_shrink_not_converged():
    small_steady = strip.height_verdict([(10, 0.648), (20, 0.629), (40, 0.610)])
    assert "within 0.02 c_R" in small_steady and "not converged" in small_steady
    shrinking = strip.height_verdict([(10, 0.660), (20, 0.640), (40, 0.634)])
    assert "the change shrinks" in shrinking and "not converged" not in shrinking
    assert "alternate in sign and do not shrink, not converged" in strip.height_verdict(
        [(10, 0.653), (20, 0.661), (40, 0.648)])
    assert "alternate in sign and shrink)" in strip.height_verdict([(10, 0.633), (20, 0.665), (40, 0.660)])
    assert "more than 0.02 c_R" in strip.height_verdict([(20, 0.598), (40, 0.571)])


def test_the_height_change_is_followed_across_m():
    rows = [row("gaussian", 4.0, 10.0, v=0.619), row("gaussian", 4.0, 20.0, v=0.598),
            row("gaussian", 5.0, 10.0, v=0.647), row("gaussian", 5.0, 20.0, v=0.629),
            row("gaussian", 8.0, 10.0, v=0.658), row("gaussian", 8.0, 20.0, v=0.655),
            row("gaussian", 6.0, 20.0, v=0.653)]      # one height: not in the sentence
    text = strip.height_change_against_m(rows, "gaussian")
    assert text == ("doubling H from 10 to 20 horizons (Delta = 2) moves v_ss/c_R by -0.0210 at "
                    "m = 4, -0.0180 at m = 5, -0.0030 at m = 8: the change shrinks at every step in m")
    rows[5]["v_ss_over_cR"] = 0.690
    assert "does not shrink at every step in m" in strip.height_change_against_m(rows, "gaussian")
    # a run that did not cross, or a single m, says nothing
    rows[5].update(crossed=False, state="branched")
    assert strip.height_change_against_m(rows[:2] + rows[4:], "gaussian") == ""
    assert "doubling H from 10 to 20 horizons" in strip.summary_text(rows[:4])


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
    # the CSV keeps it, the table and the summary say it; a CSV from before the column reads NaN
    r = {c: 1.0 for c in strip.CSV_COLUMNS}
    r.update(kernel="gaussian", m=4.0, H_over_delta=80.0, Delta=2.0, crossed=False,
             state="branched", timing="1 rank, CPU A", left_plane_over_H=1.4925)
    strip.write_csv(tmp_path / "s.csv", [r], "x")
    back = strip.read_rows(tmp_path / "s.csv")[0]
    assert back["left_plane_over_H"] == pytest.approx(1.4925)
    assert "no (branched at a + 1.49 H)" in strip.table_markdown([back])
    assert "Delta = 2 (m = 4, H/delta = 80, off the plane at a + 1.49 H)" in strip.summary_text([back])
    old = tmp_path / "old.csv"
    cols = [c for c in strip.CSV_COLUMNS if c != "left_plane_over_H"]
    old.write_text(",".join(cols) + "\n" + ",".join(
        {"kernel": "gaussian", "state": "branched", "crossed": "False", "timing": "t"}.get(c, "1")
        for c in cols) + "\n")
    back = strip.read_rows(old)[0]
    assert math.isnan(back["left_plane_over_H"])
    assert "no (branched) |" in strip.table_markdown([back])


def test_a_taller_strip_that_branched_ends_the_height_sequence_in_its_sentence():
    rows = [row("gaussian", 4.0, 10.0, v=0.619), row("gaussian", 4.0, 20.0, v=0.598),
            row("gaussian", 4.0, 40.0, v=0.571), row("gaussian", 4.0, 80.0, v=0.0)]
    rows[3].update(crossed=False, state="branched", left_plane_over_H=1.55)
    text = strip.summary_text(rows)
    assert ("0.571 at H/delta = 40 (the last refinement moves it by 0.0270 c_R: more than 0.02 c_R; "
            "the one before by 0.0210 c_R: the change does not shrink, not converged), and at "
            "H/delta = 80 the crack branched or turned, off the plane at a + 1.55 H: no steady "
            "speed there") in text
    # every height crossed: nothing added
    assert "no steady speed there" not in strip.summary_text(rows[:3])


def test_the_largest_drift_is_named_apart_when_its_run_did_not_cross():
    rows = [row("gaussian", 4.0, 10.0), row("gaussian", 4.0, 20.0), row("gaussian", 3.0, 20.0)]
    for r, drift, closure in zip(rows, (0.2, 0.3, 1.24), (0.5, -1.7, 0.0)):
        r.update(balance_pct=drift, closure_pct=closure)
    text = strip.summary_text(rows)
    assert "drifts by at most 1.24 % of the broken-bond energy in them." in text   # all crossed
    rows[2].update(crossed=False, state="branched")
    text = strip.summary_text(rows)
    assert ("drifts by at most 0.30 % of the broken-bond energy in them, and by 1.24 % in the "
            "branched run gaussian, m = 3, H/delta = 20, Delta = 2, the largest of all 3 runs.") in text

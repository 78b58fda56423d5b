"""The pure parts of the work-precision diagrams (bbpd.report.work_precision) on synthetic data: the
rows of the CSV, its round trip, the cost of reaching an error, the table computed from
them, the dispersion error at the fixed wavelength and the ring that holds that wavelength."""

import math

import numpy as np
import pytest

from bbpd import csvfile
from bbpd.report import work_precision as wp


def mode1_result(l2, peak, jl2, jpeak):
    return {"consistent": {"l2": l2, "peak": peak},
            "jintegral": {"consistent": {"l2": jl2, "peak": jpeak}}}


def kw_result(angle, band):
    return {"angle_deg": angle, "t_band_us": band}


def synthetic_runs():
    """(benchmark, kernel, dx, result, wall_s): errors fall and times grow with refinement."""
    return [
        ("mode1", "gaussian", 0.1, mode1_result(4.4, 2.0, 1.5, 0.5), 1.0),
        ("mode1", "gaussian", 0.05, mode1_result(2.3, 1.7, 0.9, 0.3), 4.0),
        ("mode1", "constant", 0.1, mode1_result(20.0, 15.0, 2.0, 1.2), 0.9),
        ("mode1", "constant", 0.05, mode1_result(13.0, 14.0, 1.1, 1.1), 3.5),
        ("kalthoff_winkler", "gaussian", 2e-3, kw_result(58.0, 21.0), 2.0),
        ("kalthoff_winkler", "gaussian", 1e-3, kw_result(61.0, 20.0), 12.0),
        ("kalthoff_winkler", "gaussian", 0.5e-3, kw_result(62.5, 19.5), 90.0),
    ]


def test_rows_hold_every_metric_and_the_kw_angle_against_the_finest_run():
    table = wp.rows(synthetic_runs())
    m1 = [r for r in table if r["benchmark"] == "mode1"]
    assert len(m1) == 4 * 2 * 2               # 4 runs x (L2, peak) x (dsif, J)
    row = [r for r in m1 if r["kernel"] == "constant" and r["resolution"] == 0.05
           and r["method"] == "jintegral" and r["error_metric"] == "L2 (%)"]
    assert len(row) == 1 and row[0]["error"] == 1.1 and row[0]["wall_s"] == 3.5
    finest = [r for r in table if r["error_metric"] == "|angle - finest| (deg)"]
    # the finest run is the reference, so only the two coarser ones have a point
    assert sorted((r["resolution"], r["error"]) for r in finest) == [
        (1e-3, pytest.approx(1.5)), (2e-3, pytest.approx(4.5))]
    exp = {r["resolution"]: r["error"] for r in table
           if r["error_metric"] == "|angle - 70 deg| (deg)"}
    assert exp == {2e-3: 12.0, 1e-3: 9.0, 0.5e-3: 7.5}


def test_csv_round_trip(tmp_path):
    table = wp.rows(synthetic_runs())
    path = tmp_path / "csv" / wp.CSV_NAME
    csvfile.write_csv(path, table, columns=wp.CSV_COLUMNS)
    assert path.read_text().splitlines()[0] == ",".join(wp.CSV_COLUMNS)
    back = csvfile.read_csv(path)[1]
    assert len(back) == len(table)
    for a, b in zip(table, back):
        assert (a["benchmark"], a["kernel"], a["method"], a["error_metric"]) == \
            (b["benchmark"], b["kernel"], b["method"], b["error_metric"])
        assert b["resolution"] == pytest.approx(a["resolution"], rel=1e-5)
        assert b["error"] == pytest.approx(a["error"], rel=1e-5)
        assert b["wall_s"] == pytest.approx(a["wall_s"], rel=1e-3)


def test_cost_to_reach_takes_the_cheapest_run_under_the_target():
    table = wp.rows(synthetic_runs())
    reach = wp.cost_to_reach(table, "mode1", "L2 (%)", 3.0)
    assert reach[("gaussian", "dsif")] == ("reached", 4.0, 0.05)
    assert reach[("constant", "dsif")] == ("missed", 13.0, 3.5, 0.05)
    # both J points reach 3 %: the cheaper (coarser) one counts
    assert reach[("gaussian", "jintegral")] == ("reached", 1.0, 0.1)
    assert reach[("constant", "jintegral")] == ("reached", 0.9, 0.1)


def test_the_reach_table_gives_each_kernels_cost_from_the_numbers():
    table = wp.rows(synthetic_runs())
    text = wp.reach_table(table)
    rows = [ln for ln in text.splitlines() if ln.startswith("| mode1 | L2 <= 3 % |")]
    assert f"| {wp.METHOD_LABEL['dsif']} | gaussian | 4 s (dx = 0.05 m) |" in text
    assert f"| {wp.METHOD_LABEL['dsif']} | constant | not reached: best 13 % at 3.5 s (dx = 0.05 m) |" in text
    # J-integral: cheapest first
    j = [r for r in rows if wp.METHOD_LABEL["jintegral"] in r]
    assert "| constant | 0.9 s" in j[0] and "| gaussian | 1 s" in j[1]
    # no Mode-II runs: no Mode-II rows
    assert "| mode2 |" not in text


def test_ring_holds_the_wavelength_at_every_m():
    for m in wp.DISPERSION_M_FULL:
        v = wp.dispersion_vars(m)
        dx = wp.DISPERSION_DELTA / m
        assert v["natoms"] * dx == pytest.approx(wp.RING_LENGTH, rel=1e-12)
        assert v["natoms"] % 2 == 0       # the analytic grid coincides with the FFT's
        assert v["nsteps"] * dx == pytest.approx(wp.RING_STEPS_PER_M * wp.DISPERSION_DELTA)
        k = 2 * math.pi * np.arange(1, v["natoms"] // 2 + 1) / (v["natoms"] * dx)
        assert np.min(np.abs(k * wp.WAVELENGTH / (2 * math.pi) - 1)) < 1e-12


def test_dispersion_error_is_read_at_the_wavelength():
    natoms, dx = 1000, 2e-4
    k = 2 * math.pi * np.arange(1, natoms // 2 + 1) / (natoms * dx)
    continuum = 5000.0 * k * (1 - 0.1 * (k * 1e-3) ** 2)
    measured = continuum * (1 + 1e-4 * k / k.max())      # error grows with k
    res = {"measured": {"k": k, "omega": measured},
           "analytic": {"gaussian": {"k": k, "omega_continuous": continuum}}}
    kw = 2 * math.pi / wp.WAVELENGTH
    assert wp.dispersion_error(res, "gaussian") == pytest.approx(1e-4 * kw / k.max())
    with pytest.raises(ValueError, match="misses"):
        wp.dispersion_error(res, "gaussian", wavelength=wp.WAVELENGTH * 1.01)


def test_a_run_without_the_wavelength_is_left_out_and_named():
    k = 2 * math.pi * np.arange(1, 501) / 0.21          # a ring 0.21 m long
    res = {"measured": {"k": k, "omega": 5000.0 * k},
           "analytic": {"constant": {"k": k, "omega_continuous": 5000.0 * k}}}
    notes = []
    table = wp.rows([("dispersion", "constant", 2e-4, res, 1.0)] + synthetic_runs()[:1], notes)
    assert [r["benchmark"] for r in table] == ["mode1"] * 4
    assert len(notes) == 1 and "dispersion constant" in notes[0] and "misses" in notes[0]

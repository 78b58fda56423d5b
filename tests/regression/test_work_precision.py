"""Work-precision diagrams of tools/reproduce (python/bbpd/report/work_precision.py) on coarse grids.

Every benchmark x kernel must have rows in report/csv/work_precision.csv with finite errors
and positive run times, every line must run through its resolutions, the short runs must be
timed more than once, and REPORT.md must show the four figures and a sentence per benchmark.
"""
import math

import pytest

from bbpd import csvfile, jobs
from bbpd.provenance import machine
from bbpd.report import work_precision as wp
from bbpd.report import make

# coarse grids: seconds per run
TINY = wp.Plan(mode1_dx=(0.2, 0.1), mode2_dx=(2.0e-3, 1.0e-3), kw_dx=(4.0e-3, 2.0e-3),
               dispersion_m=(3, 5), repeats=2)


@pytest.fixture(scope="module")
def made(tmp_path_factory):
    out = tmp_path_factory.mktemp("wp")
    specs = wp.extra_specs([], TINY)
    path, failed = make.reproduce(out, specs, workers=2, log=lambda msg: None)
    return out, path.read_text(), failed, specs


def test_no_run_failed(made):
    assert made[2] == 0


def test_csv_has_every_benchmark_and_kernel_with_finite_errors(made):
    out = made[0]
    table = csvfile.read_csv(out / "csv" / wp.CSV_NAME)[1]
    # the quasi-static rows come from the committed initiation study, whose kernels are its own
    study = {r["kernel"] for r in wp.quasi_static_rows()}
    assert study
    for bench in wp.BENCHMARKS:
        for kernel in sorted(study) if bench == "quasi_static" else TINY.kernels:
            mine = [r for r in table if r["benchmark"] == bench and r["kernel"] == kernel]
            assert mine, (bench, kernel)
            assert all(math.isfinite(r["error"]) and r["error"] >= 0 for r in mine)
            assert all(math.isfinite(r["wall_s"]) and r["wall_s"] > 0 for r in mine)
    # every line of the diagrams runs through both resolutions
    m1 = {(r["kernel"], r["method"], r["error_metric"], r["resolution"]) for r in table
          if r["benchmark"] == "mode1"}
    for kernel in TINY.kernels:
        for method in ("dsif", "jintegral"):
            for metric in ("L2 (%)", "peak (%)"):
                assert {dx for k, me, mt, dx in m1 if (k, me, mt) == (kernel, method, metric)} \
                    == set(TINY.mode1_dx)
    disp = {r["resolution"] for r in table if r["benchmark"] == "dispersion"}
    assert sorted(disp) == pytest.approx(sorted(wp.DISPERSION_DELTA / m for m in TINY.dispersion_m))
    # refining m brings the phase velocity closer to eq. 29 for every kernel
    for kernel in TINY.kernels:
        err = {r["resolution"]: r["error"] for r in table
               if r["benchmark"] == "dispersion" and r["kernel"] == kernel}
        assert err[min(err)] < err[max(err)], kernel
    finest = [r for r in table if r["error_metric"] == "|angle - finest| (deg)"]
    assert {r["resolution"] for r in finest} <= {max(TINY.kw_dx)}


def test_short_runs_are_timed_more_than_once(made):
    out, text, _, specs = made
    timing = [s for s in specs if s.bench == wp.TIMING_BENCH]
    runs = {s.job.label: s for s in specs if s.bench != wp.TIMING_BENCH}
    assert timing and all(runs[s.job.kwargs["of"]].job.estimate_s < wp.REPEAT_BELOW_S
                          for s in timing)
    results = jobs.run_jobs([s.job for s in specs], out / "runs", workers=1, log=lambda m: None)
    assert sorted(set(wp.collect(specs, results)[1].values())) == [1, 2]    # all cached: no run


def test_figures_and_sentences_are_in_the_report(made):
    out, text, _, _ = made
    sec = text.split("## Error against run time")[1]
    for bench in wp.BENCHMARKS:
        name = f"work_precision_{bench}.png"
        assert f"]({name})" in sec
        assert (out / name).stat().st_size > 10_000
    assert "| mode1 | L2 <= 3 % |" in sec
    assert machine() in sec

"""The projectile and grid-pull sections of REPORT.md (tools/reproduce, bbpd.report).

The default report runs one projectile case (Gaussian, 2 mm) and no grid-pull case; --full
runs the other kernels and 1 mm, and every grid-pull case. A coarse projectile run and a coarse
grid run (4 mm, about a second each) go through the report's own job function and
write_report: the sections appear with the runs' numbers, the contact figure, and a line for
a run that is missing.
"""
import time

import pytest

from bbpd import report
from bbpd.benchmarks import kalthoff_winkler_grid as kwg
from bbpd.benchmarks import kalthoff_winkler_projectile as kwp
from bbpd.report import make
from bbpd.report.document import write_report

DX = 4.0e-3


def by_bench(specs, bench):
    return [s for s in specs if s.bench == bench]


def test_default_report_runs_one_projectile_case_and_full_the_rest():
    default = make.job_list()
    (one,) = by_bench(default, "kwprojectile")
    assert (one.kernel, one.dx) == ("gaussian", 2.0e-3)
    assert by_bench(default, "kwgrid") == []
    full = make.job_list(full=True)
    assert {(s.kernel, s.dx) for s in by_bench(full, "kwprojectile")} == set(kwp.REPORT_CASES_FULL)
    assert len(by_bench(full, "kwgrid")) == len(kwg.jobs()) == 44


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    out = tmp_path_factory.mktemp("report-projectile")
    proj = kwp.jobs()[0]
    missing = kwp.jobs(full=True)[1]
    grid = [s for s in kwg.jobs() if s.kernel == "gaussian" and s.dx == 2.0e-3
            and s.job.kwargs["args"]["loading"] == "prescribed"
            and s.job.kwargs["args"]["grid"] in ("square", "rotated-30")]
    results = {}
    # the report's job function on a coarse grid (the specs' own dx is 2 mm)
    args = dict(proj.job.kwargs, args=dict(proj.job.kwargs["args"], dx=DX))
    results[proj.job.label] = report.run_job(str(out / "proj"), **args)
    for s in grid:
        a = dict(s.job.kwargs, args=dict(s.job.kwargs["args"], dx=DX))
        results[s.job.label] = report.run_job(str(out / s.job.label.split()[2]), **a)
    specs = [proj, missing] + grid
    meta = {"full": True, "date": "today", "lammps": "test", "plugin": "test", "git": "test",
            "machine": "test", "load": 0.0, "new": 0, "workers": 1, "runs_s": 0.0}
    path = write_report(out, specs, results, meta, time.perf_counter())
    return out, path.read_text(), results[proj.job.label], missing.job.label


def section(text, title):
    parts = [p for p in text.split("\n## ") if p.startswith(title)]
    assert len(parts) == 1, title
    return parts[0]


def test_projectile_section_holds_the_runs_numbers(written):
    out, text, r, missing = written
    sec = section(text, kwp.REPORT_TITLE)
    assert "| 2D | projectile | gaussian | 4 | 69000 |" in sec
    assert f" {r['v_interface']:.2f} |" in sec      # the table's cell
    dv = (r["v_interface"] / r["v_interface_theory"] - 1.0) * 100.0
    assert f"{dv:+.1f} %" in sec and f"{r['v_interface_theory']:.2f} m/s" in sec
    assert f"{r['momentum_drift']:.1e}" in sec
    assert "Not measured (failed or not run): " + missing in sec
    assert "](kw_projectile_contact_gaussian_dx4mm.png)" in sec
    assert (out / "kw_projectile_contact_gaussian_dx4mm.png").stat().st_size > 10_000


def test_grid_section_holds_the_runs_numbers(written):
    _, text, _, _ = written
    sec = section(text, kwg.REPORT_TITLE)
    assert "| prescribed | gaussian | 4 | square |" in sec
    assert "| prescribed | gaussian | 4 | rotated-30 |" in sec
    # the default report has no grid runs: the section says how to get them
    empty = kwg.section([], {}, None, [])
    assert empty["table"] == "" and "tools/reproduce --full" in empty["setup"]

"""The report machinery of tools/reproduce (the bbpd.report package) on a few tiny runs.

Coarse grids (seconds in all), one run that must fail, and two calls: the tables of
REPORT.md must hold the runs' own numbers beside the paper's, the failed run must show as
FAILED with LAMMPS's error while the others are reported, the second call must reuse every
finished run (and retry the failed one), and editing a declared input must rerun that job.
"""
import json
import re
from pathlib import Path

import pytest

from bbpd import csvfile, report
from bbpd.benchmarks import mode1
from bbpd.report import make, sections

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "examples"
BENCH = ROOT / "python" / "bbpd" / "benchmarks"


def tiny_specs(extra_input):
    m1 = (EX / "mode1-semi-infinite" / "in.mode1", BENCH / "mode1.py")
    m2 = (EX / "mode2-central-crack" / "in.mode2", BENCH / "mode2.py", extra_input)
    kw = (EX / "kalthoff-winkler" / "in.kalthoff_winkler", BENCH / "kalthoff_winkler.py")
    return [
        report.make_spec("dispersion", "gaussian", 0.2e-3, "bbpd.report:dispersion_run",
                         {"kernel": "gaussian"}, (EX / "dispersion-1d" / "in.dispersion",), 3.0),
        report.make_spec("mode1", "gaussian", 0.2, "bbpd.benchmarks.mode1:run",
                         {"kernel": "gaussian", "dx": 0.2, "nprocs": 1}, m1, 1.0),
        # a Table 2 row whose run fails: LAMMPS rejects the model keyword
        report.make_spec("mode1", "gaussian", 0.1, "bbpd.benchmarks.mode1:run",
                         {"kernel": "gaussian", "dx": 0.1, "model": "no/such/model",
                          "nprocs": 1}, m1, 1.0),
        report.make_spec("mode2", "constant", 2e-3, "bbpd.benchmarks.mode2:run",
                         {"kernel": "constant", "dx": 2e-3, "nprocs": 1}, m2, 1.0),
        report.make_spec("mode2", "gaussian", 2e-3, "bbpd.benchmarks.mode2:run",
                         {"kernel": "gaussian", "dx": 2e-3, "nprocs": 1}, m2, 1.0),
        report.make_spec("kw", "gaussian", 4e-3, "bbpd.benchmarks.kalthoff_winkler:run",
                         {"kernel": "gaussian", "dx": 4e-3, "nprocs": 1, "images": True}, kw,
                         1.0),
    ]


def section(text, title_start):
    """The text of one '## ' section of REPORT.md."""
    parts = re.split(r"^## ", text, flags=re.M)
    found = [p for p in parts if p.startswith(title_start)]
    assert found, f"no section '{title_start}'"
    return found[0]


def table_rows(text, first_cell):
    return [ln for ln in text.splitlines() if ln.startswith(f"| {first_cell} |")]


@pytest.fixture(scope="module")
def calls(tmp_path_factory):
    """Two calls of the report on the same folder, and a third after an input changed."""
    out = tmp_path_factory.mktemp("report")
    extra = out / "extra-input.txt"
    extra.write_text("first\n")
    logs = []
    for n in range(2):
        lines = []
        path, failed = make.reproduce(out, tiny_specs(extra), workers=2, log=lines.append)
        logs.append((lines, path.read_text(), failed, cached_results(out)))
    extra.write_text("second\n")
    lines = []
    make.reproduce(out, tiny_specs(extra), workers=2, log=lines.append)
    logs.append((lines, None, None, None))
    return out, logs


def cached_results(out):
    """(kernel, dx) -> result of every finished run in the cache"""
    runs = [json.loads(p.read_text()) for p in (out / "runs").glob("*.json")]
    return {(r["kernel"], r["dx"]): r for r in runs if "kernel" in r and "dx" in r}


def test_tables_hold_the_runs_numbers(calls):
    _, logs = calls
    text, res = logs[0][1], logs[0][3]
    for title in ("Wave dispersion", "Stationary Mode-I", "Mode-II", "Kalthoff-Winkler"):
        assert f"## {title}" in text
    # Mode II rows: our errors and the run time, as the runs measured them
    m2 = section(text, "Mode-II")
    for kernel in ("constant", "gaussian"):
        r = res[(kernel, 2e-3)]
        row = table_rows(m2, kernel)
        assert len(row) == 2    # the extrapolation's table, then the J-integral's
        cells = [c.strip() for c in row[0].split("|")[1:-1]]
        assert cells[3] == f"{r['peak']:.2f}" and cells[4] == f"{r['l2']:.2f}"
        assert cells[-1] == f"{r['wall_time']:.1f}"
    # the J-integral columns, and the verdict as data from those numbers
    r = res[("gaussian", 2e-3)]
    assert f"{r['jintegral']['peak']:.2f} / {r['jintegral']['l2']:.2f}" in m2
    j = sections.mode2_j({key: v for key, v in res.items() if "k_end_exact" in v})
    assert j["where"] in ("extrapolation", "field", "partly")
    assert j["j"][("gaussian", 2e-3)] == r["jintegral"]["k_end"] / r["k_end_exact"]
    # Mode I Table 2: ours beside the paper's Table 2 value for dx = 0.1
    m1 = section(text, "Stationary Mode-I")
    r = res[("gaussian", 0.2)]
    assert f"{r['consistent']['peak']:.2f} / {r['consistent']['l2']:.2f}" in m1
    j = r["jintegral"]["consistent"]
    assert f"{j['peak']:.2f} / {j['l2']:.2f}" in m1
    ref = mode1.PAPER_TABLE2[0.1]
    assert f"{ref[0]:.2f} / {ref[1]:.2f}" in m1
    kw = section(text, "Kalthoff-Winkler")
    assert len(table_rows(kw, "gaussian")) == 1 and "21.7" in kw   # paper's initiation time
    disp = section(text, "Wave dispersion")
    assert len(table_rows(disp, "gaussian")) == 1


def test_result_files_hold_the_runs_numbers(calls):
    # report/results/*.csv: what the READMEs are generated from (python -m bbpd.claims)
    from bbpd.report import results
    out, logs = calls
    res = logs[0][3]
    comments, rows = csvfile.read_csv(out / "results" / "mode2.csv")
    assert comments[0].startswith("made by: tools/reproduce") and "machine: " in comments[2]
    by = {(r["kernel"], r["dx_m"]): r for r in rows}
    for kernel in ("constant", "gaussian"):
        r, row = res[(kernel, 2e-3)], by[(kernel, 2e-3)]
        assert row["peak"] == pytest.approx(r["peak"], rel=1e-5)
        assert row["ratio_end"] == pytest.approx(r["k_end"] / r["k_end_exact"], rel=1e-5)
        assert row["run_time_s"] > 0    # (the third call reran these: another wall time)
    _, rows = csvfile.read_csv(out / "results" / "mode1.csv")
    assert [(r["kernel"], r["dx_m"]) for r in rows] == [("gaussian", 0.2)]    # the failed one: no row
    r = res[("gaussian", 0.2)]
    assert rows[0]["consistent_l2"] == pytest.approx(r["consistent"]["l2"], rel=1e-5)
    assert rows[0]["j_peak"] == pytest.approx(r["jintegral"]["consistent"]["peak"], rel=1e-5)
    _, rows = csvfile.read_csv(out / "results" / "kalthoff_winkler.csv")
    assert rows[0]["angle_deg"] == pytest.approx(res[("gaussian", 4e-3)]["angle_deg"], rel=1e-5)
    assert (out / "results" / "dispersion.csv").is_file()


def test_failed_run_is_reported_and_the_others_go_on(calls):
    _, logs = calls
    lines, text, failed, _ = logs[0]
    assert failed == 1
    row = [ln for ln in section(text, "Stationary Mode-I").splitlines()
           if ln.startswith("| 0.1 |") and "FAILED" in ln]    # the table of the failed runs
    assert len(row) == 1 and "ERROR" in row[0]
    assert "1 failed" in text


def test_figures_are_written(calls):
    out, logs = calls
    text, res = logs[0][1], logs[0][3]
    for name in ("fig4_dispersion.png", "fig9_resolutions.png", "fig12_kernels_dx2mm.png",
                 "damage_gaussian_dx4mm.png", "growth_gaussian_dx4mm.png"):
        assert f"]({name})" in text
        png = (out / name).read_bytes()
        assert png.startswith(b"\x89PNG\r\n\x1a\n") and len(png) > 10_000
    # the crack growing: the run's own dump image pictures, from t = 0 to the end, in a row
    assert "](growth_gaussian_dx4mm.png)" in section(text, "Kalthoff-Winkler")
    times = [t for t, _ in res[("gaussian", 4e-3)]["snapshots"]]
    assert len(times) == 5 and times[0] == 0.0 and times == sorted(set(times))


def test_versions_and_machine_are_stated(calls):
    text = calls[1][0][1]
    assert re.search(r"LAMMPS: \d+ \w+ \d{4}", text)
    assert re.search(r"plugin v\d+\.\d+", text)
    assert "cores" in text and "total wall time" in text


def test_header_versions_parsed_and_no_blank_lines_pile_up(calls):
    """every run's log gave its versions (no '?'), and the sections not run here (the loading
    study, the grid's pull) are one line each, with no run of blank lines behind them"""
    text = calls[1][0][1]
    logs = re.search(r"the runs' logs: (.*)$", text, re.M).group(1)
    assert logs and "?" not in logs
    assert "\n\n\n" not in text
    assert re.search(r"^Not run by default .*\n\n## ", text, re.M)


def test_second_call_reuses_finished_runs(calls):
    _, logs = calls
    lines, text, failed, _ = logs[1]
    reused = [ln for ln in lines if ln.strip().startswith("reuse")]
    assert len(reused) == 5                       # every run but the failed one
    ran = [ln for ln in lines if re.match(r"\s*\[\d+/\d+\]", ln)]
    assert len(ran) == 1 and "FAILED" in ran[0]   # the failed one is tried again
    assert "(1 made now, 5 reused" in text


def test_changed_input_reruns_its_jobs_only(calls):
    lines = calls[1][2][0]
    ran = [ln for ln in lines if re.match(r"\s*\[\d+/\d+\]", ln)]
    labels = sorted(re.sub(r"^\s*\[\d+/\d+\] (FAILED )?", "", ln).split(":")[0] for ln in ran)
    assert labels == ["Mode I gaussian dx = 0.1 m", "Mode II constant dx = 2 mm",
                      "Mode II gaussian dx = 2 mm"]


def test_default_jobs_declare_their_input_scripts():
    for spec in make.job_list(full=True):
        names = [Path(p).name for p in spec.job.inputs]
        assert any(n.startswith("in.") for n in names), spec.job.label
        assert all(Path(p).is_file() for p in spec.job.inputs), spec.job.label
        assert spec.job.kwargs["args"].get("nprocs", 1) == 1

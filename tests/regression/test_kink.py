"""Quasi-static kink test (examples/kink-mixed-mode).

Default suite: two coarse runs (dx = 1 mm, m = 5, Gaussian, crack along the grid's rows), each
about 2,000 steps of 7,860 atoms on one rank: the mix psi = 45 deg must kink where it did when
the sweep was made (examples/kink-mixed-mode/results/kink.csv), and pure Mode I must run
straight ahead, far from any Mode-II angle (the negative control: a loading or sign error that
swaps the modes, or a field that is not rotated with the crack, fails it).
The same two runs make the kink section of REPORT.md (bbpd.report), which must hold their
numbers, the lines filled from them and the figure.
Slow: the whole sweep against the committed CSV; the README's verdict is checked against the CSV.
"""
import csv

import pytest

from bbpd import kink
from bbpd.benchmarks import kink as bench
from bbpd.report import runs, sections

CSV = bench.RESULTS

# The reference angles are the committed sweep's (results/kink.csv; Gaussian, dx = 1 mm,
# alpha = 0, psi = 45 deg: -54.6 and -55.1 deg at 2 and 4 horizons). One rank reproduces a
# run's bits (and the AVX2, AVX-512 and portable kernels give the same bits), so the margin is
# not for noise: it guards the code, not the physics. It cannot be much wider, because a
# physics-neutral change moves one run's angle a lot (halving the ramp rate gives -45.0 and
# -50.4 deg, README), nor narrower than the CSV's rounding.
MARGIN_DEG = 2.0
K_INIT_MARGIN = 0.011    # K at the first break is read every 10 steps: 0.01 K_c apart
# the negative control: pure Mode I must run straight (measured 0.0 deg at 2 and 4 horizons: the
# grid and the load are mirror-symmetric about the crack line; 5 deg allows a one-atom wobble
# of the band) and so far from every criterion's pure-Mode-II angle (-63.6 to -75.2 deg)
MODE1_LIMIT_DEG = 5.0


def committed_rows():
    with open(CSV) as fh:
        rows = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    return rows


def measured_row(psi, alpha=0.0, dx_mm=1.0, ncross=bench.NCROSS, kernel="gaussian"):
    for r in committed_rows():
        if (r["kernel"], float(r["psi"]), float(r["alpha"]), float(r["dx_mm"]),
                float(r["ncross"])) == (kernel, psi, alpha, dx_mm, ncross):
            return r
    raise KeyError((kernel, psi, alpha, dx_mm, ncross))


@pytest.fixture(scope="module")
def coarse_runs(tmp_path_factory):
    out = {}
    for psi in (45.0, 0.0):
        work = tmp_path_factory.mktemp(f"kink{psi:g}")
        out[psi] = bench.job(str(work), "gaussian", psi, 0.0, bench.COARSE[0], bench.COARSE[1])
    return out


def test_mixed_mode_kink_is_reproduced(coarse_runs):
    res = coarse_runs[45.0]
    ref = measured_row(45.0)
    assert res["halted"] and res["extension_over_delta"] >= bench.DISTANCES[-1]
    for f in bench.DISTANCES:
        assert res[f"angle_{f:g}d"] == pytest.approx(float(ref[f"angle_{f:g}d"]), abs=MARGIN_DEG)
    # a kink to the lower side, as every criterion says for K_II > 0, and a single crack
    assert res["angle_2d"] < -30.0 and res["spread_2d"] < 10.0
    assert res["K_init_over_Kc"] == pytest.approx(float(ref["K_init_over_Kc"]), abs=K_INIT_MARGIN)


def test_pure_mode1_runs_straight(coarse_runs):
    res = coarse_runs[0.0]
    mode2 = [kink.hoop_stress_angle(0.0, 1.0), kink.max_energy_release_angle(0.0, 1.0),
             kink.hoop_strain_angle(0.0, 1.0, 1 / 3, kink.PLANE_STRESS)]
    for f in bench.DISTANCES:
        angle = res[f"angle_{f:g}d"]
        assert abs(angle) < MODE1_LIMIT_DEG
        assert min(abs(angle - a) for a in mode2) > 50.0
    # and the mixed case is not the Mode-I result
    assert abs(coarse_runs[45.0]["angle_2d"] - res["angle_2d"]) > 30.0


@pytest.mark.slow
def test_sweep_reproduces_the_committed_csv(tmp_path):
    bench.main(["--work", str(tmp_path / "work"), "--results", str(tmp_path / "kink.csv"),
                "--figure", str(tmp_path / "k.png")])
    new = {(r["kernel"], r["psi"], r["alpha"], r["dx_mm"], r["ncross"]): r
           for r in csv.DictReader(l for l in open(tmp_path / "kink.csv") if not l.startswith("#"))}
    for r in committed_rows():
        n = new[(r["kernel"], r["psi"], r["alpha"], r["dx_mm"], r["ncross"])]
        for col in ("angle_2d", "angle_4d"):
            if r[col]:
                assert float(n[col]) == pytest.approx(float(r[col]), abs=MARGIN_DEG), (r, col)


def test_readme_verdict_follows_the_csv():
    """what the README states by hand beside its verdict table, from the committed kink.csv: the
    24 coarse-grid mixed-mode angles lie closest to max. hoop stress at 2 and 4 horizons (RMS 11.2
    and 8.1 deg), the 12 fine-grid ones closest to max. hoop strain (3.6 and 3.3 deg); 3 of 37
    mixed-mode runs, all Gaussian on the coarse grid, locked onto a grid direction; the ramp
    check's angles"""
    rows = bench.read_rows(CSV)
    for dist, rms in (("2d", 11.2), ("4d", 8.1)):
        v = bench.verdict(rows, dist, bench.COARSE[0])
        assert (v["n"], v["best"], round(v["rms"]["hoop_stress"], 1)) == (24, "hoop_stress", rms)
    for dist, rms in (("2d", 3.6), ("4d", 3.3)):
        v = bench.verdict(rows, dist, bench.FINE[0])
        assert (v["n"], v["best"], round(v["rms"]["hoop_strain"], 1)) == (12, "hoop_strain", rms)
    stuck = bench.locked(rows)
    assert [(r["kernel"], r["dx"], r["psi"], r["alpha"], round(r["angle_2d"], 1)) for r in stuck] \
        == [("gaussian", 1e-3, 90.0, 0.0, -90.0), ("gaussian", 1e-3, 22.5, 22.5, -22.5),
            ("gaussian", 1e-3, 45.0, 0.0, -45.0)]
    assert sum(1 for r in rows if r["psi"] > 0) == 37
    # the ramp check: the same case at half the loading rate
    ramp = {r["ncross"]: (round(r["angle_2d"], 1), round(r["angle_4d"], 1)) for r in rows
            if (r["kernel"], r["psi"], r["alpha"], r["dx"]) == ("gaussian", 45.0, 0.0, 1e-3)}
    assert ramp[bench.NCROSS] == (-54.6, -55.1)
    assert [v for n, v in ramp.items() if n != bench.NCROSS] == [(-45.0, -50.4)]


# The J-integral of the intact crack at K = 0.6 K_c (bench.loading_check: psi = 30 deg, crack
# at 22.5 deg to the rows) measured a mix of 29.92 deg and |K_J| = 0.9635 K(t): the damped
# interior lags the ring by a few per cent. A mix 0.5 deg off, or a lag outside 0.93-1.0, means
# the boundary field, its rotation or the damping changed.
MIX_TOL_DEG = 0.5
LAG_RANGE = (0.93, 1.0)


def test_boundary_field_gives_the_prescribed_mix(tmp_path):
    res = bench.loading_check(tmp_path)
    assert res["intact"]
    assert res["mix"] == pytest.approx(bench.LOADING_CASE["psi"], abs=MIX_TOL_DEG)
    assert LAG_RANGE[0] < res["ratio"] < LAG_RANGE[1]


# Kalthoff-Winkler tie-in (bbpd.benchmarks.kink_kalthoff_winkler, Gaussian, 2 mm, one rank):
# measured (results/kalthoff_winkler_mix.json) K_I = -51.4 MPa m^1/2, K_II = 119.7 at 11.8 us,
# the last output before the first bond at the tip breaks (12.0 us): psi = 113.2 deg.
KW_PSI_DEG = 113.2
KW_PSI_MARGIN = 1.0      # deg; the run reproduces its bits, the margin covers the JSON rounding


def test_kalthoff_winkler_mix(tmp_path):
    import json
    from bbpd.benchmarks import kink_kalthoff_winkler as kk
    res = kk.run("gaussian", 2.0e-3, tmp_path, tend=14.0e-6)
    committed = json.loads(kk.SUMMARY.read_text())
    assert res["psi"] == pytest.approx(KW_PSI_DEG, abs=KW_PSI_MARGIN)
    assert res["psi"] == pytest.approx(committed["psi"], abs=1e-6)
    # Mode II dominated with the faces pressed together, and the upper notch the mirror image
    # (negative control of the sign: the two notches must have opposite K_II, equal K_I)
    assert res["KI"] < 0.0 < res["KII"]
    assert res["mirror_KII"] == pytest.approx(-1.0, abs=1e-9)
    assert res["mirror_KI"] == pytest.approx(1.0, abs=1e-9)


def test_report_section_holds_the_runs(coarse_runs, tmp_path):
    """The kink section of REPORT.md (tools/reproduce) from the two coarse runs as report
    specs, and one spec whose run is missing: the tables hold the runs' own angles and the
    README's verdict table, the figure is written."""
    assert ("kink", bench.section) in sections.BUILDERS
    default = runs.kink_specs()
    assert [s.job.kwargs["args"]["psi"] for s in default] == list(bench.MIXES_DEG)
    assert len(runs.kink_specs(full=True)) == len(bench.cases())
    by_psi = {s.job.kwargs["args"]["psi"]: s for s in default}
    specs = [by_psi[45.0], by_psi[0.0], by_psi[90.0]]
    results = {by_psi[p].job.label: coarse_runs[p] for p in (45.0, 0.0)}
    sec = bench.section(specs, results, tmp_path, [])
    for psi in (45.0, 0.0):
        res = coarse_runs[psi]
        row = [ln for ln in sec["table"].splitlines() if ln.startswith(
            f"| gaussian | 1 | 5 | 0 | {psi:g} | ")]
        assert len(row) == 1
        cells = [c.strip() for c in row[0].split("|")[1:-1]]
        assert cells[6:8] == [f"{res['angle_2d']:.1f}", f"{res['angle_4d']:.1f}"]
        assert cells[8] == f"{res['hoop_stress']:.1f}"
    # the verdict table needs two mixed-mode runs (a standard error): with the one here it has
    # no row; with a copy of it at another mix, each criterion's RMS is the run's own deviation
    assert "| mixed-mode runs |" in sec["table"] and "| 1 | 2 | " not in sec["table"]
    mixed = coarse_runs[45.0]
    table = bench.verdict_table([mixed, dict(mixed, psi=67.5)])
    for dist in ("2", "4"):
        row = [ln for ln in table.splitlines() if ln.startswith(f"| 1 | {dist} | 2 | ")]
        assert len(row) == 1
        cells = [c.strip() for c in row[0].split("|")[1:-1]]
        dev = {c: abs(mixed[f"angle_{dist}d"] - mixed[c]) for c in bench.CRITERIA}
        assert [c.split(" (")[0] for c in cells[3:6]] == [f"{dev[c]:.1f}" for c in bench.CRITERIA]
        assert cells[6] == bench.CRITERION_NAMES[min(bench.CRITERIA, key=dev.get)]
    assert not bench.whole_sweep([coarse_runs[45.0], coarse_runs[0.0]])
    assert "Not measured (failed or not run): " + by_psi[90.0].job.label in sec["text"]
    assert sec["figures"] == ["kink_angle.png"]
    assert (tmp_path / "kink_angle.png").stat().st_size > 10_000

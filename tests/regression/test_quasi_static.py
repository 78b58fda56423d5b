"""examples/quasi-static: the stress concentration at a circular hole (d/W = 0.3) in a plate
under uniaxial tension, relaxed by fix bbpd/relax, against Kirsch with Heywood's finite-width
correction K_tg = [2 + (1 - d/W)^3] / (1 - d/W) = 3.347 (bbpd.benchmarks.plate_hole says how K is measured).

The Gaussian kernel at m = 4 on the two coarse grids, delta = 2 and 1 mm (4,688 and 18,752
atoms, marked slow: 95 s with the cores shared): the load step converges, K is above the infinite-plate
3 and within ERROR_TOL of Heywood, and the error falls with delta (measured: +14.0 % and +6.2 %; the
committed results, examples/quasi-static/results/plate_hole.csv, hold every kernel: the constant kernel's
error rises as delta falls). That is the first row's value; the fitted measure (K_fit, README.md)
is checked on the coarse grid, fast, and its sweep to delta = 0.5 mm in the committed CSVs
(tests/python/test_quasi_static_results.py).

And the centre-cracked plate (bbpd.benchmarks.center_crack): the initiation stress of the Gaussian kernel at
delta = 2 mm, m = 4 (3,200 atoms, 7 one-load-step trials) within INITIATION_TOL of LEFM; its
load-displacement path through initiation with the energy account
(bbpd.benchmarks.center_crack_growth); fix bbpd/relax with bbpd/lps/gaussian and bbpd/pmb on
it; and the quasi-static section of REPORT.md (bbpd.benchmarks.quasi_static).
"""
import pytest

from bbpd.benchmarks import center_crack, center_crack_growth, dcb_growth, plate_hole, quasi_static
from bbpd.report import sections

# measured at delta = 2 mm, m = 4 (results/plate_hole.csv): +14 %; the admitted error is the
# coarse grid's, the test asks that it falls with delta (it does not for the constant kernel)
ERROR_TOL = 0.2


# the second measure, Tan's form fitted on the ligament over R + delta <= r <= 2R (README.md):
# measured at delta = 2 mm, m = 4 (results/plate_hole.csv) +1.4 % (Gaussian), against +14.0 %
# for the first row's value; the wider window (to 2.5R) -0.4 %
def test_fitted_concentration_on_the_coarse_grid(tmp_path):
    r = plate_hole.run_case("gaussian", 2.0e-3, 4, tmp_path)
    assert r["fit_rows"] >= 2 and abs(r["error_fit"]) < plate_hole.TOL, r
    assert abs(r["error_fit_wide"] - r["error_fit"]) < plate_hole.TOL, r


@pytest.mark.slow    # 95 s with the 2 cores shared (the 1 mm grid's 18,752 atoms)
def test_gaussian_error_falls_from_2_to_1_mm(tmp_path):
    coarse = plate_hole.run_case("gaussian", 2.0e-3, 4, tmp_path)
    fine = plate_hole.run_case("gaussian", 1.0e-3, 4, tmp_path)
    for r in (coarse, fine):
        assert r["K"] > 3.0 and abs(r["error"]) < ERROR_TOL, r
    assert abs(fine["error"]) < abs(coarse["error"])


# centre-cracked plate (bbpd.benchmarks.center_crack): the far-field stress at which the pre-crack starts to
# grow against LEFM, sqrt(E Gc) / (sqrt(pi a) F(a/b)) with Tada's finite-width factor. Measured,
# Gaussian, delta = 2 mm, m = 4 (results/center_crack_gaussian.csv): -2.0 %, bracketed to 0.6 %.
# A Gc off by a factor 2 moves the initiation stress by sqrt(2) (+41 %), far outside.
# The agreement is m = 4's (README.md: m = 3 / 5 at this delta give +10.3 / -11.9 %): the test
# guards the load steps, the bisection and the calibration of the critical stretch, not a
# convergence to LEFM.
INITIATION_TOL = 0.05


def test_gaussian_crack_initiation_against_lefm(tmp_path):
    r = center_crack.initiation("gaussian", 2.0e-3, 4, tmp_path)
    assert r["u_hi"] / r["u_lo"] - 1.0 <= center_crack.REL_RES, r
    assert abs(r["error"]) < INITIATION_TOL, r
    assert r["broken_at_hi"] > 0, r


# the same initiation from a dynamic ramp (in.center-crack -var solver dynamic, Gaussian,
# delta = 2 mm, m = 4) over 10 transit times to the LEFM opening, against the committed
# bisection (results/center_crack_gaussian_full.csv): the first broken bond is at a tip, and
# the opening then is within DYNAMIC_TOL of the relaxed one (measured: see
# results/center_crack_dynamic.csv); about 2,000 steps
DYNAMIC_TOL = 0.02


def test_slow_dynamic_ramp_initiates_where_the_relaxed_plate_does(tmp_path):
    import csv
    row = next(csv.DictReader(open(center_crack.HERE / "results" / "center_crack_gaussian_full.csv")))
    row = {k: float(v) for k, v in row.items() if k != "kernel"}
    r = center_crack.dynamic("gaussian", 2.0e-3, 4, 10, row, tmp_path)
    assert r["away_from_tips"] == 0, r
    assert abs(r["vs_relax"]) < DYNAMIC_TOL, r


# the centre-cracked plate's load-displacement path through initiation and its energy account
# (bbpd.benchmarks.center_crack_growth): three load steps of the Gaussian kernel at delta = 2 mm,
# m = 4, the grips opened to 0.95, 0.97 and 0.99 of the LEFM opening; the crack starts in the
# last (measured: at 0.98, 64 bonds, results/center_crack_growth.csv)
CLAPEYRON_TOL = 1.0e-4    # measured: 1.9e-5 (U = 1/2 F u: the energy account against the grips)
# measured after initiation: (W - U - B) / W = +1.16 %, the energy released at fixed opening
# beyond what the broken bonds carry (README.md); the bound is its size, not a closure
GAP_TOL = 0.03


def test_crack_growth_energy_account(tmp_path):
    steps, u_lefm, _ = center_crack_growth.path("gaussian", 2.0e-3, 4, tmp_path, du=0.02,
                                                first=0.95, max_steps=2)
    assert [s["converged"] for s in steps] == [1, 1, 1], steps
    assert [s["broken"] > 0 for s in steps] == [False, False, True], steps
    for s in steps:
        assert abs(s["clapeyron"]) < CLAPEYRON_TOL, s
    # elastic load steps: the work of the grips is the elastic energy (the trapezoid is exact)
    for s in steps[:2]:
        assert abs(s["gap"]) < CLAPEYRON_TOL and s["B_J"] == 0.0, s
    before, at = steps[1], steps[2]
    # the load drops when the crack starts: below the load before breaking at the same opening
    # and below the last load step's, though the grips opened further
    assert at["load_N"] < 0.99 * at["load_before_break_N"], at
    assert at["load_N"] < before["load_N"], (before, at)
    # the account: the elastic energy released at fixed opening is at least what the broken
    # bonds carry (D >= 0, no energy from nowhere); the rest is dissipated by the relaxation
    assert at["dB_J"] > 0.0 and at["released_J"] >= at["dB_J"], at
    assert 0.0 < at["gap"] < GAP_TOL, at
    # the trapezoid over the converged points misses the load drop's triangle
    assert at["W_trap_J"] < at["W_J"], at
    # where the release went, measured apart (thermo at every step of the same load step from
    # rest): each breaking evaluation takes out the broken bonds' energy at their stretch, at
    # least what B books at s0; the relaxations after them release the rest
    events, split = center_crack_growth.breaking_split("gaussian", 2.0e-3, 4, at["u_m"], tmp_path)
    assert sum(e["bonds"] for e in events) == at["broken"], events
    for e in events:
        assert e["bond_energy_J"] >= e["booked_J"] * (1.0 - 1.0e-6) > 0.0, e
    assert split["booked_J"] == pytest.approx(at["dB_J"], rel=1.0e-9)
    assert split["released_J"] == pytest.approx(at["released_J"], rel=1.0e-3)
    assert split["overshoot_J"] > 0.0 and split["relaxation_J"] > 0.0, split


# fix bbpd/relax with the state-based kernel styles and with bbpd/pmb, on the centre-cracked
# plate at delta = 2 mm, m = 4 (bbpd.benchmarks.center_crack.kernel_vars gives their
# pair_coeff numbers): the elastic load step converges and its energy is the grips' work
# (U = 1/2 F u), no bond breaks at the lower opening (relaxed to the end) and bonds break at the
# upper one. The openings are fractions of the LEFM opening from the plate's own stiffness.
# Measured initiation (bisected, results/center_crack_lps.csv, center_crack_pmb.csv): lps/gaussian
# +2.8 % of LEFM; pmb -27.2 % (its constant micromodulus and critical stretch from the
# continuum formulas on peri/pmb's families, no surface correction: README.md)
BRACKETS = {"lps/gaussian": (0.85, 1.15), "pmb": (0.6, 0.85)}


@pytest.mark.parametrize("kernel", sorted(BRACKETS))
def test_relax_with_state_based_and_pmb_styles(kernel, tmp_path):
    probe = center_crack.trial(kernel, 2.0e-3, 4, 1.0e-6, tmp_path, 1000000)
    assert probe["converged"] and probe["broken"] == 0, probe
    grips_work = 0.5 * probe["stress"] * center_crack.W * center_crack.H_T * 1.0e-6
    assert abs(probe["elastic"] / grips_work - 1.0) < CLAPEYRON_TOL, probe
    u_lefm = center_crack.sigma_lefm() * 1.0e-6 / probe["stress"]
    low, high = BRACKETS[kernel]
    below = center_crack.trial(kernel, 2.0e-3, 4, low * u_lefm, tmp_path, 1000000)
    assert below["converged"] and below["broken"] == 0, below
    cap = center_crack.CAP_FACTOR * probe["iterations"] + 100
    above = center_crack.trial(kernel, 2.0e-3, 4, high * u_lefm, tmp_path, cap)
    assert above["broken"] > 0, above


def test_report_section_holds_the_runs(tmp_path):
    """The quasi-static section of REPORT.md (tools/reproduce) from the plate with a hole's
    coarse run as a report spec and one spec whose run is missing: the table holds the run's
    own K and error, the missing run is named."""
    assert ("quasistatic", quasi_static.section) in sections.BUILDERS
    specs = quasi_static.jobs()
    assert all(str(center_crack.HERE / "in.center-crack") in s.job.inputs for s in specs)
    assert len(quasi_static.jobs(full=True)) > len(specs)
    hole = next(s for s in specs if s.job.kwargs["args"]["case"] == "hole")
    crack = next(s for s in specs if s.job.kwargs["args"]["case"] == "initiation")
    res = quasi_static.job(tmp_path, **hole.job.kwargs["args"])
    sec = quasi_static.section([hole, crack], {hole.job.label: res}, tmp_path, [])
    row = [ln for ln in sec["table"].splitlines() if ln.startswith("| K at the hole")]
    assert len(row) == 1 and f"| {res['measured']:.4g} |" in row[0], sec["table"]
    assert f"{100 * res['deviation']:+.1f} %" in row[0]
    assert crack.job.label in sec["text"]


# stable growth (bbpd.benchmarks.dcb_growth): the double cantilever beam at dx = 0.5 mm, m = 4
# (1,600 atoms), opened to 11.5, 12 and 12.5 um: elastic, then the crack grows in each of the
# two load steps (measured: 42 and 66 bonds) while the load falls a little (5.23, 5.10,
# 4.93 N); in each the energy released at fixed opening exceeds what the broken bonds book, and
# they book about three quarters of it (measured 0.72, 0.77; over the whole path 0.76)
def test_dcb_grows_stably_and_its_bonds_book_three_quarters(tmp_path):
    rows, totals, _ = dcb_growth.path(tmp_path, u=11.5e-6, du=0.5e-6, steps=2)
    assert [r["converged"] for r in rows] == [1, 1, 1], rows
    assert rows[0]["broken"] == 0 and abs(rows[0]["gap"]) < CLAPEYRON_TOL, rows[0]
    for prev, r in zip(rows, rows[1:]):
        assert r["broken"] > 0 and 0.8 * prev["load_N"] < r["load_N"] < prev["load_N"], (prev, r)
        assert abs(r["clapeyron"]) < CLAPEYRON_TOL, r
        assert 0.6 < r["dB_J"] / r["released_J"] < 0.9, r

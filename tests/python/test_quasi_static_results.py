"""examples/quasi-static: the plate with a hole's second measure (bbpd.benchmarks.plate_hole.fitted)
on a field of known concentration, the issue's verdict on it as data from the committed sweep,
and the README's tables of K and of the dynamic initiation against the CSVs they quote."""
import csv

import numpy as np
import pytest

from bbpd.benchmarks import center_crack, plate_hole as ph
from bbpd.report import work_precision as wp

RESULTS = ph.HERE / "results"
README = (ph.HERE / "README.md").read_text()


def rows(name):
    return list(csv.DictReader(open(RESULTS / name)))


def test_the_fit_returns_the_amplitude_of_tans_form(tmp_path):
    """sigma_xx = (K/3) Kirsch on the ligament with eps_yy = 0 (sigma_yy = nu sigma_xx): the fit
    gives K back, whatever the rows inside the hole's surface layer hold"""
    dx, k_true = 0.25e-3, 3.4
    lines = []
    for j, y in enumerate(np.arange(ph.W / 2 + ph.R + dx / 2, ph.W, dx)):
        r = y - ph.W / 2
        exx = (k_true / 3) * ph.kirsch_ligament(r)[0] * ph.SIGMA * (1 - ph.NU ** 2) / ph.E
        exx *= 1.5 if r < ph.R + 1.0e-3 else 1.0    # a surface layer the fit must skip
        for side in (-1, 1):
            x0 = ph.L / 2 + side * dx / 2
            lines.append(f"{2 * j + side} {x0 + side * exx * dx / 2!r} {y!r} {side * exx * dx / 2!r} 0")
    dump = tmp_path / "ligament.dump"
    dump.write_text("ITEM: ATOMS id x y c_u[1] c_u[2]\n" + "\n".join(lines) + "\n")
    k, n = ph.fitted(dump, 1.0e-3, ph.FIT_OUTER)
    assert k == pytest.approx(k_true, rel=1e-9) and n == 8


def test_the_readme_quotes_the_dynamic_initiation_csv():
    data = rows("center_crack_dynamic.csv")
    assert [r["solver"] for r in data[:2]] == ["relax", "relax"]
    assert all(int(r["away_from_tips"]) == 0 for r in data)
    for r in data:
        label = (f"ramp {float(r['ramp_transits']):g} T" if r["solver"] == "dynamic"
                 else f"bracket {100 * float(r['bracket']):g} %")
        cells = (f"| {label} | {int(r['steps']):,} | {float(r['u_um']):.4f} | "
                 f"{float(r['sigma_MPa']):.4f} | {float(r['sigma_grips_MPa']):.4f} | "
                 f"{100 * float(r['vs_relax']):+.2f} % | {100 * float(r['error']):+.2f} % | "
                 f"{float(r['wall_s']):.1f} s |")
        assert cells.replace("-", "−") in README.replace("-", "−"), cells


def test_the_work_precision_rows_come_from_the_csv():
    table = wp.quasi_static_rows()
    data = rows("center_crack_dynamic.csv")
    # every run against LEFM, every run but the reference against the tight bisection
    assert len(table) == 2 * len(data) - 1
    dyn = [t for t in table if t["method"] == "dynamic" and t["error_metric"].startswith("|sigma_c/r")]
    assert [t["resolution"] for t in dyn] == [float(r["ramp_transits"]) for r in data[2:]]
    assert [t["error"] for t in dyn] == pytest.approx([100 * abs(float(r["vs_relax"])) for r in data[2:]])
    assert ("quasi_static", "|sigma_c/relaxed - 1| (%)") in wp.TARGETS
    assert center_crack.TIGHT_RES in [t["resolution"] for t in table if t["method"] == "relax"]


def test_the_dynamic_reading_follows_the_csv():
    dyn = [r for r in rows("center_crack_dynamic.csv") if r["solver"] == "dynamic"]
    slow = max(abs(float(r["vs_relax"])) for r in dyn if float(r["ramp_transits"]) >= 20)
    assert f"within {100 * slow:.2f} %" in README
    bound = max(abs(float(r["vs_relax"])) * float(r["ramp_transits"]) for r in dyn)
    assert f"at most\n{100 * bound:.0f} % T" in README or f"at most {100 * bound:.0f} % T" in README
    r20 = next(r for r in dyn if float(r["ramp_transits"]) == 20)
    excess = float(r20["sigma_grips_MPa"]) / float(r20["sigma_MPa"]) - 1
    assert f"({100 * excess:+.1f} % above k u at 20 T)" in README

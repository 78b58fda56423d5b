"""bbpd.benchmarks.kfield_probe: LEFM's near-tip field on in.center-crack's grid, the K_I at which
its largest bond stretch reaches s0 (K_probe). One bond's stretch by hand, the notch's cut rule
at the tip, the Griffith field's crack opening, the committed CSV against a fresh computation,
the verdict as data, and the README's numbers against the CSVs."""
import csv
import math

import pytest

from bbpd.benchmarks import kfield_probe as kp

RESULTS = kp.HERE / "results"
README = (kp.HERE / "README.md").read_text()


def rows(name):
    return list(csv.DictReader(open(RESULTS / name)))


def bond_index(b, bond):
    """the index of bond (X_a, Y_a, X_b, Y_b) (units of Delta/2) in bonds(), either way round"""
    for i, got in enumerate(zip(*b)):
        if tuple(got) in (bond, bond[2:] + bond[:2]):
            return i
    return None


def test_the_bond_ahead_of_the_tip_by_hand():
    """the vertical bond from (Delta/2, -Delta/2) to (Delta/2, Delta/2): both ends at r = Delta/sqrt 2,
    theta = -+45 degrees, the same u_x, u_y opposite: s = 2 u_y / Delta with, for nu = 1/3
    (kappa = 2, mu = 3E/8), u_y = K/(2 mu) sqrt(r/(2 pi)) sin(pi/8) (2 - sqrt(2)/2)"""
    dx, k = 0.5e-3, 0.7e6
    u_y = (4 * k / (3 * kp.E)) * math.sqrt(dx / math.sqrt(2) / (2 * math.pi)) \
        * (math.sqrt(2 - math.sqrt(2)) / 2) * (2 - math.sqrt(2) / 2)
    b = kp.bonds(4)
    i = bond_index(b, (1, -1, 1, 1))
    assert kp.stretch(b, dx, k)[i] == pytest.approx(2 * u_y / dx, rel=1e-12)


def test_the_notch_cuts_as_fix_bbpd_notch_does():
    """bonds across y = 0 behind the tip and through the tip itself are cut (the notch's ends are
    included: tests/lammps/test_kfield_s0.py counts them against LAMMPS), those ahead are not"""
    b = kp.bonds(4)
    assert bond_index(b, (-1, -1, 1, 1)) is None       # through the tip
    assert bond_index(b, (-1, 1, 1, -1)) is None
    assert bond_index(b, (-1, -1, -1, 1)) is None      # behind it
    assert bond_index(b, (1, -1, 1, 1)) is not None    # ahead of it
    assert bond_index(b, (-1, -3, 1, 1)) is not None   # crosses at x = Delta/4
    assert bond_index(b, (-1, -1, 1, -1)) is not None  # below the crack line


def test_the_griffith_field_opens_the_crack_and_has_williams_tip():
    """Griffith's crack opening 4 sigma sqrt(a^2 - x^2) / E (plane stress) at the centre, and the
    leading term near the tip"""
    k = 0.5e6
    sigma = k / math.sqrt(math.pi * kp.A)
    (_, up), (_, down) = kp.griffith(-kp.A, 1e-12, k), kp.griffith(-kp.A, -1e-12, k)
    assert up - down == pytest.approx(4 * sigma * kp.A / kp.E, rel=1e-9)
    r = 1e-6 * kp.A
    for t in (0.3, 1.5, 2.9):
        x, y = r * math.cos(t), r * math.sin(t)
        g, w = kp.griffith(x, y, k), kp.williams(x, y, k)
        assert g[1] - kp.griffith(x, -y, k)[1] == pytest.approx(w[1] - kp.williams(x, -y, k)[1], rel=1e-5)


def test_the_csv_is_a_fresh_computation():
    fresh, saved = kp.rows(), rows("kfield_probe.csv")
    assert len(fresh) == len(saved)
    for f, s in zip(fresh, saved):
        for key, v in f.items():
            if isinstance(v, float):
                assert float(s[key]) == pytest.approx(v, rel=1e-5), (key, s)
            else:
                assert s[key] == ("" if v is None else str(v)), (key, s)


def test_the_tip_bond_stretches_as_k_over_sqrt_delta_for_every_kernel():
    """s_max = c K / (E sqrt(Delta)) with one c for every kernel, delta and m (to 1e-4: the
    stretch's nonlinearity), so K_probe / K_Ic = s0 sqrt(E Delta / Gc) / c: falling as 1/sqrt(m)"""
    data = rows("kfield_probe.csv")
    c = [float(r["tip_coefficient"]) for r in data]
    assert max(c) / min(c) - 1 < 1e-4 and 0.51 < min(c) < 0.52
    assert {r["bond"] for r in data} == {"-0.5 -1.5 0.5 0.5"}
    for r in data:
        dx = float(r["delta_mm"]) * 1e-3 / int(r["m"])
        expected = float(r["s0"]) * math.sqrt(kp.E * dx / kp.GC) / float(r["tip_coefficient"])
        assert float(r["probe"]) == pytest.approx(expected, rel=1e-5)
    # that bond (sqrt(5) Delta) is inside every family, |xi| <= delta = m Delta for LPS and pmb too
    xa, ya, xb, yb = map(float, data[0]["bond"].split())
    assert math.hypot(xb - xa, yb - ya) < min(int(r["m"]) for r in data)


def measured():
    out = {}
    for name in ("center_crack.csv", "center_crack_fine.csv", "center_crack_fine_constant.csv",
                 "center_crack_gaussian_full.csv", "center_crack_lps.csv", "center_crack_lps_1mm.csv",
                 "center_crack_lps_fine.csv", "center_crack_pmb.csv"):
        for r in (r for r in rows(name) if r["m"] == "4"):
            out.setdefault(r["kernel"], []).append((float(r["delta_mm"]), float(r["sigma_c_MPa"]) / float(r["sigma_lefm_MPa"])))
    return out


def test_the_verdict_as_data():
    v = kp.verdict(rows("kfield_probe.csv"))
    probe = {r["kernel"]: float(r["probe"]) for r in rows("kfield_probe.csv") if r["m"] == "4" and r["delta_mm"] == "0.5"}
    runs = measured()
    for kernel, got in v.items():
        deltas = sorted(runs[kernel], reverse=True)
        finest = deltas[-1][1]
        assert got["delta_mm"] == deltas[-1][0] and got["measured"] == pytest.approx(finest, rel=1e-5)
        assert got["probe"] == pytest.approx(probe[kernel], rel=2e-4)
        assert got["residual"] == pytest.approx(finest / got["probe"], rel=1e-5)
        assert got["within"] == (abs(finest - 1) <= 0.05)
        assert got["miss"] == pytest.approx(max(0.0, abs(finest - 1) - 0.05), abs=1e-5)
    assert {k: (g["within"], g["falls"], g["explained"]) for k, g in v.items()} == {
        "constant": (False, True, True), "triangular": (True, True, True),
        "gaussian": (True, False, True), "lps/constant": (False, True, True),
        "lps/triangular": (True, False, False), "lps/gaussian": (True, False, False),
        "pmb": (False, True, False)}
    # the bond-based kernels' residuals differ by less than TOL_EXPLAIN on the finest grid,
    # their initiation by 14 points: the kernels' spread is their s0's
    res = [v[k]["residual"] for k in kp.KERNELS[:3]]
    meas = [v[k]["measured"] for k in kp.KERNELS[:3]]
    assert max(res) / min(res) - 1 < kp.TOL_EXPLAIN < max(meas) / min(meas) - 1


# the README (examples/quasi-static/README.md) against the CSVs it quotes
TEXT = " ".join(README.split())


def name(kernel):
    return kernel.replace("lps/", "LPS ").replace("gaussian", "Gaussian")


def pct(x):
    return f"{100 * float(x):+.1f} %".replace("-", "−")


def three(x):
    return f"{float(x):.3f}" if x else "–"


def test_the_readme_quotes_the_probe_table():
    table = {}
    for r in rows("kfield_probe.csv"):
        table.setdefault((r["kernel"], r["m"]), {})[r["delta_mm"]] = r
    quoted = 0
    for (kernel, m), by in table.items():
        probes = [float(r["probe"]) for r in by.values()]
        assert max(probes) / min(probes) - 1 < 2e-4    # the probe does not move with delta
        if any(r["measured"] for r in by.values()):
            meas = " / ".join(three(by[d]["measured"]) for d in ("2", "1", "0.5"))
            res = " / ".join(three(by[d]["residual"]) for d in ("2", "1", "0.5"))
            line = f"| {name(kernel)} | {m} | {probes[0]:.3f} | {meas} | {res} |"
            assert line in README, line
            quoted += 1
    assert quoted == 20


def test_the_readme_quotes_the_m_series_csvs():
    for r in rows("center_crack_m_kernels.csv"):
        line = (f"| {r['kernel']} | {float(r['delta_mm']):g} | {float(r['delta_over_a']):g} | {r['m']} | "
                f"{int(r['atoms']):,} | {float(r['sigma_c_MPa']):.3f} | {float(r['sigma_lo_MPa']):.3f}–"
                f"{float(r['sigma_hi_MPa']):.3f} | {pct(r['error'])} | {r['broken_at_hi']} |")
        assert line in README, line
    for r in rows("center_crack_lps_m.csv"):
        line = (f"| {name(r['kernel'])} | {r['m']} | {int(r['atoms']):,} | {float(r['sigma_c_MPa']):.3f} | "
                f"{float(r['sigma_lo_MPa']):.3f}–{float(r['sigma_hi_MPa']):.3f} | {pct(r['error'])} | "
                f"{r['broken_at_hi']} | {float(r['wall_s']):.0f} s |")
        assert line in README, line
    err = {(r["kernel"], r["delta_mm"], r["m"]): pct(r["error"]) for r in rows("center_crack_m_kernels.csv")}
    for kernel in ("triangular", "constant"):
        for m in ("3", "5"):
            assert f"{err[(kernel, '2', m)]} / {err[(kernel, '1', m)]} at m = {m}".replace(" % /", " /") in TEXT
    lps = {(r["kernel"], r["m"]): 100 * float(r["error"]) for r in rows("center_crack_lps_m.csv")}
    falls = [round(lps[(f"lps/{k}", "3")] - lps[(f"lps/{k}", "5")]) for k in ("triangular", "gaussian", "constant")]
    assert f"from m = 3 to 5 by {falls[0]} and {falls[1]} points; the constant kernel's initiation falls by {falls[2]} points" in TEXT


def test_the_readme_reading_follows_the_probe():
    from test_kfield_s0 import notch_bonds    # tests/lammps: the count LAMMPS is checked against
    assert f"(1,104 at δ = 2 mm, m = 4)" in TEXT and notch_bonds(4, 16) == 1104
    data = rows("kfield_probe.csv")
    c = {round(float(r["tip_coefficient"]), 3) for r in data}
    assert c == {0.517} and "Its stretch is 0.517 K/(E √Δ)" in TEXT
    bb = [r for r in data if r["kernel"] in kp.KERNELS[:3] and r["measured"]]
    spans = []
    for d, label in (("2", "2 mm"), ("1", "1 mm"), ("0.5", "0.5 mm")):
        res = [float(r["residual"]) for r in bb if r["delta_mm"] == d]
        spans.append(f"{min(res):.3f}–{max(res):.3f} at {'δ = ' if d == '2' else ''}{label}")
    assert ", ".join(spans) in TEXT
    meas = [float(r["measured"]) for r in bb if r["delta_mm"] == "2"]
    assert f"spans {min(meas):.3f}–{max(meas):.3f} at δ = 2 mm" in TEXT
    res = [float(r["residual"]) for r in bb]
    assert f"{1 / max(res):.2f} to {1 / min(res):.2f} times more" in TEXT
    g4 = sorted((r for r in data if r["kernel"] == "gaussian" and r["m"] == "4"), key=lambda r: -float(r["delta_mm"]))
    assert ", ".join(three(r["residual"]) for r in g4) in TEXT
    griffith = ", ".join(f"{float(r['measured']) / float(r['probe_griffith']):.3f}" for r in g4)
    assert f"the residual is {griffith}" in TEXT
    v = kp.verdict(data)
    assert f"−10.9 %, outside by {100 * v['constant']['miss']:.1f} points" in TEXT
    assert f"−13.0 %, outside by {100 * v['lps/constant']['miss']:.1f} points" in TEXT
    assert f"{100 * (1 - v['constant']['probe'] / v['gaussian']['probe']):.1f} % below the Gaussian's" in TEXT
    assert f"(probe {v['constant']['probe']:.3f} against {v['gaussian']['probe']:.3f})" in TEXT
    assert f"same to {100 * (v['constant']['residual'] / v['gaussian']['residual'] - 1):.0f} %" in TEXT
    assert f"residual passes {1 / v['gaussian']['probe']:.3f}" in TEXT
    lpsc = [three(r["residual"]) for r in data if r["kernel"] == "lps/constant" and r["delta_mm"] == "2" and r["measured"]]
    assert f"({', '.join(lpsc)} at m = 3, 4, 5, δ = 2 mm)" in TEXT
    lps = [float(r["residual"]) for r in data if r["kernel"] in ("lps/triangular", "lps/gaussian") and r["measured"]]
    assert f"residual is {min(lps):.2f}–{max(lps):.2f}" in TEXT
    shared = lambda d: sum(float(r["residual"]) for r in bb if r["delta_mm"] == d and r["m"] == "4") / 3
    above = [float(r["residual"]) / shared(r["delta_mm"]) - 1 for r in data
             if r["kernel"] in ("lps/triangular", "lps/gaussian") and r["m"] == "4" and r["delta_mm"] in ("0.5", "2")]
    assert f"by {100 * min(above):.0f} % on the finest grid, {100 * max(above):.0f} % at δ = 2 mm" in TEXT
    low = [1 - v[k]["predicted"] / v[k]["measured"] for k in ("lps/triangular", "lps/gaussian")]
    assert all(round(100 * x) == 7 for x in low) and "predicts them 7 % low" in TEXT
    pmb = [r for r in data if r["kernel"] == "pmb" and r["measured"]]
    assert f"residual {' / '.join(three(r['residual']) for r in pmb)} at δ = 2 / 1 mm" in TEXT
    below = sorted(round(100 * (1 - float(r["residual"]) / shared(r["delta_mm"]))) for r in pmb)
    assert f"{below[0]}–{below[1]} % below the bond-based kernels'" in TEXT

# SPDX-License-Identifier: GPL-2.0-or-later
"""The crack-branching verdict (bbpd.benchmarks.branching.split_convergence) as data, against
synthetic rows and the committed results/branching.csv that examples/crack-branching/README.md
describes by hand (no run)."""
import pytest

from bbpd.benchmarks import branching


def run(kernel, m, x, t):
    return {"run": f"{kernel}-s2-m{m}", "kernel": kernel, "x_split_mm": x, "t_split_us": t}


def test_kernels_apart_by_more_than_twice_the_change_in_m_are_separated():
    rows = [run("constant", 3, 40.0, 20.0), run("constant", 4, 40.2, 20.1),
            run("gaussian", 3, 44.0, 22.0), run("gaussian", 4, 44.1, 22.2)]
    c = branching.split_convergence(rows)
    assert c["dx_m"] == pytest.approx(0.2) and c["dt_m"] == pytest.approx(0.2)
    assert c["dx_k"] == pytest.approx(3.9) and c["dt_k"] == pytest.approx(2.1)
    assert c["separated"]
    # the same kernels one grid step apart in m as far as they are from each other: not separated
    rows[1].update(x_split_mm=43.0, t_split_us=21.5)
    assert not branching.split_convergence(rows)["separated"]
    assert branching.split_convergence(rows[1::2]) is None     # no m = 3 run


def test_the_committed_runs_give_the_readme_convergence_in_m():
    """README: from m = 3 to 4 the fork moves by at most 1.21 mm and 0.42 us; the kernels differ
    by 1.25 mm and 0.44 us at m = 4, not more than twice that: the kernels are not separated"""
    c = branching.split_convergence(branching.read_rows())
    assert (round(c["dx_m"], 2), round(c["dt_m"], 2)) == (1.21, 0.42)
    assert (round(c["dx_k"], 2), round(c["dt_k"], 2)) == (1.25, 0.44)
    assert not c["separated"]


def test_the_committed_runs_give_the_readme_findings():
    """README 'Findings', by hand: at 2 MPa every run splits once into two tips; at delta = 1 mm,
    m = 4 the fork at 20.2-20.7 us, 16.6-17.9 mm, after 0.53-0.56 c_R, branches 47-48 deg apart;
    the crack atoms exact mirror images in every run that grew; at 4 MPa the fork earlier
    (8.4-8.8 us) and nearer the notch (6.9-8.4 mm)"""
    rows = branching.read_rows()
    by = {r["run"]: r for r in rows}
    two = [r for r in rows if r["sigma_MPa"] == 2.0]
    assert all((r["tips_end"], r["splits_end"]) == (2, 1) for r in two)
    base = [by[f"{k}-s2-m4"] for k in ("constant", "triangular", "gaussian")]

    def rng(col, sel, d=1):
        return round(min(r[col] for r in sel), d), round(max(r[col] for r in sel), d)
    assert rng("t_split_us", base) == (20.2, 20.7) and rng("x_split_mm", base) == (16.6, 17.9)
    assert rng("v_pre_over_cR", base, 2) == (0.53, 0.56) and rng("angle_deg", base, 0) == (47, 48)
    assert all(r["mirror_damage_frac"] == 0.0 for r in rows if branching.grown(r))
    mid = [by[f"{k}-s4-m4"] for k in ("constant", "triangular", "gaussian")]
    assert rng("t_split_us", mid) == (8.4, 8.8) and rng("x_split_mm", mid) == (6.9, 8.4)
    assert rng("v_pre_over_cR", mid, 2) == (0.61, 0.67)
    assert rng("v_mean_over_cR", mid, 2) == (0.59, 0.63)
    assert rng("v_mean_over_cR", base, 2) == (0.39, 0.42) and rng("tips_end", mid, 0) == (4, 6)
    assert rng("v_end_over_cR", base, 2) == (0.47, 0.50)


def test_the_committed_runs_give_the_readme_delta_and_12_mpa_findings():
    """README 'Findings', by hand: from delta = 1 to 0.5 mm the fork moves by -1.1 mm / -0.6 us,
    -0.2 / -0.2, -2.6 / -1.6 (constant, triangular, Gaussian), more than the kernels differ at
    1 mm, after 0.46-0.54 c_R; at 12 MPa the two waves' strain 2 sigma (1 - nu^2)/E is 109, 98
    and 92 % of s0 and the mid-line breaks at 3.91 us, the path length jumping at 15.7-15.8 c_R"""
    by = {r["run"]: r for r in branching.read_rows()}
    kernels = ("constant", "triangular", "gaussian")
    fine = [by[f"{k}-s2-m4-d0.5"] for k in kernels]
    coarse = [by[f"{k}-s2-m4"] for k in kernels]
    moves = [(round(f["x_split_mm"] - c["x_split_mm"], 1),
              round(f["t_split_us"] - c["t_split_us"], 1)) for f, c in zip(fine, coarse)]
    assert moves == [(-1.1, -0.6), (-0.2, -0.2), (-2.6, -1.6)]
    apart = branching.split_convergence(branching.read_rows())["dx_k"]    # kernels at 1 mm
    assert max(abs(x) for x, _ in moves) > apart
    assert (round(min(f["v_pre_over_cR"] for f in fine), 2),
            round(max(f["v_pre_over_cR"] for f in fine), 2)) == (0.46, 0.54)
    high = [by[f"{k}-s12-m4"] for k in kernels]
    strain = 2 * 12e6 * (1 - branching.NU**2) / branching.E
    assert [round(100 * strain / r["s0"]) for r in high] == [109, 98, 92]
    assert all(round(r["t_init_us"], 2) == 3.91 for r in high)
    assert [round(r["v_max_over_cR"], 1) for r in high] == [15.8, 15.7, 15.8]

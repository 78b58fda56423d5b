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

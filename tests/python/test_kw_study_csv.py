# SPDX-License-Identifier: GPL-2.0-or-later
"""examples/kalthoff-winkler/README.md, 'Reading the study' (hand text): its numbers against the
committed results/study.csv, the study's table (no run)."""
import pytest

from bbpd.benchmarks import kalthoff_winkler_study as study

HELD = ("paper", "v24", "v20", "v16")    # the loadings held at 32, 24, 20, 16 m/s


def num(cell):
    return None if cell in ("-", "none") else float(cell)


@pytest.fixture(scope="module")
def runs():
    rows, _ = study.read_csv()
    return {(r[0], r[1], float(r[2])): dict(zip(study.TABLE_HEADER, r)) for r in rows}


def span(runs, col, loadings, kernels=("constant", "triangular", "gaussian"), dx=1.0):
    vals = [num(runs[c, k, dx][col]) for c in loadings for k in kernels]
    return min(vals), max(vals)


def test_no_loading_gives_both(runs):
    """no run has 70 +- 2 deg (a crack of 15 mm or more at 70 us) and an initiation at 20-22 us"""
    for r in runs.values():
        long = num(r["length at 70 us (mm)"]) >= 15
        angle = long and any(num(r[c]) is not None and abs(num(r[c]) - 70) <= 2 for c in
                             ("initial (deg)", "fit 10-50 mm (deg)", "chord (deg)"))
        init = any(20 <= num(r[c]) <= 22 for c in ("first bond (us)", "damage band (us)"))
        assert not (angle and init), r


def test_velocity_sets_initiation(runs):
    first = "first bond (us)"
    assert [span(runs, first, (c,)) for c in HELD] == [(11.3, 12.4), (12.9, 15.1), (15.5, 19.8),
                                                       (21.1, 22.8)]
    assert max(abs(num(runs[c, "gaussian", 1.0][first]) - num(runs[c, "gaussian", 0.5][first]))
               for c in HELD) == pytest.approx(0.3)
    assert span(runs, "damage band (us)", ("paper",)) == (18.1, 20.0)
    assert num(runs["paper", "gaussian", 0.5]["damage band (us)"]) == 17.4
    lag = [num(runs["v16", k, 1.0]["damage band (us)"]) - num(runs["v16", k, 1.0][first])
           for k in ("constant", "triangular", "gaussian")]
    assert 5 <= min(lag) and max(lag) <= 7
    assert span(runs, "damage band (us)", ("v16",)) == (28.1, 29.4)


def test_gaussian_fine_angles_and_arrests(runs):
    """Gaussian at 0.5 mm: 62-63 deg at 32 m/s, 63-65 at 20, 67-69 at 24, 71.5-72.1 at 16; at
    16 m/s the cracks stop at 22-43 mm between 64 and 89 us, at 20-24 m/s they reach the edge
    at 81-93 us (the constant kernel at 20 m/s stops at 73 mm)"""
    defs = ("initial (deg)", "fit 10-50 mm (deg)", "chord (deg)")
    fine = {c: [num(runs[c, "gaussian", 0.5][d]) for d in defs] for c in HELD}
    assert (min(fine["paper"]), max(fine["paper"])) == (62.3, 62.7)
    assert 63 <= min(fine["v20"]) and max(fine["v20"]) <= 65.5
    assert 67 <= min(fine["v24"]) and max(fine["v24"]) <= 69.5
    assert (min(fine["v16"]), max(fine["v16"])) == (71.5, 72.1)
    slow = [r["crack stops (us)"] for (c, _, _), r in runs.items() if c in ("v16", "v16ramp")]
    times = [float(s.split()[1]) for s in slow if s.startswith("arrest")]
    lengths = [float(s.split("(")[1].split()[0]) for s in slow]
    assert (min(times), max(times), min(lengths), max(lengths)) == (64, 89, 22, 43)
    edge = [r["crack stops (us)"] for (c, _, _), r in runs.items() if c in ("v24", "v20")]
    assert sorted(s for s in edge if not s.startswith("edge")) == ["arrest 86 (73 mm)"]
    edges = [float(s.split()[1]) for s in edge if s.startswith("edge")]
    assert (min(edges), max(edges)) == (81, 93)


def test_speeds_and_symmetry(runs):
    """mean speed 0.45-0.55 c_R at 20-24 m/s, 0.62-0.66 at 32 m/s, no peak above 0.72; tips
    mirror images to 3e-14 mm"""
    col = "speed / c_R (mean, peak)"

    def speeds(loadings, which):
        return [num(r[col].split(", ")[which]) for (c, _, _), r in runs.items() if c in loadings]
    assert (min(speeds(("v24", "v20"), 0)), max(speeds(("v24", "v20"), 0))) == (0.45, 0.55)
    fast = speeds(("paper", "v32release", "thin"), 0)
    assert (min(fast), max(fast)) == (0.62, 0.66)
    assert max(s for s in speeds(study.CASES, 1) if s is not None) == 0.72
    assert max(num(r["tip mismatch (mm)"]) for r in runs.values()) <= 3e-14

"""The Mode-II verdict of the report (bbpd.report.mode2_j) follows the numbers: where the
J-integral carries the extrapolation's excess, and where it does not."""

import pytest

from bbpd import report


def runs(pairs):
    """(kernel, dx) -> result with K_II/K_ref at the window end from the extrapolation and J."""
    out = {}
    for n, (dsif, jint) in enumerate(pairs):
        out[(report.KERNELS[n % 3], 1e-3 * (1 + n // 3))] = {
            "k_end": dsif, "k_end_exact": 1.0,
            "jintegral": {"k_end": jint, "peak": 100 * abs(jint - 1), "l2": 1.0}}
    return out


@pytest.mark.parametrize("pairs,where", [
    ([(1.2, 1.01), (1.25, 0.98), (1.3, 1.02)], "extrapolation"),
    ([(1.2, 1.19), (1.25, 1.22), (1.3, 1.28)], "field"),
    ([(1.2, 1.1), (1.25, 1.02), (1.3, 1.01)], "partly"),
])
def test_verdict_follows_the_share_of_the_excess(pairs, where):
    v = report.mode2_j(runs(pairs))
    assert v["where"] == where
    assert v["share"][(report.KERNELS[0], 1e-3)] == pytest.approx((pairs[0][1] - 1) / (pairs[0][0] - 1))


def test_the_kernels_peak_errors_by_j_per_grid():
    v = report.mode2_j(runs([(1.2, 1.05), (1.25, 1.03), (1.3, 1.01)]))
    peaks = v["peaks"][1e-3]
    assert sorted(peaks, key=peaks.get) == ["gaussian", "triangular", "constant"]


def test_no_j_no_verdict():
    assert report.mode2_j({("gaussian", 1e-3): {"k_end": 1.2, "k_end_exact": 1.0}}) is None

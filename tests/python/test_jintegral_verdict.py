"""The Mode-II verdict of the report (bbpd.report.mode2_j_verdict) follows the numbers: where
the J-integral carries the extrapolation's excess, and where it does not."""

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
    ([(1.2, 1.01), (1.25, 0.98), (1.3, 1.02)], "in the near-tip displacement extrapolation"),
    ([(1.2, 1.19), (1.25, 1.22), (1.3, 1.28)], "in the peridynamic field"),
    ([(1.2, 1.1), (1.25, 1.02), (1.3, 1.01)], "partly in the field"),
])
def test_verdict_follows_the_share_of_the_excess(pairs, where):
    text = report.mode2_j_verdict(runs(pairs))
    assert f"the excess lives {where}" in text


def test_best_kernel_by_j_is_named():
    text = report.mode2_j_verdict(runs([(1.2, 1.05), (1.25, 1.03), (1.3, 1.01)]))
    assert "gaussian < triangular < constant" in text and "the Gaussian kernel is closest" in text


def test_no_j_no_verdict():
    assert report.mode2_j_verdict({("gaussian", 1e-3): {"k_end": 1.2, "k_end_exact": 1.0}}) == ""

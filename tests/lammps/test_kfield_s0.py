"""What bbpd.benchmarks.kfield_probe takes from the plugin, read back from in.center-crack's log
(delta = 2 mm, m = 4, u = 0, run 0): the critical stretch that each kernel's pair style reports
at setup, bond-based and LPS, equals the probe's s0; and the notch cuts the bonds through its
ends, as the probe cuts the bonds through the tip: fix bbpd/notch's count equals an exact count
(rational arithmetic) of the bonds |xi| < delta + Delta/2 that cross y = H/2 with the
crossing in [W/2 - a, W/2 + a], ends included; negative control: ends excluded is fewer."""
import re
from fractions import Fraction

import pytest

from bbpd.benchmarks import center_crack, kfield_probe as kp
from bbpd.runner import run_lammps

DELTA, M = 2.0e-3, 4


def setup_log(kernel, tmp_path):
    return run_lammps(str(center_crack.HERE / "in.center-crack"), tmp_path,
                      vars={**center_crack.kernel_vars(kernel, DELTA), "dx": repr(DELTA / M), "m": M,
                            "u": 0, "iters": 0}).output


def notch_bonds(m, length, ends=True):
    """bonds of the infinite grid (atoms at half-integers, units of Delta) with |xi| < m + 1/2
    that cross y = 0 with the crossing x in [-length, 0]"""
    n = 0
    for p in range(-m, m + 1):
        for q in range(1, m + 1):
            if 4 * (p * p + q * q) >= (2 * m + 1) ** 2:
                continue
            for j in range(-q, 0):    # the lower atom's row j + 1/2, the upper's j + q + 1/2
                ya = Fraction(2 * j + 1, 2)
                for i in range(-length - m - 1, m + 1):
                    xc = Fraction(2 * i + 1, 2) + p * (-ya) / q
                    n += (-length <= xc <= 0) if ends else (-length < xc < 0)
    return n


@pytest.mark.parametrize("kernel", kp.KERNELS[:6])
def test_s0_and_the_notch_as_the_probe_takes_them(kernel, tmp_path):
    out = setup_log(kernel, tmp_path)
    s0 = float(re.search(r"critical_stretch s0 = (\S+)", out).group(1))
    assert s0 == pytest.approx(kp.s0(kernel, DELTA), rel=1e-7)
    if not kernel.startswith("lps/"):    # the kernel styles' families (LPS: |xi| <= delta)
        cut = int(re.search(r"bbpd/notch: (\d+) bonds cut", out).group(1))
        length = round(2 * center_crack.A / (DELTA / M))
        assert cut == notch_bonds(M, length) > notch_bonds(M, length, ends=False)

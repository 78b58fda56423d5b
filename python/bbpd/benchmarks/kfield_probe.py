# SPDX-License-Identifier: GPL-2.0-or-later
"""K-field probe of the centre crack's first broken bond: LEFM's plane-stress mode-I field
(Williams' leading term, nu = 1/3) imposed on in.center-crack's grid at one tip, every bond's
stretch, and K_probe, the K_I at which the largest stretch reaches the kernel's s0.

    tools/python -m bbpd.benchmarks.kfield_probe    # results/kfield_probe.csv, in seconds

The grid as in.center-crack's: atoms at ((i + 1/2) Delta, (j + 1/2) Delta) from the tip, the
crack along y = 0, x <= 0, a bond cut if it crosses it at x <= 0 (fix bbpd/notch: ends included),
families |xi| < delta + Delta/2 (LPS, pmb: <= delta; the largest stretch's bond is sqrt(5) Delta),
s0 as the plugin's (tests/lammps/test_kfield_s0.py reads it back). K_probe/K_Ic is sigma_c/
sigma_LEFM of a plate that followed LEFM's field to the tip; measured/probe is the body's own.
"""
import argparse
import csv
import math

import numpy as np

from bbpd import csvfile, dsif, reference
from bbpd.benchmarks.center_crack import A, E, GC, HERE, LPS_NU

NU = 1.0 / 3.0                      # bond-based plane stress (and LPS_NU)
KAPPA, MU = (3.0 - NU) / (1.0 + NU), E / (2.0 * (1.0 + NU))
K_IC = math.sqrt(E * GC)            # plane stress
KERNELS = ("constant", "triangular", "gaussian", "lps/constant", "lps/triangular",
           "lps/gaussian", "pmb")    # pmb: bbpd/pmb with Ha & Bobaru's s0, the constant kernel's
CASES = [(d, m) for d in (2e-3, 1e-3, 0.5e-3) for m in (3, 4, 5, 6)]
TOL = 0.05            # the acceptance: initiation within 5 % of LEFM
TOL_EXPLAIN = 0.03    # the probe explains a kernel's initiation to this (README.md)


def moment(kernel, n):
    """M_n = int_0^1 W(r) r^n dr of the kernel (pmb's: the constant one)"""
    return reference.moment(kernel.split("/")[-1].replace("pmb", "constant"), n)


def s0(kernel, delta):
    """plane stress s0: bond-based sqrt(pi Gc M2 / (3 E delta M3)) (src/bbpd_kernel.h), LPS
    sqrt(pi Gc M3 / (8 G delta M4)) (doc/pair_bbpd_lps.rst)"""
    if kernel.startswith("lps/"):
        g = E / (2.0 * (1.0 + LPS_NU))
        return math.sqrt(math.pi * GC * moment(kernel, 3) / (8.0 * g * delta * moment(kernel, 4)))
    return math.sqrt(math.pi * GC * moment(kernel, 2) / (3.0 * E * delta * moment(kernel, 3)))


def williams(x, y, k):
    """(u_x, u_y) of the mode-I leading term at K_I = k, plane stress, tip at 0, crack at x < 0"""
    return dsif.williams_displacement(k, 0.0, np.hypot(x, y), np.arctan2(y, x), MU, KAPPA)


def bonds(m, reach=3):
    """the intact bonds of atoms a within reach horizons of the tip, each once, as (X_a, Y_a, X_b,
    Y_b) in units of Delta/2 (integers: the atoms sit at odd ones)"""
    odd, near = np.arange(-reach * m - 1, reach * m + 1) * 2 + 1, np.arange(-m, m + 1)
    Xa, Ya = (c.ravel() for c in np.meshgrid(odd, odd))
    p, q = (c.ravel() for c in np.meshgrid(near, near))
    keep = (4 * (p * p + q * q) < (2 * m + 1) ** 2) & ((p > 0) | ((p == 0) & (q > 0)))
    p, q, n = 2 * p[keep], 2 * q[keep], keep.sum()
    Xa, Ya = np.repeat(Xa, n), np.repeat(Ya, n)
    Xb, Yb = Xa + np.tile(p, Xa.size // n), Ya + np.tile(q, Ya.size // n)
    # across y = 0 at x <= 0: Xl Yu - Xu Yl <= 0 with l the lower end, u the upper
    cut = (Ya * Yb < 0) & (np.sign(Yb - Ya) * (Xa * Yb - Xb * Ya) <= 0)
    return tuple(c[~cut] for c in (Xa, Ya, Xb, Yb))


def griffith(x, y, k):
    """the whole LEFM field of a crack 2a long in an infinite plate under sigma_yy = k/sqrt(pi a)
    (K_I = k), tip at 0: Westergaard's biaxial 2 mu u = ((kappa -+ 1)/2 (Re, Im) Zbar
    - y (Im, Re) Z), Z = sigma z / sqrt(z^2 - a^2), plus sigma_xx = -sigma (T)"""
    sigma, z = k / math.sqrt(math.pi * A), (x + A) + 1j * y    # z from the crack's centre
    root = np.sqrt(z - A) * np.sqrt(z + A)                      # its branch cut: the crack
    zz, zbar = sigma * z / root, sigma * root
    return (((KAPPA - 1.0) / 2 * zbar.real - y * zz.imag) / (2.0 * MU) - sigma * (x + A) / E,
            ((KAPPA + 1.0) / 2 * zbar.imag - y * zz.real) / (2.0 * MU) + NU * sigma * y / E)


def stretch(b, dx, k, field=williams):
    """every bond's stretch |y|/|xi| - 1 in field at K_I = k on the grid of spacing dx"""
    xa, ya, xb, yb = (0.5 * dx * c for c in b)
    (uxa, uya), (uxb, uyb) = field(xa, ya, k), field(xb, yb, k)
    return np.hypot(xb - xa + uxb - uxa, yb - ya + uyb - uya) / np.hypot(xb - xa, yb - ya) - 1.0


def probe(kernel, delta, m, field=williams):
    """K_probe / K_Ic (the largest stretch at s0) and the bond that reaches it"""
    b, dx, k, target = bonds(m), delta / m, K_IC, s0(kernel, delta)
    for _ in range(6):    # the stretch is K-linear to O(s0): a fixed point in a few steps
        s = stretch(b, dx, k, field)
        k *= target / s.max()
    return k / K_IC, " ".join(f"{c[np.argmax(s)] / 2:g}" for c in b)


def rows():
    """results/kfield_probe.csv: the probe (Williams; griffith), c of s_max = c K / (E sqrt(Delta))
    and the measured sigma_c / sigma_LEFM (results/center_crack*.csv)"""
    seen = {(r["kernel"], float(r["delta_mm"]), int(r["m"])): 1.0 + float(r["error"])
            for path in sorted((HERE / "results").glob("center_crack*.csv"))
            for r in csv.DictReader(open(path)) if "sigma_c_MPa" in r}
    out = []
    for kernel in KERNELS:
        for delta, m in CASES:
            p, bond = probe(kernel, delta, m)
            got = seen.get((kernel, delta * 1e3, m))
            out.append({"kernel": kernel, "delta_mm": delta * 1e3, "m": m, "s0": s0(kernel, delta),
                        "probe": p, "probe_griffith": probe(kernel, delta, m, griffith)[0], "bond": bond,
                        "tip_coefficient": s0(kernel, delta) * E * math.sqrt(delta / m) / (p * K_IC),
                        "measured": got, "residual": None if got is None else got / p})
    return out


def verdict(table):
    """per kernel on its finest measured grid at m = 4 (CSV rows): measured, probe, residual, the
    acceptance (within TOL; the error falling with delta) and whether the probe times the
    bond-based kernels' mean residual on that grid gives the measured value to TOL_EXPLAIN"""
    got = [{k: (v if k in ("kernel", "bond") else float(v)) for k, v in r.items()}
           for r in table if r["measured"] not in ("", None) and int(float(r["m"])) == 4]
    shared = {d: np.mean([r["residual"] for r in got if r["delta_mm"] == d and r["kernel"] in KERNELS[:3]])
              for d in {r["delta_mm"] for r in got}}
    out = {}
    for kernel in dict.fromkeys(r["kernel"] for r in got):
        runs = sorted((r for r in got if r["kernel"] == kernel), key=lambda r: -r["delta_mm"])
        r, errs = runs[-1], [abs(q["measured"] - 1.0) for q in runs]
        p = r["probe"] * shared[r["delta_mm"]]
        out[kernel] = {"delta_mm": r["delta_mm"], "measured": r["measured"], "probe": r["probe"],
                       "residual": r["residual"], "within": errs[-1] <= TOL,
                       "miss": max(0.0, errs[-1] - TOL), "falls": all(np.diff(errs) < 0),
                       "predicted": p, "explained": abs(r["measured"] / p - 1.0) <= TOL_EXPLAIN}
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--csv", default="kfield_probe.csv", help="file name under results/")
    args = ap.parse_args(argv)
    csvfile.write_csv(HERE / "results" / args.csv, rows(), nan="nan")
    for kernel, v in verdict(csv.DictReader(open(HERE / "results" / args.csv))).items():
        print(kernel, {k: round(x, 4) if isinstance(x, float) else x for k, x in v.items()})


if __name__ == "__main__":
    main()

# SPDX-License-Identifier: GPL-2.0-or-later
"""Check the CSV files of bbpd-dispersion-curves against eq. 31 written out here.

usage: check_dispersion_curves.py DIR M DELTA DT POINTS

Run by ctest (tests/unit/CMakeLists.txt) after the tool wrote DIR/dispersion_<kernel>.csv
with --m M --delta DELTA --dt DT --volume-correction --points POINTS and E = rho = 1. Plain
Python (no numpy), independent of the C++ headers: c0 A delta^2 / E from the paper's Table 1,
the bond weights W(j/m) C_v(j dx) of eqs. 19 and 31, and the velocity-Verlet frequency
omega_t = (2/dt) asin(dt omega / 2). Exits non-zero with a message on the first mismatch.
"""
import csv
import math
import sys

RTOL = 1.0e-9    # the CSV holds 12 significant digits

E4 = math.exp(4.0)
TABLE1_1D = {"constant": 2.0, "triangular": 6.0, "gaussian": 8.0 * E4 / (E4 - 1.0)}
SHAPE = {"constant": lambda r: 1.0, "triangular": lambda r: max(0.0, 1.0 - r),
         "gaussian": lambda r: math.exp(-4.0 * r * r)}


def partial_volume(xi, delta, dx):
    return min(1.0, max(0.0, (delta + 0.5 * dx - xi) / dx))


def omega_discrete(kernel, k, m, delta):
    dx = delta / m
    total = 0.0
    for j in range(1, int(math.ceil(m + 0.5)) + 1):
        w = SHAPE[kernel](min(j / m, 1.0)) * partial_volume(j * dx, delta, dx)
        total += w * (1.0 - math.cos(j * k * dx)) / j
    return math.sqrt(2.0 * TABLE1_1D[kernel] / delta**2 * total)


def fail(msg):
    print(f"check_dispersion_curves: FAILED: {msg}")
    sys.exit(1)


def close(a, b):
    return abs(a - b) <= RTOL * max(abs(a), abs(b), 1e-300)


def main(argv):
    folder, m, delta, dt, points = argv[1], float(argv[2]), float(argv[3]), float(argv[4]), \
        int(argv[5])
    dx = delta / m
    for kernel in ("constant", "triangular", "gaussian"):
        path = f"{folder}/dispersion_{kernel}.csv"
        try:
            with open(path) as f:
                rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
        except OSError as e:
            fail(f"cannot read {path}: {e}")
        if len(rows) != points:
            fail(f"{path}: {len(rows)} rows, expected {points}")
        for n, row in enumerate(rows):
            k = float(row["k"])
            if not close(k, math.pi / dx * n / (points - 1)):
                fail(f"{path} row {n}: k = {k}")
            omega = omega_discrete(kernel, k, m, delta)
            got = float(row["omega_discrete"])
            if not close(got, omega):
                fail(f"{path} row {n}: omega_discrete {got!r}, eq. 31 gives {omega!r}")
            x = 0.5 * dt * omega
            got_t = float(row["omega_discrete_dt"])
            if x > 1.0:
                if not math.isnan(got_t):
                    fail(f"{path} row {n}: unstable step but omega_discrete_dt = {got_t!r}")
            elif not close(got_t, 2.0 / dt * math.asin(x)):
                fail(f"{path} row {n}: omega_discrete_dt {got_t!r}, expected "
                     f"{2.0 / dt * math.asin(x)!r}")
        print(f"{path}: {points} rows match eq. 31")
    print("check_dispersion_curves: OK")


if __name__ == "__main__":
    if len(sys.argv) != 6:
        fail(__doc__)
    main(sys.argv)

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Which stress for compute bbpd/jintegral: Hooke's law of the displacement gradient, or the
stress of the bond forces?

Scene: the static Williams check of tests/lammps/test_jintegral.py (square grid dx = 1,
horizon 3 dx, exact Williams field of K_I = 3 MPa m^1/2, K_II = -1.2 MPa m^1/2 imposed, no
dynamics). LAMMPS writes the displacements and the bond-force stress of each atom
(compute stress/atom NULL pair: 1/2 sum_j f_ij (x) xi_ij, the forces being force densities);
this script evaluates the static domain integral and the interaction integral of
bbpd_jintegral.h in NumPy, once with Hooke's law of the least-squares gradient (what the
compute does; the numbers must match it) and once with the bond-force stress, on three annuli.

Usage: perf/jintegral_stress.py [--model plane/stress|plane/strain]
Prints the errors of J, K_I, K_II in % for both stresses.
"""
import argparse
import importlib.util
import tempfile
from pathlib import Path

import numpy as np
from scipy.spatial import cKDTree

ROOT = Path(__file__).resolve().parents[1]
from bbpd.runner import run_lammps
# the scenes of the J-integral tests, loaded from their file (not an importable package)
_spec = importlib.util.spec_from_file_location("jintegral_scenes",
                                               ROOT / "tests" / "lammps" / "test_jintegral.py")
scene = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(scene)

ANNULI = ((6.0, 15.0), (10.0, 25.0), (15.0, 35.0))
GRADIENT_RADIUS = 2.01    # the compute's default, in dx


def elastic(model):
    nu = scene.IMPLIED_NU[model]
    stress = model == "plane/stress"
    mu = scene.YOUNGS / (2 * (1 + nu))
    lam = scene.YOUNGS * nu / (1 - nu * nu) if stress else \
        scene.YOUNGS * nu / ((1 + nu) * (1 - 2 * nu))
    kappa = (3 - nu) / (1 + nu) if stress else 3 - 4 * nu
    e_prime = scene.YOUNGS if stress else scene.YOUNGS / (1 - nu * nu)
    return mu, lam, kappa, e_prime


def williams_gradient(k1, k2, x1, x2, mu, kappa):
    r, th = np.hypot(x1, x2), np.arctan2(x2, x1)
    s, c, k = np.sin(th / 2), np.cos(th / 2), kappa
    f = np.sqrt(r / (2 * np.pi)) / (2 * mu)
    u = [f * (k1 * c * (k - 1 + 2 * s * s) + k2 * s * (k + 1 + 2 * c * c)),
         f * (k1 * s * (k + 1 - 2 * c * c) - k2 * c * (k - 1 - 2 * s * s))]
    dth = [f * (k1 * (-0.5 * s * (k - 1 + 2 * s * s) + 2 * s * c * c)
                + k2 * (0.5 * c * (k + 1 + 2 * c * c) - 2 * s * s * c)),
           f * (k1 * (0.5 * c * (k + 1 - 2 * c * c) + 2 * s * s * c)
                - k2 * (-0.5 * s * (k - 1 - 2 * s * s) - 2 * s * c * c))]
    g = np.empty((2, 2))
    for i in range(2):
        dr = u[i] / (2 * r)
        g[i] = (np.cos(th) * dr - np.sin(th) / r * dth[i], np.sin(th) * dr + np.cos(th) / r * dth[i])
    return g


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--model", default="plane/stress")
    args = ap.parse_args(argv)
    work = Path(tempfile.mkdtemp(prefix="jstress-"))
    script = ("plugin load bbpdplugin.so\n" + scene.williams_script(args.model) +
              "compute s all stress/atom NULL pair\n"
              "dump d all custom 1 dump.txt id f_ref[1] f_ref[2] x y c_s[1] c_s[2] c_s[4]\n"
              "dump_modify d format float %.17g\nrun 0\n")
    run_lammps(script, work)
    d = np.loadtxt(work / "dump.txt", skiprows=9)
    x0, u, bond = d[:, 1:3], d[:, 3:5] - d[:, 1:3], d[:, 5:8]
    mu, lam, kappa, e_prime = elastic(args.model)

    def hooke(g):
        tr = lam * (g[0, 0] + g[1, 1])
        return np.array([[tr + 2 * mu * g[0, 0], mu * (g[0, 1] + g[1, 0])],
                         [mu * (g[0, 1] + g[1, 0]), tr + 2 * mu * g[1, 1]]])

    tree = cKDTree(x0)

    def gradient(i):
        keep = []
        for j in tree.query_ball_point(x0[i], GRADIENT_RADIUS * scene.DX):
            p, q = x0[i], x0[j]
            if j == i:
                continue
            if (p[1] >= 0) != (q[1] >= 0) and p[0] + (q[0] - p[0]) * (-p[1]) / (q[1] - p[1]) < 0:
                continue    # across the crack
            keep.append(j)
        xi, du = x0[keep] - x0[i], u[keep] - u[i]
        return (du.T @ xi) @ np.linalg.inv(xi.T @ xi)

    jref = (scene.K_I**2 + scene.K_II**2) / e_prime
    print(f"{args.model}: errors (%) of J, K_I, K_II; static field, so only the annulus counts")
    for rin, rout in ANNULI:
        for name in ("hooke", "bond"):
            total = np.zeros(3)
            for i in range(len(x0)):
                r = np.hypot(*x0[i])
                if not rin < r < rout:
                    continue
                s = (r - rin) / (rout - rin)
                dq = -6 * s * (1 - s) / (rout - rin) * x0[i] / r
                g = gradient(i)
                sig = hooke(g) if name == "hooke" else \
                    np.array([[bond[i, 0], bond[i, 2]], [bond[i, 2], bond[i, 1]]])
                eps = 0.5 * (g + g.T)
                total[0] += (sig @ dq) @ g[:, 0] - 0.5 * np.sum(sig * eps) * dq[0]
                for m, (k1, k2) in enumerate(((1.0, 0.0), (0.0, 1.0))):
                    ga = williams_gradient(k1, k2, x0[i, 0], x0[i, 1], mu, kappa)
                    sa = hooke(ga)
                    total[1 + m] += ((sig @ dq) @ ga[:, 0] + (sa @ dq) @ g[:, 0]
                                     - np.sum(sa * eps) * dq[0])
            j, ki, kii = total[0], 0.5 * e_prime * total[1], 0.5 * e_prime * total[2]
            print(f"  annulus {rin:g}-{rout:g} dx, {name:5s} stress: J {100 * (j / jref - 1):+7.2f}  "
                  f"K_I {100 * (ki / scene.K_I - 1):+7.2f}  K_II {100 * (kii / scene.K_II - 1):+7.2f}")


if __name__ == "__main__":
    main()

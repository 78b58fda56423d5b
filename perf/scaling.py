#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Scaling of bbpd/constant with the number of atoms N and the horizon ratio m = delta/dx.

2D plane-stress plates of N = 1e4, 1e5, 1e6 atoms for m = 3, 5, 8, elastic, a few steps.
Prints the pair time per step, the time per directed bond evaluation (should not grow with N
or m), and the setup time (bond families + caches) per bond: all should stay flat if the
cost is linear in the number of bonds.

Usage (from the repository root): tools/python perf/scaling.py [--sizes 1e4,1e5,1e6] [--ms 3,5,8] [--steps 20]
"""
import argparse
import re
import tempfile
import time
from math import sqrt
from pathlib import Path

from bbpd.runner import run_lammps

SCRIPT = """
plugin load bbpdplugin.so
units si
dimension 2
boundary s s p
atom_style peri
atom_modify map array
lattice sq 1.0e-3
region box block 0 {n} 0 {n} -0.5 0.5
create_box 1 box
create_atoms 1 box
set group all density 7800
set group all volume 1.0e-9
pair_style bbpd/constant plane/stress thickness 1.0e-3
pair_coeff 1 1 190.0e9 none {delta}
velocity all create 1.0e-6 12345 loop geom
fix 1 all nve
fix 2 all enforce2d
neigh_modify one {one} page {page}
timestep 1.0e-8
thermo {steps}
{run}
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="1e4,1e5,1e6")
    ap.add_argument("--ms", default="3,5,8")
    ap.add_argument("--steps", type=int, default=20)
    args = ap.parse_args()
    print(f"{'N atoms':>9s} {'m':>3s} {'bonds':>11s} {'ms/step':>9s} {'ns/bond-end':>12s} "
          f"{'setup s':>8s} {'setup ns/bond':>14s}")
    with tempfile.TemporaryDirectory() as tmp:
        for size in (float(s) for s in args.sizes.split(",")):
            n = int(round(sqrt(size))) - 1
            for m in (int(x) for x in args.ms.split(",")):
                delta = (m + 1e-3) * 1e-3
                one = max(2000, 4 * m * m * 4)
                fmt = dict(n=n, delta=delta, steps=args.steps, one=one, page=one * 50)
                wd = Path(tmp) / f"{n}-{m}"
                # setup cost = (create + run 0) - (create only): families, caches, report
                t0 = time.perf_counter()
                run_lammps(SCRIPT.format(run="", **fmt), workdir=wd, timeout=3600)
                t1 = time.perf_counter()
                run_lammps(SCRIPT.format(run="run 0", **fmt), workdir=wd, timeout=3600)
                t2 = time.perf_counter()
                wall_s = max((t2 - t1) - (t1 - t0), 0.0)
                out = run_lammps(SCRIPT.format(run=f"run 0\nrun {args.steps}", **fmt), workdir=wd,
                                 timeout=3600).output
                bonds = int(re.search(r"total bonds (\d+)", out).group(1))
                pair = float(re.findall(r"^Pair\s*\|\s*([0-9.eE+-]+)", out, re.M)[-1])
                ms = 1e3 * pair / args.steps
                print(f"{(n + 1) ** 2:9d} {m:3d} {bonds:11d} {ms:9.3f} {1e6 * ms / (2 * bonds):12.3f} "
                      f"{wall_s:8.2f} {1e9 * wall_s / bonds:14.1f}", flush=True)


if __name__ == "__main__":
    main()

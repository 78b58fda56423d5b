#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Scaling of bbpd/constant with the number of atoms N and the horizon ratio m = delta/dx.

2D plane-stress plates of N = 1e4, 1e5, 1e6 atoms for m = 3, 5, 8, elastic, a few steps; with
--dim 3, 3D glass plates eight atoms thick (the plate3d scene of pair_vs_pmb.py: spacing 0.25 mm, 2.5 : 1 in
plane) of N = 1e5 to 1e6 atoms. Prints the pair time per step, the time per directed bond
evaluation (should not grow with N or m), the setup time (bond families + caches) per bond: all
should stay flat if the cost is linear in the number of bonds; and the bytes per bond of the
bonds and the pair style from the setup report.

Usage (from the repository root): tools/python perf/scaling.py [--dim 2|3] [--sizes 1e4,1e5,1e6]
    [--ms 3,5,8] [--steps 20] [--nprocs 1] [--csv perf/results/NAME.csv]
--csv also writes the rows with the CPU, the load average before and after and the command.
"""
import argparse
import csv
import re
import shlex
import sys
import tempfile
import time
from math import sqrt
from pathlib import Path

from bbpd.runner import run_lammps
from pair_vs_pmb import PLATE3D_PREAMBLE, build_isa, cpu_model, cpu_numbers, load_average

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


# a 3D glass plate 8 atoms thick, elastic, the same few steps
SCRIPT_3D = PLATE3D_PREAMBLE + """region box block 0 {nx} 0 {ny} 0 8
create_box 1 box
create_atoms 1 box
set group all density 2440
set group all volume {vol}
pair_style bbpd/constant 3d
pair_coeff 1 1 72e9 none {delta}
neighbor {dx} bin
velocity all create 1.0e-6 12345 loop geom
fix 1 all nve
timestep 2.0e-8
thermo {steps}
{run}
"""
DX_3D = 0.25e-3


def case(dim, size, m, steps):
    """(script template, its fields, atoms) of a plate of about size atoms"""
    if dim == 2:
        n = int(round(sqrt(size))) - 1
        one = max(2000, 4 * m * m * 4)
        delta = (m + 1e-3) * 1e-3
        return SCRIPT, dict(n=n, delta=delta, steps=steps, one=one, page=one * 50), (n + 1) ** 2
    ny = int(round(sqrt(size / 8 / 2.5)))
    nx = int(round(2.5 * ny))
    return SCRIPT_3D, dict(nx=nx, ny=ny, dx=DX_3D, vol=DX_3D ** 3, delta=m * DX_3D,
                           steps=steps), nx * ny * 8


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--dim", type=int, choices=(2, 3), default=2)
    ap.add_argument("--sizes", help="atoms per plate (default 1e4,1e5,1e6; 3D 1e5,3e5,1e6)")
    ap.add_argument("--ms", help="horizon ratios (default 3,5,8; 3D 4)")
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--nprocs", type=int, default=1)
    ap.add_argument("--csv", help="also write the rows to this CSV file")
    args = ap.parse_args()
    rows, load_before = [], load_average()
    sizes = args.sizes or ("1e4,1e5,1e6" if args.dim == 2 else "1e5,3e5,1e6")
    ms = args.ms or ("3,5,8" if args.dim == 2 else "4")
    print(f"{'N atoms':>9s} {'m':>3s} {'bonds':>11s} {'ms/step':>9s} {'ns/bond-end':>12s} "
          f"{'setup s':>8s} {'setup ns/bond':>14s} {'B/bond':>7s}")
    with tempfile.TemporaryDirectory() as tmp:
        for size in (float(s) for s in sizes.split(",")):
            for m in (int(x) for x in ms.split(",")):
                script, fmt, atoms = case(args.dim, size, m, args.steps)
                wd = Path(tmp) / f"{atoms}-{m}"
                run = lambda text: run_lammps(script.format(run=text, **fmt), workdir=wd,    # noqa: E731
                                              nprocs=args.nprocs, timeout=3600)
                # setup cost = (create + run 0) - (create only): families, caches, report
                t0 = time.perf_counter()
                run("")
                t1 = time.perf_counter()
                run("run 0")
                t2 = time.perf_counter()
                wall_s = max((t2 - t1) - (t1 - t0), 0.0)
                out = run(f"run 0\nrun {args.steps}").output
                bonds = int(re.search(r"total bonds (\d+)", out).group(1))
                pair = float(re.findall(r"^Pair\s*\|\s*([0-9.eE+-]+)", out, re.M)[-1])
                mem = float(re.search(r"memory of the bonds and the pair style: .* ([0-9.]+) per bond",
                                      out).group(1))
                ms_step = 1e3 * pair / args.steps
                print(f"{atoms:9d} {m:3d} {bonds:11d} {ms_step:9.3f} "
                      f"{1e6 * ms_step / (2 * bonds):12.3f} {wall_s:8.2f} {1e9 * wall_s / bonds:14.1f} "
                      f"{mem:7.1f}", flush=True)
                rows.append({"dim": args.dim, "atoms": atoms, "m": m, "bonds": bonds,
                             "nprocs": args.nprocs, "pair_ms_per_step": f"{ms_step:.3f}",
                             "ns_per_bond_end": f"{1e6 * ms_step / (2 * bonds):.3f}",
                             "setup_s": f"{wall_s:.2f}", "memory_per_bond": mem})
    if args.csv:
        family, model = cpu_numbers()
        common = {"cpu": cpu_model(), "family": family, "model": model, "isa": build_isa(),
                  "load_before": load_before, "load_after": load_average(),
                  "command": "tools/python perf/scaling.py " + " ".join(shlex.quote(a) for a in sys.argv[1:])}
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]) + list(common))
            w.writeheader()
            for r in rows:
                w.writerow(dict(r, **common))
        print(f"written: {args.csv}")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Side-by-side cost of our bbpd/* pair styles and LAMMPS's peri/pmb on the same scene.

Scene: 2D plate 200 x 100 spacing 1 mm (20,301 atoms), elastic, a small impact
on the left layer, 200 steps. peri/pmb's family is |xi| <= delta_pmb = 5.001 mm; ours is
|xi| < delta + dx/2, so delta = 4.5011 mm gives the same bonds. peri/pmb's c is set to our
constant-kernel c0 (same force law up to the partial-volume weights).

Usage (from the repository root): tools/python perf/pair_vs_pmb.py [--steps 200] [--nprocs 1] [--scenes plate,block]
Prints ms/step of the pair computation, undirected bond updates per second, bytes per
bond of our bond storage, and the ratio pmb/ours.
"""
import argparse
import re
import tempfile
from pathlib import Path

from bbpd.runner import run_lammps

E = 190e9
RHO = 7800.0
DX = 1e-3
DELTA_PMB = 5.001e-3
DELTA_OURS = DELTA_PMB - 0.5 * DX + 1e-7  # same family as peri/pmb (see module doc)
V_IMPACT = 1.0    # m/s: small, elastic
DT = 5e-8         # s, below both stable bounds

PLATE = """
units si
dimension 2
boundary s s p
atom_style peri
atom_modify map array
lattice sq {dx}
region box block 0 {nx} 0 {ny} -0.5 0.5
create_box 1 box
create_atoms 1 box
set group all density {rho}
set group all volume {vol}
{pair}
region left block INF 5.5 INF INF INF INF
group left region left
velocity left set {v} 0 0 units box
fix 1 all nve
fix 2 all enforce2d
timestep {dt}
thermo {steps}
run {steps}
"""

BLOCK = """
units si
dimension 3
boundary s s s
atom_style peri
atom_modify map array
lattice sc {dx}
region box block 0 {nx} 0 {ny} 0 {nz}
create_box 1 box
create_atoms 1 box
set group all density {rho}
set group all volume {vol}
{pair}
region left block INF 3.5 INF INF INF INF
group left region left
velocity left set {v} 0 0 units box
fix 1 all nve
timestep {dt}
thermo {steps}
run {steps}
"""


def ours(kernel, model, extra=""):
    geom = "thickness {}".format(DX) if model.startswith("plane") else ""
    return ("plugin load bbpdplugin.so\n"
            f"pair_style bbpd/{kernel} {model} {geom} {extra}\n"
            f"pair_coeff 1 1 {E} none {DELTA_OURS}")


def pmb(c0, s00=1.0):
    return f"pair_style peri/pmb\npair_coeff 1 1 {c0} {DELTA_PMB} {s00} 0.0"


def parse(out, steps):
    pair = float(re.search(r"^Pair\s*\|\s*([0-9.eE+-]+)", out, re.M).group(1))
    m = re.search(r"total bonds (\d+)", out)
    bonds = int(m.group(1)) if m else None
    if bonds is None:
        m = re.search(r"total # of bonds = (\d+)", out)
        bonds = int(m.group(1)) // 2 if m else None
    c0 = re.search(r"micromodulus c0 = ([0-9.eE+-]+)", out)
    mem = re.search(r"bond storage: ([0-9.]+) bytes per bond", out)
    return {"ms_per_step": 1e3 * pair / steps, "bonds": bonds,
            "c0": float(c0.group(1)) if c0 else None,
            "bytes_per_bond": float(mem.group(1)) if mem else None}


def run(template, pair, steps, nprocs, dims, workdir):
    vol = DX ** 3
    script = template.format(dx=DX, rho=RHO, vol=vol, pair=pair, v=V_IMPACT, dt=DT, steps=steps,
                             **dims)
    out = run_lammps(script, workdir=workdir, nprocs=nprocs).output
    return parse(out, steps)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--nprocs", type=int, default=1)
    ap.add_argument("--scenes", default="plate,contact,kernels,compact,block,mpi")
    args = ap.parse_args()
    scenes = args.scenes.split(",")
    rows = []
    speedups = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        plate = {"nx": 200, "ny": 100}
        if "plate" in scenes:
            r_ours = run(PLATE, ours("constant", "plane/stress"), args.steps, args.nprocs, plate, tmp / "a")
            r_pmb = run(PLATE, pmb(r_ours["c0"]), args.steps, args.nprocs, plate, tmp / "b")
            rows.append(("plate 2D 20,301 atoms, contact off in ours", r_ours, r_pmb))
        if "compact" in scenes:
            r_ours = run(PLATE, ours("gaussian", "plane/stress", "bond/storage compact"), args.steps, args.nprocs, plate, tmp / "k")
            r_pmb = run(PLATE, pmb(r_ours["c0"]), args.steps, args.nprocs, plate, tmp / "l")
            rows.append(("plate 2D, bbpd/gaussian bond/storage compact", r_ours, r_pmb))
        if "contact" in scenes:
            r_ours = run(PLATE, ours("constant", "plane/stress", "contact yes"), args.steps, args.nprocs, plate, tmp / "e")
            r_pmb = run(PLATE, pmb(r_ours["c0"]), args.steps, args.nprocs, plate, tmp / "f")
            rows.append(("plate 2D, contact on in both", r_ours, r_pmb))
        if "mpi" in scenes:
            r1 = run(PLATE, ours("constant", "plane/stress"), args.steps, 1, plate, tmp / "g")
            r2 = run(PLATE, ours("constant", "plane/stress"), args.steps, 2, plate, tmp / "h")
            speedups.append(("plate 2D, bbpd/constant, 2 MPI ranks vs 1", r1, r2))
        if "kernels" in scenes:
            for k in ("triangular", "gaussian"):
                r = run(PLATE, ours(k, "plane/stress"), args.steps, args.nprocs, plate, tmp / k)
                rows.append((f"plate 2D, bbpd/{k}", r, None))
        if "block" in scenes:
            block = {"nx": 40, "ny": 40, "nz": 40}
            r_ours = run(BLOCK, ours("constant", "3d"), args.steps // 4, args.nprocs, block, tmp / "c")
            r_pmb = run(BLOCK, pmb(r_ours["c0"]), args.steps // 4, args.nprocs, block, tmp / "d")
            rows.append(("block 3D 68,921 atoms", r_ours, r_pmb))
    print(f"{'scene':45s} {'ours ms/step':>12s} {'pmb ms/step':>12s} {'ratio':>7s} "
          f"{'ours Mbond/s':>13s} {'pmb Mbond/s':>12s} {'B/bond':>7s}")
    for name, a, b in rows:
        rate = a["bonds"] / a["ms_per_step"] / 1e3
        line = f"{name:45s} {a['ms_per_step']:12.3f} "
        if b:
            line += (f"{b['ms_per_step']:12.3f} {b['ms_per_step'] / a['ms_per_step']:7.1f} {rate:13.0f} "
                     f"{b['bonds'] / b['ms_per_step'] / 1e3:12.0f} ")
        else:
            line += f"{'':12s} {'':7s} {rate:13.0f} {'':12s} "
        line += f"{a['bytes_per_bond'] or float('nan'):7.1f}"
        print(line)
        if b and b["bonds"] != a["bonds"]:
            print(f"  note: bond counts differ: ours {a['bonds']}, pmb {b['bonds']}")
    for name, one, two in speedups:
        print(f"{name}: {one['ms_per_step']:.3f} -> {two['ms_per_step']:.3f} ms/step, "
              f"speed-up {one['ms_per_step'] / two['ms_per_step']:.2f}")


if __name__ == "__main__":
    main()

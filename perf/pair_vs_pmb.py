#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Side-by-side cost of our bbpd/* pair styles and LAMMPS's peri/pmb on the same scene.

Scene: 2D plate 200 x 100 spacing 1 mm (20,301 atoms), elastic, a small impact
on the left layer, 200 steps. peri/pmb's family is |xi| <= delta_pmb = 5.001 mm; ours is
|xi| < delta + dx/2, so delta = 4.5011 mm gives the same bonds. peri/pmb's c is set to our
constant-kernel c0 (same force law up to the partial-volume weights).

Usage (from the repository root): tools/python perf/pair_vs_pmb.py [--steps 200] [--nprocs 1]
    [--reps 3] [--scenes plate,block]
Prints the CPU model, then per scene ms/step of the whole loop and of the pair computation,
undirected bond updates per second, bytes per bond of our bond storage, and the ratio pmb/ours
of loop times. Each figure is the minimum over --reps repetitions, ours and peri/pmb run in turn
(A B A B ...), so that both see the same drift of a shared machine.
"""
import argparse
import platform
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


def cpu_model():
    """the CPU model as lscpu prints it (Model name), else what Python knows"""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def parse(out, steps):
    pair = float(re.search(r"^Pair\s*\|\s*([0-9.eE+-]+)", out, re.M).group(1))
    loop = float(re.search(r"^Loop time of ([0-9.eE+-]+)", out, re.M).group(1))
    m = re.search(r"total bonds (\d+)", out)
    bonds = int(m.group(1)) if m else None
    if bonds is None:
        m = re.search(r"total # of bonds = (\d+)", out)
        bonds = int(m.group(1)) // 2 if m else None
    c0 = re.search(r"micromodulus c0 = ([0-9.eE+-]+)", out)
    mem = re.search(r"bond storage: ([0-9.]+) bytes per bond", out)
    return {"ms_per_step": 1e3 * pair / steps, "loop_ms_per_step": 1e3 * loop / steps, "bonds": bonds,
            "c0": float(c0.group(1)) if c0 else None,
            "bytes_per_bond": float(mem.group(1)) if mem else None}


def run_once(template, pair, steps, nprocs, dims, workdir):
    vol = DX ** 3
    script = template.format(dx=DX, rho=RHO, vol=vol, pair=pair, v=V_IMPACT, dt=DT, steps=steps,
                             **dims)
    out = run_lammps(script, workdir=workdir, nprocs=nprocs).output
    return parse(out, steps)


def fastest(results):
    """the minimum time per step over repetitions (the other figures are the same in each)"""
    best = dict(results[0])
    for key in ("ms_per_step", "loop_ms_per_step"):
        best[key] = min(r[key] for r in results)
    return best


REPS = 3


def run_pair(template, pair_a, pair_b, steps, nprocs, dims, workdir):
    """ours (pair_a) and, if given, peri/pmb (pair_b) in turn, REPS times each; pair_b may be a
    function of our result (peri/pmb takes our c0)"""
    a_runs, b_runs = [], []
    for rep in range(REPS):
        a_runs.append(run_once(template, pair_a, steps, nprocs, dims, workdir / f"a{rep}"))
        if pair_b is not None:
            b = pair_b(a_runs[0]) if callable(pair_b) else pair_b
            b_runs.append(run_once(template, b, steps, nprocs, dims, workdir / f"b{rep}"))
    return fastest(a_runs), fastest(b_runs) if b_runs else None


def main():
    global REPS
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=200)
    ap.add_argument("--nprocs", type=int, default=1)
    ap.add_argument("--scenes", default="plate,contact,kernels,compact,block,mpi")
    ap.add_argument("--reps", type=int, default=REPS, help="repetitions of each run (minimum kept)")
    args = ap.parse_args()
    REPS = args.reps
    scenes = args.scenes.split(",")
    rows = []
    speedups = []
    pmb_of = lambda r: pmb(r["c0"])    # noqa: E731  (peri/pmb with our c0)
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        plate = {"nx": 200, "ny": 100}
        if "plate" in scenes:
            r_ours, r_pmb = run_pair(PLATE, ours("constant", "plane/stress"), pmb_of, args.steps,
                                     args.nprocs, plate, tmp / "a")
            rows.append(("plate 2D 20,301 atoms, contact off in ours", r_ours, r_pmb))
        if "compact" in scenes:
            r_comp, r_def = run_pair(PLATE, ours("gaussian", "plane/stress", "bond/storage compact"),
                                     ours("gaussian", "plane/stress"), args.steps, args.nprocs,
                                     plate, tmp / "k")
            rows.append(("plate 2D, bbpd/gaussian default", r_def, None))
            rows.append(("plate 2D, bbpd/gaussian bond/storage compact", r_comp, None))
            speedups.append(("plate 2D, bbpd/gaussian, compact vs default storage", r_comp, r_def))
        if "contact" in scenes:
            r_ours, r_pmb = run_pair(PLATE, ours("constant", "plane/stress", "contact yes"), pmb_of,
                                     args.steps, args.nprocs, plate, tmp / "e")
            rows.append(("plate 2D, contact on in both", r_ours, r_pmb))
        if "mpi" in scenes:
            r1, _ = run_pair(PLATE, ours("constant", "plane/stress"), None, args.steps, 1, plate, tmp / "g")
            r2, _ = run_pair(PLATE, ours("constant", "plane/stress"), None, args.steps, 2, plate, tmp / "h")
            speedups.append(("plate 2D, bbpd/constant, 2 MPI ranks vs 1", r1, r2))
        if "kernels" in scenes:
            for k in ("triangular", "gaussian"):
                r, _ = run_pair(PLATE, ours(k, "plane/stress"), None, args.steps, args.nprocs, plate, tmp / k)
                rows.append((f"plate 2D, bbpd/{k}", r, None))
        if "block" in scenes:
            block = {"nx": 40, "ny": 40, "nz": 40}
            r_ours, r_pmb = run_pair(BLOCK, ours("constant", "3d"), pmb_of, args.steps // 4,
                                     args.nprocs, block, tmp / "c")
            rows.append(("block 3D 68,921 atoms", r_ours, r_pmb))
    print(f"CPU: {cpu_model()}; minimum of {REPS} alternating repetitions; ratio = pmb/ours loop time")
    print(f"{'scene':45s} {'ours loop':>10s} {'ours pair':>10s} {'pmb loop':>9s} {'pmb pair':>9s} "
          f"{'ratio':>6s} {'ours Mbond/s':>13s} {'B/bond':>7s}   (times in ms/step)")
    for name, a, b in rows:
        rate = a["bonds"] / a["ms_per_step"] / 1e3
        line = f"{name:45s} {a['loop_ms_per_step']:10.3f} {a['ms_per_step']:10.3f} "
        if b:
            line += (f"{b['loop_ms_per_step']:9.3f} {b['ms_per_step']:9.3f} "
                     f"{b['loop_ms_per_step'] / a['loop_ms_per_step']:6.1f} ")
        else:
            line += f"{'':9s} {'':9s} {'':6s} "
        line += f"{rate:13.0f} {a['bytes_per_bond'] or float('nan'):7.1f}"
        print(line)
        if b and b["bonds"] != a["bonds"]:
            print(f"  note: bond counts differ: ours {a['bonds']}, pmb {b['bonds']}")
    for name, one, two in speedups:
        print(f"{name}: loop {one['loop_ms_per_step']:.3f} -> {two['loop_ms_per_step']:.3f} ms/step, "
              f"ratio {one['loop_ms_per_step'] / two['loop_ms_per_step']:.2f}")


if __name__ == "__main__":
    main()

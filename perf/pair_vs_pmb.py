#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Side-by-side cost of our bbpd/* pair styles and LAMMPS's peri/pmb on the same scene.

Scenes (peri/pmb's family is |xi| <= delta_pmb; ours is |xi| < delta + dx/2, so
delta = delta_pmb - dx/2 + a round-off guard gives the same bonds; peri/pmb's c is set to our
constant-kernel c0, the same force law up to the partial-volume weights):
  plate    2D plate 200 x 100, spacing 1 mm (20,301 atoms), elastic, a small impact on the left
           layer, 200 steps; delta_pmb = 5.001 mm
  block    3D block 41^3, spacing 1 mm, the same impact, 50 steps
  bench    the scene of LAMMPS's peridynamics benchmark: a periodic 16^3 simple-cubic block,
           spacing 0.5 mm, delta_pmb = 0.0015001 (3 spacings, 122 bonds per atom), 200 steps
           from the reference configuration (atoms at rest on the lattice)
  cylinder examples/peri-pmb-dropin: LAMMPS's peri/pmb example and its bbpd/pmb port,
           1000 steps
  plate3d  a large 3D glass plate, ours only: 400 x 160 x 8 atoms (512,000), spacing
           0.25 mm, delta 1 mm, bbpd/constant 3d, a notch through the thickness and two no-fail
           bands, 20 steps (--steps / 10) at rest
  memory   the maximum resident set of our block at 41^3 and 51^3 atoms (2 steps each):
           the bytes per bond at the margin, (RSS_51 - RSS_41) / (bonds_51 - bonds_41)
  (and plate variants: contact, kernels, compact storage, 2 MPI ranks)

Usage (from the repository root): tools/python perf/pair_vs_pmb.py [--steps 200] [--nprocs 1]
    [--reps 3] [--scenes plate,block,bench,cylinder,plate3d,memory] [--csv perf/results/NAME.csv]
    [--simd auto|portable|avx2|avx512]
Prints the CPU (model, family/model numbers) and the paths of the bond loops the plugin build
holds, then per scene ms/step of the whole loop and of the pair computation, undirected bond
updates per second, bytes per bond of our bond storage, the ratio pmb/ours of loop times and
the path our run took (its setup report's 'bond loop:' line; --simd forces one, the default is
the plugin's, auto).
Each figure is the minimum over --reps repetitions, ours and peri/pmb run in turn
(A B A B ...), so that both see the same drift of a shared machine; the load average before and
after is printed with them. --csv writes the same rows with the CPU, the ISA and the command.
"""
import argparse
import csv
import datetime
import os
import platform
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

from bbpd.runner import LMP, run_lammps

ROOT = Path(__file__).resolve().parent.parent
VERSION = os.environ.get("BBPD_LAMMPS_VERSION", "20260704")

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


# LAMMPS's peridynamics benchmark scene (see the module doc), in the units of the other scenes
BENCH = """
units si
dimension 3
boundary p p p
atom_style peri
atom_modify map array
lattice sc {dx}
region box block 0 {nx} 0 {ny} 0 {nz}
create_box 1 box
create_atoms 1 box
set group all density {rho}
set group all volume {vol}
{pair}
fix 1 all nve
timestep {dt}
thermo {steps}
run {steps}
"""
# the large 3D plate (see the module doc): its own material, ours only (peri/pmb would need
# hours for its 77 million bonds)
# the lines up to the lattice, shared with perf/scaling.py's 3D plates
PLATE3D_PREAMBLE = """
plugin load bbpdplugin.so
units si
boundary s s s
atom_style peri
atom_modify map array
lattice sc {dx} origin 0.5 0.5 0.5
"""
PLATE3D = PLATE3D_PREAMBLE + """region plate block 0 400 0 160 0 8
create_box 2 plate
create_atoms 1 region plate
region nofail block INF INF $(4*{dx}) $(156*{dx}) INF INF side out units box
set region nofail type 2
set group all density 2440
set group all volume {vol}
pair_style bbpd/constant 3d {simd}
pair_coeff 1 1 72e9 3.8 1.0e-3
pair_coeff 1 2 72e9 none 1.0e-3
pair_coeff 2 2 72e9 none 1.0e-3
neighbor {dx} bin
fix notch all bbpd/notch rectangle -1 0.02 -1 $(1+100*{dx}) 0 0 0 0 3
fix 1 all nve
timestep 2e-8
thermo {steps}
run {steps}
"""
PLATE3D_DIMS = {"dx": 0.25e-3, "vol": 0.25e-3 ** 3}

BENCH_DX = 0.5e-3
BENCH_DELTA_PMB = 0.0015001
BENCH_DIMS = {"nx": 16, "ny": 16, "nz": 16, "dx": BENCH_DX, "vol": BENCH_DX ** 3,
              "dt": DT * BENCH_DX / DX}    # the stable step scales with the spacing
CYLINDER = ROOT / "examples" / "peri-pmb-dropin"
CYLINDER_STEPS = 1000
MEMORY_SIZES = (40, 50)    # block edges in spacings: 41^3 and 51^3 atoms
MEMORY_STEPS = 2


SIMD = None    # --simd: the path our runs force (None: the plugin's default)


def ours(kernel, model, extra="", delta=DELTA_OURS):
    geom = "thickness {}".format(DX) if model.startswith("plane") else ""
    simd = f"simd {SIMD}" if SIMD else ""
    return ("plugin load bbpdplugin.so\n"
            f"pair_style bbpd/{kernel} {model} {geom} {extra} {simd}\n"
            f"pair_coeff 1 1 {E} none {delta}")


def pmb(c0, s00=1.0, delta=DELTA_PMB):
    return f"pair_style peri/pmb\npair_coeff 1 1 {c0} {delta} {s00} 0.0"


def same_bonds_delta(delta_pmb, dx):
    """our delta for peri/pmb's family |xi| <= delta_pmb (ours: |xi| < delta + dx/2)"""
    return delta_pmb - 0.5 * dx + 1e-4 * dx


def cpu_model():
    """the CPU model as lscpu prints it (Model name), else what Python knows"""
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()


def cpu_numbers():
    """(family, model) from /proc/cpuinfo, or (None, None)"""
    fields = {}
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            key, _, value = line.partition(":")
            fields.setdefault(key.strip(), value.strip())
    except OSError:
        pass
    return fields.get("cpu family"), fields.get("model")


def build_isa(builddir=None):
    """the paths of the bond loops the plugin build holds: the portable loop and each SIMD path
    whose file it compiled (src/bbpd_row_paths.h; the run's setup report says which ran), with
    the flags of every file (BBPD_NATIVE adds -march=native); for a build from before the
    paths, the instruction set its compiler's macros gave src/bbpd_row.h"""
    builddir = Path(builddir or ROOT / "build" / f"lammps-{VERSION}")
    objects = builddir / "CMakeFiles" / "bbpdplugin.dir" / "src"
    paths = [p for p in ("avx2", "avx512") if (objects / f"bbpd_row_{p}.cpp.o").is_file()]
    if (ROOT / "src" / "bbpd_row_paths.h").is_file() and (objects / "bbpd_row_paths.cpp.o").is_file():
        native = re.search(r"^BBPD_NATIVE:\w+=(ON|TRUE|1|YES)$", (builddir / "CMakeCache.txt").read_text(),
                           re.M | re.I)
        return "/".join(["portable"] + paths) + (" (-march=native)" if native else "")
    cache = (builddir / "CMakeCache.txt").read_text()

    def entry(key, default=""):
        m = re.search(rf"^{key}:[A-Z]+=(.*)$", cache, re.M)
        return m.group(1) if m else default
    flags = shlex.split(entry("CMAKE_CXX_FLAGS"))
    if entry("BBPD_NATIVE", "ON").upper() in ("ON", "TRUE", "1", "YES"):
        flags.append("-march=native")
    macros = subprocess.run([entry("CMAKE_CXX_COMPILER", "c++")] + flags + ["-dM", "-E", "-x", "c++", "-"],
                            input="", capture_output=True, text=True, check=True).stdout
    has = lambda m: re.search(rf"^#define {m} ", macros, re.M) is not None    # noqa: E731
    if has("__AVX512F__") and has("__AVX512VL__"):
        return "AVX-512"
    return "AVX2" if has("__AVX2__") else "portable"


def load_average():
    return " ".join(Path("/proc/loadavg").read_text().split()[:3])


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
    total = re.search(r"memory of the bonds and the pair style: .* ([0-9.]+) per bond", out)
    path = re.search(r"bond loop: (\w+) path", out)
    return {"path": path.group(1) if path else "","ms_per_step": 1e3 * pair / steps, "loop_ms_per_step": 1e3 * loop / steps, "bonds": bonds,
            "c0": float(c0.group(1)) if c0 else None,
            "bytes_per_bond": float(mem.group(1)) if mem else None,
            "memory_per_bond": float(total.group(1)) if total else None}


def run_once(template, pair, steps, nprocs, dims, workdir):
    """template: a scene above, formatted with pair and dims (over the plate's spacing and
    step); or pair: the path of a whole input file that takes the variable 'steps'"""
    if isinstance(pair, Path):
        script = pair.read_text()
        if SIMD:    # the input reads no other file: a copy with the keyword runs the same
            script = re.sub(r"^(pair_style\s+bbpd/.*)$", rf"\1 simd {SIMD}", script, count=1, flags=re.M)
        out = run_lammps(script, workdir=workdir, nprocs=nprocs, vars={"steps": steps}).output
        return parse(out, steps)
    params = {"dx": DX, "rho": RHO, "vol": DX ** 3, "v": V_IMPACT, "dt": DT}
    params.update(dims)
    script = template.format(pair=pair, steps=steps, **params)
    out = run_lammps(script, workdir=workdir, nprocs=nprocs).output
    return parse(out, steps)


def max_rss(script, workdir):
    """(maximum resident set in bytes, LAMMPS output) of one serial run of script"""
    workdir.mkdir(parents=True, exist_ok=True)
    (workdir / "in.lammps").write_text(script)
    with open(workdir / "out.txt", "w") as out:
        proc = subprocess.Popen([str(LMP), "-in", "in.lammps"], cwd=workdir, stdout=out,
                                stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    text = (workdir / "out.txt").read_text()
    if proc.returncode:
        sys.exit(f"pair_vs_pmb: the memory run failed:\n{text[-2000:]}")
    return usage.ru_maxrss * 1024, text    # Linux reports kilobytes


def memory_margin(workdir):
    """max RSS of our block at the two MEMORY_SIZES: [(edge, rss, bonds)] and bytes per bond"""
    runs = []
    for n in MEMORY_SIZES:
        script = BLOCK.format(dx=DX, rho=RHO, vol=DX ** 3, pair=ours("constant", "3d"), v=V_IMPACT,
                              dt=DT, steps=MEMORY_STEPS, nx=n, ny=n, nz=n)
        rss, out = max_rss(script, workdir / f"m{n}")
        runs.append((n + 1, rss, parse(out, MEMORY_STEPS)["bonds"], parse(out, MEMORY_STEPS)["bytes_per_bond"]))
    (_, r1, b1, _), (_, r2, b2, _) = runs
    return runs, (r2 - r1) / (b2 - b1)


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
    ap.add_argument("--scenes", default="plate,contact,kernels,compact,block,bench,cylinder,plate3d,memory,mpi")
    ap.add_argument("--reps", type=int, default=REPS, help="repetitions of each run (minimum kept)")
    ap.add_argument("--csv", help="also write the rows to this CSV file")
    ap.add_argument("--simd", choices=["auto", "portable", "avx2", "avx512"],
                    help="force this path of our bond loops (default: the plugin's, auto)")
    args = ap.parse_args()
    global SIMD
    SIMD = args.simd
    load_before = load_average()
    memory = None
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
        if "bench" in scenes:
            delta = BENCH_DELTA_PMB
            r_ours, r_pmb = run_pair(BENCH, ours("constant", "3d", delta=same_bonds_delta(delta, BENCH_DX)),
                                     lambda r: pmb(r["c0"], delta=delta), args.steps, args.nprocs,
                                     BENCH_DIMS, tmp / "b")
            rows.append(("LAMMPS bench: periodic 16^3, 4,096 atoms", r_ours, r_pmb))
        if "cylinder" in scenes:
            r_ours, r_pmb = run_pair(None, CYLINDER / "in.bbpd.pmb", CYLINDER / "in.peri.pmb",
                                     CYLINDER_STEPS, args.nprocs, {}, tmp / "y")
            rows.append(("cylinder (peri-pmb-dropin), bbpd/pmb", r_ours, r_pmb))
        if "plate3d" in scenes:
            dims = dict(PLATE3D_DIMS, simd=f"simd {SIMD}" if SIMD else "")
            r, _ = run_pair(PLATE3D, "", None, max(args.steps // 10, 1), args.nprocs, dims, tmp / "p3")
            rows.append(("plate 3D 512,000 atoms, notch, no-fail bands", r, None))
        if "memory" in scenes:
            memory = memory_margin(tmp / "mem")
    load_after = load_average()
    family, model = cpu_numbers()
    isa = build_isa()
    print(f"CPU: {cpu_model()} (family {family}, model {model}); plugin build: {isa}"
          f"{'; simd ' + SIMD if SIMD else ''}")
    print(f"load average (1/5/15 min) before {load_before}, after {load_after}")
    print(f"minimum of {REPS} alternating repetitions; ratio = pmb/ours loop time")
    print(f"{'scene':45s} {'ours loop':>10s} {'ours pair':>10s} {'pmb loop':>9s} {'pmb pair':>9s} "
          f"{'ratio':>6s} {'ours Mbond/s':>13s} {'B/bond':>7s} {'path':>8s}   (times in ms/step)")
    for name, a, b in rows:
        rate = a["bonds"] / a["ms_per_step"] / 1e3
        line = f"{name:45s} {a['loop_ms_per_step']:10.3f} {a['ms_per_step']:10.3f} "
        if b:
            line += (f"{b['loop_ms_per_step']:9.3f} {b['ms_per_step']:9.3f} "
                     f"{b['loop_ms_per_step'] / a['loop_ms_per_step']:6.1f} ")
        else:
            line += f"{'':9s} {'':9s} {'':6s} "
        line += f"{rate:13.0f} {a['bytes_per_bond'] or float('nan'):7.1f} {a['path']:>8s}"
        print(line)
        if b and b["bonds"] != a["bonds"]:
            print(f"  note: bond counts differ: ours {a['bonds']}, pmb {b['bonds']}")
    for name, one, two in speedups:
        print(f"{name}: loop {one['loop_ms_per_step']:.3f} -> {two['loop_ms_per_step']:.3f} ms/step, "
              f"ratio {one['loop_ms_per_step'] / two['loop_ms_per_step']:.2f}")
    if memory:
        runs, margin = memory
        for edge, rss, bonds, reported in runs:
            print(f"memory: block {edge}^3, {bonds} bonds: max RSS {rss / 1e6:.1f} MB "
                  f"(setup report: {reported} bytes per bond)")
        print(f"memory: {margin:.1f} bytes per bond at the margin (max RSS, {runs[0][0]}^3 -> {runs[1][0]}^3)")
    if args.csv:
        write_csv(args.csv, rows, memory, {"cpu": cpu_model(), "family": family, "model": model,
                                           "isa": isa, "load_before": load_before,
                                           "load_after": load_after, "reps": REPS})


def write_csv(path, rows, memory, machine):
    """one line per scene (times in ms/step) and per memory run, with the machine and the
    command that made the file"""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    command = "tools/python perf/pair_vs_pmb.py " + " ".join(shlex.quote(a) for a in sys.argv[1:])
    fields = ["scene", "ours_loop_ms", "ours_pair_ms", "pmb_loop_ms", "pmb_pair_ms", "ratio",
              "bonds", "bytes_per_bond", "memory_per_bond", "ns_per_bond_end", "max_rss_mb", "path", "cpu", "family", "model", "isa", "reps",
              "load_before", "load_after", "date", "command"]
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        common = dict(machine, date=date, command=command)
        for name, a, b in rows:
            w.writerow(dict(common, scene=name, ours_loop_ms=f"{a['loop_ms_per_step']:.4f}",
                            ours_pair_ms=f"{a['ms_per_step']:.4f}",
                            pmb_loop_ms=f"{b['loop_ms_per_step']:.4f}" if b else "",
                            pmb_pair_ms=f"{b['ms_per_step']:.4f}" if b else "",
                            ratio=f"{b['loop_ms_per_step'] / a['loop_ms_per_step']:.2f}" if b else "",
                            bonds=a["bonds"], bytes_per_bond=a["bytes_per_bond"] or "",
                            memory_per_bond=a["memory_per_bond"] or "",
                            ns_per_bond_end=f"{1e6 * a['ms_per_step'] / (2 * a['bonds']):.3f}" if a["bonds"] else "",
                            path=a["path"]))
        if memory:
            runs, margin = memory
            for edge, rss, bonds, reported in runs:
                w.writerow(dict(common, scene=f"memory: block {edge}^3, max RSS", bonds=bonds,
                                bytes_per_bond=reported, max_rss_mb=f"{rss / 1e6:.1f}"))
            w.writerow(dict(common, scene="memory: bytes per bond at the margin (max RSS)",
                            bytes_per_bond=f"{margin:.1f}"))
    print(f"written: {path}")


if __name__ == "__main__":
    main()

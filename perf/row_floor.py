#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""What bounds each force loop (AVX-512, AVX2, portable): the 3D block timed with parts of the kernel taken out.

The 3D block of pair_vs_pmb.py (41^3 atoms, m = 4.5, 15.4 M bonds), held still (no time
integration: the probes compute wrong forces on purpose), pair time of `--steps` force
evaluations. Each variant is the plugin built from HEAD with perf/probes/row_floor.patch applied
and one of its switches on (bbpd_row.h; the portable loop's table reads in pair_bbpd.cpp),
run on the path chosen with --path (the pair style's simd keyword: the plugin holds every path,
src/bbpd_row_paths.h): auto (the one the style picks), avx512, avx2 or portable:
  baseline          the kernel as it is (the patch with no switch is the same code)
  no_sqrt_div       multiplications in place of the square root and the division
  no_memory         no partner-offset or class stream and no gathers: partners i+1.., positions
                    and table entries loaded contiguously (square root and division kept):
                    the floor of the path, its arithmetic with the data in the L1 cache
  no_memory_no_sqrt_div   both: the loop's arithmetic alone
  rsqrt14_fma       (AVX-512 path only) square root and 1/r from the 14-bit estimate, Newton steps
                    and an FMA correction (no divider instruction)
  float_guess       (AVX-512 path only) 1/sqrt in single precision, two Newton steps in double
Usage (from the repository root, after tools/bootstrap):
  tools/python perf/row_floor.py [--path auto|avx512|avx2|portable] [--steps 20] [--reps 2]
      [--variants baseline,no_memory] [--csv perf/results/NAME.csv]
Prints the CPU model and family/model, the path each run took (its setup report) and, per
variant, the minimum pair time over --reps alternating rounds and its ratio to the baseline;
the baseline over no_memory is the path's distance from its floor.
The plugins are built in a temporary worktree of HEAD; the checkout is not touched.
"""
import argparse
import csv
import datetime
import importlib.util
import os
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

from bbpd.runner import run_lammps


def _pair_vs_pmb():
    """the scene and the pair lines of perf/pair_vs_pmb.py (a script beside this one)"""
    spec = importlib.util.spec_from_file_location("pair_vs_pmb", Path(__file__).with_name("pair_vs_pmb.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


PVP = _pair_vs_pmb()
ROOT = Path(__file__).resolve().parent.parent
PATCH = ROOT / "perf" / "probes" / "row_floor.patch"
VARIANTS = {
    "baseline": [],
    "no_sqrt_div": ["NO_SQRT_DIV"],
    "no_memory": ["NO_MEMORY"],
    "no_memory_no_sqrt_div": ["NO_MEMORY", "NO_SQRT_DIV"],
    "rsqrt14_fma": ["RSQRT14_FMA"],
    "float_guess": ["FLOAT_GUESS"],
}
AVX512_ONLY = ("rsqrt14_fma", "float_guess")
PATHS = ("auto", "avx512", "avx2", "portable")


def cache_entry(cache, name):
    m = re.search(rf"^{name}:[A-Z]+=(.*)$", cache, re.M)
    if not m:
        sys.exit(f"row_floor: {name} not in the build's CMakeCache.txt: run tools/bootstrap")
    return m.group(1)


def build(src, builddir, switches, lammps_dir, lammps_source):
    flags = " ".join(f"-DBBPD_PROBE_{s}=1" for s in switches)
    subprocess.run(["cmake", "-S", str(src), "-B", str(builddir), f"-DLAMMPS_DIR={lammps_dir}",
                    f"-DLAMMPS_SOURCE_DIR={lammps_source}", "-DBBPD_BUILD_TESTS=OFF",
                    f"-DCMAKE_CXX_FLAGS={flags}"], check=True,
                   capture_output=True)
    subprocess.run(["cmake", "--build", str(builddir), "--target", "bbpdplugin", "-j",
                    str(os.cpu_count() or 1)], check=True, capture_output=True)
    return builddir / "bbpdplugin.so"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--reps", type=int, default=2)
    ap.add_argument("--variants", help="default: all the path has")
    ap.add_argument("--path", default="auto", choices=PATHS)
    ap.add_argument("--csv", help="also write the variants' times to this CSV file")
    args = ap.parse_args()
    names = (args.variants.split(",") if args.variants else
             [n for n in VARIANTS if n not in AVX512_ONLY or args.path == "avx512"])
    for n in names:
        if n not in VARIANTS:
            sys.exit(f"row_floor: unknown variant {n}: choose from {', '.join(VARIANTS)}")
    version = os.environ.get("BBPD_LAMMPS_VERSION", "20260704")
    cache = (ROOT / "build" / f"lammps-{version}" / "CMakeCache.txt").read_text()
    lammps_dir = cache_entry(cache, "LAMMPS_DIR")
    lammps_source = cache_entry(cache, "LAMMPS_SOURCE_DIR")
    # held still: the force loop alone, on the lattice (the probes' forces are wrong)
    if "fix 1 all nve\n" not in PVP.BLOCK:
        sys.exit("row_floor: the block of pair_vs_pmb.py no longer integrates with 'fix 1 all nve': "
                 "update how row_floor holds it still")
    still = PVP.BLOCK.replace("fix 1 all nve\n", "")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        src = tmp / "src"
        subprocess.run(["git", "-C", str(ROOT), "worktree", "add", "--detach", str(src), "HEAD"],
                       check=True, capture_output=True)
        try:
            if subprocess.run(["git", "-C", str(src), "apply", str(PATCH)]).returncode:
                sys.exit("row_floor: perf/probes/row_floor.patch no longer applies to "
                         "src/bbpd_row.h: update the patch")
            if any(n in AVX512_ONLY for n in names) and args.path != "avx512":
                sys.exit(f"row_floor: {', '.join(AVX512_ONLY)} probe the AVX-512 kernel: "
                         "use --path avx512")
            plugins = {n: build(src, tmp / f"build-{n}", VARIANTS[n], lammps_dir, lammps_source)
                       for n in names}
            best = {n: float("inf") for n in names}
            ran = {}
            PVP.SIMD = args.path
            for rep in range(args.reps):
                for n in names:
                    pair = PVP.ours("constant", "3d").replace("plugin load bbpdplugin.so",
                                                          f"plugin load {plugins[n]}")
                    script = still.format(dx=PVP.DX, rho=PVP.RHO, vol=PVP.DX ** 3, pair=pair, v=1.0, dt=PVP.DT,
                                          steps=args.steps, nx=40, ny=40, nz=40)
                    out = run_lammps(script, workdir=tmp / f"run-{n}-{rep}").output
                    t = float(re.search(r"^Pair\s*\|\s*([0-9.eE+-]+)", out, re.M).group(1))
                    best[n] = min(best[n], 1e3 * t / args.steps)
                    ran.setdefault(n, set()).add(PVP.parse(out, args.steps)["path"])
        finally:
            subprocess.run(["git", "-C", str(ROOT), "worktree", "remove", "--force", str(src)],
                           capture_output=True)
    family, model = PVP.cpu_numbers()
    took = "/".join(sorted(set().union(*ran.values())))
    load = PVP.load_average()
    print(f"CPU: {PVP.cpu_model()} (family {family}, model {model}); simd {args.path}, "
          f"path run: {took}; load average {load}")
    print(f"3D block 41^3 held still, pair time in ms/step, minimum of {args.reps} alternating rounds")
    base = best.get("baseline")
    for n in names:
        rel = f"{best[n] / base:6.2f} x baseline" if base else ""
        print(f"{n:24s} {best[n]:8.2f}  {rel}")
    if base and "no_memory" in best:
        print(f"baseline / floor (no_memory): {base / best['no_memory']:.2f}")
    if args.csv:
        write_csv(Path(args.csv), best, {"cpu": PVP.cpu_model(), "family": family, "model": model,
                                         "simd": args.path, "path": took, "load": load,
                                         "reps": args.reps, "steps": args.steps})


def write_csv(path, best, machine):
    """one line per variant (pair ms/step), with the machine and the command"""
    path.parent.mkdir(parents=True, exist_ok=True)
    command = "tools/python perf/row_floor.py " + " ".join(shlex.quote(a) for a in sys.argv[1:])
    date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    fields = ["variant", "pair_ms", "vs_baseline"] + list(machine) + ["date", "command"]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        base = best.get("baseline")
        for n, t in best.items():
            w.writerow(dict(machine, variant=n, pair_ms=f"{t:.3f}",
                            vs_baseline=f"{t / base:.3f}" if base else "", date=date, command=command))
    print(f"written: {path}")


if __name__ == "__main__":
    main()

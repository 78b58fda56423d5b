#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Ours against LAMMPS's legacy peri/* and its bond_style bpm/peri on LAMMPS's benchmark deck.

The deck is LAMMPS's examples/bpm/peri/benchmark: a periodic 16^3 simple-cubic block (4096
nodes, spacing 0.5 mm, horizon 1.5001 mm: 122 bonds per node), K = G = 14.9 GPa, 200 steps
from the reference state, so nothing moves and the loop time is the cost of the force loop.
For each model (pmb, lps, ves, eps) three variants run in alternation, --rounds times, on each
rank count of --ranks:
  legacy  pair_style peri/MODEL           (the --anchor lmp if given, else ours: the same source)
  bpm     bond_style bpm/peri MODEL       (only with --anchor PATH, an lmp with the BPM package)
  ours    pair_style bbpd/MODEL 3d         (tools/lmp with bbpdplugin.so; the path auto chooses)
  ours-P  pair_style bbpd/MODEL 3d simd P  (each path P of --forced, after ours in each round:
                                            what auto's choice costs against each path forced)
A model whose bbpd style this plugin lacks is left out of 'ours'. Before the timings, a check:
the same block, free (boundary s s s, where peri/lps's weighted volume needs no minimum image),
set moving by a smooth velocity field, 200 steps: pe and ke of ours and of peri/MODEL at steps 0
and 200 must agree to CHECK_TOL of the run's largest value, else the script stops (exit 1).

Printed: each run and a summary of the minimum loop times with the ratios legacy/ours and
bpm/ours; --csv writes one row per run with the CPU (model name, family, model), the plugin's
paths, the path our setup report names, the load average before and after, the date and the
command.

--scene cylinder runs LAMMPS's examples/peri cylinder instead (3,487 nodes shattered by an
indenter, 1000 steps: breaking, the state's ghost exchange and contact in the cost), with the
mean damage at the end of each run in place of the thermo check. bpm/peri's short-range force
starts at 1.35 lattice constants for every pair that has no bond (pair_bpm_peri.cpp), so a
nearest-neighbour bond that breaks (0.5 mm long, peri/*: contact below 0.9 of that) is pushed
apart at once: its cylinder runs away once bonds break (mean damage 0.27 at step 150 against
peri/lps's 0.0003): its timings there are printed, not comparable.

Usage (from the repository root):
  tools/python perf/vs_bpm.py [--anchor ~/.cache/bbpd/bpm-anchor/build/lmp] [--rounds 3]
      [--ranks 1 2] [--models pmb lps ves eps] [--scene deck|cylinder] [--forced avx2 avx512]
      [--csv perf/results/NAME.csv]
(the anchor is built by ../shared/anchors/bpm-peri/build.sh where that kit is at hand.)
"""
import argparse
import csv
import datetime
import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from bbpd.runner import LMP, MPIRUN, error_line
from pair_vs_pmb import build_isa, cpu_model, cpu_numbers, load_average

MODELS = ("pmb", "lps", "ves", "eps")
STEPS = 200
# LAMMPS's examples/bpm/peri/benchmark: material and bond numbers of its README's lines
K = G = 14.9e9
HORIZON = 0.0015001
S00, ALPHA = 0.5, 0.25
C_PMB = 1.6863e22               # peri/pmb's micromodulus of the deck
LAMBDA_I, TAU_B = 0.5, 0.001    # peri/ves: m_lambdai, m_taubi
YIELD = 10.0e8                  # peri/eps: m_yieldstress


def legacy_coeff(model, s00=S00):
    """pair_coeff of peri/MODEL (and bbpd/MODEL) with critical stretch s00"""
    return {"pmb": f"{C_PMB} {HORIZON} {s00} {ALPHA}",
            "lps": f"{K} {G} {HORIZON} {s00} {ALPHA}",
            "ves": f"{K} {G} {HORIZON} {s00} {ALPHA} {LAMBDA_I} {TAU_B}",
            "eps": f"{K} {G} {HORIZON} {s00} {ALPHA} {YIELD}"}[model]


def bpm_coeff(model, s00=S00):
    """bond_coeff of bond_style bpm/peri, as in the benchmark's README"""
    return {"pmb": f"pmb {C_PMB} {HORIZON} {s00} {ALPHA}",
            "lps": f"lps {K} {G} {HORIZON} {s00} {ALPHA}",
            "ves": f"ves {K} {G} {LAMBDA_I} {TAU_B} {HORIZON} {s00} {ALPHA}",
            "eps": f"eps {K} {G} {YIELD} {HORIZON} {s00} {ALPHA}"}[model]


# the fracture scene (--scene cylinder): LAMMPS's examples/peri, a glass cylinder of radius 5 mm
# and height 5 mm (3,487 nodes) shattered by a spherical indenter at 100 m/s, s00 = 0.0005,
# 1000 steps; the mean damage at the end is printed for each variant (bpm/peri's ves and eps are
# other models than peri/ves and peri/eps by design, so theirs may differ)
CYLINDER_S00 = 0.0005
CYLINDER_STEPS = 1000
CYLINDER = """units si
boundary s s s
atom_modify map array
neighbor 0.0010 bin
lattice sc 0.0005
region target cylinder y 0.0 0.0 0.0050 -0.0050 0.0 units box
"""
INDENTER = f"""velocity all set 0.0 0.0 0.0 sum no units box
fix 1 all nve
variable y equal "0.00155 + step*dt*(-100)"
fix 2 all indent 1e17 sphere 0.0000 v_y 0.0000 0.0015 units box
compute dmean all reduce ave c_1
thermo_style custom step c_dmean ke
thermo_modify format float %.10g
timestep 1.0e-7
thermo {CYLINDER_STEPS}
run {CYLINDER_STEPS}
"""
DAMAGE = {"legacy": "damage/atom", "ours": "bbpd/damage/atom", "bpm": "bpm/peri/damage/atom"}
# the thermo check: what ours and peri/* may differ by, relative to the run's largest value
# (both sum the same bonds in other orders: round-off of ~1e-13 measured, see the docstring)
CHECK_TOL = 1e-9

BLOCK = """units si
boundary {boundary}
atom_modify map array
neighbor 0.0005 bin
lattice sc 0.0005
region box block 0 16 0 16 0 16 units lattice
"""
VOLUME = "1.25e-10"    # (0.5 mm)^3
RUN = f"""fix 1 all nve
timestep 1.0e-7
thermo 100
run {STEPS}
"""
# the check's motion: a smooth field of at most 1 m/s over the block's 8 mm
MOTION = """variable L equal 0.008
variable vx atom 0.5*sin(2*PI*x/v_L)+0.5*sin(2*PI*y/v_L)
variable vy atom 0.5*sin(2*PI*z/v_L)
variable vz atom 0.5*sin(2*PI*x/v_L)
velocity all set v_vx v_vy v_vz units box
thermo_style custom step pe ke
thermo_modify format float %23.16e
"""


# the paths of the simd keyword that --forced takes (bbpd_path_choice.h)
FORCED_PATHS = ("portable", "avx2", "avx512")


def is_ours(variant):
    """ours with the path auto chooses ('ours') or with a forced path ('ours-avx2', ...)"""
    return variant == "ours" or variant.startswith("ours-")


def forced_path(variant):
    """the path a variant forces ('ours-avx2': 'avx2'), or None"""
    return variant[len("ours-"):] if variant.startswith("ours-") else None


def deck(model, variant, check=False, cylinder=False):
    """the input of one run: the benchmark deck, with check the free, moving block, with
    cylinder the fracture scene"""
    text = CYLINDER if cylinder else BLOCK.format(boundary="s s s" if check else "p p p")
    box = "target" if cylinder else "box"
    create = f"create_box 1 {box}"
    atoms = f"create_atoms 1 {'region target' if cylinder else 'box'}\n"
    s00 = CYLINDER_S00 if cylinder else S00
    if variant == "bpm":
        text = ("atom_style bond\nspecial_bonds lj 0.0 1.0 1.0 coul 0.0 1.0 1.0\nnewton on off\n"
                "comm_modify cutoff 0.004\n" + text +
                f"{create} bond/types 1 extra/bond/per/atom 200 extra/special/per/atom 250\n" + atoms +
                # bpm/peri computes force densities as peri/* do: the mass is the density
                "mass * 2200\nfix vol all property/atom d_vfrac ghost yes\n"
                f"set group all d_vfrac {VOLUME}\n"
                f"pair_style bpm/peri\npair_coeff * * {C_PMB} {HORIZON}\n"
                f"create_bonds many all all 1 0.0 {HORIZON}\n"
                "special_bonds lj 0.0 1.0 1.0 coul 1.0 1.0 1.0\n"
                f"bond_style bpm/peri\nbond_coeff 1 {bpm_coeff(model, s00)}\n")
    else:
        forced = f" simd {forced_path(variant)}" if forced_path(variant) else ""
        style = f"bbpd/{model} 3d{forced}" if is_ours(variant) else f"peri/{model}"
        text = (("plugin load bbpdplugin.so\n" if is_ours(variant) else "") + "atom_style peri\n" + text +
                f"{create}\n" + atoms +
                f"pair_style {style}\npair_coeff * * {legacy_coeff(model, s00)}\n"
                f"set group all density 2200\nset group all volume {VOLUME}\n")
    if cylinder:
        return text + f"compute 1 all {DAMAGE['ours' if is_ours(variant) else variant]}\n" + INDENTER
    text += MOTION if check else "velocity all set 0.0 0.0 0.0 units box\n"
    return text + RUN


def run(exe, script, nprocs, workdir):
    """run one input with the lmp `exe`; the output, or None when ours lacks the style"""
    workdir.mkdir(parents=True, exist_ok=True)
    (workdir / "in.lammps").write_text(script)
    cmd = [str(exe), "-in", "in.lammps", "-log", "log.lammps"]
    if nprocs > 1:
        cmd = MPIRUN + ["-np", str(nprocs)] + cmd
    env = dict(os.environ, OMP_NUM_THREADS="1")
    proc = subprocess.run(cmd, cwd=workdir, env=env, capture_output=True, text=True, timeout=1800)
    out = proc.stdout + proc.stderr
    err = error_line(out)
    if err and "Unrecognized pair style" in err:
        return None
    if err or proc.returncode != 0:
        raise RuntimeError(f"{exe} failed in {workdir}: {err or proc.returncode}\n{out[-2000:]}")
    return out


def thermo_rows(out):
    """{step: (pe, ke)} of the check's thermo output"""
    rows = re.finditer(r"^\s*(\d+)\s+([-0-9.eE+]+)\s+([-0-9.eE+]+)\s*$", out, re.M)
    return {int(m.group(1)): (float(m.group(2)), float(m.group(3))) for m in rows}


def check_thermo(models, legacy_exe, workdir):
    """ours against peri/* on the moving block; returns the models ours has"""
    have = []
    for model in models:
        ours = run(LMP, deck(model, "ours", check=True), 1, workdir / f"check-ours-{model}")
        if ours is None:
            print(f"check {model}: this plugin has no bbpd/{model}: left out")
            continue
        legacy = thermo_rows(run(legacy_exe, deck(model, "legacy", check=True), 1,
                                 workdir / f"check-legacy-{model}"))
        ours = thermo_rows(ours)
        scale = max(abs(v) for row in legacy.values() for v in row)
        worst = max(abs(a - b) for s in (0, STEPS) for a, b in zip(ours[s], legacy[s])) / scale
        print(f"check {model}: pe, ke at steps 0 and {STEPS}: ours - peri/{model} = {worst:.1e} of "
              f"the largest value ({'ok' if worst <= CHECK_TOL else 'DIFFERENT'})")
        if worst > CHECK_TOL:
            sys.exit(f"vs_bpm: ours and peri/{model} differ by {worst:.1e} (> {CHECK_TOL}): "
                     "the timings would compare different physics")
        have.append(model)
    return have


def final_damage(out):
    """the mean damage at the last thermo line of a cylinder run"""
    rows = re.findall(r"^\s*(\d+)\s+([-0-9.eE+]+)\s+([-0-9.eE+]+)\s*$", out, re.M)
    return float(rows[-1][1]) if rows else None


def timing(out):
    loop = float(re.search(r"^Loop time of ([0-9.eE+-]+)", out, re.M).group(1))
    pair = re.search(r"^Pair\s*\|\s*([0-9.eE+-]+)", out, re.M)
    bond = re.search(r"^Bond\s*\|\s*([0-9.eE+-]+)", out, re.M)
    path = re.search(r"bond loop: (\w+) path", out)
    return {"loop_s": loop, "pair_s": float(pair.group(1)) if pair else None,
            "bond_s": float(bond.group(1)) if bond else None, "path": path.group(1) if path else ""}


def summary(results):
    print("\nminimum loop time over the rounds (s) and ratios:")
    keys = sorted({(r["ranks"], r["model"]) for r in results}, key=lambda k: (k[0], MODELS.index(k[1])))
    for ranks, model in keys:
        best = {r["variant"]: min(x["loop_s"] for x in results if (x["ranks"], x["model"], x["variant"]) ==
                                  (ranks, model, r["variant"]))
                for r in results if (r["ranks"], r["model"]) == (ranks, model)}
        line = f"  {ranks} rank(s) {model}: " + ", ".join(f"{v} {t:.3f}" for v, t in best.items())
        if "ours" in best:
            line += "; " + ", ".join(f"{v}/ours {best[v] / best['ours']:.2f}x" for v in best if v != "ours")
        print(line)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--anchor", type=Path, help="an lmp with bond_style bpm/peri (and the PERI package)")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--ranks", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--models", nargs="+", choices=MODELS, default=list(MODELS))
    ap.add_argument("--scene", choices=("deck", "cylinder"), default="deck",
                    help="LAMMPS's benchmark deck, or the examples/peri cylinder (fracture)")
    ap.add_argument("--forced", nargs="+", choices=FORCED_PATHS, default=[],
                    help="also run ours with each of these paths forced (variants ours-PATH)")
    ap.add_argument("--csv", type=Path)
    args = ap.parse_args()
    cylinder = args.scene == "cylinder"
    if args.anchor and not os.access(args.anchor, os.X_OK):
        sys.exit(f"vs_bpm: --anchor {args.anchor} is not an executable lmp")
    legacy_exe = args.anchor or LMP
    family, model_no = cpu_numbers()
    machine = {"cpu": cpu_model(), "family": family, "cpu_model": model_no, "isa": build_isa()}
    print(f"CPU: {machine['cpu']} (family {family} model {model_no}); plugin paths: {machine['isa']}; "
          f"legacy and bpm: {legacy_exe}")
    variants = ["legacy"] + (["bpm"] if args.anchor else []) + ["ours"] + [f"ours-{p}" for p in args.forced]
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        # the cylinder's check is its damage, printed with each run
        ours_models = args.models if cylinder else check_thermo(args.models, legacy_exe, tmp)
        for ranks in args.ranks:
            for rnd in range(1, args.rounds + 1):
                for model in args.models:
                    for variant in variants:
                        if is_ours(variant) and model not in ours_models:
                            continue
                        exe = LMP if is_ours(variant) else legacy_exe
                        before = load_average()
                        out = run(exe, deck(model, variant, cylinder=cylinder), ranks,
                                  tmp / f"{ranks}-{rnd}-{model}-{variant}")
                        if out is None:    # this plugin lacks the model
                            continue
                        r = dict(timing(out), round=rnd, ranks=ranks, model=model, variant=variant,
                                 damage=final_damage(out) if cylinder else "",
                                 load_before=before, load_after=load_average())
                        results.append(r)
                        print(f"{ranks} rank(s), round {rnd}, {model} {variant}: loop {r['loop_s']:.3f} s"
                              + (f" ({r['path']} path)" if r["path"] else "")
                              + (f", mean damage {r['damage']:.6g}" if cylinder else ""), flush=True)
    summary(results)
    if args.csv:
        command = "tools/python perf/vs_bpm.py " + " ".join(sys.argv[1:])
        date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
        fields = ["scene", "ranks", "round", "model", "variant", "loop_s", "pair_s", "bond_s", "path", "steps",
                  "damage", "cpu",
                  "family", "cpu_model", "isa", "load_before", "load_after", "date", "command"]
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=fields)
            w.writeheader()
            for r in results:
                w.writerow(dict(r, scene=args.scene, steps=CYLINDER_STEPS if cylinder else STEPS, **machine,
                                date=date, command=command))
        print(f"wrote {args.csv}")


if __name__ == "__main__":
    main()

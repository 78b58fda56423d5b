#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""bbpd/lps against LAMMPS's peri/lps on LAMMPS's own examples/peri/in.peri.lps (and, with
--family ves or eps, bbpd/ves or bbpd/eps against peri/ves or peri/eps on in.peri.ves, in.peri.eps).

The two inputs of examples/peri-FAMILY-dropin (the glass cylinder, 3,487 atoms, shattered by an
indenter; one with peri/FAMILY, one ported to bbpd/FAMILY) run in turn, bbpd/* first, --reps
rounds, one MPI rank each. Per run: the loop time and the Pair time of LAMMPS's timing
summary, the processor time of the process (user + system, from the operating system), and
the mean damage and the number of atoms with damage > 0.5 at steps 500 and the last. Printed
and written with --csv: one row per run, with the CPU (model name, family and model numbers),
the vector ISA of the plugin build, the load average before and after and the command; the
summary gives the ratio peri/lps / bbpd/lps of the minimum loop times, of each round's loop
times (median) and of the processor times.

Usage (from the repository root): tools/python perf/lps_vs_peri.py [--family lps|ves|eps]
    [--reps 3] [--steps 1000] [--csv perf/results/NAME.csv]
"""
import argparse
import csv
import datetime
import re
import resource
import statistics
import sys
import tempfile
from pathlib import Path

from bbpd.runner import run_lammps
from pair_vs_pmb import build_isa, cpu_model, cpu_numbers, load_average

ROOT = Path(__file__).resolve().parents[1]
FAMILIES = ("lps", "ves", "eps")


def inputs(family):
    """{style: input file} of examples/peri-FAMILY-dropin, ours first"""
    example = ROOT / "examples" / f"peri-{family}-dropin"
    return {f"bbpd/{family}": example / f"in.bbpd.{family}",
            f"peri/{family}": example / f"in.peri.{family}"}
REPORT_STEP = 500    # a damage row before the cylinder shatters


def children_cpu():
    use = resource.getrusage(resource.RUSAGE_CHILDREN)
    return use.ru_utime + use.ru_stime


def run(style, path, steps, workdir):
    before = children_cpu()
    out = run_lammps(path.read_text(), workdir=workdir, vars={"steps": steps}).output
    cpu = children_cpu() - before
    loop = float(re.search(r"^Loop time of ([0-9.eE+-]+)", out, re.M).group(1))
    pair = float(re.search(r"^Pair\s*\|\s*([0-9.eE+-]+)", out, re.M).group(1))
    rows = {int(m.group(1)): (float(m.group(2)), int(float(m.group(3))))
            for m in re.finditer(r"^\s+(\d+)\s+([0-9.eE+-]+)\s+([0-9.eE+-]+)\s+[0-9.eE+-]+\s*$", out, re.M)}
    mid, last = rows.get(REPORT_STEP, (None, None)), rows[max(rows)]
    memory = float(re.search(r"^Per MPI rank memory allocation \(min/avg/max\) = \S+ \| \S+ \| "
                             r"([0-9.eE+-]+) Mbytes", out, re.M).group(1))
    return {"style": style, "steps": steps, "loop_s": loop, "pair_s": pair, "cpu_s": round(cpu, 3),
            "damage_mid": mid[0], "cracked_mid": mid[1], "damage_end": last[0], "cracked_end": last[1],
            "memory_mb": memory, "bonds": bond_count(out)}


def bond_count(out):
    """Bonds at the setup: peri/lps prints the bond ends ('total # of bonds', each bond twice)."""
    ours = re.search(r"total bonds (\d+)", out)
    if ours:
        return int(ours.group(1))
    return int(re.search(r"total # of bonds = (\d+)", out).group(1)) // 2


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--family", choices=FAMILIES, default="lps")
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--steps", type=int, default=1000)
    ap.add_argument("--csv", type=Path)
    args = ap.parse_args()
    styles = inputs(args.family)
    ours, theirs = styles
    family, model = cpu_numbers()
    machine = {"cpu": cpu_model(), "family": family, "model": model, "isa": build_isa()}
    print(f"CPU: {machine['cpu']} (family {family} model {model}); plugin paths: {machine['isa']}")
    load_before = load_average()
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        for rep in range(args.reps):
            for style, path in styles.items():
                r = run(style, path, args.steps, Path(tmp) / f"{rep}-{style.replace('/', '-')}")
                r["round"] = rep + 1
                results.append(r)
                print(f"round {rep + 1} {style}: loop {r['loop_s']:.3f} s, pair {r['pair_s']:.3f} s, "
                      f"cpu {r['cpu_s']:.3f} s; damage {r['damage_mid']} / {r['damage_end']}, "
                      f"atoms > 0.5: {r['cracked_mid']} / {r['cracked_end']}", flush=True)
    load_after = load_average()
    by = {s: [r for r in results if r["style"] == s] for s in styles}
    ratio_min = min(r["loop_s"] for r in by[theirs]) / min(r["loop_s"] for r in by[ours])
    rounds = [b["loop_s"] / a["loop_s"] for a, b in zip(by[ours], by[theirs])]
    cpu_ratio = min(r["cpu_s"] for r in by[theirs]) / min(r["cpu_s"] for r in by[ours])
    print(f"loop time ratio {theirs} / {ours}: {ratio_min:.2f} (minima), {statistics.median(rounds):.2f} "
          f"(median of the rounds {', '.join(f'{x:.2f}' for x in rounds)}); processor time: "
          f"{cpu_ratio:.2f}; load {load_before} -> {load_after}")
    for style, rs in by.items():
        print(f"{style}: memory per rank {rs[0]['memory_mb']:.2f} Mbytes, {rs[0]['bonds']} bonds: "
              f"{rs[0]['memory_mb'] * 1e6 / rs[0]['bonds']:.1f} bytes per bond")
    if args.csv:
        command = "tools/python perf/lps_vs_peri.py " + " ".join(sys.argv[1:])
        date = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
        fields = ["round", "style", "steps", "loop_s", "pair_s", "cpu_s", "damage_mid", "cracked_mid",
                  "damage_end", "cracked_end", "memory_mb", "bonds", "cpu", "family", "model", "isa", "load_before",
                  "load_after", "date", "command"]
        with open(args.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=fields)
            w.writeheader()
            for r in results:
                w.writerow(dict(r, **machine, load_before=load_before, load_after=load_after,
                                date=date, command=command))
        print(f"wrote {args.csv}")


if __name__ == "__main__":
    main()

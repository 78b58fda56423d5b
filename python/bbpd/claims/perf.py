# SPDX-License-Identifier: GPL-2.0-or-later
"""The README's speed block for one CPU, from the CSVs that perf/pair_vs_pmb.py --csv wrote."""
import csv

from bbpd.jobs import ROOT

ZEN3 = ROOT / "perf" / "results" / "zen3-avx2.csv"
ZEN3_PLATE_BLOCK = ROOT / "perf" / "results" / "zen3-avx2-plate-block.csv"
# the memory rows again after the family list became half and its freed pages were handed back
ZEN3_MEMORY = ROOT / "perf" / "results" / "zen3-avx2-memory.csv"
# the README's name of each scene of pair_vs_pmb.py, in its order
SCENES = (("plate 2D", "plate 200 × 100, 785 k bonds", "ms/step"),
          ("block 3D", "3D block 41³, 15.4 M bonds", "ms/step"),
          ("LAMMPS bench", "LAMMPS's benchmark scene, periodic 16³, 250 k bonds", "ms/step"),
          ("cylinder", "`compat pmb` cylinder, 1000 steps", "s"))
MARGIN = "memory: bytes per bond at the margin"


def _rows(path):
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def _ms(text):
    v = float(text)
    return f"{v:.1f}" if v >= 100 else f"{v:.2f}"


def zen3_readme(data):
    """Later files win: the plate and block were measured again at a lower load, the memory
    after the change that lowered it."""
    rows = {}
    for path in (ZEN3, ZEN3_PLATE_BLOCK, ZEN3_MEMORY):
        for r in _rows(path):
            rows[r["scene"]] = r
    lines = ["| scene | ours | peri/pmb | ratio |", "|---|---|---|---|"]
    for prefix, name, unit in SCENES:
        r = next(r for s, r in rows.items() if s.startswith(prefix))
        ours, pmb = float(r["ours_loop_ms"]), float(r["pmb_loop_ms"])
        if unit == "s":
            cells = f"{ours:.2f} s | {pmb:.2f} s"
        else:
            cells = f"{_ms(r['ours_loop_ms'])} ms/step | {_ms(r['pmb_loop_ms'])} ms/step"
        lines.append(f"| {name} | {cells} | {pmb / ours:.1f}× |")
    margin = next(r for s, r in rows.items() if s.startswith(MARGIN))
    r0 = rows[next(iter(rows))]
    head = (f"On an {r0['cpu']} Zen 3 (family {r0['family']} model {r0['model']}, "
            f"{r0['isa']} kernel, one core, a shared machine at load 3-17;\n"
            "`perf/results/zen3-avx2-plate-block.csv`, `perf/results/zen3-avx2.csv` and\n"
            "`perf/results/zen3-avx2-memory.csv`, commands in "
            "[doc/performance.md](doc/performance.md)):")
    return (head + "\n\n" + "\n".join(lines) + "\n\nMemory at the margin (max RSS, block 41³ → "
            f"51³): {float(margin['bytes_per_bond']):.1f} bytes per bond.")

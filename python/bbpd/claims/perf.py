# SPDX-License-Identifier: GPL-2.0-or-later
"""The README's speed block for one CPU, from the CSVs that perf/pair_vs_pmb.py --csv wrote."""
import csv

from bbpd.jobs import ROOT

RESULTS = ROOT / "perf" / "results"
# later files win: the plate and block measured again at a lower load, the memory after the
# change that lowered it, then every scene at load 1 (a quiet machine)
ZEN3_FILES = tuple(RESULTS / name for name in (
    "zen3-avx2.csv", "zen3-avx2-plate-block.csv", "zen3-avx2-memory.csv",
    "zen3-avx2-quiet.csv", "zen3-avx2-quiet-block.csv"))
# the README's name of each scene of pair_vs_pmb.py, in its order
SCENES = (("plate 2D", "plate 200 × 100, 785 k bonds", "ms/step"),
          ("block 3D", "3D block 41³, 15.4 M bonds", "ms/step"),
          ("LAMMPS bench", "LAMMPS's benchmark scene, periodic 16³, 250 k bonds", "ms/step"),
          ("cylinder", "`bbpd/pmb` cylinder, 1000 steps", "s"))
MARGIN = "memory: bytes per bond at the margin"


def _rows(path):
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def _ms(text):
    v = float(text)
    return f"{v:.1f}" if v >= 100 else f"{v:.2f}"


def _loads(rows):
    """the range of the 1-minute load averages before and after the runs of these rows"""
    values = [float(r[key].split()[0]) for r in rows for key in ("load_before", "load_after")]
    return f"{min(values):.1f}-{max(values):.1f}"


def zen3_readme(data):
    """The Zen 3 table: each scene from the last file that measured it."""
    rows, source = {}, {}
    for path in ZEN3_FILES:
        for r in _rows(path):
            rows[r["scene"]] = r
            source[r["scene"]] = path.name
    lines = ["| scene | ours | peri/pmb | ratio |", "|---|---|---|---|"]
    used = []
    for prefix, name, unit in SCENES:
        scene = next(s for s in rows if s.startswith(prefix))
        r = rows[scene]
        used.append(scene)
        ours, pmb = float(r["ours_loop_ms"]), float(r["pmb_loop_ms"])
        if unit == "s":
            cells = f"{ours:.2f} s | {pmb:.2f} s"
        else:
            cells = f"{_ms(r['ours_loop_ms'])} ms/step | {_ms(r['pmb_loop_ms'])} ms/step"
        lines.append(f"| {name} | {cells} | {pmb / ours:.1f}× |")
    margin_scene = next(s for s in rows if s.startswith(MARGIN))
    used.append(margin_scene)
    margin = rows[margin_scene]
    r0 = rows[used[0]]
    files = sorted({source[s] for s in used}, key=[p.name for p in ZEN3_FILES].index)
    reps = {s: rows[s]["reps"] for s in used[:-1]}
    common = max(set(reps.values()), key=list(reps.values()).count)
    odd = [f"{s.split(',')[0].split(' 2D')[0].split(' 3D')[0]}: {n}" for s, n in reps.items() if n != common]
    runs = f"minimum of {common} alternating runs" + (f" ({'; '.join(odd)})" if odd else "")
    head = (f"On an {r0['cpu']} Zen 3 (family {r0['family']} model {r0['model']}, "
            f"{r0['isa']} kernel, one core, load {_loads([rows[s] for s in used])}, {runs};\n"
            + ", ".join(f"`perf/results/{f}`" for f in files)
            + ", commands in [doc/performance.md](doc/performance.md)):")
    return (head + "\n\n" + "\n".join(lines) + "\n\nMemory at the margin (max RSS, block 41³ → "
            f"51³): {float(margin['bytes_per_bond']):.1f} bytes per bond.")

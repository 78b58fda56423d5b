# SPDX-License-Identifier: GPL-2.0-or-later
"""The README's speed block for one CPU, from the CSVs that perf/pair_vs_pmb.py --csv wrote."""
import csv

from bbpd.jobs import ROOT
from bbpd.markdown import table as md_table

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
# the newest CPU with simd auto (README.md): plate and block, then the other scenes
ZEN5_AUTO_FILES = (RESULTS / "zen5-simd-auto.csv", RESULTS / "zen5-simd-auto-bench-cylinder-memory.csv")


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


def scene_table(files):
    """Each scene of pair_vs_pmb.py from the last of files that measured it: ours against
    peri/pmb, the ratio, the path run, and the memory per bond at the margin."""
    rows, source = {}, {}
    for path in files:
        for r in _rows(path):
            rows[r["scene"]] = r
            source[r["scene"]] = path.name
    table, used = [], []
    for prefix, name, unit in SCENES:
        used.append(next(s for s in rows if s.startswith(prefix)))
        r = rows[used[-1]]
        ours, pmb = float(r["ours_loop_ms"]), float(r["pmb_loop_ms"])
        table.append([name, *([f"{ours:.2f} s", f"{pmb:.2f} s"] if unit == "s" else
                              [f"{_ms(r[k])} ms/step" for k in ("ours_loop_ms", "pmb_loop_ms")]),
                      f"{pmb / ours:.1f}×"])
    margin_scene = next(s for s in rows if s.startswith(MARGIN))
    used.append(margin_scene)
    margin = rows[margin_scene]
    r0 = rows[used[0]]
    names = [p.name for p in files]
    reps = {s: rows[s]["reps"] for s in used[:-1]}
    common = max(set(reps.values()), key=list(reps.values()).count)
    odd = [f"{s.split(',')[0].split(' 2D')[0].split(' 3D')[0]}: {n}" for s, n in reps.items() if n != common]
    runs = f"minimum of {common} alternating runs" + (f" ({'; '.join(odd)})" if odd else "")
    path = {rows[s].get("path") or r0["isa"] for s in used[:-1]}
    head = (f"{r0['cpu']} family {r0['family']} model {r0['model']}, {'/'.join(sorted(path))} "
            f"path, one core, load {_loads([rows[s] for s in used])}, {runs}, {r0['date'][:10]}; "
            + ", ".join(f"`perf/results/{f}`" for f in sorted({source[s] for s in used}, key=names.index))
            + ":")
    return (head + "\n\n" + md_table(["scene", "ours", "peri/pmb", "ratio"], table) + "\n\nMemory at the margin (max RSS, block 41³ → "
            f"51³): {float(margin['bytes_per_bond']):.1f} bytes per bond.")


# perf/lps_vs_peri.py --csv runs of the peri/lps cylinder, one file per CPU, in the doc's order,
# with the CPU's vector ISA (the CSVs' isa column lists the paths the plugin build holds)
LPS_FILES = ((RESULTS / "spr-lps-cylinder.csv", "AVX-512"), (RESULTS / "zen3-lps-cylinder.csv", "AVX2"))


def lps_cylinder(data):
    """doc/performance.md's bbpd/lps against peri/lps: per CPU the minimum loop and processor
    times of the rounds, their ratios, and LAMMPS's memory per rank where the CSV has it."""
    out = []
    for path, isa in LPS_FILES:
        rows = _rows(path)
        by = {s: [r for r in rows if r["style"] == s] for s in ("peri/lps", "bbpd/lps")}
        loop = {s: min(float(r["loop_s"]) for r in rs) for s, rs in by.items()}
        cpu = {s: min(float(r["cpu_s"]) for r in rs) for s, rs in by.items()}
        rounds = ", ".join(f"{float(b['loop_s']) / float(a['loop_s']):.2f}"
                           for a, b in zip(by["bbpd/lps"], by["peri/lps"]))
        r0 = rows[0]
        if r0.get("memory_mb"):
            mem = {s: float(rs[0]["memory_mb"]) for s, rs in by.items()}
            per_bond = {s: mem[s] * 1e6 / float(rs[0]["bonds"]) for s, rs in by.items()}
            memory = [f"{mem['peri/lps']:.2f} / {mem['bbpd/lps']:.2f}",
                      f"{per_bond['peri/lps']:.1f} / {per_bond['bbpd/lps']:.1f}"]
        else:
            memory = ["not recorded", ""]
        out.append([f"{r0['cpu']} (family {r0['family']} model {r0['model']})", isa,
                    f"{loop['peri/lps']:.2f}", f"{loop['bbpd/lps']:.2f}",
                    f"**{loop['peri/lps'] / loop['bbpd/lps']:.2f}** ({rounds})",
                    f"{cpu['peri/lps'] / cpu['bbpd/lps']:.2f}", *memory])
    return md_table(["CPU", "vector ISA", "`peri/lps` loop, min (s)", "`bbpd/lps` loop, min (s)",
                     "loop ratio (rounds)", "processor time ratio",
                     "memory per rank: `peri/lps` / `bbpd/lps` (MB)", "bytes per bond"], out)


# One CPU's run-time SIMD choice (doc/performance.md): perf/pair_vs_pmb.py --simd PATH and
# perf/row_floor.py --path PATH, each into perf/results/<prefix>-simd-PATH.csv and
# <prefix>-row-floor-PATH.csv, and the other scenes with auto in <prefix>-simd-auto-bench-cylinder-memory.csv
SIMD_PATHS = ("auto", "avx512", "avx2", "portable")
FLOOR_PATHS = ("avx512", "avx2", "portable")
SIMD_SCENES = (("plate 2D", "plate"), ("block 3D", "block"))


def _scene(rows, prefix):
    return next(r for r in rows if r["scene"].startswith(prefix))


def _ratio(r):
    return float(r["pmb_loop_ms"]) / float(r["ours_loop_ms"])


def _simd_runs(prefix):
    """{simd keyword: rows of its pair_vs_pmb.py CSV}"""
    return {p: _rows(RESULTS / f"{prefix}-simd-{p}.csv") for p in SIMD_PATHS}


def _floor(path):
    """(kernel pair ms/step, floor pair ms/step, load) of a row_floor.py CSV"""
    rows = {r["variant"]: r for r in _rows(path)}
    return (float(rows["baseline"]["pair_ms"]), float(rows["no_memory"]["pair_ms"]),
            rows["baseline"]["load"].split()[0])


def simd_table(prefix):
    """Per simd keyword, the plate and block against peri/pmb (each within its own invocation),
    the path that ran and the load; the best ratio of each scene in bold."""
    runs = _simd_runs(prefix)
    best = {s: max(SIMD_PATHS, key=lambda p: _ratio(_scene(runs[p], s))) for s, _ in SIMD_SCENES}
    out = []
    for p, rows in runs.items():
        cells = [p]
        for s, _ in SIMD_SCENES:
            r, ratio = _scene(rows, s), f"{_ratio(_scene(rows, s)):.1f}"
            cells += [f"{_ms(r['ours_loop_ms'])} / {_ms(r['pmb_loop_ms'])}",
                      f"**{ratio}**" if best[s] == p else ratio]
        out.append(cells + [", ".join(_scene(rows, s)["path"] for s, _ in SIMD_SCENES), _loads(rows)])
    return md_table(["`simd`", "plate 2D: ours / `peri/pmb` (ms/step)", "ratio",
                     "block 3D 41^3: ours / `peri/pmb` (ms/step)", "ratio", "path run", "load"], out)


def floor_table(prefix):
    """Per path the 3D block held still: the kernel's pair time against its floor (no_memory)."""
    floors = {p: _floor(RESULTS / f"{prefix}-row-floor-{p}.csv") for p in FLOOR_PATHS}
    return md_table(["path (3D block held still, `perf/row_floor.py`)", "kernel ms/step",
                     "floor (`no_memory`) ms/step", "ratio", "load"],
                    [[p, f"{k:.2f}", f"{f:.2f}", f"{k / f:.2f}", load] for p, (k, f, load) in floors.items()])


# LAMMPS's bpm/peri benchmark deck, ours against peri/* and bond_style bpm/peri
# (perf/vs_bpm.py --csv): one file per CPU
VS_BPM_FILES = (RESULTS / "spr-vs-bpm.csv", RESULTS / "zen4-vs-bpm.csv")
BPM_MODELS = ("pmb", "lps", "ves", "eps")


# the runs of the deck on one CPU that a verdict on the targets takes together
ZEN4_VS_BPM_RUNS = (RESULTS / "zen4-vs-bpm.csv", RESULTS / "zen4-vs-bpm-repeat.csv",
                    RESULTS / "zen4-vs-bpm-third.csv", RESULTS / "zen4-vs-bpm-fourth.csv",
                    RESULTS / "zen4-vs-bpm-fifth.csv")
# the targets ours / bpm/peri on the deck, per rank count, that a LAMMPS user compares with
BPM_TARGETS = {1: 4.0, 2: 3.0}


def loop_minima(rows):
    """the minimum loop time over the rounds of a perf/vs_bpm.py CSV, per (ranks, model, variant)"""
    best = {}
    for r in rows:
        key = (int(r["ranks"]), r["model"], r["variant"])
        best[key] = min(best.get(key, float(r["loop_s"])), float(r["loop_s"]))
    return best


def deck_ratios(path):
    """ours / bpm/peri of the minimum loop times of one run, per (ranks, model)"""
    best = loop_minima(_rows(path))
    return {(n, m): best[(n, m, "bpm")] / best[(n, m, "ours")] for n, m, v in best if v == "ours"}


def round_ratio_range(path, ranks, model):
    """the smallest and largest ours / bpm/peri of one round (the two runs of a round follow each
    other), over the rounds of one run: how far the machine moves a ratio within a run"""
    loops = {}
    for r in _rows(path):
        if int(r["ranks"]) == ranks and r["model"] == model and r["variant"] in ("bpm", "ours"):
            loops.setdefault(int(r["round"]), {})[r["variant"]] = float(r["loop_s"])
    ratios = [v["bpm"] / v["ours"] for v in loops.values()]
    return min(ratios), max(ratios)


def deck_verdict(paths, ranks):
    """per model, whether every run reaches the target of this rank count ('reached'), none
    does ('not reached') or the runs disagree ('not settled')"""
    runs = [deck_ratios(p) for p in paths]
    out = {}
    for model in BPM_MODELS:
        hits = [run[(ranks, model)] >= BPM_TARGETS[ranks] for run in runs]
        out[model] = "reached" if all(hits) else "not reached" if not any(hits) else "not settled"
    return out


def vs_bpm(data):
    """doc/performance.md's table of perf/vs_bpm.py: per CPU, rank count and model the minimum
    loop time of each variant over the rounds, and the ratios of peri/* and bpm/peri to ours."""
    out = []
    for path in VS_BPM_FILES:
        rows = _rows(path)
        r0 = rows[0]
        # the path auto chose for the pmb runs (each model's run names its own in the CSV)
        paths = sorted({r["path"] for r in rows if r["variant"] == "ours" and r["model"] == "pmb"})
        where = (f"{r0['cpu']} (family {r0['family']} model {r0['cpu_model']}), "
                 f"pmb: {'/'.join(paths)}, {r0['date'][:10]}, load {_loads(rows)}")
        minima = loop_minima(rows)
        for ranks in sorted({int(r["ranks"]) for r in rows}):
            for model in BPM_MODELS:
                best = {v: t for (n, m, v), t in minima.items() if (n, m) == (ranks, model)}
                if not best:
                    continue
                out.append([where, ranks, model]
                            + [f"{best[v]:.2f}" if v in best else "-" for v in ("legacy", "bpm", "ours")]
                            + [f"{best[v] / best['ours']:.2f}×" if v in best and "ours" in best else "-"
                               for v in ("legacy", "bpm")])
                where = ""
    return md_table(["CPU, path, load", "ranks", "model", "`peri/*` (s)", "`bpm/peri` (s)", "ours (s)",
                     "`peri/*` / ours", "`bpm/peri` / ours"], out)


# the deck with each path forced beside auto's (perf/vs_bpm.py --forced avx2 avx512)
FORCED_RUN = RESULTS / "zen4-vs-bpm-fifth.csv"


def forced_paths(path, ranks):
    """per model of a perf/vs_bpm.py --forced run on this rank count: the minimum loop time over
    the rounds of ours with the path auto chose ('auto') and with each forced path, and how
    many rounds auto chose each path ('chosen')"""
    out = {}
    for r in _rows(path):
        if int(r["ranks"]) != ranks or not r["variant"].startswith("ours"):
            continue
        t = out.setdefault(r["model"], {"chosen": {}})
        name = "auto" if r["variant"] == "ours" else r["variant"][len("ours-"):]
        t[name] = min(t.get(name, float(r["loop_s"])), float(r["loop_s"]))
        if name == "auto":
            t["chosen"][r["path"]] = t["chosen"].get(r["path"], 0) + 1
    return {m: out[m] for m in BPM_MODELS if m in out}


def forced_table(data):
    """doc/performance.md's table of auto against the forced paths on the deck (FORCED_RUN)"""
    out, paths = [], set()
    for ranks in sorted({int(r["ranks"]) for r in _rows(FORCED_RUN)}):
        for model, t in forced_paths(FORCED_RUN, ranks).items():
            forced = {p: v for p, v in t.items() if p not in ("auto", "chosen")}
            paths |= set(forced)
            fastest = min(forced, key=forced.get)
            out.append([ranks, model, f"{t['auto']:.3f}"] + [f"{forced[p]:.3f}" for p in sorted(forced)]
                       + [fastest, f"{t['auto'] / forced[fastest]:.2f}",
                          ", ".join(f"{p} {n}" for p, n in sorted(t["chosen"].items()))])
    return md_table(["ranks", "model", "auto (s)"] + [f"{p} forced (s)" for p in sorted(paths)]
                    + ["fastest forced", "auto / fastest forced", "rounds auto chose"], out)


# the LPS deck with perf/probes/lps_kept_lengths.patch (new) against the plugin without (base):
# two invocations of perf/two_builds.sh
KEPT_LENGTHS_RUNS = (RESULTS / "zen4-lps-kept-lengths.csv", RESULTS / "zen4-lps-kept-lengths-2.csv")


def two_builds(path):
    """a perf/two_builds.sh CSV of one input: the minimum loop time of each build, the number of
    rounds and the rounds in which the new build ran faster than the base"""
    rounds = {}
    for r in _rows(path):
        rounds.setdefault(int(r["round"]), {})[r["build"]] = float(r["loop_s"])
    return {"base": min(v["base"] for v in rounds.values()), "new": min(v["new"] for v in rounds.values()),
            "rounds": len(rounds), "new_faster": sum(v["new"] < v["base"] for v in rounds.values())}


# LAMMPS's examples/peri cylinder for each model (perf/vs_bpm.py --scene cylinder --csv)
VS_BPM_CYLINDER_FILES = (RESULTS / "spr-vs-bpm-cylinder.csv", RESULTS / "zen4-vs-bpm-cylinder.csv")


def vs_bpm_cylinder(data):
    """the cylinder's table: per CPU and model the minimum loop time of each variant, the ratios
    to ours, and each variant's mean damage at the end (the same in every round)"""
    out = []
    for path in VS_BPM_CYLINDER_FILES:
        rows = _rows(path)
        where = f"{rows[0]['cpu']} (family {rows[0]['family']} model {rows[0]['cpu_model']}), load {_loads(rows)}"
        for model in BPM_MODELS:
            mine = [r for r in rows if r["model"] == model]
            best = {v: min(float(r["loop_s"]) for r in mine if r["variant"] == v) for v in ("legacy", "bpm", "ours")}
            damage = {r["variant"]: float(r["damage"]) for r in mine}
            out.append([where, model] + [f"{best[v]:.2f}" for v in ("legacy", "bpm", "ours")]
                       + [f"{best[v] / best['ours']:.2f}×" for v in ("legacy", "bpm")]
                       + [f"{damage[v]:.4f}" for v in ("legacy", "bpm", "ours")])
            where = ""
    return md_table(["CPU, load", "model", "`peri/*` (s)", "`bpm/peri` (s)", "ours (s)", "`peri/*` / ours",
                     "`bpm/peri` / ours", "damage `peri/*`", "damage `bpm/peri`", "damage ours"], out)

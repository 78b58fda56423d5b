# SPDX-License-Identifier: GPL-2.0-or-later
"""Crack branching in glass: where, when and how fast the crack of
examples/crack-branching/in.crack_branching splits, per kernel, m, delta and traction
(examples/crack-branching/README.md defines each measure and has the commands).
"""

import time
from pathlib import Path

import numpy as np

from bbpd import crack_tip, csvfile, freund, plots, readers
from bbpd import jobs as jobmod
from bbpd.provenance import cpu
from bbpd.kernels import KERNELS
from bbpd.markdown import table as md_table
from bbpd.runner import run_or_reuse
from bbpd.benchmarks import cli

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "crack-branching" / "in.crack_branching"
RESULTS = ROOT / "examples" / "crack-branching" / "results" / "branching.csv"
README = ROOT / "examples" / "crack-branching" / "README.md"

# soda-lime glass of the decks (fracture-anchors.md); BBPD's Poisson ratio in plane stress
E, RHO, G0, NU = 72.0e9, 2440.0, 3.8, 1.0 / 3.0
C_D = freund.dilatational_wave_speed(E, NU, RHO, freund.PLANE_STRESS)
C_S = freund.shear_wave_speed(E, NU, RHO)
C_R = freund.rayleigh_wave_speed(C_S, C_D)
# experiments on glass: terminal speed about half the Rayleigh speed (Bowden et al. 1967, as
# quoted by Ha & Bobaru 2010)
EXPERIMENT_SPEED_OVER_CR = 0.5
PRE_WINDOW = 4.0e-6       # s before the fork over which v_pre is fitted
END_WINDOW = 5.0e-6       # s at the end over which v_end is fitted
THRESHOLD = crack_tip.DEFAULT_THRESHOLD

# name -> (kernel, delta in m, m, sigma in Pa); the order is that of the CPU budget
RUNS = {f"{k}-s{s}-m{m}{suffix}": (k, delta, m, s * 1.0e6)
        for s, m, delta, suffix in ((2, 4, 1.0e-3, ""), (2, 3, 1.0e-3, ""), (4, 4, 1.0e-3, ""),
                                    (12, 4, 1.0e-3, ""), (2, 4, 0.5e-3, "-d0.5"))
        for k in KERNELS}
DEFAULT_RUNS = [n for n in RUNS if not n.endswith("d0.5")]

CSV_COLUMNS = ("run", "kernel", "delta_mm", "m", "dx_mm", "sigma_MPa", "atoms", "steps",
               "loop_s", "t_init_us", "t_split_us", "t_seen_us", "x_split_mm", "y_split_mm",
               "v_pre", "v_pre_over_cR", "v_mean", "v_mean_over_cR", "v_end", "v_end_over_cR",
               "v_max_over_cR",
               "angle_deg", "tips_end", "splits_end", "mirror_x_dx", "mirror_y_dx",
               "mirror_damage_frac", "extension_end_mm", "s0")
TEXT_COLUMNS = ("run", "kernel")


def read_tips(path):
    """tips.dat (fix ave/time mode vector) -> {step: rows (array, 9 columns)}"""
    out, lines = {}, [l for l in Path(path).read_text().splitlines() if l and l[0] != "#"]
    k = 0
    while k < len(lines):
        step, nrows = (int(v) for v in lines[k].split())
        out[step] = np.array([[float(v) for v in l.split()[1:]]
                              for l in lines[k + 1:k + 1 + nrows]])
        k += 1 + nrows
    return out


def slope(t, l, t0, t1):
    """Least-squares slope of l(t) over t0 <= t <= t1 (nan with fewer than 3 points)."""
    w = (t >= t0) & (t <= t1)
    return float(np.polyfit(t[w], l[w], 1)[0]) if w.sum() >= 3 else float("nan")


def mirror_damage_fraction(ref_dump, damage_dump, dx):
    """Fraction of the crack atoms of the last damage snapshot whose mirror image about y = 0
    is not a crack atom (the grid is symmetric: the image of an atom is an atom)."""
    ref = readers.read_dump(ref_dump)
    pos = {int(i): (x, y) for i, x, y in zip(ref["id"], ref["x"], ref["y"])}
    last = readers.dump_snapshots(damage_dump)[-1][1]
    crack = {tuple(np.round(np.array(pos[int(i)]) / dx - 0.5).astype(int))
             for i, d in zip(last["id"], last["c_damage"]) if d >= THRESHOLD}
    if not crack:
        return 0.0
    return sum((i, -j - 1) not in crack for i, j in crack) / len(crack)


def measure(t, vec, tips, dx):
    """The numbers of one run from the tip outputs: t (s), vec (tip.dat values per output),
    tips ({index of output: rows})."""
    ext, ntips = vec[:, 2], vec[:, 6]
    res = dict.fromkeys(("t_split_us", "t_seen_us", "x_split_mm", "y_split_mm", "angle_deg",
                         "v_pre", "v_mean", "mirror_x_dx", "mirror_y_dx"), float("nan"))
    grown = np.flatnonzero(ext > 0.0)
    t_init = float(t[grown[0]]) if grown.size else float("nan")
    res["t_init_us"] = 1e6 * t_init
    res["v_end"] = slope(t, ext, t[-1] - END_WINDOW, t[-1])
    res["v_max_over_cR"] = float(vec[:, 3].max()) / C_R
    res["tips_end"] = int(ntips[-1])
    res["splits_end"] = int(vec[-1, 7])
    res["extension_end_mm"] = 1e3 * float(ext[-1])
    seen = np.flatnonzero(vec[:, 7] >= 1)
    if seen.size:
        k = int(seen[0])
        rows = tips[k]
        first = next(r for r in rows if r[7] >= 0.0) if (rows[:, 7] >= 0.0).any() else None
        if first is not None:
            t_seen, l_s = first[7], first[8]
            before = np.arange(k + 1)
            t_split = float(np.interp(l_s, ext[before], t[before]))   # ext grows before it
            res.update({"t_seen_us": 1e6 * t_seen, "t_split_us": 1e6 * t_split,
                        "x_split_mm": 1e3 * first[5], "y_split_mm": 1e3 * first[6]})
            res["v_pre"] = slope(t, ext, t_split - PRE_WINDOW, t_split)
            res["v_mean"] = l_s / (t_split - t_init)
            # the two tips of the first split: the one that records it and the one that
            # continued its parent (no split, or an earlier one); mirror images if symmetric
            dev_x = dev_y = 0.0
            angle = float("nan")
            for j in range(k, len(t)):
                rows = tips[j]
                mine = [r for r in rows[:int(ntips[j])] if r[7] == t_seen]
                rest = [r for r in rows[:int(ntips[j])] if r[7] < 0.0 or r[7] < t_seen]
                if not mine or not rest:
                    continue
                a, b = rest[0], mine[0]
                dev_x = max(dev_x, abs(a[0] - b[0]) / dx)
                dev_y = max(dev_y, abs(a[1] + b[1]) / dx)
                angle = abs(np.degrees(np.arctan2(a[1] - first[6], a[0] - first[5])
                                       - np.arctan2(b[1] - first[6], b[0] - first[5])))
            res.update({"mirror_x_dx": dev_x, "mirror_y_dx": dev_y, "angle_deg": angle})
    for key in ("v_pre", "v_mean", "v_end"):
        res[f"{key}_over_cR"] = res[key] / C_R
    return res


def run(name, workdir, reuse=False, nprocs=1):
    """Run one entry of RUNS in workdir (reuse: measure an earlier run's outputs) and
    measure it (the report's job)."""
    return run_case(workdir, *RUNS[name], name=name, reuse=reuse, nprocs=nprocs)


def run_case(workdir, kernel, delta, m, sigma, name=None, reuse=False, nprocs=1):
    """Run the example with these parameters and measure it."""
    name = name or f"{kernel}-s{sigma * 1e-6:g}-m{m:g}-d{delta * 1e3:g}"
    dx = delta / m
    workdir = Path(workdir)
    vars_ = {"kernel": kernel, "dx": repr(dx), "m": m, "sigma": repr(sigma)}
    output, _ = run_or_reuse(EXAMPLE, workdir, vars_, nprocs, reuse=reuse)
    loop_s, _ = readers.loop_time(output)
    s0 = readers.pair_setup(output)["critical_stretch"]
    head = output.split("CRACK-BRANCHING:")[-1].split("\n")[0].split()
    info = dict(zip(head[::2], head[1::2]))
    dt = float(info["dt"])
    vec = np.loadtxt(workdir / "tip.dat", comments="#", ndmin=2)
    t = vec[:, 0] * dt
    by_step = read_tips(workdir / "tips.dat")
    tips = {k: by_step[int(s)] for k, s in enumerate(vec[:, 0])}
    res = measure(t, vec[:, 1:], tips, dx)
    res["mirror_damage_frac"] = mirror_damage_fraction(workdir / "ref.dump",
                                                       workdir / "damage.dump", dx)
    res.update({"run": name, "kernel": kernel, "delta_mm": 1e3 * delta, "m": m,
                "workdir": str(workdir),
                "dx_mm": 1e3 * dx, "sigma_MPa": 1e-6 * sigma, "atoms": int(info["atoms"]),
                "steps": int(info["steps"]), "loop_s": loop_s, "s0": s0})
    return res


# --------------------------------------------------------------------------- outputs

def write_csv(path, rows, command):
    csvfile.write_csv(path, rows, (f"made by: {command}", f"timing: LAMMPS loop time, 1 rank, "
                                   f"{cpu()}"), CSV_COLUMNS, TEXT_COLUMNS, nan="nan")


def read_rows(path=RESULTS):
    return csvfile.read_csv(path, TEXT_COLUMNS)[1]


def _f(v, fmt):
    return "–" if v != v else format(v, fmt)


def grown(r):
    """Did the crack grow from its tip all along (no jump faster than c_R)?"""
    return r["v_max_over_cR"] <= 1.0


def table(rows):
    """The README table of the results CSV (a run whose crack jumped: no split or speed)."""
    out = []
    for r in rows:
        cells = [r["kernel"], f"{r['delta_mm']:g}", f"{r['m']:g}", f"{r['sigma_MPa']:g}",
                 f"{int(r['atoms'])}", _f(r["t_init_us"], ".2f")]
        if grown(r):
            cells += [f"{_f(r['v_pre'], '.0f')}, {_f(r['v_pre_over_cR'], '.2f')}",
                      _f(r["v_mean_over_cR"], ".2f"),
                      f"{_f(r['t_split_us'], '.1f')}, {_f(r['t_seen_us'], '.1f')}, "
                      f"{_f(r['x_split_mm'], '.1f')}, {_f(r['y_split_mm'], '+.2f')}",
                      _f(r["angle_deg"], ".0f"),
                      f"{_f(r['v_end'], '.0f')}, {_f(r['v_end_over_cR'], '.2f')}",
                      f"{int(r['tips_end'])}, {int(r['splits_end'])}",
                      f"{_f(r['mirror_x_dx'], '.0f')}/{_f(r['mirror_y_dx'], '.0f')}, "
                      f"{_f(100 * r['mirror_damage_frac'], '.1f')}"]
        else:
            cells += ["mid-line broken by the loading waves: no crack growth to measure"] + \
                     ["–"] * 5 + [f"–, {_f(100 * r['mirror_damage_frac'], '.1f')}"]
        out.append(cells + [_f(r["v_max_over_cR"], ".2f"), _f(r["loop_s"], ".0f")])
    return md_table(("kernel", "δ (mm)", "m", "σ (MPa)", "atoms", "t_init (µs)",
                     "v before split (m/s), /c_R", "mean v to split, /c_R",
                     "first split: t (µs), seen (µs), x (mm), y (mm)", "branch angle (°)",
                     "v at end, /c_R", "tips, splits at end", "mirror: tips (dx), damage (%)",
                     "v_max/c_R", "loop (s)"), out)


FIGURE = "damage_maps.png"
MAP_TIMES_US = (15.0, 25.0, 35.0, 43.0)
SIGMA_FIGURE = "damage_maps_sigma.png"
SIGMA_MAP_TIMES_US = (4.0, 5.0, 10.0, 20.0, 43.0)


def damage_maps(workdirs, path, times_us=MAP_TIMES_US):
    """Damage maps of the runs in workdirs ({label: folder}) at times_us, one row per run."""
    with plots.figure(path, len(workdirs), len(times_us), squeeze=False, dpi=130,
                      figsize=(3.2 * len(times_us), 1.45 * len(workdirs) + 0.4)) as (fig, axes):
        for row, (label, work) in zip(axes, workdirs.items()):
            work = Path(work)
            ref = readers.read_dump(work / "ref.dump")
            pos = dict(zip(ref["id"].astype(int), zip(ref["x"], ref["y"])))
            out = (work / "log.lammps").read_text()
            dt = float(out.split("CRACK-BRANCHING:")[-1].split(" dt ")[1].split()[0])
            snaps = readers.dump_snapshots(work / "damage.dump")
            for ax, t_us in zip(row, times_us):
                step, cols = min(snaps, key=lambda s: abs(s[0] * dt * 1e6 - t_us))
                xy = np.array([pos[int(i)] for i in cols["id"]]) * 1e3
                ax.scatter(xy[:, 0], xy[:, 1], c=cols["c_damage"], s=0.3, cmap="inferno_r",
                           vmin=0.0, vmax=0.6, marker="s", linewidths=0)
                ax.set(xlim=(-50, 50), ylim=(-20, 20), aspect="equal", xticks=[], yticks=[])
                ax.set_title(f"{label}, t = {step * dt * 1e6:.0f} µs", fontsize=7)
    return Path(path)


KERNEL_SEPARATION = 2.0   # a kernel effect must exceed this many times the change from m = 3 to 4


def split_convergence(rows, sigma=2.0):
    """The fork at sigma (MPa), delta = 1 mm: how far it moves from m = 3 to 4 kernel by kernel
    (the largest, 'dx_m' mm and 'dt_m' us) against how far the kernels' forks lie apart at m = 4
    ('dx_k', 'dt_k'); 'separated' when the kernels differ by more than KERNEL_SEPARATION times
    that change in both x and t (the kernel then moves the split)"""
    by = {r["run"]: r for r in rows}
    base = [by[f"{k}-s{sigma:g}-m4"] for k in KERNELS if f"{k}-s{sigma:g}-m4" in by]
    pairs = [(by[f"{a['kernel']}-s{sigma:g}-m3"], a) for a in base if f"{a['kernel']}-s{sigma:g}-m3" in by]
    if not pairs:
        return None
    out = dict(dx_m=max(abs(a["x_split_mm"] - b["x_split_mm"]) for b, a in pairs),
               dt_m=max(abs(a["t_split_us"] - b["t_split_us"]) for b, a in pairs),
               dx_k=max(r["x_split_mm"] for r in base) - min(r["x_split_mm"] for r in base),
               dt_k=max(r["t_split_us"] for r in base) - min(r["t_split_us"] for r in base))
    out["separated"] = (out["dx_k"] > KERNEL_SEPARATION * out["dx_m"]
                        and out["dt_k"] > KERNEL_SEPARATION * out["dt_m"])
    return out


def cost_table(rows):
    """Work against precision at 2 MPa: per kernel and resolution, the loop time and the
    distance of the split (x, t) from that of the kernel's finest run (not an error: the
    finest run is not converged, see the findings)."""
    by, out = {r["run"]: r for r in rows}, []
    for k in KERNELS:
        runs = [by[n] for n in (f"{k}-s2-m3", f"{k}-s2-m4", f"{k}-s2-m4-d0.5") if n in by]
        finest = min(runs, key=lambda r: r["dx_mm"], default=None)
        out += [[k, f"δ = {r['delta_mm']:g} mm, m = {r['m']:g}", int(r["atoms"]), f"{r['loop_s']:.0f}",
                 f"{r['x_split_mm'] - finest['x_split_mm']:+.2f}",
                 f"{r['t_split_us'] - finest['t_split_us']:+.2f}"] for r in runs]
    return md_table(["kernel", "resolution", "atoms", "loop (s)", "x_split − finest (mm)",
                     "t_split − finest (µs)"], out)


# --------------------------------------------------------------------------- report

REPORT_TITLE = "Crack branching in glass (Ha & Bobaru 2010; Bobaru & Zhang 2015)"
REPORT_SETUP = ("Plate 100 x 40 mm, notch from the left edge to the centre along y = 0, soda-lime "
                "glass (E = 72 GPa, rho = 2440 kg/m^3, G_0 = 3.8 J/m^2), plane stress, traction "
                "sigma held from t = 0 on the top and bottom rows, no-fail bands one horizon wide "
                "along them, 43 us; tips, splits and speeds from compute bbpd/crack/tip with "
                "branches yes; c_R = %.0f m/s (the model's, nu = 1/3); see "
                "examples/crack-branching/README.md." % C_R)


# the report's runs: the Gaussian kernel at sigma = 2 MPa, delta = 1 mm, m = 4 (45 s); --full
# adds DEFAULT_RUNS; one single-rank run's wall time (s) by m
REPORT_RUNS = ("gaussian-s2-m4",)
ESTIMATE_S = {4: 60.0, 3: 25.0}


def jobs(full=False):
    """The report's branching runs as bbpd.report specs."""
    inputs = (EXAMPLE, Path(__file__), Path(readers.__file__), Path(freund.__file__),
              Path(__file__).with_name("mode1_propagation.py"))
    return jobmod.report_specs("branching", "bbpd.benchmarks.branching:run", inputs, (
        (RUNS[n][0], RUNS[n][1] / RUNS[n][2], f"crack branching {n}", {"name": n},
         ESTIMATE_S.get(RUNS[n][2], 400.0)) for n in (DEFAULT_RUNS if full else REPORT_RUNS)))


def section(specs, results, figdir, notes):
    """The section of REPORT.md (bbpd.report.document.write_report) from the report's branching runs."""
    def figures(rows):
        maps = {f"{r['kernel']} {r['sigma_MPa']:g} MPa m = {r['m']:g}": r["workdir"] for r in rows
                if Path(r.get("workdir", "")).joinpath("damage.dump").exists()}
        return [damage_maps(maps, Path(figdir) / ("branching_" + FIGURE)).name] if maps else []
    return jobmod.section(REPORT_TITLE, REPORT_SETUP, specs, results, table, lambda rows: [
        f"Experiments on glass: terminal speed about {EXPERIMENT_SPEED_OVER_CR:g} c_R."], figures, notes)


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/bbpd-branching", reuse=True,
                    csv="results CSV (rows of runs not made now are kept)",
                    figures="folder for damage_maps.png (the sigma = 2 MPa, m = 4 runs) and "
                    "damage_maps_sigma.png (the Gaussian at 2, 4, 12 MPa)")
    ap.add_argument("--runs", nargs="+", default=DEFAULT_RUNS, choices=list(RUNS))
    args = ap.parse_args(argv)
    command = cli.command("branching", argv, drop=("--reuse",))
    rows = {}
    if args.csv and Path(args.csv).exists():
        rows = {r["run"]: r for r in read_rows(args.csv)}
    for name in args.runs:
        start = time.perf_counter()
        res = run(name, Path(args.work) / name, reuse=args.reuse)
        rows[name] = res
        print(f"{name:24s} split at t {res['t_split_us']:.1f} us x {res['x_split_mm']:.1f} mm, "
              f"v_pre {res['v_pre']:.0f} m/s ({res['v_pre_over_cR']:.2f} c_R), angle "
              f"{res['angle_deg']:.0f} deg, tips {res['tips_end']}, mirror "
              f"{res['mirror_x_dx']:.0f}/{res['mirror_y_dx']:.0f} dx "
              f"{100 * res['mirror_damage_frac']:.1f} %, loop {res['loop_s']:.1f} s "
              f"(wall {time.perf_counter() - start:.0f} s)", flush=True)
    ordered = [rows[n] for n in RUNS if n in rows]
    if args.csv:
        write_csv(args.csv, ordered, command)
    if args.figures:
        done = {n for n in RUNS if (Path(args.work) / n / "damage.dump").exists()}
        maps = {RUNS[n][0]: Path(args.work) / n for n in RUNS
                if n.endswith("-s2-m4") and n in done}
        if maps:
            damage_maps(maps, Path(args.figures) / FIGURE)
        maps = {f"gaussian, {s} MPa": Path(args.work) / f"gaussian-s{s}-m4" for s in (2, 4, 12)
                if f"gaussian-s{s}-m4" in done}
        if maps:
            damage_maps(maps, Path(args.figures) / SIGMA_FIGURE, SIGMA_MAP_TIMES_US)


if __name__ == "__main__":
    main()

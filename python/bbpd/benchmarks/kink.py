# SPDX-License-Identifier: GPL-2.0-or-later
"""Quasi-static kink test: the angle at which a straight crack under the mixed-mode Williams
field kinks, against the maximum hoop stress, hoop strain and energy release rate criteria
(bbpd.kink). examples/kink-mixed-mode/README.md defines the measures (initiation, kink angle at
2 and 4 delta, extension) and has the commands.
"""

import json
import math
import re
import time
from pathlib import Path

import numpy as np
from matplotlib.lines import Line2D

from bbpd import crack_path, csvfile, kink, plots, readers
from bbpd import jobs as jobmod
from bbpd.jobs import run_jobs
from bbpd.kernels import COLORS, KERNELS
from bbpd.provenance import cpu
from bbpd.runner import run_lammps
from bbpd.markdown import cell
from bbpd.markdown import table as md_table
from bbpd.benchmarks import cli

ROOT = Path(__file__).resolve().parents[3]
FOLDER = ROOT / "examples" / "kink-mixed-mode"
EXAMPLE = FOLDER / "in.kink"
RESULTS = FOLDER / "results" / "kink.csv"

MIXES_DEG = (90.0, 67.5, 45.0, 22.5, 0.0)        # psi = arctan(K_II/K_I)
ALPHAS_DEG = (0.0, 22.5)                          # crack direction to the grid's rows
COARSE = (1.0e-3, 5)                              # dx (m), m = delta/dx: delta = 5 mm
FINE = (0.5e-3, 10)                               # same horizon, half the spacing
FINE_CASES = ((90.0, 0.0), (45.0, 0.0), (0.0, 0.0))   # (psi, alpha)
FINE_KERNEL = "gaussian"
# the fine grid for the other kernels and for the crack at 22.5 deg, in the order they are run
# (the budget may stop the list early: pure Mode II first, where the criteria differ most)
FINE_MORE = tuple((k, p, a) for p in (90.0, 45.0, 0.0)
                  for k, a in (("constant", 0.0), ("triangular", 0.0), (FINE_KERNEL, 22.5),
                               ("constant", 22.5), ("triangular", 22.5)))
# time step in dx/c_d: 0.64 of the velocity-Verlet limit the pair style prints at m = 5 and
# 0.70 at m = 10 (the limit is set by the horizon, not by dx)
DTFACTOR = {5: 0.8, 10: 1.6}
NCROSS = 10.0              # in.kink's default ramp rate: K_c per 10 transit times
RAMP_CHECK = ("gaussian", 45.0, 0.0, 20.0)        # the same case at half the rate
DISTANCES = (2.0, 4.0)                            # where the angle is measured, in horizons
TEST_SE = 2.0       # a mean deviation within 2 standard errors is consistent with zero (about 95 %)
CRITERIA = ("hoop_stress", "hoop_strain", "energy")
CRITERION_NAMES = {"hoop_stress": "max. hoop stress", "hoop_strain": "max. hoop strain",
                   "energy": "max. energy release rate"}
def cases():
    """(kernel, psi, alpha, dx, m, ncross) of the sweep: every kernel, mix and angle on the
    coarse grid; the Gaussian at FINE_CASES on the fine grid; one case at half the ramp rate."""
    out = [(k, p, a) + COARSE + (NCROSS,) for k in KERNELS for a in ALPHAS_DEG for p in MIXES_DEG]
    out += [(FINE_KERNEL, p, a) + FINE + (NCROSS,) for p, a in FINE_CASES]
    out += [(k, p, a) + FINE + (NCROSS,) for k, p, a in FINE_MORE]
    k, p, a, n = RAMP_CHECK
    out.append((k, p, a) + COARSE + (n,))
    return out


# --------------------------------------------------------------------------- one run

def read_log(path):
    text = Path(path).read_text()
    m = re.search(r"^KINK: kernel (\S+) model (\S+) psi (\S+) alpha (\S+) dx (\S+) delta (\S+) "
                  r"R (\S+) dt (\S+) maxsteps (\d+) atoms (\d+) ring (\d+) Kc (\S+) tc (\S+) "
                  r"t1 (\S+) nu (\S+)", text, re.M)
    if not m:
        raise RuntimeError(f"{path}: no 'KINK:' line; was it written by in.kink?")
    keys = ("kernel", "model", "psi", "alpha", "dx", "delta", "R", "dt", "maxsteps", "atoms",
            "ring", "Kc", "tc", "t1", "nu")
    info = {k: (v if k in ("kernel", "model") else float(v)) for k, v in zip(keys, m.groups())}
    info["steps"] = int(re.search(r"^Loop time of \S+ on \d+ procs for (\d+) steps", text, re.M)[1])
    info["halted"] = "Fix halt condition" in text
    info["loop_s"], info["nprocs"] = readers.loop_time(text)
    return info


def analyse(workdir):
    workdir = Path(workdir)
    res = read_log(workdir / "log.lammps")
    data = np.loadtxt(workdir / "tip.dat", comments="#")
    K, dtip = data[:, 1], data[:, 2]    # columns: step, K, tip distance
    rise = np.nonzero(dtip > dtip[0] * (1.0 + 1e-9) + 1e-12)[0]
    res["K_init_over_Kc"] = float(K[rise[0]] / res["Kc"]) if len(rise) else None
    res["K_end_over_Kc"] = float(K[-1] / res["Kc"])
    snap = readers.dump_snapshots(workdir / "final.dump")[-1][1]
    delta, dx = res["delta"], res["dx"]
    dist = [f * delta for f in DISTANCES]
    meas = crack_path.kink_angles(snap["f_ref[1]"], snap["f_ref[2]"], snap["c_dmg"], (0.0, 0.0),
                                  res["alpha"], dx, dist, seed=delta)
    res["extension_over_delta"] = meas["extension"] / delta
    for f, d in zip(DISTANCES, dist):
        a = meas[d]
        res[f"angle_{f:g}d"] = None if a is None else a[0]
        res[f"spread_{f:g}d"] = None if a is None else a[1]
    psi = math.radians(res["psi"])
    KI, KII = (0.0 if res["psi"] == 90.0 else math.cos(psi)), math.sin(psi)
    res.update(kink.criteria_angles(KI, KII, res["nu"], res["model"]))
    return res


def job(workdir, kernel, psi, alpha, dx, m, ncross=NCROSS, nprocs=1):
    """One case, for bbpd.jobs (one rank unless nprocs: the run's bits do not depend on it)."""
    variables = {"kernel": kernel, "psi": repr(psi), "alpha": repr(alpha), "dx": repr(dx),
                 "m": repr(float(m)), "ncross": repr(ncross), "dtfactor": repr(DTFACTOR[m])}
    start = time.perf_counter()
    run_lammps(str(EXAMPLE), workdir, nprocs=nprocs, vars=variables)
    res = analyse(workdir)
    res["wall_s"] = time.perf_counter() - start
    res["ncross"] = ncross
    return res


# the boundary ring's Williams field must produce the intended (K_I, K_II) at the tip: the
# J-integral (compute bbpd/jintegral, default annulus 2-5 delta, inside the free atoms) of the
# intact crack after the fast ramp and one transit time of the slow one (K = 0.6 K_c, before the
# first bond breaks), crack rotated against the grid
LOADING_CASE = dict(kernel="gaussian", psi=30.0, alpha=22.5)
LOADING_JSON = FOLDER / "results" / "loading_check.json"
J_LINES = """compute         J inner bbpd/jintegral tip 0.0 0.0 direction ${ca} ${sa}
variable        nrun equal ceil((${t1}+2.0*${R}/v_cd)/${dt})
thermo_style    custom step time v_K c_J[1] c_J[2] c_J[3] c_dtip
thermo_modify   format float %.10g
run             ${nrun}
"""


def loading_check(workdir):
    """K_I, K_II of the J-integral against the prescribed K(t) (in.kink up to K = 0.6 K_c)."""
    head, _, _ = EXAMPLE.read_text().partition("run             ${nmax}")
    variables = {k: (v if isinstance(v, str) else repr(v)) for k, v in LOADING_CASE.items()}
    out = run_lammps(head + J_LINES, workdir, vars=variables).output
    t = readers.thermo_tables(out)[-1]
    K, KI, KII = (float(t[c][-1]) for c in ("v_K", "c_J[2]", "c_J[3]"))
    return dict(LOADING_CASE, K=K, KI=KI, KII=KII, mix=math.degrees(math.atan2(KII, KI)),
                ratio=math.hypot(KI, KII) / K, intact=bool(t["c_dtip"][-1] == t["c_dtip"][0]))


# --------------------------------------------------------------------------- verdict

def rms(values):
    v = np.asarray([x for x in values if x is not None], dtype=float)
    return float(np.sqrt(np.mean(v**2))) if len(v) else None


def verdict(rows, dist="2d", dx=COARSE[0], cases=None):
    """Numbers behind the README's sentence, from the mixed-mode rows of one grid (psi > 0: in
    pure Mode I every criterion says 0; cases: only these (kernel, psi, alpha)): RMS and mean
    (measured - criterion) with its standard error, for all kernels and angles and per kernel;
    the grid's pull = mean |angle(alpha = 22.5) - angle(alpha = 0)| over
    kernels and mixes; the kernel effect = the spread (max - min) of the angle across the
    kernels at one (mix, alpha)."""
    grid = [r for r in rows if r["dx"] == dx and r["ncross"] == NCROSS]
    key = f"angle_{dist}"
    mixed = [r for r in grid if r["psi"] > 0 and r[key] is not None
             and (cases is None or (r["kernel"], r["psi"], r["alpha"]) in cases)]
    out = {"n": len(mixed), "rms": {}, "bias": {}, "se": {}, "rms_kernel": {}}
    for c in CRITERIA:
        d = np.array([r[key] - r[c] for r in mixed])
        out["rms"][c] = rms(d)
        out["bias"][c] = float(d.mean())
        out["se"][c] = float(d.std(ddof=1) / math.sqrt(len(d))) if len(d) > 1 else math.nan
        for k in KERNELS:
            out["rms_kernel"][k, c] = rms([r[key] - r[c] for r in mixed if r["kernel"] == k])
    out["best"] = min(CRITERIA, key=lambda c: out["rms"][c])
    present = [k for k in KERNELS if out["rms_kernel"][k, CRITERIA[0]] is not None]
    out["best_kernel"] = {k: min(CRITERIA, key=lambda c: out["rms_kernel"][k, c]) for k in present}
    by = {(r["kernel"], r["psi"], r["alpha"]): r[key] for r in mixed}
    pairs = [(k, p) for k in KERNELS for p in MIXES_DEG
             if (k, p, ALPHAS_DEG[1]) in by and (k, p, ALPHAS_DEG[0]) in by]
    pulls = [abs(by[k, p, ALPHAS_DEG[1]] - by[k, p, ALPHAS_DEG[0]]) for k, p in pairs]
    out["pull_mean"] = float(np.mean(pulls)) if pulls else None
    out["pull_max"] = float(np.max(pulls)) if pulls else None
    groups = [(p, a) for p in MIXES_DEG for a in ALPHAS_DEG
              if all((k, p, a) in by for k in KERNELS)]
    spreads = [max(by[k, p, a] for k in KERNELS) - min(by[k, p, a] for k in KERNELS)
               for p, a in groups]
    out["kernel_spread_mean"] = float(np.mean(spreads)) if spreads else None
    out["kernel_spread_max"] = float(np.max(spreads)) if spreads else None
    return out


LOCK_DEG = 1.0     # a kink within this of a lattice direction counts as locked onto it


def admitted(v):
    """The criteria the mean deviation admits: |mean| <= TEST_SE standard errors."""
    return [c for c in CRITERIA if abs(v["bias"][c]) <= TEST_SE * v["se"][c]]


K0_CHECK = FOLDER / "results" / "k0_check.json"
# --------------------------------------------------------------------------- outputs

COLUMNS = ("kernel", "dx_mm", "m", "alpha", "psi", "ncross", "K_init_over_Kc", "K_end_over_Kc",
           "extension_over_delta", "angle_2d", "spread_2d", "angle_4d", "spread_4d",
           "hoop_stress", "hoop_strain", "energy", "halted", "steps", "atoms", "nprocs",
           "wall_s")


def write_csv(rows, path, provenance):
    """provenance: the 'made by' and 'rows added by' lines (csvfile.continue_csv)"""
    csvfile.write_csv(path, rows, [
        *provenance, f"CPU: {cpu()}; nprocs MPI ranks per run (empty: one), on a shared machine "
        "(wall_s); angles in degrees (theta < 0 for K_II > 0), extension in horizons"], COLUMNS)


def read_rows(path):
    """Rows of a CSV written by write_csv, numbers as floats (rounded, so that no -0.0 reaches
    the tables), dx in m."""
    rows = csvfile.read_csv(path)[1]
    for r in rows:
        r.update({k: round(v, 9) + 0.0 for k, v in r.items() if isinstance(v, float)},
                 halted=r["halted"] == "True")
        r["dx"] = r["dx_mm"] * 1e-3
        r["delta"] = r["m"] * r["dx"]
    return rows


def wall_cell(r):
    """The run's wall time (s), with its MPI ranks when more than one."""
    ranks = int(r.get("nprocs") or 1)
    return f"{r['wall_s']:.0f}" + (f" ({ranks} ranks)" if ranks > 1 else "")


def table(rows):
    head = ("kernel", "dx (mm)", "m", "crack to rows (deg)", "psi (deg)", "K at 1st break / K_c",
            "angle at 2 delta", "angle at 4 delta", "hoop stress", "hoop strain", "max G (HPU)",
            "extension (delta)", "ramp (transits per K_c)", "wall (s)")
    return md_table(head, ([
        r["kernel"], f"{r['dx'] * 1e3:g}", f"{round(r['delta'] / r['dx'])}", f"{r['alpha']:g}",
        f"{r['psi']:g}", cell(r["K_init_over_Kc"], ".2f"), cell(r["angle_2d"], ".1f"),
        cell(r["angle_4d"], ".1f"), f"{r['hoop_stress']:.1f}", f"{r['hoop_strain']:.1f}",
        f"{r['energy']:.1f}", f"{r['extension_over_delta']:.1f}", f"{r['ncross']:g}", wall_cell(r)]
        for r in sorted(rows, key=lambda r: (-r["dx"], r["ncross"], KERNELS.index(r["kernel"]),
                                             r["alpha"], -r["psi"]))))


def plot(rows, path):
    psi = np.linspace(0.0, 90.0, 91)
    theory = {c: [kink.criteria_angles(0.0 if p == 90 else math.cos(math.radians(p)),
                                       math.sin(math.radians(p)))[c] for p in psi] for c in CRITERIA}
    with plots.figure(path, 1, 2, figsize=(10, 4.2), sharey=True, dpi=130) as (fig, axes):
        for ax, dist in zip(axes, ("2d", "4d")):
            for g in (-45.0, -90.0):     # a grid diagonal and column seen from a 0-deg crack
                ax.axhline(g, color="grey", lw=0.8, alpha=0.5)
            for c, style in zip(CRITERIA, ("k-", "k--", "k:")):
                ax.plot(psi, theory[c], style, label=CRITERION_NAMES[c])
            for r in rows:
                a = r[f"angle_{dist}"]
                if a is None or r["ncross"] != NCROSS:    # the ramp check is in the text
                    continue
                fine = r["dx"] != COARSE[0]
                marker = ("s" if fine else "o") if r["alpha"] == 0 else ("D" if fine else "^")
                off = {"constant": -1.5, "triangular": 0.0, "gaussian": 1.5}[r["kernel"]]
                ax.plot(r["psi"] + off, a, marker, color=COLORS[r["kernel"]],
                        mfc="none" if fine else COLORS[r["kernel"]], ms=6)
            ax.set_xlabel("mode mix arctan(K_II/K_I) (deg)")
            ax.set_title(f"kink angle at {dist[0]} horizons from the tip", fontsize=10)
            ax.grid(alpha=0.3)
        axes[0].set_ylabel("kink angle theta (deg)")
        handles = [Line2D([], [], color=COLORS[k], marker="o", ls="", label=k) for k in KERNELS]
        handles += [Line2D([], [], color="grey", marker=mk, ls="", mfc=f, label=lab)
                    for mk, f, lab in (("o", "grey", "crack 0 deg, dx 1 mm"),
                                       ("^", "grey", "crack 22.5 deg, dx 1 mm"),
                                       ("s", "none", "crack 0 deg, dx 0.5 mm"),
                                       ("D", "none", "crack 22.5 deg, dx 0.5 mm"))]
        handles.append(Line2D([], [], color="grey", lw=0.8, alpha=0.5,
                              label="grid directions (crack 0 deg)"))
        axes[0].legend(fontsize=7, loc="lower left")
        axes[1].legend(handles=handles, fontsize=7, loc="lower left")


# --------------------------------------------------------------------------- report

REPORT_TITLE = "Quasi-static kink under mixed-mode loading (kink angle against the mode mix)"
REPORT_SETUP = ("A straight crack from the edge to the centre of a disk (R = 50 mm, plane "
                "stress, glass-like, G_c = 8 J/m^2) whose boundary ring follows the leading "
                "Williams field of (K_I, K_II) = K(t) (cos psi, sin psi), K ramped slowly with "
                "damping until the crack has grown 5 horizons; the kink angle is the direction "
                "of the grown crack's centroid at 2 and 4 horizons from the tip (theta < 0 for "
                "K_II > 0), against the maximum hoop stress (Erdogan-Sih), maximum hoop strain "
                "(the model's nu = 1/3) and maximum energy release rate (Hussain-Pu-Underwood) "
                "criteria; delta = 5 mm, dx = 1 mm (m = 5) or 0.5 mm (m = 10); see "
                "examples/kink-mixed-mode/README.md.")
FULL_COVERAGE = (len(KERNELS), len(ALPHAS_DEG))    # kernels and crack angles of the verdict


def locked(rows):
    """The mixed-mode runs whose crack left the tip within LOCK_DEG of a grid direction (a
    multiple of 45 deg in the lattice frame) while more than 2 LOCK_DEG from every criterion"""
    return [r for r in rows if r["psi"] > 0 and r["angle_2d"] is not None
            and abs((r["angle_2d"] + r["alpha"] + 22.5) % 45.0 - 22.5) <= LOCK_DEG
            and min(abs(r["angle_2d"] - r[c]) for c in CRITERIA) > 2 * LOCK_DEG]


def verdict_table(rows):
    """verdict() per grid and distance from the tip as a table: the README's verdict, and
    REPORT.md's over the runs the report made."""
    out = []
    for dx in sorted({r["dx"] for r in rows if r["ncross"] == NCROSS}, reverse=True):
        for dist in ("2d", "4d"):
            v = verdict(rows, dist, dx=dx)
            if v["n"] < 2:
                continue
            out.append([f"{dx * 1e3:g}", dist[0], v["n"],
                        *(f"{v['rms'][c]:.1f} ({v['bias'][c]:+.1f} ± {v['se'][c]:.1f})"
                          for c in CRITERIA),
                        CRITERION_NAMES[v["best"]],
                        ", ".join(CRITERION_NAMES[c] for c in admitted(v)) or "none",
                        "; ".join(f"{k} {CRITERION_NAMES[c]}" for k, c in v["best_kernel"].items()),
                        f"{cell(v['pull_mean'], '.1f')} ({cell(v['pull_max'], '.1f')})",
                        f"{cell(v['kernel_spread_mean'], '.1f')} "
                        f"({cell(v['kernel_spread_max'], '.1f')})"])
    head = ("dx (mm)", "horizons from the tip", "mixed-mode runs",
            *(f"{CRITERION_NAMES[c]}: RMS (mean ± s.e.), deg" for c in CRITERIA), "nearest",
            "within 2 s.e.", "nearest per kernel", "crack 0 -> 22.5 deg to the rows: change, "
            "mean (max), deg", "kernels' spread at one case, mean (max), deg")
    return md_table(head, out)


def whole_sweep(rows):
    """Every kernel and crack direction of the coarse sweep ran: the verdict needs them all."""
    coarse = [r for r in rows if r["ncross"] == NCROSS and r["dx"] == COARSE[0]]
    return (len({r["kernel"] for r in coarse}), len({r["alpha"] for r in coarse})) == FULL_COVERAGE


# REPORT.md's lines under the tables: the runs locked onto a grid direction, and, without the
# whole coarse sweep, where the verdict is
LOCKED = ("On a grid direction (within {0:g} deg of a multiple of 45 deg in the lattice frame, "
          "more than {1:g} deg from every criterion): {2}.")
TOO_FEW = ("Too few runs for a verdict between the criteria: `tools/reproduce --full` runs the "
           "whole sweep, whose verdict is in examples/kink-mixed-mode/README.md.")


def summary_text(rows):
    stuck = "; ".join(f"{r['kernel']} dx {r['dx'] * 1e3:g} mm, crack {r['alpha']:g} deg, psi "
                      f"{r['psi']:g} deg: {r['angle_2d']:.1f} deg"
                      for r in locked([r for r in rows if r["ncross"] == NCROSS]))
    return ([LOCKED.format(LOCK_DEG, 2 * LOCK_DEG, stuck)] if stuck else []) + (
        [] if whole_sweep(rows) else [TOO_FEW])


def section(specs, results, figdir, notes):
    """The section of REPORT.md (bbpd.report.document.write_report) from the report's kink runs."""
    def figure(rows):
        plot(rows, Path(figdir) / "kink_angle.png")
        return ["kink_angle.png"]
    return jobmod.section(REPORT_TITLE, REPORT_SETUP, specs, results,
                          lambda rows: table(rows) + "\n\n" + verdict_table(rows), summary_text,
                          figure, notes)


ESTIMATE_S = {COARSE[0]: 20.0, FINE[0]: 600.0}    # one single-rank run (s), by dx


def jobs(cases, nprocs=1):
    """The runs of cases [(kernel, psi, alpha, dx, m, ncross)] as bbpd.report specs (the report's
    and this module's command); nprocs: ranks of each run (the bits do not depend on it)."""
    inputs = (EXAMPLE, Path(__file__), Path(kink.__file__), Path(crack_path.__file__),
              Path(readers.__file__))
    extra = {"nprocs": nprocs} if nprocs > 1 else {}
    return jobmod.report_specs("kink", "bbpd.benchmarks.kink:job", inputs, (
        (k, dx, f"kink {k} dx = {dx * 1e3:g} mm psi = {p:g} crack at {a:g} deg"
         + ("" if n == NCROSS else f" ramp {n:g} transits per K_c"),
         dict(kernel=k, psi=p, alpha=a, dx=dx, m=m, ncross=n, **extra), ESTIMATE_S[dx])
        for k, p, a, dx, m, n in cases))


def case_key(r):
    """What identifies a row: kernel, mix, crack angle, grid and ramp."""
    return (r["kernel"], float(r["psi"]), float(r["alpha"]), round(float(r["dx_mm"]), 9),
            float(r["ncross"]))


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/kink", nprocs=1, kernels=KERNELS)
    ap.add_argument("--workers", type=int, default=2, help="runs at a time")
    grids = ap.add_mutually_exclusive_group()
    grids.add_argument("--coarse-only", action="store_true")
    grids.add_argument("--fine-only", action="store_true")
    ap.add_argument("--max-runs", type=int, help="the first N cases of the selection only")
    ap.add_argument("--add-missing", action="store_true",
                    help="run only the selected cases that --results lacks and add their rows "
                         "to it (the loading check is not repeated)")
    ap.add_argument("--from-csv", action="store_true",
                    help="run nothing: the figure from --results as it is")
    ap.add_argument("--results", default=str(RESULTS), help="CSV to write")
    ap.add_argument("--figure", default=str(FOLDER / "kink_angle.png"), help="PNG to write")
    args = ap.parse_args(argv)
    if args.from_csv:
        return plot(read_rows(args.results), Path(args.figure))
    todo = [c for c in cases() if not (args.coarse_only and c[3] != COARSE[0])
            and not (args.fine_only and c[3] != FINE[0]) and c[0] in args.kernels]
    todo.sort(key=lambda c: (-c[3], c[5]))    # the coarse grid first, the ramp check last
    path = Path(args.results)
    earlier, old, made = csvfile.continue_csv(path if args.add_missing else None,
                                              cli.command("kink", argv).strip(), read_rows)
    have = {case_key(r) for r in old}
    todo = [c for c in todo if (c[0], c[1], c[2], round(c[3] * 1e3, 9), c[5]) not in have]
    todo = todo[:args.max_runs]
    specs = jobs(todo, args.nprocs)
    results = run_jobs([sp.job for sp in specs], args.work, workers=args.workers)
    done, failed = jobmod.finished(specs, results)
    rows = [{**res, "dx_mm": res["dx"] * 1e3, "m": round(res["delta"] / res["dx"])}
            for res in (results[sp.job.label] for sp in done)]
    if failed:
        print("FAILED:", failed)
    mine = {case_key(r) for r in rows}
    write_csv([r for r in old if case_key(r) not in mine] + rows, path, [*earlier, made])
    if not args.add_missing:
        check = loading_check(Path(args.work) / "loading-check")
        print(f"J-integral check: {check}")
        path.with_name(LOADING_JSON.name).write_text(json.dumps(check, indent=1) + "\n")
    plot(read_rows(args.results), Path(args.figure))
    print(table(read_rows(args.results)))


if __name__ == "__main__":
    main()

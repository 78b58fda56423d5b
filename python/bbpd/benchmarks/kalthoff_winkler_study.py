# SPDX-License-Identifier: GPL-2.0-or-later
"""Kalthoff-Winkler loading study: which loading (CASES) and which angle measure reproduce the
experiment's 70 deg and the paper's 20-22 us (examples/kalthoff-winkler/README.md, "Loading
study", defines the measures and has the commands).
"""

import json
import math
from pathlib import Path

from bbpd import csvfile
from bbpd import jobs as jobmod
from bbpd import readers
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.kernels import COLORS
from bbpd.runner import run_noted
from bbpd import markdown
from bbpd.markdown import cell as f
from bbpd import plots
from bbpd.benchmarks import cli

C_BAR = math.sqrt(kw.E / kw.RHO)          # bar (1D) wave speed in the projectile

# Projectile of the experiment: a steel cylinder of the plate's steel, 50 mm long (Kalthoff &
# Winkler 1988, as quoted in the later literature; the paper gives no projectile).  The two
# bodies have the same impedance, so the contact face moves at v0/2 and the projectile
# separates when the compressive wave has run to its rear face and back: t_c = 2 L / c_bar.
PROJECTILE_LENGTH = 0.050
T_CONTACT = 2.0 * PROJECTILE_LENGTH / C_BAR    # ~20.3 us

TEND = 100.0e-6          # s: every study run (cracks at 70 us have not all reached the edge)
ANGLE_TARGET_DEG, ANGLE_TOL_DEG = kw.EXPERIMENT_ANGLE_DEG, 2.0
INIT_WINDOW_US = (20.0, 22.0)       # the paper's initiation times 20.0-21.7 us

# The loadings: name -> (description, input-script variables).  "layer": "dx" means one column
# of atoms (x < dx).  Every case runs to TEND.
CASES = {
    "paper": ("paper: 32 m/s held, layer delta", {}),
    "v24": ("24 m/s held", {"v0": 24.0}),
    "v20": ("20 m/s held", {"v0": 20.0}),
    "v16": ("16 m/s held (contact velocity v0/2)", {"v0": 16.0}),
    "v16ramp": ("16 m/s, 1 us ramp, held", {"v0": 16.0, "tramp": 1.0e-6}),
    "v32release": (f"32 m/s released at t_c = {T_CONTACT * 1e6:.1f} us",
                   {"v0": 32.0, "thold": T_CONTACT}),
    "thin": ("32 m/s held, layer dx (one column)", {"layer": "dx"}),
    "contact": (f"16 m/s, 1 us ramp, released at t_c = {T_CONTACT * 1e6:.1f} us",
                {"v0": 16.0, "tramp": 1.0e-6, "thold": T_CONTACT}),
}
STUDY_KERNEL_DX = [(k, 1.0e-3) for k in kw.KERNELS] + [("gaussian", 0.5e-3)]


# ---------------------------------------------------------------------------- running

def run_case(workdir, kernel, dx, case, nprocs=1, tend=TEND):
    """Run one loading case in workdir and measure it (the job of the study and the report)."""
    extra = {k: float(dx) if v == "dx" else float(v) for k, v in CASES[case][1].items()}
    note = run_noted(kw.EXAMPLE, workdir, kw.variables(kernel, dx, tend=tend, **extra),
                     {"case": case, "kernel": kernel, "dx": dx}, nprocs)
    res = kw.analyse(workdir)
    res.update(case=case, wall_s=note["wall_s"])
    return res


# ---------------------------------------------------------------------------- verdicts

def angle(res, definition):
    """The angle of one definition as the verdicts use it: initial, or fit/chord at 70 us;
    None for a crack shorter than kw.INITIAL_RANGE[1] at 70 us (its direction is no path)."""
    if (res.get("length_t70_mm") or 0.0) < kw.INITIAL_RANGE[1] * 1e3:
        return None
    return res.get("initial_deg") if definition == "initial" else res.get(f"{definition}_t70_deg")


def hits(results):
    """{'angle': [(case, kernel, dx, definitions)] of the runs at 70 +- 2 deg, 'initiation':
    [(case, kernel, dx, readings)] in the paper's window, 'both': [(case, kernel, dx)]}"""
    out = {"angle": [], "initiation": [], "both": []}
    for (case, k, dx), r in sorted(results.items(), key=_order):
        defs = [d for d in kw.ANGLE_DEFS if (a := angle(r, d)) is not None
                and abs(a - ANGLE_TARGET_DEG) <= ANGLE_TOL_DEG]
        inits = [n for n, key in (("first bond", "t_init_us"), ("damage band", "t_band_us"))
                 if r[key] is not None and INIT_WINDOW_US[0] <= r[key] <= INIT_WINDOW_US[1]]
        out["angle"] += [(case, k, dx, defs)] if defs else []
        out["initiation"] += [(case, k, dx, inits)] if inits else []
        out["both"] += [(case, k, dx)] if defs and inits else []
    return out


def conclusion(results):
    """REPORT.md's lines under the study's table: hits() filled into fixed templates"""
    h = hits(results)

    def runs(items):
        return "; ".join(f"{c} ({k}, {dx * 1e3:g} mm)" + (f": {', '.join(x[0])}" if x else "")
                         for c, k, dx, *x in items) or "no run"
    return [f"Angle 70 +- 2 deg (initial; fit and chord at {kw.T_EVAL_US:.0f} us): {runs(h['angle'])}.",
            f"Initiation in {INIT_WINDOW_US[0]:.0f}-{INIT_WINDOW_US[1]:.0f} us: {runs(h['initiation'])}.",
            f"Both at once: {runs(h['both'])}."]


def _order(item):
    (case, k, dx), _ = item
    return (list(CASES).index(case), -dx, kw.KERNELS.index(k))


# ---------------------------------------------------------------------------- table, figures

TABLE_HEADER = ["loading", "kernel", "dx (mm)", "first bond (us)", "damage band (us)",
                "initial (deg)", "fit 10-50 mm (deg)", "chord (deg)", "fit at end (deg)",
                "chord at end (deg)", "length at 70 us (mm)", "crack stops (us)",
                "speed / c_R (mean, peak)", "far-edge crack (us; abs(y - 100) mm)",
                "tip mismatch (mm)",
                "run time (s)"]


def table_rows(results):
    rows = []
    for (case, k, dx), r in sorted(results.items(), key=_order):
        far = "none"
        if r.get("far_edge_own_us") is not None:
            y = r["far_edge_y_mm"]
            far = f"{r['far_edge_own_us']:.0f}; {y[0]:.0f}-{y[1]:.0f}"
        rows.append([case, k, f"{dx * 1e3:g}", f(r["t_init_us"], ".1f"), f(r["t_band_us"], ".1f"),
                     f(r.get("initial_deg"), ".1f"), f(r.get("fit_t70_deg"), ".1f"),
                     f(r.get("chord_t70_deg"), ".1f"), f(r.get("fit_end_deg"), ".1f"),
                     f(r.get("chord_end_deg"), ".1f"), f(r.get("length_t70_mm"), ".0f"),
                     stops(r),
                     f"{f(r.get('speed_over_cR'), '.2f')}, {f(r.get('speed_peak_over_cR'), '.2f')}",
                     far, f"{r['symmetry_tip_mm']:.2g}", f(r.get("wall_s"), ".0f")])
    return rows


def stops(r):
    """How the crack ends: at the plate edge (time), arrested (time, length), or running."""
    if r.get("t_edge_us") is not None:
        return f"edge {r['t_edge_us']:.0f}"
    if r.get("t_arrest_us") is not None:
        return f"arrest {r['t_arrest_us']:.0f} ({r['length_end_mm']:.0f} mm)"
    return f"running ({r.get('length_end_mm', 0.0):.0f} mm)"


CSV = kw.ROOT / "examples" / "kalthoff-winkler" / "results" / "study.csv"


def write_csv(path, rows, command):
    csvfile.write_csv(path, [dict(zip(TABLE_HEADER, r)) for r in rows], [f"made by: {command}"],
                      TABLE_HEADER, TABLE_HEADER)


def read_csv(path=CSV):
    rows = csvfile.read_csv(path, TABLE_HEADER)[1]
    return [[r[c] for c in TABLE_HEADER] for r in rows], csvfile.provenance(path)


def cases_table():
    rows = [[name, desc, f"{v.get('v0', 32.0):g}", f"{v.get('tramp', 0.0) * 1e6:g}",
             f"{v['thold'] * 1e6:.1f}" if "thold" in v else "held",
             "dx" if v.get("layer") == "dx" else "delta = 5 dx"] for name, (desc, v) in CASES.items()]
    return markdown.table(["case", "loading", "v0 (m/s)", "ramp (us)", "released at (us)", "layer"],
                          rows)


def plot_paths_case(results, case, path):
    """Crack-tip paths of one loading for every kernel/resolution, with the 70-degree line."""
    runs = [(f"{k} {dx * 1e3:g} mm ({f(r.get('fit_t70_deg'), '.1f')} deg)", r,
             "-" if dx >= 1e-3 - 1e-12 else ":", COLORS[k])
            for (c, k, dx), r in sorted(results.items(), key=_order) if c == case]
    g = runs[0][1]
    return kw.plot_paths(runs, path, f"{CASES[case][0]}, to {g['nsteps'] * g['dt'] * 1e6:.0f} us",
                         fontsize=6)


def plot_damage_cases(results, kernel, dx, path):
    """Damage at the end of the run for every loading of one kernel and resolution."""
    runs = [(c, r) for (c, k, d), r in sorted(results.items(), key=_order)
            if k == kernel and abs(d - dx) < 1e-12]
    with plots.figure(path, 1, len(runs), figsize=(2.0 * len(runs) + 0.8, 4.2), squeeze=False,
                      dpi=130) as (fig, axes):
        for ax, (c, r) in zip(axes[0], runs):
            sc = kw.damage_panel(ax, r, 1.0)
            ax.set_title(c, fontsize=8)
            ax.tick_params(labelsize=6)
        fig.colorbar(sc, ax=list(axes[0]), label="damage", shrink=0.8)
        fig.suptitle(f"{kernel}, dx = {dx * 1e3:g} mm, t = "
                     f"{runs[0][1]['nsteps'] * runs[0][1]['dt'] * 1e6:.0f} us", fontsize=9)
    return path


def figures(results, figdir):
    """All study figures; returns their file names."""
    figdir = Path(figdir)
    names = []
    for case in CASES:
        if any(c == case for c, _, _ in results):
            names.append(plot_paths_case(results, case, figdir / f"study_paths_{case}.png").name)
    for k, dx in STUDY_KERNEL_DX:
        if any(kk == k and abs(d - dx) < 1e-12 for _, kk, d in results):
            names.append(plot_damage_cases(results, k, dx,
                                           figdir / f"study_damage_{k}_dx{dx * 1e3:g}mm.png").name)
    return names


# ---------------------------------------------------------------------------- jobs, report

def jobs(nprocs=1):
    """The study's runs as bbpd.report specs (the report's --full and this module's command)."""
    inputs = (kw.EXAMPLE, Path(kw.__file__), Path(__file__),
              kw.ROOT / "potentials" / "kalthoff_winkler_steel.bbpd", Path(readers.__file__))
    return jobmod.report_specs(
        "kwstudy", "bbpd.benchmarks.kalthoff_winkler_study:run_case", inputs,
        ((k, dx, f"Kalthoff-Winkler study {case} {k} dx = {dx * 1e3:g} mm",
          {"kernel": k, "dx": dx, "case": case, "nprocs": nprocs}, 500.0 if dx < 1e-3 else 90.0)
         for case in CASES for k, dx in STUDY_KERNEL_DX))


def collect(specs, results):
    """{(case, kernel, dx): result} of the finished runs among specs."""
    return {(s.job.kwargs["args"]["case"], s.kernel, s.dx): results[s.job.label]
            for s in jobmod.finished(specs, results)[0]}


def section(specs, results, figdir, notes):
    """The study's section of report/REPORT.md (bbpd.report.document.write_report)."""
    done = collect(specs, results)
    return jobmod.section(
        "Kalthoff-Winkler loading study (what reproduces 70 deg and 20-22 us)",
        cases_table() + "\n\nEvery run to 100 us; angles at 70 us unless 'at end' (100 us), "
        f"projectile contact time t_c = 2 L / c_bar = {T_CONTACT * 1e6:.1f} us (L = 50 mm), "
        f"Rayleigh speed c_R = {kw.C_R:.0f} m/s; the measures are defined in "
        "examples/kalthoff-winkler/README.md, 'Loading study'.",
        specs, results, lambda rows: markdown.table(TABLE_HEADER, table_rows(done)),
        lambda rows: conclusion(done), lambda rows: figures(done, figdir), notes,
        not_run="Not run by default (32 runs, about 1 h of single-core run time): "
        "`tools/reproduce --full` runs it; the last measured table is in "
        "examples/kalthoff-winkler/README.md, 'Loading study'.")


def main_study(work, figdir, workers=1, log=print, reuse_only=False, csv=None, command=""):
    """Run (or reuse) the study's runs in work and write study.md, figures and, given
    csv, the table's CSV. reuse_only: re-analyse the finished run folders in work (with this
    code), run nothing."""
    specs = sorted(jobs(), key=lambda s: s.job.estimate_s)   # the 1 mm runs first
    if reuse_only:
        done = {}
        for path in sorted(Path(work).glob("*/case.json")):
            c = json.loads(path.read_text())
            if c["case"] in CASES:
                res = kw.analyse(path.parent)
                res.update(case=c["case"], wall_s=c["wall_s"])
                done[(c["case"], c["kernel"], c["dx"])] = res
    else:
        results = jobmod.run_jobs([s.job for s in specs], work, workers=workers, log=log)
        done = collect(specs, results)
    figdir = Path(figdir)
    figdir.mkdir(parents=True, exist_ok=True)
    figures(done, figdir)
    text = markdown.table(TABLE_HEADER, table_rows(done)) + "\n\n" + "\n".join(f"- {s}" for s in conclusion(done))
    (Path(work) / "study.md").write_text(cases_table() + "\n\n" + text + "\n")
    if csv:
        write_csv(csv, table_rows(done), command)
    log(text)
    return done


def main(argv=None):
    args = cli.parser(__doc__, "/tmp/kw-study", figures="write the PNGs here (default: --work)",
                      reuse=True, csv="write the table's CSV here (the README's table comes from "
                      "it through tools/python -m bbpd.claims --write)").parse_args(argv)
    main_study(Path(args.work), Path(args.figures or args.work), reuse_only=args.reuse,
               csv=args.csv, command=cli.command("kalthoff_winkler_study", argv))


if __name__ == "__main__":
    main()

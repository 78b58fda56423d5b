# SPDX-License-Identifier: GPL-2.0-or-later
"""Kalthoff-Winkler struck by the experiment's projectile, for the steel's published
toughness values (GC_VALUES): the loading study's angles and the contact measures of
projectile.dat (examples/kalthoff-winkler/README.md, "Projectile and toughness", defines each
and has the commands).
"""

import itertools
import json
import math
import re
from pathlib import Path

import numpy as np

from bbpd import csvfile, readers
from bbpd import jobs as jobmod
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import kalthoff_winkler_study as study
from bbpd.runner import run_noted
from bbpd import plots
from bbpd.markdown import columns
from bbpd.benchmarks import cli

# ---------------------------------------------------------------------------- physics

EXAMPLE_3D = kw.EXAMPLE.with_name("in.kalthoff_winkler_3d")
V0 = 32.0                                   # m/s, the experiment's impact velocity
# experiment (Kalthoff & Winkler 1988): projectile 50 mm in diameter; plate 9 mm thick, struck
# between notches 50 mm apart. The 2D projectile's E and rho carry this ratio (input script).
AREA_RATIO = math.pi * 0.025 ** 2 / (0.050 * 0.009)       # 4.363
V_INTERFACE = V0 * AREA_RATIO / (AREA_RATIO + 1.0)         # 26.03 m/s (1D two-bar)
# the projectile's waves: E and rho scaled alike keep the plate's speeds (plane strain, nu = 1/4)
C_P = kw.C_P                                              # 5407 m/s, plane wave
C_STRIP = math.sqrt(kw.E / (1.0 - kw.NU ** 2) / kw.RHO)   # 5097 m/s, plane-strain strip

# the interface speed is averaged from the end of the contact's rise to the return of the
# plate's wave from the notch tips (2 x 50 mm / c_p = 18.5 us), where the struck strip widens
INTERFACE_WINDOW_US = (2.0, 2.0 * 0.050 / C_P * 1e6)
OPEN_FRACTION = 1.0e-9
OPEN_MIN_US = 1.0
# J/m^2: the paper; K_Ic = 90 MPa sqrt(m) with E = 191 GPa; phase-field decks after Borden et al. 2012
GC_VALUES = {"paper": 6.9e4, "KIc90": 4.24e4, "phasefield": 2.213e4}
TEND = 100.0e-6


# ---------------------------------------------------------------------------- measurements

def read_projectile(path):
    """projectile.dat: step, x momentum (plate, projectile, both), y momentum, contact force on
    the projectile, mean vx and x of the plate's face column and of the projectile's front."""
    d = np.loadtxt(path, comments="#")
    names = ("step", "px_plate", "px_proj", "px", "py", "force", "v_plate", "v_proj",
             "x_plate", "x_proj")
    return {n: d[:, k] for k, n in enumerate(names)}


def measure_contact(d, dt):
    """The contact measures (README, "Projectile and toughness") from read_projectile's columns."""
    t = d["step"] * dt * 1e6
    p0 = d["px"][0]
    out = {"momentum_drift": float(np.max(np.abs(d["px"] - p0)) / abs(p0)),
           "momentum_y": float(np.max(np.abs(d["py"])) / abs(p0))}
    win = (t >= INTERFACE_WINDOW_US[0]) & (t <= INTERFACE_WINDOW_US[1])
    out["v_plate_face"] = float(d["v_plate"][win].mean())
    out["v_proj_face"] = float(d["v_proj"][win].mean())
    out["v_interface"] = 0.5 * (out["v_plate_face"] + out["v_proj_face"])
    out["v_interface_theory"] = V_INTERFACE
    f = -d["force"]                                  # the plate pushes the projectile back
    plateau = float(f[win].mean())
    out["force_plateau"] = plateau
    gap = d["x_plate"] - d["x_proj"]
    out["gap_min"] = float(gap.min())
    drop = np.nonzero((t > INTERFACE_WINDOW_US[1]) & (f < 0.5 * plateau))[0]
    out["t_drop_us"] = float(t[drop[0]]) if len(drop) else None
    # open: the first time the force is zero and stays zero for OPEN_MIN_US (shorter gaps are
    # the faces chattering); touch again: the first nonzero force after that
    touching = np.abs(f) >= OPEN_FRACTION * np.abs(f).max()
    out["t_open_us"], out["t_retouch_us"] = None, None
    for k in np.nonzero((t > INTERFACE_WINDOW_US[1]) & ~touching)[0]:
        later = np.nonzero(touching[k:])[0]
        end = t[k + later[0]] if len(later) else np.inf
        if end - t[k] >= OPEN_MIN_US or not len(later):
            out["t_open_us"] = float(t[k])
            out["t_retouch_us"] = None if not len(later) else float(end)
            break
    out["px_plate_end"] = float(d["px_plate"][-1] / p0)
    return out


def loop_cpu(text):
    """CPU seconds of the run's loop, all ranks: LAMMPS's loop (wall) time x its CPU use.
    On a shared machine the wall time follows the load; the CPU time much less."""
    loop, use = readers.loop_time(text)[0], re.search(r"([0-9.]+)% CPU use with (\d+) MPI tasks", text)
    return None if loop is None or use is None else loop * float(use[1]) / 100.0 * int(use[2])


def analyse(workdir):
    """The study's measures plus, for a projectile run, the contact measures."""
    workdir = Path(workdir)
    res = kw.analyse(workdir)
    log = (workdir / "log.lammps").read_text()
    proj = re.search(r"^KW projectile: Lp (\S+) \((\d+) columns\)", log, re.M)
    res["loading"] = "prescribed" if proj is None else "projectile"
    res["setup"] = "3d" if re.search(r"^KW 3d:", log, re.M) else "2d"
    res["loop_cpu_s"] = loop_cpu(log)
    m = re.search(r"types 1 1: E = \S+\s+Gc = (\S+)", log)
    res["Gc"] = float(m[1]) if m else None
    if proj is not None:
        res.update(Lp=float(proj[1]), ncol=int(proj[2]), Lp_effective=int(proj[2]) * res["dx"])
        res.update(measure_contact(read_projectile(workdir / "projectile.dat"), res["dt"]))
        # the contact stress: force over the struck face (width between the notch lines x
        # thickness: dx in 2D, one layer of cells; the plate's in 3D)
        m3 = re.search(r"^KW 3d: thickness (\S+)", log, re.M)
        thick = float(m3[1]) if m3 else res["dx"]
        res["contact_stress_MPa"] = res["force_plateau"] / ((res["yhi"] - res["ylo"]) * thick) / 1e6
        # the faces' largest overlap past the contact distance, in grid spacings
        res["overlap_max_dx"] = (0.9 * res["dx"] - res["gap_min"]) / res["dx"]
        # 2 Lp / c of the projectile (us) with the plane-wave and the strip speed
        res["two_l_over_c_us"] = tuple(2.0 * res["Lp_effective"] / c * 1e6 for c in (C_P, C_STRIP))
    return res


# ---------------------------------------------------------------------------- running

def run_case(workdir, kernel, dx, loading, gc, nprocs=1, tend=TEND, lp=None, reuse=False,
             dim=2):
    """Run one case in workdir (unless reuse and it has finished) and measure it; dim = 3
    runs in.kalthoff_winkler_3d."""
    variables = kw.variables(kernel, dx, tend=float(tend), loading=loading, Gc=float(gc),
                             Lp=None if lp is None else float(lp))
    case = run_noted(kw.EXAMPLE if dim == 2 else EXAMPLE_3D, workdir, variables,
                     {"kernel": kernel, "dx": dx, "loading": loading, "Gc": gc}, nprocs, reuse)
    res = analyse(workdir)
    res["wall_s"], res["nprocs"] = case["wall_s"], case["nprocs"]
    return res


# ---------------------------------------------------------------------------- figures

def plot_contact(workdir, path):
    """Face velocities and contact force of a projectile run against the two-bar estimate."""
    r = analyse(workdir)
    d = read_projectile(Path(workdir) / "projectile.dat")
    t = d["step"] * r["dt"] * 1e6
    with plots.figure(path, 2, 1, figsize=(6.0, 5.5), sharex=True) as (fig, (a1, a2)):
        a1.plot(t, d["v_proj"], lw=0.8, label="projectile front column")
        a1.plot(t, d["v_plate"], lw=0.8, label="plate's struck column")
        a1.axhline(V_INTERFACE, color="k", ls="--", lw=1,
                   label=f"two-bar estimate {V_INTERFACE:.2f} m/s")
        a1.set_ylabel("x velocity (m/s)")
        a1.legend(fontsize=7)
        a2.plot(t, -d["force"] / 1e3, lw=0.8, color="tab:red")
        for x, name, h in zip(r["two_l_over_c_us"], ("2Lp/c_p", "2Lp/c_strip"), (0.92, 0.82)):
            a2.axvline(x, color="k", ls=":", lw=1)
            a2.text(x, a2.get_ylim()[1] * h, " " + name, fontsize=7)
        if r["t_open_us"] is not None:
            a2.axvline(r["t_open_us"], color="tab:red", ls="--", lw=1)
            a2.text(r["t_open_us"], 0.0, f" opens {r['t_open_us']:.1f} us", fontsize=7)
        a2.set_ylabel("contact force (kN)")
        a2.set_xlabel("t (us)")
        a1.set_title(f"projectile, {r['kernel']}, dx = {r['dx'] * 1e3:g} mm, "
                     f"Gc = {r['Gc']:g} J/m2", fontsize=9)
    return path


# ---------------------------------------------------------------------------- table

COLUMNS = ("setup", "loading", "kernel", "dx_mm", "Gc", "first_bond_us", "band_us", "initial_deg",
           "fit_deg", "chord_deg", "length_end_mm", "crack_stops", "far_edge_us",
           "v_interface", "contact_stress_MPa", "overlap_max_dx", "t_drop_us", "t_open_us",
           "t_retouch_us", "momentum_drift", "tip_mismatch_mm", "loop_cpu_s", "nprocs")


def row(r):
    """One CSV row of a result (numbers as measured; None as empty)."""
    stops = study.stops(r).split(" (")[0]
    return {"setup": r["setup"], "loading": r["loading"], "kernel": r["kernel"],
            "dx_mm": r["dx"] * 1e3,
            "Gc": r["Gc"], "first_bond_us": r["t_init_us"], "band_us": r["t_band_us"],
            "initial_deg": study.angle(r, "initial"), "fit_deg": study.angle(r, "fit"),
            "chord_deg": study.angle(r, "chord"), "length_end_mm": r["length_end_mm"],
            "crack_stops": stops, "far_edge_us": r.get("far_edge_own_us"),
            "v_interface": r.get("v_interface"), "contact_stress_MPa": r.get("contact_stress_MPa"),
            "overlap_max_dx": r.get("overlap_max_dx"), "t_drop_us": r.get("t_drop_us"),
            "t_open_us": r.get("t_open_us"), "t_retouch_us": r.get("t_retouch_us"), "momentum_drift": r.get("momentum_drift"),
            "tip_mismatch_mm": r["symmetry_tip_mm"],
            "loop_cpu_s": r["loop_cpu_s"], "nprocs": r["nprocs"]}


def at_target(r):
    """the angle definitions by which a run's crack lies within 70 +- 2 deg, if its cracks cross
    the plate (else none)"""
    return [d for d in ("initial", "fit", "chord") if r["crack_stops"].startswith("edge")
            and r[f"{d}_deg"] is not None
            and abs(r[f"{d}_deg"] - study.ANGLE_TARGET_DEG) <= study.ANGLE_TOL_DEG]


def markdown(rows):
    return columns(rows, (
        ("setup", lambda r: r["setup"].upper()), ("loading", "loading"), ("kernel", "kernel"),
        ("dx (mm)", "dx_mm", "g"), ("Gc (J/m2)", "Gc", "g"), ("first bond (us)", "first_bond_us", ".1f"),
        ("damage band (us)", "band_us", ".1f"), ("initial (deg)", "initial_deg", ".1f"),
        ("fit (deg)", "fit_deg", ".1f"), ("chord (deg)", "chord_deg", ".1f"),
        ("crack length at end (mm)", "length_end_mm", ".0f"), ("crack stops (us)", "crack_stops"),
        ("far-edge crack (us)", "far_edge_us", ".0f"), ("interface speed (m/s)", "v_interface", ".2f"),
        ("contact force drop (us)", "t_drop_us", ".1f"), ("contact opens (us)", "t_open_us", ".1f"),
        ("momentum drift", "momentum_drift", ".1e"), ("loop CPU (s)", "loop_cpu_s", ".0f"),
        ("ranks", "nprocs", "g"), ("70 ± 2° and crosses", lambda r: ", ".join(at_target(r)) or "-")))


# ---------------------------------------------------------------------------- report

# tools/reproduce: the Gaussian at 2 mm by default; --full adds the other kernels and 1 mm
REPORT_CASES = (("gaussian", 2.0e-3),)
REPORT_CASES_FULL = tuple((k, 2.0e-3) for k in kw.KERNELS) + (("gaussian", 1.0e-3),)
REPORT_TITLE = "Kalthoff-Winkler struck by the projectile (the experiment's loading)"


def report_run(workdir, kernel, dx, nprocs=1):
    """One projectile run of the report (paper's G_c, to TEND): its CSV row, the run folder
    and 2 Lp / c."""
    res = run_case(workdir, kernel, dx, "projectile", GC_VALUES["paper"], nprocs=nprocs)
    out = row(res)
    out.update(workdir=str(workdir), two_l_over_c_us=list(res["two_l_over_c_us"]),
               v_interface_theory=res["v_interface_theory"],
               px_plate_end=res["px_plate_end"])
    return out


def jobs(full=False, nprocs=1):
    """The report's projectile runs as bbpd.report specs."""
    inputs = (kw.EXAMPLE, Path(kw.__file__), Path(study.__file__), Path(__file__),
              kw.ROOT / "potentials" / "kalthoff_winkler_steel.bbpd")
    return jobmod.report_specs(
        "kwprojectile", "bbpd.benchmarks.kalthoff_winkler_projectile:report_run", inputs,
        ((kernel, dx, f"Kalthoff-Winkler projectile {kernel} dx = {dx * 1e3:g} mm",
          {"kernel": kernel, "dx": dx, "nprocs": nprocs}, 25.0 if dx > 1.5e-3 else 200.0)
         for kernel, dx in (REPORT_CASES_FULL if full else REPORT_CASES)))


# REPORT.md's line per run under the table (which has the interface speed and when the
# contact opens): both against the two-bar estimates
TWO_BAR = ("{kernel} {dx_mm:g} mm: interface speed {dv:+.1f} % from the two-bar estimate "
           "{v_interface_theory:.2f} m/s; 2 Lp/c = {lo:.1f}-{hi:.1f} us for the contact's opening.")


def report_text(rows):
    return [TWO_BAR.format(dv=(r["v_interface"] / r["v_interface_theory"] - 1.0) * 100.0,
                           lo=r["two_l_over_c_us"][0], hi=r["two_l_over_c_us"][1], **r) for r in rows]


def section(specs, results, figdir, notes):
    """The projectile's section of report/REPORT.md (bbpd.report.document.write_report)."""
    def figures(rows):
        names = [f"kw_projectile_contact_{r['kernel']}_dx{r['dx_mm']:g}mm.png" for r in rows]
        for r, name in zip(rows, names):
            plot_contact(r["workdir"], Path(figdir) / name)
        return names
    return jobmod.section(
        REPORT_TITLE, "The paper's plate (plane strain, m = 5, G_c = 6.9e4 J/m2) struck at 32 m/s "
        "by an elastic steel projectile 100 mm long of type 2 atoms, pushing through contact (no "
        f"bonds between the bodies), its E and rho scaled by the experiment's area ratio "
        f"{AREA_RATIO:.3f}; to {TEND * 1e6:.0f} us. Angles as in the loading study (initial; fit "
        "and chord at 70 us). See examples/kalthoff-winkler/README.md, 'Projectile and toughness'.",
        specs, results,
        markdown,
        report_text, figures, notes)


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/kw-projectile", nprocs=1, kernels=["gaussian"], dx=[2e-3],
                    reuse=True, csv="write every finished run in --work here", figures=True)
    ap.add_argument("--loadings", nargs="+", default=["prescribed", "projectile"])
    ap.add_argument("--gc", nargs="+", type=float, default=list(GC_VALUES.values()))
    ap.add_argument("--dim", type=int, default=2, choices=(2, 3))
    ap.add_argument("--tend", type=float, default=TEND)
    args = ap.parse_args(argv)
    work = Path(args.work)
    for dx, kernel, loading, gc in itertools.product(args.dx, args.kernels, args.loadings, args.gc):
        wd = work / f"{'3d-' if args.dim == 3 else ''}{loading}-{kernel}-dx{dx * 1e3:g}mm-Gc{gc:g}"
        r = run_case(wd, kernel, dx, loading, gc, nprocs=args.nprocs, reuse=args.reuse,
                     dim=args.dim, tend=args.tend)
        print(f"{wd.name}: fit {r.get('fit_t70_deg')} chord {r.get('chord_t70_deg')} "
              f"v_i {r.get('v_interface')} open {r.get('t_open_us')} wall {r['wall_s']:.0f} s",
              flush=True)
    order = {"prescribed": 0, "projectile": 1}
    rows = []
    for p in sorted(work.glob("*/case.json")):
        c = json.loads(p.read_text())
        rows.append(row(run_case(p.parent, c["kernel"], c["dx"], c["loading"], c["Gc"],
                                 reuse=True)))
    rows.sort(key=lambda r: (r["setup"], order[r["loading"]], kw.KERNELS.index(r["kernel"]),
                             -r["dx_mm"], -r["Gc"]))
    if args.csv:
        csvfile.write_csv(args.csv, rows, columns=COLUMNS)
        print(markdown(csvfile.read_csv(args.csv)[1]))
    if args.figures:
        figs = Path(args.figures)
        for p in sorted(work.glob("projectile-*-Gc69000/case.json")):
            plot_contact(p.parent, figs / f"projectile_contact_{p.parent.name.split('-', 1)[1]}.png")
        for kernel, dx in itertools.product(kw.KERNELS, (2e-3, 1e-3)):
            tag = f"{kernel}-dx{dx * 1e3:g}mm"
            runs = [(f"{loading}, Gc {gc:g}", wd) for loading in ("prescribed", "projectile")
                    for gc in GC_VALUES.values()
                    if ((wd := work / f"{loading}-{tag}-Gc{gc:g}") / "case.json").is_file()]
            if len(runs) > 1:
                kw.plot_paths([(n, kw.analyse(d), "-", None) for n, d in runs],
                              figs / f"projectile_paths_{tag}.png",
                              f"crack-tip paths, {kernel}, dx = {dx * 1e3:g} mm")


if __name__ == "__main__":
    main()

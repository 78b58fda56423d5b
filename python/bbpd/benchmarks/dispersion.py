# SPDX-License-Identifier: GPL-2.0-or-later
"""Wave dispersion of a 1D BBPD bar (Bouaraquia & Mabssout 2026, sec. 4.1, Figs. 4-6): omega(k)
measured from examples/dispersion-1d/in.dispersion (bbpd-measure-dispersion) against the
analytic curves of bbpd-dispersion-curves (eq. 29, eq. 31 as printed, eq. 31 with C_v, each
with and without the velocity-Verlet shift); examples/dispersion-1d/README.md defines the
errors and has the commands.
"""

import glob
import json
import math
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
from matplotlib.lines import Line2D

from bbpd import plots, readers
from bbpd.kernels import COLORS, KERNELS
from bbpd.markdown import cell
from bbpd.markdown import table as md_table
from bbpd.csvfile import columns
from bbpd.runner import run_lammps
from bbpd.benchmarks import cli

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "dispersion-1d" / "in.dispersion"

PAPER_M, PAPER_DELTA = 5, 1.0e-3   # Figs. 4-6: m = 5, delta = 1 mm
KDX_RANGE = (0.1, 2.5)             # agreement required up to k dx = 2.5 at least
MIN_POWER = 1.0e-6                 # "carries energy": ridge power relative to the strongest;
                                   # dump round-off (10 digits) sits near 1e-18
TABLE_KDX = (1.0, 2.0, 2.5)        # where the note quotes phase velocities
FINE_POINTS = 3001                 # k samples of the analytic curves for tables and figures


# --------------------------------------------------------------------------- tools

def find_tool(name):
    """Path of a command-line tool of src/tools, built by tools/bootstrap.

    Looks in $BBPD_TOOLS_DIR, build/lammps-$BBPD_LAMMPS_VERSION/src/tools (default version
    20260704), any other build/*/src/tools (newest first), then PATH."""
    candidates = []
    if os.environ.get("BBPD_TOOLS_DIR"):
        candidates.append(Path(os.environ["BBPD_TOOLS_DIR"]) / name)
    version = os.environ.get("BBPD_LAMMPS_VERSION", "20260704")
    candidates.append(ROOT / "build" / f"lammps-{version}" / "src" / "tools" / name)
    others = [Path(p) for p in glob.glob(str(ROOT / "build" / "*" / "src" / "tools" / name))]
    candidates += sorted(others, key=lambda p: p.stat().st_mtime, reverse=True)
    for c in candidates:
        if c.is_file() and os.access(c, os.X_OK):
            return c
    on_path = shutil.which(name)
    if on_path:
        return Path(on_path)
    raise FileNotFoundError(f"{name} is not built: run tools/bootstrap (looked in "
                            f"{', '.join(str(c.parent) for c in candidates[:2])} and PATH)")


def run_tool(name, args, cwd):
    cmd = [str(find_tool(name))] + [str(a) for a in args]
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError(f"{' '.join(cmd)} failed:\n{proc.stdout}{proc.stderr}")
    return proc.stdout


# --------------------------------------------------------------------------- analytic

def analytic_curves(outdir, m, delta, E, rho, dt=0.0, volume_correction=True, points=FINE_POINTS):
    """bbpd-dispersion-curves for every kernel: kernel -> columns (k from 0 to pi/dx)."""
    outdir = Path(outdir)
    args = ["--m", m, "--delta", delta, "--E", E, "--rho", rho, "--points", points,
            "--out", outdir]
    if dt > 0.0:
        args += ["--dt", dt]
    if volume_correction:
        args.append("--volume-correction")
    outdir.mkdir(parents=True, exist_ok=True)
    run_tool("bbpd-dispersion-curves", args, cwd=outdir)
    return {k: columns(outdir / f"dispersion_{k}.csv") for k in KERNELS}


NEGATIVE_TOL = 1.0e-9   # v_g/v below -NEGATIVE_TOL is negative; round-off of exact zeros is not


def negative_intervals(curve, column, tol=NEGATIVE_TOL):
    """k dx intervals where a group velocity column is negative, ends by linear interpolation
    of the sign changes: [[start, end], ...]."""
    kdx, vg = curve["k_dx"], curve[column]
    neg = vg < -tol

    def crossing(i):    # zero of the line through samples i and i + 1
        return float(kdx[i] + (kdx[i + 1] - kdx[i]) * vg[i] / (vg[i] - vg[i + 1]))

    out, start = [], None
    for i in range(len(kdx)):
        if neg[i] and start is None:
            start = crossing(i - 1) if i > 0 else float(kdx[0])
        if start is not None and (not neg[i] or i == len(kdx) - 1):
            out.append([start, crossing(i - 1) if not neg[i] else float(kdx[i])])
            start = None
    return out


def analytic_table(workdir, m=PAPER_M, delta=PAPER_DELTA, E=1.0, rho=1.0):
    """Phase velocity / v at TABLE_KDX and the onset of negative group velocity for each kernel:
    continuous (eq. 29), discrete as printed (eq. 31) and discrete with C_v (pair bbpd)."""
    workdir = Path(workdir)
    paper = analytic_curves(workdir / "analytic-paper", m, delta, E, rho, volume_correction=False)
    cv = analytic_curves(workdir / "analytic-cv", m, delta, E, rho, volume_correction=True)
    table = {}
    for k in KERNELS:
        row = {}
        for label, curve, suffix in (("continuous", paper[k], "continuous"),
                                     ("discrete", paper[k], "discrete"),
                                     ("discrete_cv", cv[k], "discrete")):
            row[label] = {
                "phase": {f"{x:g}": float(np.interp(x, curve["k_dx"], curve["phase_" + suffix]))
                          for x in TABLE_KDX},
                "phase_k0": float(curve["phase_" + suffix][1]),
                "group_negative": negative_intervals(curve, "group_" + suffix),
                "group_min": float(curve["group_" + suffix].min()),
                "group_min_kdx": float(curve["k_dx"][np.argmin(curve["group_" + suffix])]),
            }
        table[k] = row
    return table, paper, cv


# --------------------------------------------------------------------------- measured

RUN_KEYS = {"kernel": str, "natoms": int, "dx": float, "delta": float, "m": float, "E": float,
            "rho": float, "dt": float, "every": int, "nsteps": int}


def read_run_info(output):
    """Parameters from in.dispersion's 'DISPERSION: key value ...' line and the run's log."""
    line = re.search(r"^DISPERSION:(.*)$", output, re.M)
    if not line:
        raise RuntimeError("no 'DISPERSION:' line: was the run made with in.dispersion?")
    words = line[1].split()
    pairs = dict(zip(words[0::2], words[1::2]))
    missing = set(RUN_KEYS) - set(pairs)
    if missing:
        raise RuntimeError(f"'DISPERSION:' line lacks {sorted(missing)}")
    info = {key: conv(pairs[key]) for key, conv in RUN_KEYS.items()}
    builds = re.search(r"^Neighbor list builds = (\d+)", output, re.M)
    info["neighbor_builds"] = int(builds[1]) if builds else None
    info["loop_s"], _ = readers.loop_time(output)
    return info


def check_grid(path, natoms, dx):
    """grid.dump: atom id i + 1 must sit at x_i = (i + 1/2) dx (the FFT tool maps id -> i)."""
    d = np.loadtxt(path, skiprows=9)
    ids, x = d[:, 0].astype(int), d[:, 1]
    expected = (ids - 0.5) * dx
    if len(ids) != natoms or np.max(np.abs(x - expected)) > 1e-6 * dx:
        raise RuntimeError(f"{path}: atom ids do not number the grid in x")


def run_kernel(kernel, workdir, nprocs=1, **lmp_vars):
    """Run in.dispersion for one kernel and measure omega(k): returns (info, measured)."""
    workdir = Path(workdir)
    proc = run_lammps(str(EXAMPLE), workdir, nprocs=nprocs,
                      vars={"kernel": kernel, **lmp_vars})
    info = read_run_info(proc.output)
    check_grid(workdir / "grid.dump", info["natoms"], info["dx"])
    sample_dt = info["dt"] * info["every"]
    run_tool("bbpd-measure-dispersion",
             ["--dx", repr(info["dx"]), "--sample-dt", repr(sample_dt), "--out", "measured.csv",
              "u.dump"], cwd=workdir)
    # the 10-digit text dump is only needed by the FFT tool
    (workdir / "u.dump").unlink()
    return info, columns(workdir / "measured.csv")


def deviation(measured, omega_ref, kdx_range=KDX_RANGE, min_power=MIN_POWER):
    """Max relative deviation of the measured ridge from omega_ref (same k grid) over the
    energetic k in kdx_range: dict(max, at_kdx, points, energetic_up_to)."""
    kdx = measured["k_dx"]
    energetic = measured["power"] >= min_power
    sel = energetic & (kdx >= kdx_range[0]) & (kdx <= kdx_range[1] + 1e-12)
    rel = np.abs(measured["omega"][sel] / omega_ref[sel] - 1.0)
    i = int(np.argmax(rel)) if len(rel) else None
    return {"max": float(rel[i]) if len(rel) else math.nan,
            "at_kdx": float(kdx[sel][i]) if len(rel) else math.nan,
            "points": int(sel.sum()),
            "energetic_up_to": float(kdx[energetic].max()) if energetic.any() else 0.0}


def analytic_on_grid(workdir, info, dt=None):
    """Analytic curves on the measured k grid k_n = 2 pi n/(natoms dx): points = natoms/2 + 1
    makes bbpd-dispersion-curves' grid pi/dx * i/(points - 1) coincide with it (n = i)."""
    if info["natoms"] % 2:
        raise ValueError("natoms must be even so that the k grids coincide")
    kw = dict(m=info["m"], delta=info["delta"], E=info["E"], rho=info["rho"],
              dt=info["dt"] if dt is None else dt, points=info["natoms"] // 2 + 1)
    cv = analytic_curves(Path(workdir) / "analytic-cv", volume_correction=True, **kw)
    paper = analytic_curves(Path(workdir) / "analytic-paper", volume_correction=False, **kw)
    # drop k = 0: the measured ridge starts at n = 1
    strip = lambda c: {n: v[1:] for n, v in c.items()}  # noqa: E731
    return ({k: strip(c) for k, c in cv.items()}, {k: strip(c) for k, c in paper.items()})


def check_same_grid(measured, curve):
    if len(measured["k"]) != len(curve["k"]) or not np.allclose(measured["k"], curve["k"],
                                                                 rtol=1e-9, atol=0.0):
        raise RuntimeError("measured and analytic k grids differ")


def measure(kernels=KERNELS, work="/tmp/bbpd-dispersion", nprocs=1, kdx_range=KDX_RANGE,
            **lmp_vars):
    """Run and measure every kernel; compare with each analytic relation.

    Returns kernel -> dict(info, measured, analytic (kernel -> curve, C_v and dt), errors)."""
    work = Path(work)
    results = {}
    for kernel in kernels:
        wd = work / kernel
        info, meas = run_kernel(kernel, wd, nprocs=nprocs, **lmp_vars)
        cv, paper = analytic_on_grid(wd, info)
        check_same_grid(meas, cv[kernel])
        ref = cv[kernel]
        errors = {
            "discrete_dt": deviation(meas, ref["omega_discrete_dt"], kdx_range),
            "discrete_dt_full": deviation(meas, ref["omega_discrete_dt"], (kdx_range[0], math.pi)),
            "discrete_no_dt": deviation(meas, ref["omega_discrete"], kdx_range),
            "paper_eq31_dt": deviation(meas, paper[kernel]["omega_discrete_dt"], kdx_range),
            "continuous": deviation(meas, ref["omega_continuous"], kdx_range),
        }
        results[kernel] = dict(info=info, measured=meas, analytic=cv, errors=errors)
    return results


# --------------------------------------------------------------------------- figures

MARK_EVERY = 8        # measured points plotted: every 8th k (the grid has natoms/2 of them)
OMEGA_UNIT = 1.0e6    # Fig. 4 plots omega in 1e6 rad/s


def measured_group_velocity(meas):
    """d omega/dk of the measured ridge by central differences (one-sided at the ends)."""
    return np.gradient(meas["omega"], meas["k"])


def plot_figures(results, paper, cv, figdir):
    """Figs. 4-6 (omega, phase and group velocity vs k; m = 5, delta = 1 mm) for the three
    kernels: continuous (eq. 29), discrete as printed (eq. 31), discrete with C_v, and, where a
    run exists, discrete with C_v and the run's time step (what LAMMPS integrates) with the
    measured points on top. paper, cv: analytic_table() curves (v = 1). Returns the PNG paths."""
    figdir = Path(figdir)
    figdir.mkdir(parents=True, exist_ok=True)
    runs = [r["info"] for r in results.values()]
    v = math.sqrt(runs[0]["E"] / runs[0]["rho"]) if runs else 1.0    # the runs' wave speed
    dx = PAPER_DELTA / PAPER_M
    relations = ((paper, "continuous", ":", "continuous (eq. 29)"),
                 (paper, "discrete", "--", "discrete (eq. 31 as printed)"),
                 (cv, "discrete", "-", r"discrete with $C_v$ (eq. 19)"))
    dt_style = dict(linestyle="-.", linewidth=0.9)
    panels = (("fig4_dispersion.png", "omega", r"$\omega$ ($10^6$ rad/s)", "Fig. 4: dispersion"),
              ("fig5_phase_velocity.png", "phase", r"phase velocity $c/v$",
               "Fig. 5: phase velocity"),
              ("fig6_group_velocity.png", "group", r"group velocity $v_g/v$",
               "Fig. 6: group velocity"))
    paths = []
    for fname, what, ylabel, title in panels:
        with plots.figure(figdir / fname, figsize=(9.0, 4.8)) as (fig, ax):
            # the analytic curves have v = 1: omega scales with v, velocities are c/v and v_g/v
            scale = v / OMEGA_UNIT if what == "omega" else 1.0
            unit = OMEGA_UNIT if what == "omega" else 1.0
            for kernel in KERNELS:
                col = COLORS[kernel]
                for curves, suffix, style, _ in relations:
                    c = curves[kernel]
                    ax.plot(c["k"], c[f"{what}_{suffix}"] * scale, style, color=col, linewidth=1.2)
                if kernel not in results:
                    continue
                meas, ana = results[kernel]["measured"], results[kernel]["analytic"][kernel]
                # the run's curves carry its own E and rho: omega in rad/s already
                ax.plot(ana["k"], ana[f"{what}_discrete_dt"] / unit, color=col, **dt_style)
                if what == "omega":
                    y = meas["omega"] / OMEGA_UNIT
                elif what == "phase":
                    y = meas["omega"] / meas["k"] / v
                else:
                    y = measured_group_velocity(meas) / v
                s = slice(MARK_EVERY - 1, None, MARK_EVERY)
                ax.plot(meas["k"][s], y[s], "o", color=col, markersize=3.5, markerfacecolor="none")
            handles = [Line2D([], [], color=COLORS[k], linewidth=2.0, label=k) for k in KERNELS]
            handles += [Line2D([], [], color="black", linestyle=st, label=lab)
                        for _, _, st, lab in relations]
            if runs:
                dts = sorted({f"{r['dt']:.3g}" for r in runs})
                handles.append(Line2D([], [], color="black", label=r"discrete with $C_v$, "
                                      f"time step {', '.join(dts)} s", **dt_style))
                handles.append(Line2D([], [], color="black", marker="o", linestyle="none",
                                      markerfacecolor="none", label="measured (LAMMPS + FFT)"))
            ax.set(xlabel=r"wave number $k$ (1/m)", ylabel=ylabel)
            ax.set_title(f"{title} (m = {PAPER_M}, $\\delta$ = {PAPER_DELTA * 1e3:g} mm"
                         + (f", v = {v:g} m/s)" if what == "omega" else ")"))
            top = ax.secondary_xaxis("top", functions=(lambda k: k * dx, lambda q: q / dx))
            top.set_xlabel(r"$k\,\Delta x$")
            if what == "group":
                ax.axhline(0.0, color="black", linewidth=0.6)
            ax.grid(True, alpha=0.3)
            ax.legend(handles=handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0))
        paths.append(figdir / fname)
    return paths


# --------------------------------------------------------------------------- table

def table(runs, analytic):
    """The measured phase velocity beside the analytic relations at TABLE_KDX, the deviations
    and the smallest group velocity of each kernel's run (runs: kernel -> measure()'s result;
    analytic: analytic_table()'s table): (header, rows, numbers), numbers holding per kernel the
    smallest measured v_g/v over the energetic k ('min_vg') and the deviation from what LAMMPS
    integrates ('dev')."""
    header = ["kernel", "c/v measured at k dx = " + " / ".join(f"{x:g}" for x in TABLE_KDX),
              "eq. 31 + C_v + dt (what LAMMPS integrates)", "paper: eq. 31 as printed",
              "continuous eq. 29", "max dev. from eq. 31 + C_v + dt", "from eq. 31 as printed + dt",
              "min v_g/v: measured / paper's eq. 31", "run time (s)"]
    rows, min_vg, dev = [], {}, {}
    for k, r in runs.items():
        v = math.sqrt(r["info"]["E"] / r["info"]["rho"])
        meas, ana, t = r["measured"], r["analytic"][k], analytic[k]
        phase = meas["omega"] / meas["k"] / v
        energetic = ((meas["power"] >= MIN_POWER) & (meas["k_dx"] >= KDX_RANGE[0])
                     & (meas["k_dx"] <= KDX_RANGE[1]))
        vg = measured_group_velocity(meas) / v
        min_vg[k] = float(vg[energetic].min()) if energetic.any() else None
        dev[k] = r["errors"]["discrete_dt"]["max"]
        rows.append([k, " / ".join(f"{np.interp(x, meas['k_dx'], phase):.3f}" for x in TABLE_KDX),
                     " / ".join(f"{np.interp(x, ana['k_dx'], ana['phase_discrete_dt']):.3f}"
                                for x in TABLE_KDX),
                     " / ".join(f"{t['discrete']['phase'][f'{x:g}']:.3f}" for x in TABLE_KDX),
                     " / ".join(f"{t['continuous']['phase'][f'{x:g}']:.3f}" for x in TABLE_KDX),
                     f"{dev[k]:.1e}", f"{r['errors']['paper_eq31_dt']['max']:.1e}",
                     f"{cell(min_vg[k], '.3f')} / {t['discrete']['group_min']:.3f}",
                     cell(r.get("wall_time"), ".1f")])
    return header, rows, {"min_vg": min_vg, "dev": dev}


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/bbpd-dispersion", nprocs=1, kernels=KERNELS,
                    figures="write the PNGs here (default: --work)")
    ap.add_argument("--natoms", type=int, default=None)
    ap.add_argument("--nsteps", type=int, default=None)
    ap.add_argument("--dtv", type=float, default=None, help="time step in units of dx/v")
    ap.add_argument("--every", type=int, default=None, help="steps between two samples")
    args = ap.parse_args(argv)

    lmp_vars = {k: getattr(args, k) for k in ("natoms", "nsteps", "dtv", "every")
                if getattr(args, k)}
    work = Path(args.work)
    results = measure(args.kernels, work, nprocs=args.nprocs, **lmp_vars)
    analytic, paper, cv = analytic_table(work)
    print(md_table(*table(results, analytic)[:2]))
    paths = plot_figures(results, paper, cv, args.figures or work)
    for p in paths:
        print("wrote", p)
    out = {k: {"info": r["info"], "errors": r["errors"]} for k, r in results.items()}
    out["analytic"] = analytic
    (work / "dispersion.json").write_text(json.dumps(out, indent=1))
    print("wrote", work / "dispersion.json")


if __name__ == "__main__":
    main()

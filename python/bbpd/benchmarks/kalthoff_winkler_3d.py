# SPDX-License-Identifier: GPL-2.0-or-later
"""Kalthoff-Winkler in 3D, the 9 mm plate resolved through its thickness, beside the 2D plate
of the same grid (examples/kalthoff-winkler/README.md, "3D plate resolved through its
thickness", has the commands).
"""

import re
import sys
from pathlib import Path

import numpy as np

from bbpd import csvfile, readers
from bbpd import jobs as jobmod
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import kalthoff_winkler_projectile as projectile
from bbpd.benchmarks import kalthoff_winkler_study as study
from bbpd.provenance import cpu
from bbpd.jobs import ROOT
from bbpd.runner import run_lammps
from bbpd.markdown import cell as _f
from bbpd.markdown import columns
from bbpd.benchmarks import cli

CSV = ROOT / "examples" / "kalthoff-winkler" / "results" / "kw3d.csv"
PLATE_THICKNESS = 9.0e-3          # m, the experiment's plate
MIN_HORIZONS_THROUGH = 4          # what "resolved through the thickness" asks
M = 3.0
RESOLUTIONS = (1.0e-3, 0.75e-3)   # dx: delta = 3 and 2.25 mm
KERNEL = "gaussian"
TEND = 100.0e-6                   # the loading study's: the 2D cracks reach the edge at ~80 us
MONITOR = 5                       # steps between monitor lines: first bond to 5 dt = 0.3-0.4 us
NPROCS = 2
TIMEOUT_S = 4 * 3600              # a 3D run on a shared 2-core machine
COLUMNS = ("setup", "kernel", "dx_mm", "m", "delta_mm", "horizons_through", "atoms", "bonds",
           "steps", "first_bond_us", "band_us", "initial_deg", "fit_deg", "chord_deg",
           "fit_face_lo_deg", "fit_face_hi_deg", "chord_face_deg", "length_end_mm", "crack_stops",
           "loop_s", "memory_MB", "nprocs")


def case_vars(dx, m=M, setup="3d"):
    return kw.variables(KERNEL, dx, m=float(m), loading="projectile", tend=TEND,
                        monitor=MONITOR if setup == "3d" else None)


def log_figures(text):
    """atoms, bonds, steps, loop time and memory (all ranks, MB) from a LAMMPS log"""
    loop = re.search(r"Loop time of (\S+) on (\d+) procs for (\d+) steps with (\d+) atoms", text)
    bonds = re.findall(r"total bonds (\d+)", text)
    mem = re.findall(r"Per MPI rank memory allocation \(min/avg/max\) = \S+ \| \S+ \| (\S+) Mbytes",
                     text)
    out = {"atoms": None, "bonds": None, "steps": None, "loop_s": None, "memory_MB": None}
    if loop:
        out.update(loop_s=float(loop[1]), steps=int(loop[3]), atoms=int(loop[4]))
        if mem:
            out["memory_MB"] = max(float(v) for v in mem) * int(loop[2])
    if bonds:
        out["bonds"] = int(bonds[0])
    return out


def face_angles(workdir, g, t_us):
    """kw.angles_of on each face (damage_faces.dump) at the last snapshot at or before t_us"""
    snaps = readers.dump_snapshots(Path(workdir) / "damage_faces.dump")
    times = [step * g["dt"] * 1e6 for step, _ in snaps]
    k = max([i for i, t in enumerate(times) if t <= t_us + 1e-6], default=len(snaps) - 1)
    s = snaps[k][1]
    z = s["f_ref[3]"]
    out = {}
    for name, layer in (("lo", z.min()), ("hi", z.max())):
        sel = np.abs(z - layer) < 0.25 * g["dx"]
        out[name] = kw.angles_of(s["f_ref[1]"][sel], s["f_ref[2]"][sel], s["c_dmg"][sel], g)
    return out


def measure(workdir, setup, dx, m):
    workdir = Path(workdir)
    r = projectile.analyse(workdir)
    log = (workdir / "log.lammps").read_text()
    delta = m * dx
    row = {"setup": setup, "kernel": r["kernel"], "dx_mm": dx * 1e3, "m": m,
           "delta_mm": delta * 1e3,
           "horizons_through": PLATE_THICKNESS / delta if setup == "3d" else None,
           "first_bond_us": r["t_init_us"], "band_us": r["t_band_us"],
           "initial_deg": r.get("initial_deg"), "fit_deg": r.get("fit_t70_deg"),
           "chord_deg": r.get("chord_t70_deg"), "length_end_mm": r["length_end_mm"],
           "fit_face_lo_deg": None, "fit_face_hi_deg": None, "chord_face_deg": None,
           "nprocs": NPROCS if setup == "3d" else 1,
           "crack_stops": projectile.row(r)["crack_stops"]}
    row.update(log_figures(log))
    if setup == "3d":    # r holds the run's geometry (kw.read_log)
        faces = face_angles(workdir, r, kw.T_EVAL_US)
        for f in ("lo", "hi"):
            row[f"fit_face_{f}_deg"] = kw.mean_or_none([faces[f][sd]["fit"] for sd in ("lo", "hi")])
        row["chord_face_deg"] = kw.mean_or_none([faces[f][sd]["chord"] for f in ("lo", "hi")
                                                    for sd in ("lo", "hi")])
    return {c: row[c] for c in COLUMNS}


def run_case(workdir, setup, dx, m=M, reuse=False, nprocs=None):
    """One run in workdir/SETUP-dxDXmm-mM, measured; nprocs: ranks of a 3D run (default NPROCS;
    the report runs every job on one rank: the bits do not depend on it)"""
    wd = Path(workdir) / f"{setup}-dx{dx * 1e3:g}mm-m{m:g}"
    ranks = (NPROCS if nprocs is None else nprocs) if setup == "3d" else 1
    if not (reuse and (wd / "log.lammps").is_file()):
        script = projectile.EXAMPLE_3D if setup == "3d" else kw.EXAMPLE
        run_lammps(str(script), wd, nprocs=ranks, vars=case_vars(dx, m, setup), timeout=TIMEOUT_S)
    row = measure(wd, setup, dx, m)
    row["nprocs"] = readers.loop_time((wd / "log.lammps").read_text())[1] or ranks
    return row


def table(rows):
    def faces(r):
        return ("-" if r["fit_face_lo_deg"] is None else
                f"{r['fit_face_lo_deg']:.1f} / {r['fit_face_hi_deg']:.1f}")
    return columns(sorted(rows, key=lambda r: (-r["dx_mm"], r["setup"])), (
        ("setup", lambda r: r["setup"].upper()), ("dx (mm)", "dx_mm", "g"), ("m", "m", "g"),
        ("delta (mm)", "delta_mm", "g"), ("horizons through 9 mm", "horizons_through", ".0f"),
        ("atoms", "atoms", ".0f"), ("bonds", "bonds", ".3g"), ("steps", "steps", ".0f"),
        ("first bond (us)", "first_bond_us", ".1f"), ("damage band (us)", "band_us", ".1f"),
        ("initial (deg)", "initial_deg", ".1f"), ("fit, mid-plane (deg)", "fit_deg", ".1f"),
        ("fit, faces (deg)", faces), ("chord, mid-plane / faces (deg)", lambda r:
                                      f"{_f(r['chord_deg'], '.1f')} / {_f(r['chord_face_deg'], '.1f')}"),
        ("crack length (mm)", "length_end_mm", ".0f"), ("crack stops (us)", "crack_stops"),
        ("loop (s)", "loop_s", ".0f"), ("memory (MB)", "memory_MB", ".0f"), ("ranks", "nprocs", "g")))


def against_2d(rows):
    """Per resolution (coarsest first) the 3D run beside the 2D plate of the same grid:
    [(3D row, 2D row or None, 3D minus 2D fit angle or None)], and the change of the 3D
    mid-plane fit angle from the coarsest to the finest resolution (None for one)"""
    by = {(r["setup"], r["dx_mm"]): r for r in rows}
    pairs = []
    for dx in sorted({r["dx_mm"] for r in rows}, reverse=True):
        d3, d2 = by.get(("3d", dx)), by.get(("2d", dx))
        if d3:
            ok = d2 and d2["fit_deg"] is not None and d3["fit_deg"] is not None
            pairs.append((d3, d2, d3["fit_deg"] - d2["fit_deg"] if ok else None))
    res = [d3 for d3, _, _ in pairs if d3["fit_deg"] is not None]
    return pairs, (res[-1]["fit_deg"] - res[0]["fit_deg"] if len(res) >= 2 else None)


# ---------------------------------------------------------------------------- report

REPORT_TITLE = "Kalthoff-Winkler in 3D, resolved through the plate's thickness"
ESTIMATE_S = {("3d", 1.0e-3): 1400.0, ("3d", 0.75e-3): 3400.0, ("2d", 1.0e-3): 60.0,
              ("2d", 0.75e-3): 120.0}    # wall time on 1 rank, from the 2-rank runs (CSV)


def jobs():
    """The runs as bbpd.report specs (tools/reproduce --full)."""
    inputs = (kw.EXAMPLE, projectile.EXAMPLE_3D, Path(__file__), Path(kw.__file__),
              Path(study.__file__), Path(projectile.__file__))
    return jobmod.report_specs("kw3d", "bbpd.benchmarks.kalthoff_winkler_3d:run_case", inputs, (
        (KERNEL, dx, f"Kalthoff-Winkler {setup} m = {M:g} dx = {dx * 1e3:g} mm",
         {"setup": setup, "dx": dx, "nprocs": 1}, ESTIMATE_S[setup, dx])
        for dx in RESOLUTIONS for setup in ("2d", "3d")))


def section(specs, results, figdir, notes):
    """The 3D plate's section of REPORT.md (tools/reproduce --full)."""
    return jobmod.section(
        REPORT_TITLE, f"The 9 mm plate struck by the projectile, Gaussian kernel, m = {M:g}, beside "
        "the 2D plate of the same grid; see examples/kalthoff-winkler/README.md.",
        specs, results, table,
        not_run=f"Not run by default ({len(jobs())} runs, about 1.4 h on one core): "
        "`tools/reproduce --full` runs them; the last measured table is in "
        "examples/kalthoff-winkler/README.md, '3D plate resolved through its thickness'.")


def read_rows(path=CSV):
    return csvfile.read_csv(path)[1]


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/kw3d", dx=RESOLUTIONS, reuse=True, csv=True)
    ap.add_argument("--setups", nargs="+", default=["2d", "3d"], choices=["2d", "3d"])
    a = ap.parse_args(argv)
    rows = []
    for dx in a.dx:
        if PLATE_THICKNESS / (M * dx) < MIN_HORIZONS_THROUGH - 1e-9:
            print(f"dx {dx:g}: delta {M * dx:g} m gives fewer than {MIN_HORIZONS_THROUGH} horizons "
                  "through the plate", flush=True)
        for setup in a.setups:
            r = run_case(a.work, setup, dx, reuse=a.reuse)
            print(f"{setup} dx {dx * 1e3:g} mm: fit {_f(r['fit_deg'], '.1f')} faces "
                  f"{_f(r['fit_face_lo_deg'], '.1f')}/{_f(r['fit_face_hi_deg'], '.1f')} first bond "
                  f"{_f(r['first_bond_us'], '.1f')} us loop {_f(r['loop_s'], '.0f')} s memory "
                  f"{_f(r['memory_MB'], '.0f')} MB", flush=True)
            rows.append(r)
    if a.csv:
        csvfile.write_csv(a.csv, rows, comments=[f"made by: {cli.command('kalthoff_winkler_3d', argv)}",
                                                 f"timing: LAMMPS loop time, {cpu()}, shared"])
    print(table(rows))
    return 0


if __name__ == "__main__":
    sys.exit(main())

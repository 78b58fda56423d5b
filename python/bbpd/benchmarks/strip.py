# SPDX-License-Identifier: GPL-2.0-or-later
"""Steady crack growth in a pre-stretched strip between fixed grips: the model's kinetic law.

Runs examples/strip-steady-crack/in.strip and measures, per run (plane stress, BBPD's
nu = 1/3; energies per unit thickness, i.e. the compute's joules over the slab thickness h):

U'        the model's stored energy per unit length of the uniform strain, measured at t = 0
          by compute bbpd/energy on a column of atoms one strip height wide in the middle
          (STRIP-UPRIME); Delta' = U'/G_c beside the nominal Delta = W H / G_c of CCM.
crossed   the tip reached the far end (x >= L - H/2) before tend.
v_ss      steady speed: least-squares slope of the tip position x(t) while the tip runs over
          the MIDDLE (from a + 2 H to L - H; the crack reaches a steady speed after about two
          strip heights), over the model's Rayleigh speed c_R (Rayleigh equation, nu = 1/3).
Gamma     energy the broken bonds take per unit crack area, slope of the broken-bond energy
          against the tip position over the same span, over G_c.
Phi       energy the crack leaves as waves per unit crack area, Phi_behind + Phi_ahead:
          behind  slope against the tip position of the elastic + kinetic energy of the atoms
                  more than H behind the tip plus what the damped seed zone absorbed (the
                  waves sent back), over the same span;
          ahead   slope of what the damped far zone absorbed (waves faster than the crack).
closure   (Gamma + Phi - U')/U': zero at steady state (the grips do no work, and the strip
          ahead of the near-tip field loses U' per unit length).
balance   drift of compute bbpd/energy's balance over the run, over the broken-bond energy.

Command line (from the repository root):
  tools/python -m bbpd.benchmarks.strip --kernels gaussian --Delta 1.5 2 3 \
      --work /tmp/strip --csv examples/strip-steady-crack/results/strip.csv
"""

import argparse
import csv
import re
import sys
import time
from pathlib import Path

import numpy as np

from bbpd import freund
from bbpd.benchmarks.mode1_propagation import machine
from bbpd.runner import run_lammps

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "strip-steady-crack" / "in.strip"

# soda-lime glass (the example's defaults; fracture-anchors: Ha & Bobaru 2010)
E, RHO, G_C = 72.0e9, 2440.0, 3.8
NU = 1.0 / 3.0                      # BBPD in plane stress
DX = 2.5e-4                         # m, the example's default grid
M = 4.0                             # delta/dx
H_OVER_DELTA = 20.0                 # strip height in horizons
L_OVER_H = 8.0                      # strip length in strip heights
MIDDLE_START_H = 2.0                # steady from a + 2 H (the trial: ~2 H)
MIDDLE_END_H = 1.0                  # to L - H (the run stops at L - H/2)
MIN_MIDDLE_POINTS = 5
CSV_COLUMNS = ("kernel", "m", "H_over_delta", "dx", "Delta", "Delta_model", "crossed",
               "v_ss_over_cR", "v_ss", "Gamma_over_Gc", "Phi_over_Gc", "Phi_behind_over_Gc",
               "Phi_ahead_over_Gc", "closure_pct", "balance_pct", "atoms", "steps", "loop_s")


def wave_speeds():
    """c_d, c_s, c_R of the model (plane stress, nu = 1/3)."""
    c_d = freund.dilatational_wave_speed(E, NU, RHO, freund.PLANE_STRESS)
    c_s = freund.shear_wave_speed(E, NU, RHO)
    return c_d, c_s, freund.rayleigh_wave_speed(c_s, c_d)


def geometry(dx=DX, m=M, H_over_delta=H_OVER_DELTA):
    delta = m * dx
    H = H_over_delta * delta
    return {"delta": delta, "H": H, "L": L_OVER_H * H, "a": H}


def measure(rows, uprime, g, h, Gc=G_C):
    """The steady-state numbers of one run from the rows of strip.dat (see the module doc).
    rows: step, t, tip x, y, extension, speed, direction, U, K, B, W, balance (the strip),
    U + K more than H behind the tip, work on the seed zone, work on the far zone."""
    t, x = rows[:, 1], rows[:, 2]
    B, bal = rows[:, 9], rows[:, 11]
    c_R = wave_speeds()[2]
    H, L, a = g["H"], g["L"], g["a"]
    crossed = bool(x[-1] >= L - 0.5 * H - 2.0 * g["delta"])
    mid = (x >= a + MIDDLE_START_H * H) & (x <= L - MIDDLE_END_H * H)
    nan = float("nan")
    res = {"crossed": crossed, "v_ss": 0.0, "v_ss_over_cR": 0.0, "Gamma_over_Gc": nan,
           "Phi_over_Gc": nan, "Phi_behind_over_Gc": nan, "Phi_ahead_over_Gc": nan,
           "closure_pct": nan}
    res["balance_pct"] = 100.0 * float(np.max(np.abs(bal - bal[0])) / max(B[-1], 1e-300))
    if not crossed or np.count_nonzero(mid) < MIN_MIDDLE_POINTS:
        return res
    v_ss = float(np.polyfit(t[mid], x[mid], 1)[0])
    gamma = float(np.polyfit(x[mid], B[mid], 1)[0]) / h
    # left behind: the elastic + kinetic energy more than H behind the tip, and what the damped
    # seed zone absorbed of the waves sent back (its work is negative)
    phi = float(np.polyfit(x[mid], rows[mid, 12] - rows[mid, 13], 1)[0]) / h
    # sent ahead, faster than the crack, and absorbed by the damped far zone
    phi_ahead = float(np.polyfit(x[mid], -rows[mid, 14], 1)[0]) / h
    res.update({"v_ss": v_ss, "v_ss_over_cR": v_ss / c_R, "Gamma_over_Gc": gamma / Gc,
                "Phi_behind_over_Gc": phi / Gc, "Phi_ahead_over_Gc": phi_ahead / Gc,
                "Phi_over_Gc": (phi + phi_ahead) / Gc,
                "closure_pct": 100.0 * (gamma + phi + phi_ahead - uprime) / uprime})
    return res


def run(workdir, kernel="gaussian", Delta=2.0, dx=DX, m=M, H_over_delta=H_OVER_DELTA,
        nprocs=1, reuse=False):
    """Run the example once (reuse=True: measure the outputs already in workdir)."""
    workdir = Path(workdir)
    g = geometry(dx, m, H_over_delta)
    vars_ = {"kernel": kernel, "dx": dx, "m": m, "Delta": Delta, "H": f"{g['H']:.10g}",
             "L": f"{g['L']:.10g}", "a": f"{g['a']:.10g}", "E": E, "rho": RHO, "Gc": G_C}
    start = time.perf_counter()
    if reuse:
        output = (workdir / "log.lammps").read_text()
    else:
        output = run_lammps(str(EXAMPLE), workdir, nprocs=nprocs, vars=vars_).output
    wall = time.perf_counter() - start
    uprime = float(output.split("STRIP-UPRIME: ")[-1].split()[0])
    words = output.split("STRIP: ")[-1].split("\n")[0].split()
    setup = dict(zip(words[0::2], words[1::2]))
    rows = np.loadtxt(workdir / "strip.dat", comments="#", ndmin=2)
    loop_s = float(re.findall(r"Loop time of ([0-9.eE+-]+) on", output)[-1])    # the crack's run
    res = measure(rows, uprime, g, dx)
    res.update({"kernel": kernel, "m": m, "H_over_delta": H_over_delta, "dx": dx,
                "Delta": Delta, "Delta_model": uprime / G_C, "atoms": int(setup["atoms"]),
                "steps": int(rows[-1, 0]), "loop_s": loop_s, "wall_s": wall,
                "t": rows[:, 1], "x": rows[:, 2]})
    return res


def write_csv(path, rows, command):
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        f.write(f"# made by: {command}\n# timing: LAMMPS loop time, 1 rank, {machine()}\n")
        w = csv.writer(f)
        w.writerow(CSV_COLUMNS)
        for r in rows:
            w.writerow([r[c] if isinstance(r[c], (str, bool)) else f"{r[c]:.6g}" for c in CSV_COLUMNS])


def read_rows(path):
    """The CSV of write_csv as dicts (kernel a string, crossed a bool, the rest floats)."""
    lines = [ln for ln in Path(path).read_text().splitlines() if ln and not ln.startswith("#")]
    names = lines[0].split(",")
    out = []
    for ln in lines[1:]:
        row = {}
        for n, v in zip(names, ln.split(",")):
            row[n] = v if n == "kernel" else (v == "True") if n == "crossed" else float(v)
        out.append(row)
    return out


def kinetic_law(rows, kernel, m=5.0, H_over_delta=H_OVER_DELTA):
    """G_run/G_c against v/c_R of one kernel at (m, H/delta), from the runs that crossed:
    arrays (u, g) sorted by u, with G_run = U' (the model's) at the steady speed."""
    pts = sorted((r["v_ss_over_cR"], r["Delta_model"]) for r in rows
                 if r["kernel"] == kernel and r["m"] == m and r["H_over_delta"] == H_over_delta
                 and r["crossed"])
    return np.array([p[0] for p in pts]), np.array([p[1] for p in pts])


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--kernels", nargs="+", default=["gaussian"])
    p.add_argument("--Delta", nargs="+", type=float, default=[2.0])
    p.add_argument("--m", nargs="+", type=float, default=[M])
    p.add_argument("--H-over-delta", nargs="+", type=float, default=[H_OVER_DELTA])
    p.add_argument("--work", default="/tmp/strip")
    p.add_argument("--csv", help="write (or, with --append, add to) this results CSV")
    p.add_argument("--append", action="store_true")
    p.add_argument("--reuse", action="store_true", help="measure earlier runs in --work")
    a = p.parse_args(argv)
    rows = read_rows(a.csv) if a.append and a.csv and Path(a.csv).is_file() else []
    for kernel in a.kernels:
        for m in a.m:
            for hd in a.H_over_delta:
                for D in a.Delta:
                    wd = Path(a.work) / f"{kernel}-m{m:g}-H{hd:g}-D{D:g}"
                    r = run(wd, kernel, D, DX * M / m, m, hd, reuse=a.reuse)
                    print(f"{kernel} m {m:g} H/delta {hd:g} Delta {D:g} (model {r['Delta_model']:.3f}): "
                          f"crossed {r['crossed']} v_ss/c_R {r['v_ss_over_cR']:.3f} Gamma/Gc "
                          f"{r['Gamma_over_Gc']:.3f} Phi/Gc {r['Phi_over_Gc']:.3f} closure "
                          f"{r['closure_pct']:.2f} % balance {r['balance_pct']:.3f} % loop {r['loop_s']:.1f} s",
                          flush=True)
                    rows = [q for q in rows if not (q["kernel"] == kernel and q["m"] == m and
                                                    q["H_over_delta"] == hd and q["Delta"] == D)]
                    rows.append(r)
    if a.csv:
        rows.sort(key=lambda r: (r["kernel"], r["m"], r["H_over_delta"], r["Delta"]))
        write_csv(a.csv, rows, "tools/python -m bbpd.benchmarks.strip " + " ".join(argv or sys.argv[1:]))
    return 0


if __name__ == "__main__":
    sys.exit(main())

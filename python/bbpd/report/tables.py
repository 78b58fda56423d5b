# SPDX-License-Identifier: GPL-2.0-or-later
"""The report's tables: the runs' results (as the job cache holds them) turned into rows of
numbers beside the paper's, and the CSV files of the dispersion curves."""
import json
import math
import re
from pathlib import Path

import numpy as np

from bbpd import jobs as jobmod
from bbpd.benchmarks import dispersion as disp
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import mode1, mode2
from bbpd.kernels import KERNELS
from bbpd.markdown import cell as f
from bbpd.markdown import table as md_table

from .runs import MODE1_TABLE3_DX

DISP_KDX = (1.0, 2.0, 2.5)


# --------------------------------------------------------------------------- results, cells

def _plain(obj):
    """The JSON form of a result (what the cache holds), so that fresh and reused results are
    handled alike."""
    return json.loads(json.dumps(obj, default=jobmod._jsonable))


def _arrays(d, keys):
    return {**d, **{k: np.asarray(d[k], dtype=float) for k in keys if k in d}}


def failed(res):
    return res is None or "error" in res


def failure_text(res):
    msg = "not run" if res is None else str(res["error"]).splitlines()[0]
    msg = re.sub(r"^RuntimeError: (?=\w+Error: )", "", msg)    # run_job's wrapping
    return "FAILED: " + msg.replace("|", "/")[:160]


def run_time(res):
    """Wall time of the run (s): the LAMMPS run (dispersion: run + FFT measurement)."""
    for key in ("wall_time", "wall_s", "job_s"):
        if res.get(key) is not None:
            return float(res[key])
    return None


def failed_row(res, ncols, lead):
    """A table row for a failed run: the leading cells, then the error across the rest."""
    return list(lead) + [failure_text(res)] + [""] * (ncols - len(lead) - 1)


# --------------------------------------------------------------------------- dispersion

def dispersion_runs(specs, results):
    """kernel -> finished dispersion result, its curves as arrays."""
    runs = {}
    for s in specs:
        res = results.get(s.job.label)
        if not failed(res):
            res = dict(res)
            res["measured"] = _arrays(res["measured"], res["measured"].keys())
            res["analytic"] = {k: _arrays(c, c.keys()) for k, c in res["analytic"].items()}
            runs[s.kernel] = res
    return runs


def dispersion_csv(runs, figdir):
    """The analytic curves of Figs. 4-6 at m = 5, delta = 1 mm, kept as CSV beside the figures
    (csv/analytic-paper: eqs. 29 and 31 as printed; csv/analytic-cv: with the C_v weights), and
    the measured points; returns dispersion.analytic_table's (table, paper, cv)."""
    csvdir = Path(figdir) / "csv"
    table, paper, cv = disp.analytic_table(csvdir)
    for k, r in runs.items():
        meas = r["measured"]
        np.savetxt(csvdir / f"measured_{k}.csv",
                   np.column_stack([meas["k"], meas["k_dx"], meas["omega"], meas["power"]]),
                   delimiter=",", header="k (1/m), k dx, omega (rad/s), relative power",
                   comments="# ")
    return table, paper, cv


def dispersion_table(specs, results, runs, table):
    """(header, rows, numbers): numbers holds per kernel the smallest measured v_g/v ('min_vg')
    and the deviation from what LAMMPS integrates ('dev')."""
    info = next(iter(runs.values()))["info"] if runs else None
    v = math.sqrt(info["E"] / info["rho"]) if info else 1.0

    header = ["kernel", "c/v measured at k dx = 1 / 2 / 2.5",
              "eq. 31 + C_v + dt (what LAMMPS integrates)", "paper: eq. 31 as printed",
              "continuous eq. 29", "max dev. from eq. 31 + C_v + dt", "from eq. 31 as printed + dt",
              "min v_g/v: measured / paper's eq. 31", "run time (s)"]
    rows, min_vg, dev = [], {}, {}
    for s in specs:
        k = s.kernel
        if k not in runs:
            rows.append(failed_row(results.get(s.job.label), len(header), [k]))
            continue
        r = runs[k]
        meas, ana = r["measured"], r["analytic"][k]
        phase = meas["omega"] / meas["k"] / v
        meas_phase = [float(np.interp(x, meas["k_dx"], phase)) for x in DISP_KDX]
        lammps = [float(np.interp(x, ana["k_dx"], ana["phase_discrete_dt"])) for x in DISP_KDX]
        energetic = ((meas["power"] >= disp.MIN_POWER) & (meas["k_dx"] >= disp.KDX_RANGE[0])
                     & (meas["k_dx"] <= disp.KDX_RANGE[1]))
        vg = disp.measured_group_velocity(meas) / v
        min_vg[k] = float(vg[energetic].min()) if energetic.any() else None
        dev[k] = r["errors"]["discrete_dt"]["max"]
        t = table[k]
        rows.append([k, " / ".join(f"{p:.3f}" for p in meas_phase),
                     " / ".join(f"{p:.3f}" for p in lammps),
                     " / ".join(f"{t['discrete']['phase'][f'{x:g}']:.3f}" for x in DISP_KDX),
                     " / ".join(f"{t['continuous']['phase'][f'{x:g}']:.3f}" for x in DISP_KDX),
                     f"{dev[k]:.1e}", f"{r['errors']['paper_eq31_dt']['max']:.1e}",
                     f"{f(min_vg[k], '.3f')} / {t['discrete']['group_min']:.3f}",
                     f(run_time(r), ".1f")])
    return header, rows, {"min_vg": min_vg, "dev": dev}


# --------------------------------------------------------------------------- Mode I

def mode1_results(specs, results):
    """(kernel, dx) -> result of every run, and of the finished ones with arrays."""
    by = {(s.kernel, s.dx): results.get(s.job.label) for s in specs}
    ok = {key: _arrays(r, ("t", "k_paper", "k_consistent", "k_ii"))
          for key, r in by.items() if not failed(r)}
    return by, ok


def mode1_tables(by, ok):
    """Table 2 (Gaussian, every dx) and Table 3 (three kernels): (header, rows, finished runs
    by dx or kernel) of each."""

    def cells(r):
        p, c = r["paper"], r["consistent"]
        j = r.get("jintegral", {}).get("consistent")
        return [f"{p['peak']:.2f} / {p['l2']:.2f}", f"{c['peak']:.2f} / {c['l2']:.2f}",
                f"{j['peak']:.2f} / {j['l2']:.2f}" if j else "-",
                f"{r['dt']:.3g}", f(run_time(r), ".1f")]

    h2 = ["dx (m)", "atoms", "paper's Table 2: peak / L2", "ours, paper convention: peak / L2",
          "ours, consistent: peak / L2", "K_I from J, consistent: peak / L2", "dt (s)",
          "run time (s)"]
    rows2, rows2_ok = [], {}
    for dx in sorted({dx for k, dx in by if k == "gaussian"}, reverse=True):
        ref = mode1.PAPER_TABLE2.get(dx)
        lead = [f"{dx:g}", f"{int(round(10 / dx))} x {int(round(4 / dx))}",
                "-" if ref is None else f"{ref[0]:.2f} / {ref[1]:.2f}"]
        r = ok.get(("gaussian", dx))
        if r is None:
            rows2.append(failed_row(by[("gaussian", dx)], len(h2), lead))
        else:
            rows2.append(lead + cells(r))
            rows2_ok[dx] = r

    h3 = ["kernel", "paper's Table 3: peak / L2", "ours, paper convention: peak / L2",
          "ours, consistent: peak / L2", "K_I from J, consistent: peak / L2", "dt (s)",
          "run time (s)"]
    rows3, rows3_ok = [], {}
    for k in KERNELS:
        key = (k, MODE1_TABLE3_DX)
        if key not in by:
            continue
        ref = mode1.PAPER_TABLE3[k]
        lead = [k, f"{ref[0]:.2f} / {ref[1]:.2f}"]
        if key not in ok:
            rows3.append(failed_row(by[key], len(h3), lead))
        else:
            rows3.append(lead + cells(ok[key]))
            rows3_ok[k] = ok[key]
    return (h2, rows2, rows2_ok), (h3, rows3, rows3_ok)


# --------------------------------------------------------------------------- Mode II

def mode2_table(specs, results):
    """(header, rows, {(kernel, dx): finished result with arrays})"""
    header = ["kernel", "dx (mm)", "atoms", "peak (%)", "L2 (%)",
              "K_II/(tau sqrt(pi a)) at window end: ours / reference", "ours/reference",
              "K_II from J: peak / L2 (%)", "from J: ours/reference", "paper", "run time (s)"]
    rows, ok = [], {}
    for s in sorted(specs, key=lambda s: (-s.dx, KERNELS.index(s.kernel))):
        res = results.get(s.job.label)
        natoms = int(round(2 * mode2.HALF_LENGTH / s.dx)) * int(round(2 * mode2.HALF_HEIGHT / s.dx))
        lead = [s.kernel, f"{s.dx * 1e3:g}", f"{natoms}"]
        if failed(res):
            rows.append(failed_row(res, len(header), lead))
            continue
        r = _arrays(res, ("t", "k_ii", "k_i", "k_ii_left", "k_ii_j"))
        ok[(s.kernel, s.dx)] = r
        j = r.get("jintegral")
        rows.append(lead + [f"{r['peak']:.2f}", f"{r['l2']:.2f}",
                            f"{r['k_end']:.3f} / {r['k_end_exact']:.3f}",
                            f"{r['k_end'] / r['k_end_exact']:.3f}",
                            f"{j['peak']:.2f} / {j['l2']:.2f}" if j else "-",
                            f"{j['k_end'] / r['k_end_exact']:.3f}" if j else "-", "figure only",
                            f(run_time(r), ".1f")])
    return header, rows, ok


# --------------------------------------------------------------------------- Kalthoff-Winkler

def kw_table(specs, results):
    """(header, rows, {(kernel, dx): finished result})"""
    header = ["kernel", "dx (mm)", "atoms", "first bond (us)", "damage band (us)",
              "paper initiation (us)", "angle (deg)", "experiment (deg)", "speed (m/s)",
              "far-edge crack from (us)", "run time (s)"]
    rows, ok = [], {}
    for s in sorted(specs, key=lambda s: (KERNELS.index(s.kernel), -s.dx)):
        res = results.get(s.job.label)
        lead = [s.kernel, f"{s.dx * 1e3:g}"]
        if failed(res):
            rows.append(failed_row(res, len(header), lead))
            continue
        ok[(s.kernel, s.dx)] = res
        rows.append(lead + [
            str(len(res["damage_map"]["x"])), f(res["t_init_us"], ".1f"),
            f(res["t_band_us"], ".1f"), f"{kw.PAPER_INITIATION_US[s.kernel]:.1f}",
            f(res["angle_deg"], ".1f"), f"{kw.EXPERIMENT_ANGLE_DEG:.0f}", f(res["speed"], ".0f"),
            f(res["t_far_edge_us"], ".0f") if res["far_edge_crack"] else "none",
            f(run_time(res), ".1f")])
    return header, rows, ok

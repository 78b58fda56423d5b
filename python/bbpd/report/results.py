# SPDX-License-Identifier: GPL-2.0-or-later
"""The report's numbers as CSV, one file per benchmark in OUT/results/ and one row per finished
run: what the tables and sentences of the READMEs are generated from (bbpd.claims keeps a
committed copy of each under examples/<benchmark>/results/).

The first lines of each file, starting with '#', say what made it: the command, date, LAMMPS
and plugin builds, and the machine (CPU), which the run times belong to."""
import math
from pathlib import Path

import numpy as np

from bbpd.benchmarks import mode1, mode2
from bbpd.csvfile import write_csv
from bbpd.kernels import KERNELS

from .tables import DISP_KDX, failed, run_time

FOLDER = "results"
# Spec.bench of every run that belongs to a benchmark's file (the work-precision runs complete
# the grids of the tables; its timing repeats are left out)
FAMILY = {"mode1": ("mode1", "wp-mode1"), "mode2": ("mode2", "wp-mode2"),
          "kalthoff_winkler": ("kw", "wp-kw")}


def _kmax_ratio(res, key, exact):
    """max K over 0 <= t <= 3 t_c divided by max K_exact there (Mode I)."""
    t = np.asarray(res["t"], dtype=float)
    w = t <= 3.0 * res["consistent"]["t_c"]
    return float(np.max(np.asarray(res[key], dtype=float)[w]) / np.max(exact(t[w])))


def mode1_row(res):
    exact, _ = mode1.reference("consistent", res.get("model", "plane/stress"))
    j = (res.get("jintegral") or {}).get("consistent") or {}
    jp = (res.get("jintegral") or {}).get("paper") or {}
    kii_j = None
    if "kii_j" in res:    # K_II/K_I of the interaction integral over the window: 0 by symmetry
        t = np.asarray(res["t"], dtype=float)
        w = t <= 3.0 * res["consistent"]["t_c"]
        kii_j = float(np.max(np.abs(np.asarray(res["kii_j"], dtype=float)[w]))
                      / np.max(np.abs(np.asarray(res["k_j"], dtype=float)[w])))
    return {"paper_peak": res["paper"]["peak"], "paper_l2": res["paper"]["l2"],
            "consistent_peak": res["consistent"]["peak"],
            "consistent_l2": res["consistent"]["l2"],
            "j_peak": j.get("peak"), "j_l2": j.get("l2"),
            "kmax_ratio": _kmax_ratio(res, "k_consistent", exact),
            "kmax_ratio_j": _kmax_ratio(res, "k_j", exact) if "k_j" in res else None,
            "j_paper_peak": jp.get("peak"), "j_paper_l2": jp.get("l2"),
            "kii_over_ki": res.get("kii_over_ki"), "kii_j_over_k_j": kii_j, "dt_s": res["dt"], "atoms": res.get("atoms")}


def mode2_row(res):
    j = res.get("jintegral") or {}
    natoms = (int(round(2 * mode2.HALF_LENGTH / res["dx"]))
              * int(round(2 * mode2.HALF_HEIGHT / res["dx"])))
    return {"atoms": natoms, "peak": res["peak"], "l2": res["l2"], "k_end": res["k_end"],
            "k_end_exact": res["k_end_exact"], "ratio_end": res["k_end"] / res["k_end_exact"],
            "j_peak": j.get("peak"), "j_l2": j.get("l2"),
            "j_ratio_end": (j["k_end"] / res["k_end_exact"]) if "k_end" in j else None,
            "left_right": res.get("left_right"), "ki_over_kii": res.get("ki_over_kii"),
            "dt_s": res["dt"]}


def kw_row(res):
    return {"atoms": len(res["damage_map"]["x"]), "first_bond_us": res["t_init_us"],
            "damage_band_us": res["t_band_us"], "angle_deg": res["angle_deg"],
            "speed_m_s": res["speed"], "symmetry_tip_mm": res["symmetry_tip_mm"],
            "far_edge_crack_us": res["t_far_edge_us"] if res["far_edge_crack"] else None,
            "far_damage_other_atoms": res.get("far_damage_other")}


def dispersion_row(res, kernel):
    info = res["info"]
    v = math.sqrt(info["E"] / info["rho"])
    meas = res["measured"]
    phase = np.asarray(meas["omega"], dtype=float) / np.asarray(meas["k"], dtype=float) / v
    kdx = np.asarray(meas["k_dx"], dtype=float)
    row = {f"phase_kdx{x:g}": float(np.interp(x, kdx, phase)) for x in DISP_KDX}
    row["max_dev_discrete_dt"] = res["errors"]["discrete_dt"]["max"]
    return row


ROWS = {"mode1": mode1_row, "mode2": mode2_row, "kalthoff_winkler": kw_row}


def tables(specs, results):
    """{benchmark: [row dict]} of the finished runs, rows ordered by kernel then dx (coarse
    first); every row starts with kernel, dx_m and ends with run_time_s."""
    out = {}
    for name, benches in FAMILY.items():
        seen, rows = set(), []
        for s in sorted((s for s in specs if s.bench in benches),
                        key=lambda s: (KERNELS.index(s.kernel), -s.dx)):
            res = results.get(s.job.label)
            key = (s.kernel, round(s.dx, 12))
            if failed(res) or key in seen:
                continue
            seen.add(key)
            rows.append({"kernel": s.kernel, "dx_m": s.dx, **ROWS[name](res),
                         "run_time_s": run_time(res)})
        out[name] = rows
    rows = []
    for s in specs:
        res = results.get(s.job.label)
        if s.bench == "dispersion" and not failed(res):
            rows.append({"kernel": s.kernel, "dx_m": s.dx, **dispersion_row(res, s.kernel),
                         "run_time_s": run_time(res)})
    out["dispersion"] = rows
    return out


def provenance_lines(meta):
    """The '#' lines at the top of every file."""
    option = " --full" if meta.get("full") else " --finer" if meta.get("finer") else ""
    return [f"made by: tools/reproduce{option} "
            f"on {meta.get('date', '?')}",
            f"LAMMPS: {meta.get('lammps', '?')}; plugin {meta.get('plugin', '?')}, "
            f"source {meta.get('git', '?')}",
            f"machine: {meta.get('machine', '?')}; runs single-rank, {meta.get('workers', '?')} "
            "at a time (run_time_s includes the other runs' competition for the cores)"]


def write(out, specs, results, meta):
    """Write OUT/results/<benchmark>.csv; returns their paths."""
    folder = Path(out) / FOLDER
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, rows in tables(specs, results).items():
        if not rows:
            continue
        path = folder / f"{name}.csv"
        write_csv(path, rows, provenance_lines(meta))
        paths.append(path)
    return paths

# SPDX-License-Identifier: GPL-2.0-or-later
"""The report's numbers as CSV, one file per benchmark in OUT/results/ and one row per finished
run: what the tables and sentences of the READMEs are generated from (bbpd.claims keeps a
committed copy of each under examples/<benchmark>/results/).

The first lines of each file, starting with '#', say what made it: the command, date, LAMMPS
and plugin builds, and the machine (CPU), which the run times belong to."""
import math
from pathlib import Path

import numpy as np

from bbpd.benchmarks import dispersion
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import mode1, mode2
from bbpd.csvfile import write_csv
from bbpd.kernels import KERNELS

from .tables import failed, run_time

FOLDER = "results"
# Spec.bench of every run that belongs to a benchmark's file (the work-precision runs complete
# the grids of the tables; its timing repeats are left out)
FAMILY = {"mode1": ("mode1", "wp-mode1"), "mode2": ("mode2", "wp-mode2"),
          "kalthoff_winkler": ("kw", "wp-kw")}


def dispersion_row(res, kernel):
    info = res["info"]
    v = math.sqrt(info["E"] / info["rho"])
    meas = res["measured"]
    phase = np.asarray(meas["omega"], dtype=float) / np.asarray(meas["k"], dtype=float) / v
    kdx = np.asarray(meas["k_dx"], dtype=float)
    row = {f"phase_kdx{x:g}": float(np.interp(x, kdx, phase)) for x in dispersion.TABLE_KDX}
    row["max_dev_discrete_dt"] = res["errors"]["discrete_dt"]["max"]
    return row


ROWS = {"mode1": mode1.row, "mode2": mode2.row, "kalthoff_winkler": kw.row}


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
            rows.append(ROWS[name](res))
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

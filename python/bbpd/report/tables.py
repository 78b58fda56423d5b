# SPDX-License-Identifier: GPL-2.0-or-later
"""The report's tables: the runs' results (as the job cache holds them) turned into rows of
numbers beside the paper's, and the CSV files of the dispersion curves."""
import json
import re
from pathlib import Path

import numpy as np

from bbpd import jobs as jobmod
from bbpd.benchmarks import dispersion as disp
from bbpd.markdown import table as md_table


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


def finished(specs, results, arrays=()):
    """{(kernel, dx): result} of the finished runs among specs, its `arrays` as arrays."""
    return {(s.kernel, s.dx): _arrays(results[s.job.label], arrays) for s in specs
            if not failed(results.get(s.job.label))}


def failures(specs, results):
    """The failed runs among specs as a table (dx, kernel, error), '' when none failed."""
    bad = [s for s in specs if failed(results.get(s.job.label))]
    return md_table(["dx (m)", "kernel", "run"], [[f"{s.dx:g}", s.kernel,
                                                   failure_text(results.get(s.job.label))]
                                                  for s in bad]) if bad else ""


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

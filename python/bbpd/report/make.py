# SPDX-License-Identifier: GPL-2.0-or-later
"""Make the report: run (or reuse) the runs through bbpd.jobs, longest first, then write
REPORT.md with the provenance of this call."""
import json
import os
import time
from pathlib import Path

from bbpd import jobs as jobmod
from . import work_precision

from . import results as result_files
from .document import write_report
from bbpd.provenance import git_revision, lammps_build, machine, plugin_version
from .runs import ESTIMATES_ENV, benchmark_specs
from .tables import _plain, failed


def job_list(full=False, finer=False):
    """Every run of the report: the benchmarks' runs at default resolutions (or the paper's full
    ones with full=True, or with finer=True the finer grids of the benchmarks' tables alone),
    then the runs and timing repeats of the work-precision diagrams."""
    specs = benchmark_specs(full or finer, study=full)
    return specs + work_precision.extra_specs(specs, work_precision.plan(full))


def reproduce(out, specs, workers, full=False, log=None, finer=False):
    """Run (or reuse) the jobs of specs and write out/REPORT.md; returns (path, failed runs)."""
    log = log or (lambda msg: print(msg, flush=True))
    start = time.perf_counter()
    out = Path(out).resolve()
    out.mkdir(parents=True, exist_ok=True)
    load = os.getloadavg()[0]
    # longest first: the last runs to finish are then short ones on every core
    specs = sorted(specs, key=lambda s: -s.job.estimate_s)
    os.environ[ESTIMATES_ENV] = json.dumps({s.job.label: s.job.estimate_s for s in specs})
    cache = out / "runs"
    new = sum(not (cache / f"{s.job.key(jobmod.plugin_path())}.json").is_file() for s in specs)
    log(f"reproduce: {len(specs)} runs "
        f"({'full' if full else 'finer' if finer else 'default'} resolutions), "
        f"results in {out}")
    results = jobmod.run_jobs([s.job for s in specs], cache, workers=workers, log=log)
    results = {label: _plain(r) for label, r in results.items()}
    runs_s = time.perf_counter() - start
    log("reproduce: writing the report and figures")
    meta = {"full": full, "finer": finer, "date": time.strftime("%Y-%m-%d %H:%M"), "lammps": lammps_build(),
            "plugin": plugin_version(), "git": git_revision(), "machine": machine(),
            "load": load, "new": new, "workers": workers, "runs_s": runs_s}
    path = write_report(out, specs, results, meta, start)
    try:    # the numbers the READMEs are generated from (python -m bbpd.claims)
        result_files.write(out, specs, results, meta)
    except Exception as exc:  # the report itself stands without them
        log(f"reproduce: results/*.csv not written: {type(exc).__name__}: {exc}")
    n_failed = sum(failed(results.get(s.job.label)) for s in specs)
    log(f"reproduce: wrote {path} in {jobmod._fmt(time.perf_counter() - start)}"
        + (f"; {n_failed} run(s) FAILED (see the report)" if n_failed else ""))
    return path, n_failed

# SPDX-License-Identifier: GPL-2.0-or-later
"""Run benchmark jobs on all cores with progress, reusing finished runs whose inputs did not change.

A job is a module-level function called with keyword arguments and a work folder; it returns a
JSON-serialisable dict. Its cache key hashes the function's name, its arguments, the files it
declares as inputs (input scripts) and the plugin binary, so editing an input script or
rebuilding the plugin reruns exactly the jobs that depend on it.
"""
import concurrent.futures as cf
import hashlib
import importlib
import json
import os
import time
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


@dataclass
class Job:
    label: str                 # what the progress line shows
    func: str                  # "module:function", called as func(workdir=..., **kwargs)
    kwargs: dict = field(default_factory=dict)
    inputs: tuple = ()         # files whose content is part of the cache key
    estimate_s: float = 10.0   # expected wall time, for the time-left estimate

    def key(self, plugin):
        h = hashlib.sha256()
        h.update(self.func.encode())
        h.update(json.dumps(self.kwargs, sort_keys=True).encode())
        for path in self.inputs:
            h.update(Path(path).read_bytes())
        if plugin and Path(plugin).is_file():
            h.update(Path(plugin).read_bytes())
        return h.hexdigest()[:16]


@dataclass
class Spec:
    """A job of the report, with what it computes: benchmark, kernel and grid spacing."""
    bench: str       # dispersion | mode1 | mode2 | kw | kwstudy | ...
    kernel: str
    dx: float        # m (dispersion: the example's fixed grid, 0.2 mm)
    job: Job


def report_spec(bench, kernel, dx, label, target, args, inputs, estimate_s):
    """A run of the report as a Spec: target(workdir, **args) through bbpd.report:run_job, a
    cached job whose key covers the files in inputs (input script, analysis code)"""
    return Spec(bench, kernel, dx, Job(label=label, func="bbpd.report:run_job",
                                       kwargs={"target": target, "args": args, "label": label},
                                       inputs=tuple(str(p) for p in inputs), estimate_s=estimate_s))


def report_specs(bench, target, inputs, cases):
    """report_spec of every (kernel, dx, label, args, estimate_s) in cases"""
    return [report_spec(bench, kernel, dx, label, target, args, inputs, estimate)
            for kernel, dx, label, args, estimate in cases]


def finished(specs, results):
    """(the specs whose run finished without an error, the labels of the others)"""
    done = [s for s in specs if results.get(s.job.label) and "error" not in results[s.job.label]]
    return done, [s.job.label for s in specs if s not in done]


def section(title, setup, specs, results, table, text=None, figures=None, notes=None,
            not_run=None):
    """A report section whose runs each return one result (a row): the setup not_run when it is
    given and no spec ran; else table(rows), the lines text(rows) with the runs not measured
    named after them, and the figure names figures(rows) (a failure is noted in notes: the
    report must still be written)"""
    if not specs and not_run is not None:
        return {"title": title, "setup": not_run, "table": "", "text": "", "figures": []}
    done, bad = finished(specs, results)
    rows = [results[s.job.label] for s in done]
    lines = list(text(rows)) if rows and text else []
    names = []
    if rows and figures:
        try:
            names = list(figures(rows))
        except Exception as exc:  # the report must still be written
            notes.append(f"{title}: figures not made: {type(exc).__name__}: {exc}")
    return {"title": title, "setup": setup, "table": table(rows) if rows else "",
            "text": " ".join(t for t in lines + ([f"Not measured (failed or not run): "
                                                  f"{', '.join(bad)}."] if bad else []) if t),
            "figures": names}


def plugin_path():
    version = os.environ.get("BBPD_LAMMPS_VERSION", "20260704")
    return ROOT / "build" / f"lammps-{version}" / "bbpdplugin.so"


def function(func):
    """The function that a "module:function" name names."""
    module, name = func.split(":")
    return getattr(importlib.import_module(module), name)


def _call(func, workdir, kwargs):
    start = time.perf_counter()
    result = function(func)(workdir=workdir, **kwargs)
    result.setdefault("wall_s", time.perf_counter() - start)
    return result


def _jsonable(obj):
    """numpy arrays and scalars in job results"""
    return obj.tolist() if hasattr(obj, "tolist") else float(obj)


def _fmt(seconds):
    seconds = int(round(seconds))
    return f"{seconds // 60}m{seconds % 60:02d}s"


def run_jobs(jobs, cache_dir, workers=None, log=print):
    """Run jobs (reusing cached results); return {job.label: result}."""
    cache_dir = Path(cache_dir)
    cache_dir.mkdir(parents=True, exist_ok=True)
    workers = workers or os.cpu_count() or 1
    plugin = plugin_path()
    results, todo = {}, []
    for job in jobs:
        key = job.key(plugin)
        cached = cache_dir / f"{key}.json"
        if cached.is_file():
            results[job.label] = json.loads(cached.read_text())
            log(f"  reuse  {job.label} (finished earlier, inputs unchanged)")
        else:
            todo.append((job, key))
    if not todo:
        return results
    remaining = sum(j.estimate_s for j, _ in todo)
    log(f"  {len(todo)} run(s) to do on {workers} core(s), about {_fmt(remaining / workers)}")
    start = time.perf_counter()
    done = 0
    with cf.ProcessPoolExecutor(max_workers=workers) as pool:
        futures = {}
        for job, key in todo:
            workdir = cache_dir / key
            workdir.mkdir(exist_ok=True)
            futures[pool.submit(_call, job.func, str(workdir), job.kwargs)] = (job, key)
        for fut in cf.as_completed(futures):
            job, key = futures[fut]
            done += 1
            remaining -= job.estimate_s
            try:
                res = fut.result()
            except Exception as exc:  # a failed run is reported, the others go on
                res = {"error": f"{type(exc).__name__}: {exc}"}
                log(f"  [{done}/{len(todo)}] FAILED {job.label}: {res['error'][:300]}")
            else:
                (cache_dir / f"{key}.json").write_text(json.dumps(res, default=_jsonable))
                elapsed = time.perf_counter() - start
                log(f"  [{done}/{len(todo)}] {job.label}: {res.get('wall_s', 0):.1f} s; "
                    f"elapsed {_fmt(elapsed)}, about {_fmt(max(remaining, 0) / workers)} left")
            results[job.label] = res
    return results

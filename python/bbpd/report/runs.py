# SPDX-License-Identifier: GPL-2.0-or-later
"""Which runs the report makes, as jobs of bbpd.jobs, and what every job runs in its worker.

Job functions are named "bbpd.report:run_job" and "bbpd.report:dispersion_run" (the package
re-exports them): the names are part of each run's cache key, so finished runs stay reusable.
"""
import json
import os
import threading
import time
from pathlib import Path

from bbpd import jobs as jobmod
from bbpd import readers
from bbpd.benchmarks import (branching, dispersion, kalthoff_winkler_3d, kalthoff_winkler_deck,
                             kalthoff_winkler_grid, kalthoff_winkler_projectile,
                             kalthoff_winkler_study, kink, kink_convergence, mode1,
                             quasi_static, strip)
from bbpd.jobs import ROOT
from bbpd.kernels import KERNELS

BENCH = ROOT / "python" / "bbpd" / "benchmarks"
FREUND_PY = ROOT / "python" / "bbpd" / "freund.py"
METRICS_PY = ROOT / "python" / "bbpd" / "metrics.py"
READERS_PY = ROOT / "python" / "bbpd" / "readers.py"    # the benchmarks read their outputs with it

HEARTBEAT_S = 30.0            # a running job says so this often
ESTIMATES_ENV = "BBPD_REPORT_ESTIMATES"   # label -> expected seconds, for the heartbeat

# Resolutions.  Default: the whole set of LAMMPS runs stays within minutes on 2 cores (the
# README has the measured time); --full adds finer grids.
MODE1_TABLE2_DX = (0.1, 0.05, 0.025)        # m, Gaussian (paper Table 2)
MODE1_TABLE3_DX = mode1.TABLE3_DX           # m, three kernels (paper Table 3)
MODE2_DX = (1.0e-3, 0.5e-3)                 # m, three kernels (Fig. 12; the paper gives no dx)
MODE2_DX_FULL = (1.0e-3, 0.5e-3, 0.25e-3)
KW_DX = (2.0e-3, 1.0e-3)                    # m, three kernels (1 mm: the paper's, Figs. 14-15)
KW_GAUSSIAN_DX_FULL = (0.5e-3,)             # m, Gaussian only
KW_GROWTH = ("gaussian", 1.0e-3)            # the run whose damage pictures show the crack growing
KW_GAUSSIAN_DX_STUDY = (0.25e-3,)           # m, Gaussian only, --full: 320,000 atoms, one rank
MODE1PROP_DX = (0.1, 0.05)                  # m, three kernels (crack growth)
MODE1PROP_DX_FULL = (0.1, 0.05, 0.025)
# the kink test: by default the Gaussian kernel on the coarse grid with the crack along the
# rows at the five mixes (the cheapest set that draws the angle against the mix); --full runs
# the sweep of examples/kink-mixed-mode (bbpd.benchmarks.kink.cases)
KINK_DEFAULT = ("gaussian", 0.0)     # kernel, crack angle to the grid's rows (deg)

# Expected wall time of each single-rank run here, 2 at a time on 2 shared cores (s); only
# the time-left estimate and the job order (longest first) use them.
ESTIMATE_S = {
    "dispersion": 6.0,
    ("mode1", 0.1): 2.0, ("mode1", 0.05): 6.0, ("mode1", 0.025): 60.0, ("mode1", 0.0125): 300.0,
    ("mode2", 1.0e-3): 2.0, ("mode2", 0.5e-3): 8.0, ("mode2", 0.25e-3): 30.0,
    ("kw", 2.0e-3): 8.0, ("kw", 1.0e-3): 75.0, ("kw", 0.5e-3): 200.0, ("kw", 0.25e-3): 1200.0,
    ("mode1prop", 0.1): 3.0, ("mode1prop", 0.05): 15.0, ("mode1prop", 0.025): 160.0,
}


def run_job(workdir, target, args, label):
    """What every job runs (in a worker process): target(workdir=..., **args), announced when
    it starts and, while it runs, every HEARTBEAT_S; adds the LAMMPS and plugin versions its
    log reports, so that reused results say which build made them."""
    fn = jobmod.function(target)
    expected = json.loads(os.environ.get(ESTIMATES_ENV, "{}")).get(label)
    print(f"  start  {label}" + (f" (about {jobmod._fmt(expected)})" if expected else ""),
          flush=True)
    start = time.perf_counter()
    stop = threading.Event()

    def heartbeat():
        while not stop.wait(HEARTBEAT_S):
            print(f"  ...    {label}: running for {jobmod._fmt(time.perf_counter() - start)}"
                  + (f" of about {jobmod._fmt(expected)}" if expected else ""), flush=True)

    threading.Thread(target=heartbeat, daemon=True).start()
    try:
        res = dict(fn(workdir=workdir, **args))
    except Exception as exc:
        # re-raised as a plain RuntimeError: runner.LammpsError cannot be unpickled in the
        # parent (its __init__ needs two arguments), which would break the whole process pool
        raise RuntimeError(f"{type(exc).__name__}: {exc}") from None
    finally:
        stop.set()
    res["job_s"] = time.perf_counter() - start
    res.update(build_of_run(workdir))
    return res


def build_of_run(workdir):
    """LAMMPS version and plugin version from the first log.lammps under workdir."""
    for log in sorted(Path(workdir).rglob("log.lammps")):
        return readers.build_versions(log.read_text(errors="replace"))
    return {}


def dispersion_run(workdir, kernel):
    """One kernel of the dispersion benchmark: run, FFT ridge, deviations (dispersion.measure)."""
    start = time.perf_counter()
    res = dispersion.measure((kernel,), work=workdir)[kernel]
    res["wall_time"] = time.perf_counter() - start
    return res


def _tools():
    """The dispersion tools, part of the dispersion jobs' inputs when built."""
    out = []
    for name in ("bbpd-measure-dispersion", "bbpd-dispersion-curves"):
        try:
            out.append(str(dispersion.find_tool(name)))
        except FileNotFoundError:
            pass
    return tuple(out)


def bench_inputs(bench):
    """The files a run of bench depends on (input script, analysis code, potential file): part
    of its cache key, so that editing one reruns exactly the runs that read it."""
    if bench == "dispersion":
        return (ROOT / "examples" / "dispersion-1d" / "in.dispersion", BENCH / "dispersion.py",
                READERS_PY) + _tools()
    return {"mode1": (ROOT / "examples" / "mode1-semi-infinite" / "in.mode1", BENCH / "mode1.py",
                      FREUND_PY, METRICS_PY, READERS_PY),
            "mode2": (ROOT / "examples" / "mode2-central-crack" / "in.mode2", BENCH / "mode2.py",
                      FREUND_PY, METRICS_PY, READERS_PY),
            "kw": (ROOT / "examples" / "kalthoff-winkler" / "in.kalthoff_winkler",
                   BENCH / "kalthoff_winkler.py",
                   ROOT / "potentials" / "kalthoff_winkler_steel.bbpd", READERS_PY),
            "mode1prop": (ROOT / "examples" / "mode1-propagation" / "in.mode1-propagation",
                          BENCH / "mode1_propagation.py", BENCH / "mode1.py",
                          ROOT / "python" / "bbpd" / "crack_motion.py",
                          ROOT / "python" / "bbpd" / "crack_tip.py", FREUND_PY,
                          READERS_PY)}[bench]


def label_of(bench, kernel, dx, args):
    """The run's name in the log and the report (part of its cache key)."""
    return {"dispersion": f"dispersion {kernel}",
            "mode1": f"Mode I {kernel} dx = {dx:g} m",
            "mode2": f"Mode II {kernel} dx = {dx * 1e3:g} mm",
            "kw": f"Kalthoff-Winkler {kernel} dx = {dx * 1e3:g} mm",
            "mode1prop": f"Mode I propagation {kernel} dx = {dx:g} m"}[bench]


def make_spec(bench, kernel, dx, target, args, inputs, estimate):
    """One run of the report: target(workdir, **args) as a cached job whose key covers the
    files in inputs (input script, analysis code)."""
    return jobmod.report_spec(bench, kernel, dx, label_of(bench, kernel, dx, args), target, args,
                              inputs, estimate)


def _runs(bench, cases, target, estimate_s):
    """a single-rank run of target for every (kernel, dx) of cases (the KW_GROWTH run of the
    Kalthoff-Winkler plate draws its damage pictures)"""
    inputs, specs = bench_inputs(bench), []
    for k, dx in cases:
        args = {"kernel": k, "dx": dx, "nprocs": 1}
        if bench == "kw" and (k, dx) == KW_GROWTH:
            args["images"] = True
        specs.append(make_spec(bench, k, dx, target, args, inputs,
                               ESTIMATE_S.get((bench, dx), estimate_s)))
    return specs


def benchmark_specs(full=False, study=None):
    """The benchmarks' runs of the report: default resolutions, or the paper's full ones with
    full=True, with the loading study unless study=False (make.job_list adds the
    work-precision runs)."""
    study = full if study is None else study
    specs = [make_spec("dispersion", k, 0.2e-3, "bbpd.report:dispersion_run", {"kernel": k},
                       bench_inputs("dispersion"), ESTIMATE_S["dispersion"]) for k in KERNELS]
    mode1 = [("gaussian", dx) for dx in MODE1_TABLE2_DX]
    mode1 += [(k, MODE1_TABLE3_DX) for k in KERNELS if (k, MODE1_TABLE3_DX) not in mode1]
    specs += _runs("mode1", mode1, "bbpd.benchmarks.mode1:run", 60.0)
    specs += _runs("mode2", [(k, dx) for dx in (MODE2_DX_FULL if full else MODE2_DX)
                             for k in KERNELS], "bbpd.benchmarks.mode2:run", 60.0)
    kw = [(k, dx) for dx in KW_DX for k in KERNELS]
    kw += [("gaussian", dx) for dx in KW_GAUSSIAN_DX_FULL if full]
    # where the Gaussian angle converges (examples/kalthoff-winkler/README.md)
    kw += [("gaussian", dx) for dx in KW_GAUSSIAN_DX_STUDY if study]
    specs += _runs("kw", kw, "bbpd.benchmarks.kalthoff_winkler:run", 600.0)
    specs += _runs("mode1prop", [(k, dx) for dx in (MODE1PROP_DX_FULL if study else MODE1PROP_DX)
                                 for k in KERNELS], "bbpd.benchmarks.mode1_propagation:run", 160.0)
    # the experiment's projectile: the Gaussian at 2 mm; --full adds the other kernels and 1 mm
    specs += kalthoff_winkler_projectile.jobs(full=study)
    specs += kink_specs(study)
    specs += strip.jobs(full=study)    # the strip: Gaussian on a short strip; --full the sweep
    specs += branching.jobs(full=study)    # crack branching: the Gaussian at 2 MPa; --full the sweep
    specs += quasi_static.jobs(full=full)    # examples/quasi-static (fix bbpd/relax)
    if study:    # the Kalthoff-Winkler loading study (32 runs, about 1 h of single-core run time)
        specs += kalthoff_winkler_study.jobs()
        specs += kalthoff_winkler_grid.jobs()    # the grid's pull (44 runs)
        specs += kalthoff_winkler_deck.jobs()    # both decks, bond-based and state-based (30 runs)
        specs += kalthoff_winkler_3d.jobs()      # the 3D plate, 4 horizons through it (4 runs)
        specs += kink_convergence.jobs()         # the kink angle against m and R/delta (6 runs)
    return specs


def kink_specs(full=False):
    """The kink test's runs: KINK_DEFAULT's five mixes, or with full=True the whole sweep."""
    kernel, alpha = KINK_DEFAULT
    return kink.jobs([c for c in kink.cases() if full or (c[0], c[2], c[3], c[5]) ==
                      (kernel, alpha, kink.COARSE[0], kink.NCROSS)])

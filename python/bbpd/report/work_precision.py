# SPDX-License-Identifier: GPL-2.0-or-later
"""Work-precision diagrams: error against run time for every benchmark of tools/reproduce, one
line per kernel through its resolutions (doc/work_precision.md). extra_specs() adds the runs
the report lacks and the timing repeats; section() writes the CSV, the figures and the report
section.
"""

import math
import shutil
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from bbpd.benchmarks import center_crack, dispersion
from bbpd.benchmarks.kalthoff_winkler import EXPERIMENT_ANGLE_DEG
from bbpd import csvfile
from bbpd import jobs as jobmod
from bbpd.jobs import Job, Spec
from bbpd.kernels import KERNELS
from .sections import figure_names
from bbpd.provenance import machine
from .runs import ESTIMATE_S, bench_inputs, build_of_run, label_of
from .tables import failed, md_table
from .work_precision_figure import METHOD_LABEL, plot

BENCHMARKS = ("mode1", "mode2", "dispersion", "kalthoff_winkler", "quasi_static")
CSV_COLUMNS = ("benchmark", "kernel", "method", "resolution", "error_metric", "error", "wall_s")
CSV_NAME = "work_precision.csv"

# report.py's benchmark names -> ours; "wp-*" are the runs added here
BENCH_OF_SPEC = {"mode1": "mode1", "wp-mode1": "mode1", "mode2": "mode2", "wp-mode2": "mode2",
                 "dispersion": "dispersion", "wp-dispersion": "dispersion",
                 "kw": "kalthoff_winkler", "wp-kw": "kalthoff_winkler"}
TIMING_BENCH = "wp-timing"

# resolutions (m): one line per kernel through them
MODE1_DX = (0.1, 0.05, 0.025)
MODE1_DX_FULL = MODE1_DX + (0.0125,)
MODE2_DX = (1.0e-3, 0.5e-3)
MODE2_DX_FULL = MODE2_DX + (0.25e-3,)
KW_DX = (2.0e-3, 1.0e-3)
KW_DX_FULL = KW_DX + (0.5e-3,)

# dispersion: the example's ring (1000 atoms at dx = delta/5 = 0.2 mm) kept at its physical
# length and run time while m = delta/dx grows at the paper's delta = 1 mm
DISPERSION_M = (3, 5, 10)
DISPERSION_M_FULL = DISPERSION_M + (20,)
DISPERSION_DELTA = 1.0e-3          # m, paper Figs. 4-6
RING_LENGTH = 0.2                  # m: in.dispersion's default 1000 atoms x 0.2 mm
RING_STEPS_PER_M = 400             # in.dispersion's default 2000 steps at m = 5, dt = dx/v
RING_SAMPLES = 1000                # samples of u(x, t): in.dispersion's 2000 steps / every 2
WAVELENGTH_MODE = 64               # the fixed wave: 64 wavelengths on the ring (k delta = 2.01)
WAVELENGTH = RING_LENGTH / WAVELENGTH_MODE
K_MATCH_RTOL = 1.0e-9              # the ring's k grid holds 2 pi/WAVELENGTH to round-off

TIMING_REPEATS = 3                 # runs timed this often (median) when expected short
REPEAT_BELOW_S = 10.0              # "short": expected loop time below this

# expected wall time of the dispersion rings (s; the other runs': runs.ESTIMATE_S): job order
# and the choice of which runs are repeated for timing only
DISPERSION_ESTIMATE_S = {3: 2.0, 5: 3.0, 10: 6.0, 20: 9.0}

# the error that the report asks each kernel's cost for
TARGETS = {("mode1", "L2 (%)"): 3.0,        # the paper's Gaussian L2 at dx = 0.05 m: 2.86 %
           ("mode1", "peak (%)"): 1.0,
           ("mode2", "L2 (%)"): 10.0,
           ("dispersion", "|c/c_29 - 1|"): 5.0e-3,
           ("kalthoff_winkler", "|angle - finest| (deg)"): 3.0,
           ("kalthoff_winkler", "|angle - 70 deg| (deg)"): 10.0,
           ("quasi_static", "|sigma_c/relaxed - 1| (%)"): 1.0}

# quasi-static crack initiation (examples/quasi-static): not run by the report, read from the
# example's committed CSV (bbpd.benchmarks.center_crack --dynamic); its resolution is the
# bisection's bracket (relax, below 1) or the ramp in transit times (dynamic, 1 and above)
QUASI_STATIC_CSV = center_crack.HERE / "results" / "center_crack_dynamic.csv"


@dataclass(frozen=True)
class Plan:
    """Resolutions of the work-precision study (dx in m; dispersion: m)."""
    mode1_dx: tuple = MODE1_DX
    mode2_dx: tuple = MODE2_DX
    kw_dx: tuple = KW_DX
    dispersion_m: tuple = DISPERSION_M
    kernels: tuple = KERNELS
    repeats: int = TIMING_REPEATS


def plan(full=False):
    if full:
        return Plan(MODE1_DX_FULL, MODE2_DX_FULL, KW_DX_FULL, DISPERSION_M_FULL)
    return Plan()


# --------------------------------------------------------------------------- jobs

def dispersion_vars(m):
    """in.dispersion variables of the ring at m = delta/dx: fixed length, duration, samples."""
    natoms = int(round(RING_LENGTH * m / DISPERSION_DELTA))
    nsteps = int(round(RING_STEPS_PER_M * m))
    return {"m": m, "delta": DISPERSION_DELTA, "natoms": natoms, "nsteps": nsteps,
            "every": max(1, int(round(nsteps / RING_SAMPLES)))}


def dispersion_run(workdir, kernel, m):
    """One kernel of the dispersion ring at m = delta/dx (dispersion.measure)."""
    res = dispersion.measure((kernel,), work=workdir, **dispersion_vars(m))[kernel]
    res["analytic"] = {kernel: res["analytic"][kernel]}    # the other kernels' are not needed
    return res


def loop_time(res):
    """The LAMMPS loop time (s) a benchmark result reports, or None."""
    for value in (res.get("loop_time"), res.get("loop_s"), (res.get("info") or {}).get("loop_s")):
        if value is not None:
            return float(value)
    return None


def repeat_run(workdir, target, args, repeats, of=None):
    """Time target(**args) again, up to `repeats` times, while its loop time stays short:
    returns the loop times (s).  Only the times are kept; the outputs are deleted.
    of: the label of the report's run of the same arguments (only names it)."""
    fn = jobmod.function(target)
    times, build = [], {}
    for n in range(repeats):
        sub = Path(workdir) / f"repeat{n}"
        try:
            t = loop_time(dict(fn(workdir=str(sub), **args)))
            # read before the outputs go: REPORT.md's header names the build of every run
            build = build or build_of_run(sub)
        finally:
            shutil.rmtree(sub, ignore_errors=True)
        if t is None:
            raise RuntimeError(f"{target}: the run reports no loop time")
        times.append(t)
        if t >= REPEAT_BELOW_S:
            break
    return {"loop_times": times, **build}


def _timing_spec(spec, repeats):
    label = f"timing of {spec.job.label}"
    kw = spec.job.kwargs
    job = Job(label=label, func="bbpd.report.work_precision:repeat_run",
              kwargs={"target": kw["target"], "args": kw["args"], "repeats": repeats,
                      "of": spec.job.label},
              # this file too: a result cached by an older repeat_run (without the versions
              # of its build) is made again
              inputs=tuple(spec.job.inputs) + (__file__,), estimate_s=spec.job.estimate_s * repeats)
    return Spec(TIMING_BENCH, spec.kernel, spec.dx, job)


def extra_specs(specs, the_plan):
    """The runs of the_plan that specs (the report's benchmark runs) lacks, and timing repeats of the
    short ones (estimate below REPEAT_BELOW_S): a list of Spec."""
    have = {(BENCH_OF_SPEC.get(s.bench), s.kernel, round(s.dx, 12)): s for s in specs
            if s.bench != TIMING_BENCH}
    out, runs = [], []

    def want(bench, kernel, dx, make):
        key = (bench, kernel, round(dx, 12))
        if key not in have:
            have[key] = make()
            out.append(have[key])
        runs.append(have[key])

    # (benchmark, its name in bbpd.report.runs, target, resolutions, estimate where runs has none)
    benches = (("mode1", "mode1", "bbpd.benchmarks.mode1:run", the_plan.mode1_dx, 60.0),
               ("mode2", "mode2", "bbpd.benchmarks.mode2:run", the_plan.mode2_dx, 60.0),
               ("kalthoff_winkler", "kw", "bbpd.benchmarks.kalthoff_winkler:run",
                the_plan.kw_dx, 600.0))
    for k in the_plan.kernels:
        for m in the_plan.dispersion_m:
            dx = DISPERSION_DELTA / m
            want("dispersion", k, dx, lambda: jobmod.report_spec(
                "wp-dispersion", k, dx, f"dispersion {k} m = {m:g}",
                "bbpd.report.work_precision:dispersion_run", {"kernel": k, "m": m},
                bench_inputs("dispersion"), DISPERSION_ESTIMATE_S.get(m, 60.0)))
        for bench, name, target, dxs, default in benches:
            for dx in dxs:    # the same inputs as the report's own runs of the benchmark
                args = {"kernel": k, "dx": dx, "nprocs": 1}
                want(bench, k, dx, lambda: jobmod.report_spec(
                    "wp-" + name, k, dx, label_of(name, k, dx, args), target, args,
                    bench_inputs(name), ESTIMATE_S.get((name, dx), default)))
    if the_plan.repeats > 1:
        out += [_timing_spec(s, the_plan.repeats - 1) for s in runs
                if s.job.estimate_s < REPEAT_BELOW_S]
    return out


# --------------------------------------------------------------------------- measurements

def dispersion_error(res, kernel, wavelength=WAVELENGTH):
    """|c_measured/c_29 - 1| at the wave number 2 pi/wavelength (a point of the ring's grid)."""
    meas, ana = res["measured"], res["analytic"][kernel]
    k = np.asarray(meas["k"], dtype=float)
    target = 2.0 * math.pi / wavelength
    i = int(np.argmin(np.abs(k - target)))
    if abs(k[i] / target - 1.0) > K_MATCH_RTOL:
        raise ValueError(f"the ring's k grid misses k = {target:.6g} 1/m (nearest {k[i]:.6g}): "
                         "its length must be a multiple of the wavelength")
    if abs(float(ana["k"][i]) / k[i] - 1.0) > K_MATCH_RTOL:
        raise ValueError("measured and analytic k grids differ")
    phase = float(meas["omega"][i]) / k[i]
    continuum = float(ana["omega_continuous"][i]) / float(ana["k"][i])
    return abs(phase / continuum - 1.0)


def points_of(bench, res, kernel):
    """[(method, error_metric, error)] of one finished run (the KW angle against the finest run
    is added later, in rows())."""
    if bench == "mode1":
        out = [("dsif", "L2 (%)", res["consistent"]["l2"]),
               ("dsif", "peak (%)", res["consistent"]["peak"])]
        j = (res.get("jintegral") or {}).get("consistent")
        if j:
            out += [("jintegral", "L2 (%)", j["l2"]), ("jintegral", "peak (%)", j["peak"])]
        return out
    if bench == "mode2":
        out = [("dsif", "L2 (%)", res["l2"])]
        if res.get("jintegral"):
            out.append(("jintegral", "L2 (%)", res["jintegral"]["l2"]))
        return out
    if bench == "dispersion":
        return [("ridge", "|c/c_29 - 1|", dispersion_error(res, kernel))]
    out = []
    if res.get("angle_deg") is not None:
        out.append(("damage", "|angle - 70 deg| (deg)",
                    abs(res["angle_deg"] - EXPERIMENT_ANGLE_DEG)))
    if res.get("t_band_us") is not None:
        out.append(("damage", "initiation time (us)", res["t_band_us"]))
    return out


def rows(runs, notes=None):
    """CSV rows from runs: [(benchmark, kernel, dx, result, wall_s)] of finished runs.
    Adds the Kalthoff-Winkler angle against each kernel's finest run (not for that run).
    A run that cannot be measured (e.g. a ring without the wavelength) is left out and named
    in notes."""
    out = []
    finest = {}
    for bench, kernel, dx, res, wall in runs:
        if bench == "kalthoff_winkler" and res.get("angle_deg") is not None:
            if kernel not in finest or dx < finest[kernel][0]:
                finest[kernel] = (dx, res["angle_deg"])
    for bench, kernel, dx, res, wall in runs:
        try:
            points = points_of(bench, res, kernel)
        except ValueError as exc:
            if notes is not None:
                notes.append(f"work-precision: {bench} {kernel} dx = {dx:g} m left out: {exc}")
            continue
        for method, metric, err in points:
            out.append(dict(benchmark=bench, kernel=kernel, method=method, resolution=dx,
                            error_metric=metric, error=float(err), wall_s=wall))
        if (bench == "kalthoff_winkler" and kernel in finest and dx > finest[kernel][0]
                and res.get("angle_deg") is not None):
            out.append(dict(benchmark=bench, kernel=kernel, method="damage", resolution=dx,
                            error_metric="|angle - finest| (deg)",
                            error=abs(res["angle_deg"] - finest[kernel][1]), wall_s=wall))
    order = {b: n for n, b in enumerate(BENCHMARKS)}
    out.sort(key=lambda r: (order[r["benchmark"]], r["error_metric"], r["method"],
                            KERNELS.index(r["kernel"]) if r["kernel"] in KERNELS else 99,
                            -r["resolution"]))
    return out


def quasi_static_rows(path=QUASI_STATIC_CSV):
    """rows() of the committed initiation study: the error against LEFM and against the
    tightest bisection, per solver (relax: resolution = the bracket; dynamic: the ramp)"""
    out = []
    for r in csvfile.read_csv(path)[1]:
        res = r["ramp_transits"] if r["solver"] == "dynamic" else r["bracket"]
        for metric, err in (("|sigma_c/LEFM - 1| (%)", r["error"]),
                            ("|sigma_c/relaxed - 1| (%)", r["vs_relax"])):
            if metric.startswith("|sigma_c/r") and res == center_crack.TIGHT_RES:
                continue    # the reference itself
            out.append(dict(benchmark="quasi_static", kernel=r["kernel"], method=r["solver"],
                            resolution=res, error_metric=metric, error=100 * abs(err),
                            wall_s=r["wall_s"]))
    return out


# --------------------------------------------------------------------------- cost of a target

def cost_to_reach(table, benchmark, metric, target):
    """(kernel, method) -> (wall_s, resolution) of the cheapest run with error <= target, or
    None with the best error instead: {(kernel, method): ("reached", wall, dx) | ("missed",
    best error, wall, dx)}."""
    out = {}
    for r in table:
        if r["benchmark"] != benchmark or r["error_metric"] != metric:
            continue
        key = (r["kernel"], r["method"])
        if r["error"] <= target:
            cur = out.get(key)
            if cur is None or cur[0] == "missed" or r["wall_s"] < cur[1]:
                out[key] = ("reached", r["wall_s"], r["resolution"])
        else:
            cur = out.get(key)
            if cur is None or (cur[0] == "missed" and r["error"] < cur[1]):
                out[key] = ("missed", r["error"], r["wall_s"], r["resolution"])
    return out


def _fmt_s(seconds):
    return f"{seconds:.2g} s" if seconds < 10 else f"{seconds:.0f} s"


def _fmt_dx(benchmark, dx):
    if benchmark == "dispersion":
        return f"m = {DISPERSION_DELTA / dx:.3g}"
    if benchmark == "mode1":
        return f"dx = {dx:g} m"
    if benchmark == "quasi_static":
        return f"bracket {100 * dx:g} %" if dx < 1 else f"ramp {dx:g} T"
    return f"dx = {dx * 1e3:g} mm"


def _fmt_err(metric, value):
    if metric.startswith("|c/"):
        return f"{100 * value:.2g} %"
    unit = " %" if "(%)" in metric else " deg" if "(deg)" in metric else ""
    return f"{value:.3g}{unit}"


def reach_table(table):
    """Markdown: for each target of TARGETS, method and kernel, the cheapest run that reaches
    it (run time, resolution), or the best error reached and at what cost."""
    body = []
    for (bench, metric), target in TARGETS.items():
        reach = cost_to_reach(table, bench, metric, target)
        for (kernel, method), v in sorted(reach.items(), key=lambda kv: (
                list(METHOD_LABEL).index(kv[0][1]), kv[1][0] != "reached", kv[1][1])):
            cost = (f"{_fmt_s(v[1])} ({_fmt_dx(bench, v[2])})" if v[0] == "reached" else
                    f"not reached: best {_fmt_err(metric, v[1])} at {_fmt_s(v[2])} ({_fmt_dx(bench, v[3])})")
            body.append([bench, f"{metric.split(' (')[0]} <= {_fmt_err(metric, target)}",
                         METHOD_LABEL[method], kernel, cost])
    return md_table(["benchmark", "target", "method", "kernel", "run time of the cheapest run "
                     "that reaches it"], body) if body else ""


# --------------------------------------------------------------------------- report section

# the title of each benchmark's work-precision figure
TITLES = {"mode1": "Mode I: K_I against Freund (consistent constants)",
          "mode2": "Mode II: K_II against the FE-checked reference",
          "dispersion": f"1D dispersion: phase velocity against eq. 29,\nwavelength "
                        f"{WAVELENGTH * 1e3:g} mm, delta = {DISPERSION_DELTA * 1e3:g} mm",
          "kalthoff_winkler": "Kalthoff-Winkler: crack angle and initiation",
          "quasi_static": "Quasi-static crack initiation (centre crack, Gaussian, delta = 2 mm):\n"
                          "relaxed bisection and dynamic ramps"}


SETUP = ("Error against run time for every benchmark, one line per kernel through its resolutions "
         "(Mode I and II: per K extraction method; both methods come from the same run, so they "
         "share its time). Run time: the LAMMPS loop time of the single-rank run (\"Loop time of "
         "X on 1 procs\": the time steps, without start-up and setup), the median of {repeats} "
         "timings for runs expected under {below:g} s (timings per run: {counts}); the runs share "
         "the cores with each other and with anything else on the machine. Dispersion: a ring of "
         "fixed length {ring:g} m and fixed horizon {delta:g} mm (m = delta/dx in the table), "
         "error |c/c_29 - 1| at the wavelength {wl:g} mm (k delta = {kd:.2f}). Kalthoff-Winkler: "
         "initiation = the damage band leaves the tip. Quasi-static initiation: {qs}, committed "
         "(wall time of the whole LAMMPS runs). Machine: {machine}. All points: {csv}.")


def collect(specs, results):
    """Finished runs and their run times: ([(benchmark, kernel, dx, result, wall_s)],
    {label: number of timings})."""
    repeats = {}
    for s in specs:
        if s.bench == TIMING_BENCH:
            res = results.get(s.job.label)
            if not failed(res):
                repeats[s.job.kwargs["of"]] = list(res["loop_times"])
    runs, samples, seen = [], {}, set()
    for s in specs:
        bench = BENCH_OF_SPEC.get(s.bench)
        if bench is None:
            continue
        key = (bench, s.kernel, round(s.dx, 12))
        res = results.get(s.job.label)
        if key in seen or failed(res):
            continue
        seen.add(key)
        times = [t for t in [loop_time(res)] + repeats.get(s.job.label, []) if t is not None]
        if not times:
            continue
        samples[s.job.label] = len(times)
        runs.append((bench, s.kernel, s.dx, res, float(np.median(times))))
    return runs, samples


def section(specs, results, figdir, notes):
    """The report section: CSV, one figure per benchmark, the error per resolution and the cost
    of reaching each target."""
    figdir = Path(figdir)
    runs, samples = collect(specs, results)
    table = rows(runs, notes) + quasi_static_rows()
    csv_path = figdir / "csv" / CSV_NAME    # resolution: dx in m
    csvfile.write_csv(csv_path, table, columns=CSV_COLUMNS)
    figs = []
    for bench in BENCHMARKS:
        if not any(r["benchmark"] == bench for r in table):
            continue
        path = figdir / f"work_precision_{bench}.png"
        figs += figure_names(lambda: [plot(path, table, bench, TITLES[bench],
                                           lambda dx: _fmt_dx(bench, dx))], f"figure {path.name}", notes)
    reach = reach_table(table)
    text = ["The cost of reaching each target error:\n\n" + reach] if reach else []
    setup = SETUP.format(repeats=TIMING_REPEATS, below=REPEAT_BELOW_S,
                         counts=", ".join(map(str, sorted(set(samples.values())))) or "-",
                         ring=RING_LENGTH, delta=DISPERSION_DELTA * 1e3, wl=WAVELENGTH * 1e3,
                         kd=2 * math.pi * DISPERSION_DELTA / WAVELENGTH, qs=QUASI_STATIC_CSV.name,
                         machine=machine(), csv=f"{csv_path.parent.name}/{csv_path.name}")
    return {"title": "Error against run time (work-precision diagrams)", "setup": setup,
            "table": summary_table(table), "text": " ".join(text), "figures": figs}


def summary_table(table):
    """Markdown: one row per benchmark, kernel, method and metric: error (run time) per
    resolution, coarsest first."""
    def key(r):
        return r["benchmark"], r["kernel"], r["method"], r["error_metric"]
    body = []
    for bench, kernel, method, metric in dict.fromkeys(map(key, table)):    # in the table's order
        pts = sorted(((r["resolution"], r["error"], r["wall_s"]) for r in table
                      if key(r) == (bench, kernel, method, metric)), reverse=True)
        body.append([bench, kernel, METHOD_LABEL[method], metric,
                     "; ".join(f"{_fmt_dx(bench, dx)}: {_fmt_err(metric, e)} ({_fmt_s(w)})"
                               for dx, e, w in pts)])
    return md_table(["benchmark", "kernel", "method", "metric",
                     "error (run time) per resolution"], body)

# SPDX-License-Identifier: GPL-2.0-or-later
"""Kalthoff-Winkler on perturbed and rotated grids: how far the square grid's preferred
directions move the crack angle (examples/kalthoff-winkler/README.md, "The grid's pull").

Runs examples/kalthoff-winkler/in.kalthoff_winkler with `-var grid square | perturbed |
rotated` (GRIDS), under the paper's prescribed loading and with the projectile, with the
paper's G_c, to 100 us, and measures each run with the loading study's definitions
(kalthoff_winkler_study.analyse; the projectile's contact measures from
kalthoff_winkler_projectile.analyse).  The square grid is mirror-symmetric about the mid-line,
so its two cracks are mirror images; off the square grid they are not (a rotated grid's
mirror image is the grid rotated the other way), so every crack is measured on its own:

angles        initial, fit and chord (the study's; fit and chord at 70 us) of each crack,
              None for a crack shorter than 15 mm at 70 us
pull          per kernel, loading, grid spacing and angle definition: the square grid's angle
              minus the mean over the cracks of every perturbed and rotated grid, with the
              standard deviation of those cracks and the standard error of their mean

Command line (from the repository root; finished runs are cached in --work):
  tools/python -m bbpd.benchmarks.kalthoff_winkler_grid --work /tmp/kw-grid \\
      --csv examples/kalthoff-winkler/results/grid_pull.csv
"""

import argparse
import math
import time
from pathlib import Path

import numpy as np

from bbpd import jobs as jobmod
from bbpd import provenance, readers
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import kalthoff_winkler_projectile as projectile
from bbpd.benchmarks import kalthoff_winkler_study as study
from bbpd.csvfile import read_csv, write_csv
from bbpd.jobs import Job, Spec
from bbpd.runner import run_lammps

CSV = kw.EXAMPLE.parent / "results" / "grid_pull.csv"
COMMAND = ("tools/python -m bbpd.benchmarks.kalthoff_winkler_grid --work /tmp/kw-grid "
           "--csv examples/kalthoff-winkler/results/grid_pull.csv")

# name -> the input script's grid variables.  Three seeds of the perturbed grid (points moved
# by up to the script's default 0.2 dx) and two rotations: at 22.5 deg the grid's directions
# (22.5 + k 45 deg) are the same for both cracks, with one at 67.5 deg; at 30 deg they are
# 30 + k 45 deg, i.e. 75 deg for the upper crack and 60 deg for the lower one.
GRIDS = {
    "square": {},
    "perturbed-1": {"grid": "perturbed", "seed": 5879},
    "perturbed-2": {"grid": "perturbed", "seed": 7411},
    "perturbed-3": {"grid": "perturbed", "seed": 9137},
    "rotated-22.5": {"grid": "rotated", "gridangle": 22.5},
    "rotated-30": {"grid": "rotated", "gridangle": 30.0},
}
LOADINGS = ("prescribed", "projectile")
# (kernel, dx, grids): every kernel and grid at 2 mm; the Gaussian at 1 mm on one grid of each
# kind (a 1 mm projectile run costs about 8 of 2 mm)
CASES = ([(k, 2.0e-3, tuple(GRIDS)) for k in kw.KERNELS]
         + [("gaussian", 1.0e-3, ("square", "perturbed-1", "rotated-22.5", "rotated-30"))])
TEND = projectile.TEND
ANGLES = study.ANGLE_DEFS
SIDES = ("lo", "hi")


# ---------------------------------------------------------------------------- running

def grid_vars(grid):
    return {k: (v if isinstance(v, str) else repr(v)) for k, v in GRIDS[grid].items()}


# per-atom data of the analysis, not needed for the rows
BULKY = ("damage_map", "trajectory", "crack_lo", "crack_hi")


def run_case(workdir, kernel, dx, loading, grid, nprocs=1, tend=TEND):
    """Run one case in workdir and measure it (the job of this module and the report); the
    rows are made from the result by row(), outside the job, so that the table's code is no
    part of the runs' cache key."""
    workdir = Path(workdir)
    variables = {"kernel": kernel, "dx": repr(float(dx)), "tend": repr(float(tend)),
                 "loading": loading}
    variables.update(grid_vars(grid))
    start = time.perf_counter()
    run_lammps(str(kw.EXAMPLE), workdir, nprocs=nprocs, vars=variables)
    wall = time.perf_counter() - start
    res = projectile.analyse(workdir)
    res.update(nprocs=nprocs, wall_s=wall, grid=grid)
    return {k: v for k, v in res.items() if k not in BULKY}


def side_angle(res, side, definition):
    """One crack's angle (the study's definitions), None if it is shorter than the initial
    range at 70 us (its direction is no path yet)."""
    a70 = res.get("angles_t70", {}).get(side)
    if a70 is None or a70["length_mm"] < study.INITIAL_RANGE[1] * 1e3:
        return None
    if definition == "initial":
        return res["initial_side_deg"][side]
    return a70[definition]


COLUMNS = (("grid", "loading", "kernel", "dx_mm", "first_bond_us", "band_us")
           + tuple(f"{d}_{s}_deg" for d in ANGLES for s in SIDES)
           + ("length_lo_mm", "length_hi_mm", "length_end_mm", "crack_stops", "far_edge_us",
              "v_interface", "loop_cpu_s", "nprocs"))


def row(res, grid):
    """The CSV row of one run: both cracks' angles, initiation, length, how the crack stops."""
    out = {"grid": grid, "loading": res["loading"], "kernel": res["kernel"],
           "dx_mm": res["dx"] * 1e3, "first_bond_us": res["t_init_us"],
           "band_us": res["t_band_us"]}
    for d in ANGLES:
        for side in SIDES:
            out[f"{d}_{side}_deg"] = side_angle(res, side, d)
    for side in SIDES:
        out[f"length_{side}_mm"] = res["angles_t70"][side]["length_mm"] if "angles_t70" in res else None
    out["length_end_mm"] = res["length_end_mm"]
    out["crack_stops"] = study.stops(res).split(" (")[0]
    out["far_edge_us"] = res.get("far_edge_own_us")
    out["v_interface"] = res.get("v_interface")
    out["loop_cpu_s"] = res["loop_cpu_s"]
    out["nprocs"] = res["nprocs"]
    return out


def jobs(cases=CASES, loadings=LOADINGS, nprocs=1):
    """The runs as bbpd.report specs (this module's command and tools/reproduce --full)."""
    inputs = (kw.EXAMPLE, Path(kw.__file__), Path(study.__file__), Path(projectile.__file__),
              kw.ROOT / "potentials" / "kalthoff_winkler_steel.bbpd",
              Path(readers.__file__))
    specs = []
    for kernel, dx, grids in cases:
        for grid in grids:
            for loading in loadings:
                label = f"Kalthoff-Winkler grid {grid} {loading} {kernel} dx = {dx * 1e3:g} mm"
                job = Job(label=label, func="bbpd.report:run_job",
                          kwargs={"target": "bbpd.benchmarks.kalthoff_winkler_grid:run_case",
                                  "args": {"kernel": kernel, "dx": dx, "loading": loading,
                                           "grid": grid, "nprocs": nprocs},
                                  "label": label},
                          inputs=tuple(str(p) for p in inputs),
                          estimate_s=(8.0 if dx > 1.5e-3 else 60.0) * (
                              2.5 if loading == "projectile" else 1.0))
                specs.append(Spec("kwgrid", kernel, dx, job))
    return specs


def collect(specs, results):
    """The rows of the finished runs among specs, in the CSV's order."""
    rows = [row(results[s.job.label], results[s.job.label]["grid"]) for s in specs
            if s.job.label in results and "error" not in results[s.job.label]]
    return sorted(rows, key=order)


def order(r):
    return (LOADINGS.index(r["loading"]), kw.KERNELS.index(r["kernel"]), -float(r["dx_mm"]),
            list(GRIDS).index(r["grid"]))


# ---------------------------------------------------------------------------- the pull

def pull(rows):
    """{(loading, kernel, dx_mm, definition): dict(square, off=[angles of every off-grid
    crack], mean, sd, se, pull = square - mean)} over the groups with a square run and at least
    one off-grid crack with that angle."""
    out = {}
    groups = {}
    for r in rows:
        groups.setdefault((r["loading"], r["kernel"], float(r["dx_mm"])), []).append(r)
    for (loading, kernel, dx), rs in groups.items():
        sq = [r for r in rs if r["grid"] == "square"]
        if not sq:
            continue
        for d in ANGLES:
            square = [sq[0][f"{d}_{s}_deg"] for s in SIDES if sq[0][f"{d}_{s}_deg"] is not None]
            off = [r[f"{d}_{s}_deg"] for r in rs if r["grid"] != "square" for s in SIDES
                   if r[f"{d}_{s}_deg"] is not None]
            if not square or not off:
                continue
            mean = float(np.mean(off))
            sd = float(np.std(off, ddof=1)) if len(off) > 1 else None
            out[(loading, kernel, dx, d)] = {
                "square": float(np.mean(square)), "off": off, "n": len(off), "mean": mean,
                "sd": sd, "se": None if sd is None else sd / math.sqrt(len(off)),
                "pull": float(np.mean(square)) - mean}
    return out


def pull_sentence(rows):
    """How many degrees the square grid moves the angle, per kernel: computed from the rows."""
    p = pull(rows)
    head = []
    for dx in sorted({k[2] for k in p}, reverse=True):
        parts = []
        for kernel in kw.KERNELS:
            v = [q["pull"] for k, q in p.items() if k[1] == kernel and k[2] == dx]
            if v:
                parts.append(f"{kernel} {min(v):+.1f} to {max(v):+.1f}°")
        head.append(f"at {dx:g} mm " + ", ".join(parts))
    text = ["The square grid moves the angle, against the mean of the perturbed and rotated "
            "grids' cracks (both loadings, the three angle definitions): " + "; ".join(head)
            + "."] if head else []
    for dx in sorted({k[2] for k in p}, reverse=True):
        for loading in LOADINGS:
            parts = []
            for kernel in kw.KERNELS:
                defs = [(d, p[(loading, kernel, dx, d)]) for d in ANGLES
                        if (loading, kernel, dx, d) in p]
                if not defs:
                    continue
                parts.append(f"{kernel} " + ", ".join(
                    f"{d} {q['pull']:+.1f}" + ("" if q["se"] is None else f" ± {q['se']:.1f}")
                    for d, q in defs))
            if not parts:
                continue
            n = max(q["n"] for k, q in p.items() if k[0] == loading and k[2] == dx)
            text.append(f"{dx:g} mm, {loading} (square grid minus the mean of up to {n} "
                        f"off-grid cracks ± its standard error, deg): " + "; ".join(parts) + ".")
    sig = [(k, q) for k, q in p.items() if q["se"] is not None
           and abs(q["pull"]) > 2.0 * q["se"]]
    big = max(p.items(), key=lambda kq: abs(kq[1]["pull"])) if p else None
    sd = [q["sd"] for q in p.values() if q["sd"] is not None]
    summary = (f"Of {len(p)} pulls, {len(sig)} exceed twice their standard error"
               + (": " + "; ".join(f"{k[1]} {k[0]} {k[2]:g} mm {k[3]} {q['pull']:+.1f}"
                                  for k, q in sig) if sig else "") + ".")
    if big:
        k, q = big
        summary += (f" The largest is {q['pull']:+.1f} deg ({k[1]}, {k[0]}, {k[2]:g} mm, "
                    f"{k[3]}).")
    if sd:
        lo, hi = f"{min(sd):.1f}", f"{max(sd):.1f}"
        summary += (" The off-grid cracks of one case scatter with a standard deviation of "
                    + (lo if lo == hi else f"{lo}–{hi}") + " deg.")
    return text + [summary]


# ---------------------------------------------------------------------------- table

def _f(v, spec):
    return "-" if v in (None, "") else format(float(v), spec)


def _pair(r, d):
    return f"{_f(r[f'{d}_lo_deg'], '.1f')} / {_f(r[f'{d}_hi_deg'], '.1f')}"


def markdown(rows, comments=()):
    """The README's table (one row per run, lower / upper crack) and the computed sentences;
    comments: the CSV's '#' lines (what made it, on which machine)."""
    head = ["loading", "kernel", "dx (mm)", "grid", "first bond (us)", "damage band (us)",
            "initial lo / hi (deg)", "fit lo / hi (deg)", "chord lo / hi (deg)",
            "crack length at end (mm)", "crack stops (us)", "loop CPU (s)"]
    lines = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    for r in rows:
        lines.append("| " + " | ".join([
            r["loading"], r["kernel"], f"{float(r['dx_mm']):g}", r["grid"],
            _f(r["first_bond_us"], ".1f"), _f(r["band_us"], ".1f"), _pair(r, "initial"),
            _pair(r, "fit"), _pair(r, "chord"), _f(r["length_end_mm"], ".0f"),
            r["crack_stops"], _f(r["loop_cpu_s"], ".0f")]) + " |")
    text = "\n".join(lines)
    made, cpu = made_by(comments), machine_of(comments)
    if made:
        text += (f"\n\nFrom `examples/kalthoff-winkler/results/grid_pull.csv` (made by: {made}). "
                 f"Loop CPU: LAMMPS's loop time x its CPU use, one rank, on {cpu} shared with "
                 "other jobs; every other number is deterministic.")
    return text + "\n\n" + "\n".join(f"- {s}" for s in pull_sentence(rows))


# ---------------------------------------------------------------------------- summary

def _hit_defs(angles):
    """The definitions whose angle lies within 70 +- 2 deg: angles = {definition: deg or None}."""
    return [d for d, a in angles.items() if a is not None
            and abs(a - study.ANGLE_TARGET_DEG) <= study.ANGLE_TOL_DEG]


def hits(proj_rows, grid_rows):
    """Every run with an angle of 70 +- 2 deg (any definition; off the square grid either crack)
    whose cracks reach the plate's edge, as dicts (dx_mm, name, defs, square): projectile.csv's
    setups (loadings, toughness values, 3D) and the grid-pull runs off the square grid."""
    out = []
    num = projectile._num
    for r in proj_rows:
        defs = _hit_defs({d: num(r[f"{d}_deg"]) for d in ANGLES})
        if defs and projectile.crosses_plate(r):
            out.append(dict(dx_mm=float(r["dx_mm"]), defs=defs, square=True,
                            name=f"{r['setup'].upper()} {r['loading']} {r['kernel']} "
                                 f"{float(r['dx_mm']):g} mm G_c = {float(r['Gc']):g} "
                                 f"({', '.join(defs)})"))
    for r in grid_rows:
        if r["grid"] == "square" or not str(r["crack_stops"]).startswith("edge"):
            continue
        for side, name in (("lo", "lower"), ("hi", "upper")):
            defs = _hit_defs({d: r[f"{d}_{side}_deg"] for d in ANGLES})
            if defs:
                out.append(dict(dx_mm=float(r["dx_mm"]), defs=defs, square=False,
                                name=f"{r['grid']} grid {r['loading']} {r['kernel']} "
                                     f"{float(r['dx_mm']):g} mm, {name} crack "
                                     f"({', '.join(defs)})"))
    return out


def _span(values):
    return f"{min(values):.1f}–{max(values):.1f}°"


# the Kalthoff-Winkler tips' mode mix, taken at two fair instants (kink_kalthoff_winkler.py):
# the first broken bond and the damage band leaving the tip (keys of kalthoff_winkler_mix.json)
MIXES = (("the first broken bond", "", "t_mix_us", "psi"),
         ("the damage band", "_band", "t_band_mix_us", "psi_band"))
CRITERIA = (("hoop strain", "hoop_strain"), ("hoop stress", "hoop_stress"),
            ("maximum energy release rate", "energy"))
MEASURED = ("initial", "fit")    # the angles the verdict is read on (study.ANGLE_DEFS)
AGREE_SE = 2.0    # a criterion agrees with a mean angle within this many standard errors


def _nearest(angle, predicted):
    return min(predicted, key=lambda c: abs(angle - predicted[c]))


def mix_verdict(mix, angles, dx_mm):
    """What the kink criteria say about the measured angles (dict definition -> angles of the
    setups), at each mix of MIXES; a verdict is stated only where every mix and definition
    supports it, else it is said to depend on the mix."""
    if not angles or any(len(v) < 2 for v in angles.values()):
        raise ValueError("mix_verdict needs at least two setups' angles for every definition "
                         f"(got {({d: len(v) for d, v in angles.items()})})")
    pred = {m: {c: -mix[key + suffix] for c, key in CRITERIA} for m, suffix, _, _ in MIXES}
    stats = {d: (float(np.mean(v)), float(np.std(v, ddof=1) / np.sqrt(len(v)))) for d, v in angles.items()}
    text = "The criteria's angles at the tips' mix: " + "; ".join(
        f"at {m} (psi = {mix[psi]:.1f}°, {mix[t]:.1f} µs) "
        + ", ".join(f"{c} {pred[m][c]:.1f}°" for c, _ in CRITERIA)
        for m, _, t, psi in MIXES) + ". "
    text += (f"The {dx_mm:g} mm setups' mean angles (± one standard error): "
             + ", ".join(f"{d} {mu:.1f} ± {se:.1f}°" for d, (mu, se) in stats.items()) + ". ")
    nearest = {(m, d): _nearest(mu, pred[m]) for m in pred for d, (mu, _) in stats.items()}
    agree = {(m, d): abs(mu - pred[m][nearest[m, d]]) <= AGREE_SE * se
             for m in pred for d, (mu, se) in stats.items()}
    gaps = [stats[d][0] - pred[m][nearest[m, d]] for m, d in nearest]
    names = set(nearest.values())
    if len(names) == 1:
        c = names.pop()
        text += (f"At both mixes and by both definitions they lie nearest {c} "
                 f"({min(gaps):+.1f} to {max(gaps):+.1f}°)")
        held = [m for m in pred if all(agree[m, d] for d in stats)]
        if len(held) == len(pred):
            text += f", within {AGREE_SE:g} standard errors at both: the crack follows {c}."
        else:
            if held:
                text += (f", but agree with it within {AGREE_SE:g} standard errors only at "
                         f"{held[0]}'s mix: that the crack follows {c} depends on which "
                         "instant's mix is taken, and is not settled.")
            else:
                text += (f", but below it by more than {AGREE_SE:g} standard errors at both "
                         f"mixes: nearer {c} than the other criteria, not on it; that the "
                         f"crack follows {c} is not settled.")
    else:
        text += ("The nearest criterion depends on the mix or the definition ("
                 + "; ".join(f"{d} at {m}: {nearest[m, d]}" for m, d in nearest)
                 + "): no criterion is singled out.")
    target = study.ANGLE_TARGET_DEG
    exp = {m: _nearest(target, pred[m]) for m in pred}
    if len(set(exp.values())) == 1:
        text += f" The experiment's {target:.0f}° lies nearest {exp[MIXES[0][0]]} at both mixes."
    else:
        text += (f" The experiment's {target:.0f}° lies nearest "
                 + " and ".join(f"{exp[m]} at {m}'s mix" for m in pred)
                 + ": whether it is a hoop-strain or a hoop-stress angle is not settled by the mix.")
    return text


def summary(proj_rows, grid_rows, kink_rows, mix, kink_limit):
    """The summary of the Kalthoff-Winkler setups against the experiment's 70 deg and what the
    kink test says about it, computed from projectile.csv, grid_pull.csv, the kink test's
    kink.csv and its Kalthoff-Winkler mix (kalthoff_winkler_mix.json); kink_limit is the kink
    test's sentence on its limit in m (kink_convergence.limit_sentence)."""
    found = hits(proj_rows, grid_rows)
    fine = min(float(r["dx_mm"]) for r in proj_rows if r["setup"] == "2d")
    text = ("**Summary.** Setups with 70 ± 2° and cracks that cross the plate: "
            + ("; ".join(h["name"] for h in found) if found else "none") + ".")
    at_fine = [h for h in found if h["dx_mm"] == fine]
    fine_defs = sorted({d for h in at_fine for d in h["defs"]}, key=ANGLES.index)
    text += (f" On the {fine:g} mm grid: " + (
        f"{len(at_fine)} of them, by the {' and '.join(fine_defs)} angle"
        + (", all off the square grid" if not any(h["square"] for h in at_fine) else "")
        if at_fine else "none") + ".")
    # the finest 2D runs with the paper's G_c: every loading and grid
    ang = {}
    for d in MEASURED + ("chord",):
        v = [projectile._num(r[f"{d}_deg"]) for r in proj_rows if r["setup"] == "2d"
             and float(r["dx_mm"]) == fine and float(r["Gc"]) == 6.9e4]
        v += [r[f"{d}_{s}_deg"] for r in grid_rows for s in SIDES if float(r["dx_mm"]) == fine]
        ang[d] = [a for a in v if a is not None]
    mode2 = next(r for r in kink_rows if r["kernel"] == "gaussian" and r["psi"] == 90.0
                 and r["alpha"] == 0.0 and r["dx"] == min(k["dx"] for k in kink_rows))
    text += (f" With the paper's G_c the {fine:g} mm cracks run at {_span(ang['fit'])} by the fit "
             f"angle (their direction 10–50 mm from the tip) and {_span(ang['chord'])} by the "
             "chord, over both loadings and the square, perturbed and rotated grids. On the kink "
             f"test's m = {mode2['m']:g} grid pure Mode II kinks at {mode2['angle_2d']:.1f} / "
             f"{mode2['angle_4d']:.1f}° (2 / 4 horizons) against {mode2['hoop_strain']:.1f}° (hoop "
             f"strain) and {mode2['hoop_stress']:.1f}° (hoop stress). {kink_limit}")
    text += " " + mix_verdict(mix, {d: ang[d] for d in MEASURED}, fine)
    chord_pull = [q["pull"] for k, q in pull(grid_rows).items() if k[2] == fine and k[3] == "chord"]
    if at_fine and fine_defs == ["chord"] and chord_pull:
        text += (f" The {fine:g} mm setups at 70 ± 2° reach it by the chord alone (the line from "
                 "the notch tip to the crack tip)"
                 + (" and only off the square grid, which flattens the chord there by "
                    f"{_span([-c for c in chord_pull])[:-1]}°"
                    if not any(h["square"] for h in at_fine) else "") + ".")
    return text


# ---------------------------------------------------------------------------- report

REPORT_TITLE = "Kalthoff-Winkler: the grid's pull (perturbed and rotated grids)"


def section(specs, results, figdir, notes):
    """The grid-pull section of report/REPORT.md (tools/reproduce --full)."""
    if not specs:
        return {"title": REPORT_TITLE,
                "setup": f"Not run by default ({len(jobs())} runs): `tools/reproduce --full` "
                         "runs them; the last measured table is in "
                         "examples/kalthoff-winkler/README.md, 'The grid's pull'.",
                "table": "", "text": "", "figures": []}
    rows = collect(specs, results)
    bad = jobmod.finished(specs, results)[1]
    text = pull_sentence(rows) if rows else []
    if bad:
        text.append(jobmod.not_measured(bad))
    return {"title": REPORT_TITLE,
            "setup": "The Kalthoff-Winkler plate (paper's G_c, to 100 us) on the square grid, on "
                     "a perturbed grid (points moved by up to 0.2 dx, three seeds) and on grids "
                     "rotated by 22.5 and 30 deg (-var grid), under the paper's prescribed "
                     "loading and with the projectile. Angles of the lower / upper crack as in "
                     "the loading study; see examples/kalthoff-winkler/README.md, 'The grid's "
                     "pull'.",
            "table": markdown(rows).split("\n\n- ")[0] if rows else "",
            "text": " ".join(text), "figures": []}


# ---------------------------------------------------------------------------- files

def write(rows, path, command=COMMAND, workers=1):
    comments = [f"made by: {command} on {time.strftime('%Y-%m-%d %H:%M')}",
                f"LAMMPS: {provenance.lammps_build()}; plugin {provenance.plugin_version()}, "
                f"source {provenance.git_revision()}",
                f"machine: {provenance.machine()}; runs single-rank, {workers} at a time "
                "(loop_cpu_s: LAMMPS's loop time x its CPU use, on cores shared with other jobs)"]
    write_csv(path, rows, comments)


def read_rows(path=CSV):
    comments, rows = read_csv(path)
    return comments, rows


def machine_of(comments):
    """The CPU named in the CSV's 'machine:' line."""
    for c in comments:
        if c.startswith("machine:"):
            return c[len("machine:"):].split(",")[0].strip()
    return "an unnamed CPU"


def made_by(comments):
    for c in comments:
        if c.startswith("made by:"):
            return c[len("made by:"):].strip()
    return None


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", default="/tmp/kw-grid", help="the runs are cached here")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time (single-rank each)")
    ap.add_argument("--coarse-only", action="store_true", help="the 2 mm runs only")
    ap.add_argument("--csv", default=None, help="write the rows here")
    args = ap.parse_args(argv)
    cases = [c for c in CASES if not (args.coarse_only and c[1] < 1.5e-3)]
    specs = sorted(jobs(cases), key=lambda s: -s.job.estimate_s)
    results = jobmod.run_jobs([s.job for s in specs], args.work, workers=args.jobs)
    rows = collect(specs, results)
    if args.csv:
        write(rows, args.csv, workers=args.jobs)
        _, rows = read_rows(args.csv)
    print(markdown(rows))


if __name__ == "__main__":
    main()

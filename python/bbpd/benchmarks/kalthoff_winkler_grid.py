# SPDX-License-Identifier: GPL-2.0-or-later
"""Kalthoff-Winkler on perturbed and rotated grids (GRIDS): how far the square grid's
preferred directions pull the crack angle (examples/kalthoff-winkler/README.md, "The grid's
pull", defines the pull and has the commands).
"""

import math
import time
from pathlib import Path

import numpy as np

from bbpd import jobs as jobmod
from bbpd import provenance, readers
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import kalthoff_winkler_projectile as projectile
from bbpd.benchmarks import kalthoff_winkler_study as study
from bbpd.csvfile import comment, read_csv, write_csv
from bbpd.runner import run_or_reuse
from bbpd.markdown import cell as _f
from bbpd.markdown import table as md_table
from bbpd.benchmarks import cli

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
ANGLES = kw.ANGLE_DEFS
SIDES = ("lo", "hi")


# ---------------------------------------------------------------------------- running

# per-atom data of the analysis, not needed for the rows
BULKY = ("damage_map", "trajectory", "crack_lo", "crack_hi")


def run_case(workdir, kernel, dx, loading, grid, nprocs=1, tend=TEND):
    """Run one case in workdir and measure it (the job of this module and the report); the
    rows are made from the result by row(), outside the job, so that the table's code is no
    part of the runs' cache key."""
    workdir = Path(workdir)
    variables = kw.variables(kernel, dx, tend=float(tend), loading=loading, **GRIDS[grid])
    wall = run_or_reuse(kw.EXAMPLE, workdir, variables, nprocs)[1]
    res = projectile.analyse(workdir)
    res.update(nprocs=nprocs, wall_s=wall, grid=grid)
    return {k: v for k, v in res.items() if k not in BULKY}


def side_angle(res, side, definition):
    """One crack's angle (the study's definitions), None if it is shorter than the initial
    range at 70 us (its direction is no path yet)."""
    a70 = res.get("angles_t70", {}).get(side)
    if a70 is None or a70["length_mm"] < kw.INITIAL_RANGE[1] * 1e3:
        return None
    if definition == "initial":
        return res["initial_side_deg"][side]
    return a70[definition]


COLUMNS = (("grid", "loading", "kernel", "dx_mm", "first_bond_us", "band_us")
           + tuple(f"{d}_{s}_deg" for d in ANGLES for s in SIDES)
           + ("length_lo_mm", "length_hi_mm", "length_end_mm", "crack_stops", "far_edge_us",
              "v_interface", "loop_cpu_s", "nprocs"))


def row(res, grid):
    """The CSV row of one run: projectile.row's, with both cracks' angles and lengths."""
    out = {c: v for c, v in projectile.row(res).items() if c in COLUMNS}
    out["grid"] = grid
    for d in ANGLES:
        for side in SIDES:
            out[f"{d}_{side}_deg"] = side_angle(res, side, d)
    for side in SIDES:
        out[f"length_{side}_mm"] = res["angles_t70"][side]["length_mm"] if "angles_t70" in res else None
    return {c: out[c] for c in COLUMNS}


def jobs(cases=CASES, loadings=LOADINGS, nprocs=1):
    """The runs as bbpd.report specs (this module's command and tools/reproduce --full)."""
    inputs = (kw.EXAMPLE, Path(kw.__file__), Path(study.__file__), Path(projectile.__file__),
              kw.ROOT / "potentials" / "kalthoff_winkler_steel.bbpd",
              Path(readers.__file__))
    return jobmod.report_specs("kwgrid", "bbpd.benchmarks.kalthoff_winkler_grid:run_case", inputs, (
        (kernel, dx, f"Kalthoff-Winkler grid {grid} {loading} {kernel} dx = {dx * 1e3:g} mm",
         {"kernel": kernel, "dx": dx, "loading": loading, "grid": grid, "nprocs": nprocs},
         (8.0 if dx > 1.5e-3 else 60.0) * (2.5 if loading == "projectile" else 1.0))
        for kernel, dx, grids in cases for grid in grids for loading in loadings))


def collect(specs, results):
    """The rows of the finished runs among specs, in the CSV's order."""
    return sorted((row(results[s.job.label], results[s.job.label]["grid"])
                   for s in jobmod.finished(specs, results)[0]), key=order)


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


def significant(q):
    """a pull larger than twice its standard error"""
    return q["se"] is not None and abs(q["pull"]) > 2.0 * q["se"]


def pull_table(rows):
    """The pulls as a table: per grid spacing, loading, kernel and angle definition the square
    grid's angle, the mean of the off-grid cracks, and their difference with its standard error."""
    p = pull(rows)
    order = sorted(p, key=lambda k: (-k[2], LOADINGS.index(k[0]), kw.KERNELS.index(k[1]),
                                     ANGLES.index(k[3])))
    return md_table(
        ["dx (mm)", "loading", "kernel", "angle", "square grid (deg)",
         "off-grid mean (deg, cracks)", "pull ± s.e. (deg)", "beyond 2 s.e."],
        ([f"{k[2]:g}", k[0], k[1], k[3], f"{p[k]['square']:.1f}", f"{p[k]['mean']:.1f} ({p[k]['n']})",
          f"{p[k]['pull']:+.1f}" + ("" if p[k]["se"] is None else f" ± {p[k]['se']:.1f}"),
          "yes" if significant(p[k]) else "no"] for k in order))


# ---------------------------------------------------------------------------- table

def _pair(r, d):
    return f"{_f(r[f'{d}_lo_deg'], '.1f')} / {_f(r[f'{d}_hi_deg'], '.1f')}"


def markdown(rows, comments=()):
    """The README's tables (one row per run, lower / upper crack; the pulls);
    comments: the CSV's '#' lines (what made it, on which machine)."""
    text = md_table(
        ["loading", "kernel", "dx (mm)", "grid", "first bond (us)", "damage band (us)",
         "initial lo / hi (deg)", "fit lo / hi (deg)", "chord lo / hi (deg)",
         "crack length at end (mm)", "crack stops (us)", "loop CPU (s)"],
        ([r["loading"], r["kernel"], f"{float(r['dx_mm']):g}", r["grid"],
          _f(r["first_bond_us"], ".1f"), _f(r["band_us"], ".1f"), _pair(r, "initial"),
          _pair(r, "fit"), _pair(r, "chord"), _f(r["length_end_mm"], ".0f"), r["crack_stops"],
          _f(r["loop_cpu_s"], ".0f")] for r in rows))
    made = comment(comments, "made by")
    cpu = (comment(comments, "machine") or "an unnamed CPU").split(",")[0]
    if made:
        text += (f"\n\nFrom `examples/kalthoff-winkler/results/grid_pull.csv` (made by: {made}). "
                 f"Loop CPU: LAMMPS's loop time x its CPU use, one rank, on {cpu} shared with "
                 "other jobs; every other number is deterministic.")
    return text + "\n\n" + pull_table(rows)


# ---------------------------------------------------------------------------- summary

# the Kalthoff-Winkler tips' mode mix, taken at two fair instants (kink_kalthoff_winkler.py):
# the first broken bond and the damage band leaving the tip (keys of kalthoff_winkler_mix.json)
MIXES = (("the first broken bond", "", "t_mix_us", "psi"),
         ("the damage band", "_band", "t_band_mix_us", "psi_band"))
CRITERIA = (("hoop strain", "hoop_strain"), ("hoop stress", "hoop_stress"),
            ("maximum energy release rate", "energy"))
MEASURED = ("initial", "fit")    # the angles the verdict is read on (kw.ANGLE_DEFS)
AGREE_SE = 2.0    # a criterion agrees with a mean angle within this many standard errors


def _nearest(angle, predicted):
    return min(predicted, key=lambda c: abs(angle - predicted[c]))


def fine_angles(proj_rows, grid_rows):
    """(dx_mm, {definition: angles}) of the finest 2D runs with the paper's G_c, over every
    loading and grid (projectile.csv and grid_pull.csv, both cracks): what mix_verdict reads"""
    fine = min(r["dx_mm"] for r in proj_rows if r["setup"] == "2d")
    ang = {}
    for d in MEASURED + ("chord",):
        v = [r[f"{d}_deg"] for r in proj_rows if r["setup"] == "2d" and r["dx_mm"] == fine
             and r["Gc"] == 6.9e4]
        v += [r[f"{d}_{s}_deg"] for r in grid_rows for s in SIDES if float(r["dx_mm"]) == fine]
        ang[d] = [a for a in v if a is not None]
    return fine, ang


def mix_verdict(mix, angles):
    """What the kink criteria say about the measured angles (dict definition -> angles of the
    setups), at each instant's mix of MIXES: {'pred': {instant: {criterion: angle}}, 'stats':
    {definition: (mean, standard error)}, 'nearest': {(instant, definition): criterion},
    'agree': {(instant, definition): within AGREE_SE standard errors}, 'follows': the criterion
    nearest at every instant and definition and agreed with at all of them, else None,
    'experiment': {instant: the criterion nearest the experiment's angle}}"""
    if not angles or any(len(v) < 2 for v in angles.values()):
        raise ValueError("mix_verdict needs at least two setups' angles for every definition "
                         f"(got {({d: len(v) for d, v in angles.items()})})")
    pred = {m: {c: -mix[key + suffix] for c, key in CRITERIA} for m, suffix, _, _ in MIXES}
    stats = {d: (float(np.mean(v)), float(np.std(v, ddof=1) / np.sqrt(len(v)))) for d, v in angles.items()}
    nearest = {(m, d): _nearest(mu, pred[m]) for m in pred for d, (mu, _) in stats.items()}
    agree = {(m, d): abs(mu - pred[m][nearest[m, d]]) <= AGREE_SE * se
             for m in pred for d, (mu, se) in stats.items()}
    names = set(nearest.values())
    follows = names.pop() if len(names) == 1 and all(agree.values()) else None
    return dict(pred=pred, stats=stats, nearest=nearest, agree=agree, follows=follows,
                experiment={m: _nearest(study.ANGLE_TARGET_DEG, pred[m]) for m in pred})


# ---------------------------------------------------------------------------- report

REPORT_TITLE = "Kalthoff-Winkler: the grid's pull (perturbed and rotated grids)"


def section(specs, results, figdir, notes):
    """The grid-pull section of report/REPORT.md (tools/reproduce --full)."""
    return jobmod.section(
        REPORT_TITLE, "The Kalthoff-Winkler plate (paper's G_c, to 100 us) on the square grid, on a "
        "perturbed grid (points moved by up to 0.2 dx, three seeds) and on grids rotated by 22.5 "
        "and 30 deg (-var grid), under the paper's prescribed loading and with the projectile. "
        "Angles of the lower / upper crack as in the loading study; see "
        "examples/kalthoff-winkler/README.md, 'The grid's pull'.", specs, results,
        lambda _: markdown(collect(specs, results)),
        not_run=f"Not run by default ({len(jobs())} runs): `tools/reproduce --full` runs them; "
        "the last measured table is in examples/kalthoff-winkler/README.md, 'The grid's pull'.")


# ---------------------------------------------------------------------------- files

def write(rows, path, command=COMMAND, workers=1):
    comments = [f"made by: {command} on {time.strftime('%Y-%m-%d %H:%M')}",
                f"LAMMPS: {provenance.lammps_build()}; plugin {provenance.plugin_version()}, "
                f"source {provenance.git_revision()}",
                f"machine: {provenance.machine()}; runs single-rank, {workers} at a time "
                "(loop_cpu_s: LAMMPS's loop time x its CPU use, on cores shared with other jobs)"]
    write_csv(path, rows, comments)


def main(argv=None):
    ap = cli.parser(__doc__, "/tmp/kw-grid", csv=True)
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time (single-rank each)")
    ap.add_argument("--coarse-only", action="store_true", help="the 2 mm runs only")
    args = ap.parse_args(argv)
    cases = [c for c in CASES if not (args.coarse_only and c[1] < 1.5e-3)]
    specs = sorted(jobs(cases), key=lambda s: -s.job.estimate_s)
    results = jobmod.run_jobs([s.job for s in specs], args.work, workers=args.jobs)
    rows = collect(specs, results)
    if args.csv:
        write(rows, args.csv, workers=args.jobs)
        _, rows = read_csv(args.csv)
    print(markdown(rows))


if __name__ == "__main__":
    main()

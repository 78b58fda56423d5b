# SPDX-License-Identifier: GPL-2.0-or-later
"""The quasi-static section of report/REPORT.md (examples/quasi-static, fix bbpd/relax): the
stress concentration at the hole against Heywood, the centre crack's initiation stress against
LEFM, and the load-displacement path through crack growth with its energy account.

Default (about a minute on 2 cores): the Gaussian kernel at delta = 2 mm, m = 4 for the hole
and the initiation (with lps/gaussian beside it) and a coarse growth path; --full adds delta =
1 mm (and the hole at 0.5 mm)."""
from pathlib import Path

from bbpd import jobs as jobmod
from bbpd.benchmarks import center_crack, center_crack_growth, plate_hole
from bbpd.markdown import table as md_table

TITLE = "Quasi-static loading: plate with a hole, centre-crack initiation and growth (fix bbpd/relax)"
CASES = (("hole", "gaussian", 2.0e-3), ("initiation", "gaussian", 2.0e-3),
         ("initiation", "lps/gaussian", 2.0e-3), ("growth", "gaussian", 2.0e-3))
CASES_FULL = CASES + (("hole", "gaussian", 1.0e-3), ("hole", "gaussian", 0.5e-3),
                      ("initiation", "gaussian", 1.0e-3), ("initiation", "lps/gaussian", 1.0e-3))
M = 4
GROWTH_DU, GROWTH_FIRST = 0.01, 0.95    # the report's coarse path (README: 0.005 from 0.9)
ESTIMATE_S = {"hole": 5.0, "initiation": 25.0, "growth": 90.0}


def job(workdir, case, kernel, delta):
    """One run for bbpd.jobs: a row of the section's table (JSON)"""
    if case == "hole":
        r = plate_hole.run_case(kernel, delta, M, workdir)
        return {"case": case, "kernel": kernel, "delta_mm": delta * 1e3, "atoms": r["atoms"],
                "measured": r["K_fit"], "reference": r["K_heywood"], "deviation": r["error_fit"],
                "iterations": r["iterations"], "wall_s": r["wall_s"]}
    if case == "initiation":
        r = center_crack.initiation(kernel, delta, M, workdir)
        return {"case": case, "kernel": kernel, "delta_mm": delta * 1e3, "atoms": r["atoms"],
                "measured": r["sigma_c_MPa"], "reference": r["sigma_lefm_MPa"],
                "deviation": r["error"], "iterations": r["elastic_iterations"], "wall_s": r["wall_s"]}
    steps, u_lefm, atoms = center_crack_growth.path(kernel, delta, M, workdir, du=GROWTH_DU,
                                                    first=GROWTH_FIRST)
    s = center_crack_growth.summary(steps)
    first = next(x for x in steps if x["broken"] > 0)
    return {"case": case, "kernel": kernel, "delta_mm": delta * 1e3, "atoms": atoms,
            "measured": first["u_m"] / u_lefm, "reference": 1.0, "deviation": first["u_m"] / u_lefm - 1.0,
            "iterations": sum(x["iterations"] for x in steps), "wall_s": s["wall_s"],
            "gap_initiation": first["gap"], "gap_before": s["gap_before_separation"],
            "gap_final": s["gap_final"], "clapeyron": s["clapeyron_max"],
            "load_drop": 1.0 - first["load_N"] / first["load_before_break_N"],
            "steps": len(steps)}


def jobs(full=False):
    """The report's quasi-static runs as bbpd.report specs."""
    here = center_crack.HERE
    inputs = (here / "in.plate-hole", here / "in.center-crack", Path(__file__),
              Path(plate_hole.__file__), Path(center_crack.__file__),
              Path(center_crack_growth.__file__))
    return [jobmod.report_spec("quasistatic", kernel, delta / M,
                               f"quasi-static {case} {kernel} delta = {delta * 1e3:g} mm",
                               "bbpd.benchmarks.quasi_static:job",
                               {"case": case, "kernel": kernel, "delta": delta}, inputs,
                               ESTIMATE_S[case] * (2.0e-3 / delta) ** 3)
            for case, kernel, delta in (CASES_FULL if full else CASES)]


WHAT = {"hole": "K at the hole (fit) vs Heywood", "initiation": "sigma_c (MPa) vs LEFM",
        "growth": "first break, u/u_LEFM"}


def table(rows):
    header = ["case", "kernel", "delta (mm)", "m", "atoms", "measured", "reference", "deviation",
              "iterations", "wall (s)"]
    return md_table(header, [[WHAT[r["case"]], r["kernel"], f"{r['delta_mm']:g}", str(M),
                              f"{r['atoms']:,}", f"{r['measured']:.4g}", f"{r['reference']:.4g}",
                              f"{100 * r['deviation']:+.1f} %", f"{r['iterations']:,}",
                              f"{r['wall_s']:.1f}"] for r in rows])


def text(rows):
    lines = ["Iterations: of the load step (hole), of the elastic step (initiation, a bisection "
             "of one-load-step runs to 1 %), of the whole path (growth)."]
    for r in rows:
        if r["case"] == "growth":
            lines.append(
                f"Growth ({r['kernel']}, delta = {r['delta_mm']:g} mm, {r['steps']} load steps "
                f"of {GROWTH_DU:g} u_LEFM): the load drops by {100 * r['load_drop']:.1f} % at "
                f"initiation; U = F u/2 to {r['clapeyron']:.1e} in every converged state; the "
                f"energy account W - U - B is {100 * r['gap_initiation']:.2f} % of the work "
                f"after initiation, {100 * r['gap_before']:.1f} % before the plate separates and "
                f"{100 * r['gap_final']:.0f} % after: the energy released at fixed opening "
                "beyond the broken bonds' (examples/quasi-static/README.md).")
    return lines


def section(specs, results, figdir, notes):
    """The quasi-static section of report/REPORT.md."""
    return jobmod.section(
        TITLE,
        "Glass (E = 72 GPa, G_c = 3.8 J/m2), plane stress, m = 4, fix bbpd/relax tol 1e-6: a 60 x "
        "20 mm plate with a 6 mm hole under 10 MPa (Heywood's K_tg = 3.347) and a 20 x 40 mm "
        "plate with a central crack 2a = 8 mm under gripped tension (LEFM with Tada's factor: "
        "4.207 MPa). See examples/quasi-static/README.md.", specs, results, table, text,
        notes=notes, not_run="Not run.")

# SPDX-License-Identifier: GPL-2.0-or-later
"""Steady crack growth in a pre-stretched strip between fixed grips: the model's kinetic law
from examples/strip-steady-crack/in.strip (examples/strip-steady-crack/README.md defines each
measure and has the commands).
"""

import itertools
import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np

from bbpd import csvfile, freund, reference
from bbpd import jobs as jobmod
from bbpd.provenance import cpu
from bbpd.kernels import COLORS
from bbpd import plots
from bbpd.runner import LammpsError, run_or_reuse
from bbpd.markdown import cell as f
from bbpd.markdown import table as md_table
from bbpd.benchmarks import cli

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "strip-steady-crack" / "in.strip"

# soda-lime glass (the example's defaults; fracture-anchors: Ha & Bobaru 2010)
E, RHO, G_C = 72.0e9, 2440.0, 3.8
NU = 1.0 / 3.0                      # BBPD in plane stress
DX = 2.5e-4                         # m, the example's default grid
M = 4.0                             # delta/dx
H_OVER_DELTA = 20.0                 # strip height in horizons
L_OVER_H = 8.0                      # strip length in strip heights
MIDDLE_START_H = 2.0                # steady from a + 2 H (the trial: ~2 H)
MIDDLE_END_H = 1.0                  # to L - H (the run stops at L - H/2)
MIN_MIDDLE_POINTS = 5
# the sweeps in load and m run at H = 10 horizons (a run costs ~(H/delta)^3: 8x less than at 20,
# what the shared 2-core machine allowed); H/delta = 20 (and 40 where run) check that choice
SWEEP_H_OVER_DELTA = 10.0
# a run at H/delta = 40 took 1150 s of loop on one core of a quiet machine; on a shared one
# (load 6-8) a run at H/delta = 20, m = 5 overran LAMMPS's default 30 min
RUN_TIMEOUT_S = 6 * 3600
# a tip further than this many horizons from y = 0 has turned or branched: the run's state is
# 'branched', and in.strip stops the run there (-var offplane)
OFF_PLANE_HORIZONS = 1.0
CSV_COLUMNS = ("kernel", "m", "H_over_delta", "dx", "Delta", "Delta_model", "crossed", "state",
               "v_ss_over_cR", "v_ss", "Gamma_over_Gc", "Phi_over_Gc", "Phi_behind_over_Gc",
               "Phi_ahead_over_Gc", "closure_pct", "balance_pct", "atoms", "steps", "loop_s",
               "timing", "left_plane_over_H")
TEXT_COLUMNS = ("kernel", "state", "timing")


def wave_speeds():
    """c_d, c_s, c_R of the model (plane stress, nu = 1/3)."""
    c_d = freund.dilatational_wave_speed(E, NU, RHO, freund.PLANE_STRESS)
    c_s = freund.shear_wave_speed(E, NU, RHO)
    return c_d, c_s, freund.rayleigh_wave_speed(c_s, c_d)


def grid_rayleigh_ratio(kernel, m):
    """c_R of the model's own dispersion over c_R: the Rayleigh speed of the long-wave speeds
    that the grid's lattice sum gives along the crack (bbpd.reference.grid_wave_speeds); it
    depends on the kernel and m only (the sum scales with dx)."""
    c_d, c_s = reference.grid_wave_speeds(kernel, "plane/stress", E, RHO, m, DX)
    return freund.rayleigh_wave_speed(c_s, c_d) / wave_speeds()[2]


def geometry(dx=DX, m=M, H_over_delta=H_OVER_DELTA):
    delta = m * dx
    H = H_over_delta * delta
    return {"delta": delta, "H": H, "L": L_OVER_H * H, "a": H}


def measure(rows, uprime, g, h, Gc=G_C):
    """The steady-state numbers of one run from the rows of strip.dat (README: the measures).
    rows: step, t, tip x, y, extension, speed, direction, U, K, B, W, balance (the strip),
    U + K more than H behind the tip, work on the seed zone, work on the far zone."""
    t, x = rows[:, 1], rows[:, 2]
    B, bal = rows[:, 9], rows[:, 11]
    c_R = wave_speeds()[2]
    H, L, a = g["H"], g["L"], g["a"]
    crossed = bool(x[-1] >= L - 0.5 * H - 2.0 * g["delta"])
    # a crack that left the plane y = 0 by more than a horizon has branched or turned (the
    # tracker follows its longest branch)
    away = np.abs(rows[:, 3]) > OFF_PLANE_HORIZONS * g["delta"]
    off_plane = bool(np.any(away))
    state = "branched" if off_plane else "crossed" if crossed else "arrested"
    mid = (x >= a + MIDDLE_START_H * H) & (x <= L - MIDDLE_END_H * H)
    nan = float("nan")
    res = {"crossed": crossed and not off_plane, "state": state, "v_ss": 0.0, "v_ss_over_cR": 0.0, "Gamma_over_Gc": nan,
           "Phi_over_Gc": nan, "Phi_behind_over_Gc": nan, "Phi_ahead_over_Gc": nan,
           "closure_pct": nan,
           # where the tip first stood off the plane, in strip heights past the seed's end
           "left_plane_over_H": float((x[np.argmax(away)] - a) / H) if off_plane else nan}
    res["balance_pct"] = 100.0 * float(np.max(np.abs(bal - bal[0])) / max(B[-1], 1e-300))
    if state != "crossed" or np.count_nonzero(mid) < MIN_MIDDLE_POINTS:
        return res
    v_ss = float(np.polyfit(t[mid], x[mid], 1)[0])
    gamma = float(np.polyfit(x[mid], B[mid], 1)[0]) / h
    # left behind: the elastic + kinetic energy more than H behind the tip, and what the damped
    # seed zone absorbed of the waves sent back (its work is negative)
    phi = float(np.polyfit(x[mid], rows[mid, 12] - rows[mid, 13], 1)[0]) / h
    # sent ahead, faster than the crack, and absorbed by the damped far zone
    phi_ahead = float(np.polyfit(x[mid], -rows[mid, 14], 1)[0]) / h
    if gamma > uprime:
        # the bonds took more than the strip releases per unit length: no single steady crack
        # (damage spread off the plane or ahead of the tip); the numbers are kept, not the law
        res["state"] = "unsteady"
        res["crossed"] = False
    res.update({"v_ss": v_ss, "v_ss_over_cR": v_ss / c_R, "Gamma_over_Gc": gamma / Gc,
                "Phi_behind_over_Gc": phi / Gc, "Phi_ahead_over_Gc": phi_ahead / Gc,
                "Phi_over_Gc": (phi + phi_ahead) / Gc,
                "closure_pct": 100.0 * (gamma + phi + phi_ahead - uprime) / uprime})
    return res


def run(workdir, kernel="gaussian", Delta=2.0, dx=DX, m=M, H_over_delta=H_OVER_DELTA,
        nprocs=1, reuse=False):
    """Run the example once (reuse=True: measure the outputs already in workdir)."""
    workdir = Path(workdir)
    g = geometry(dx, m, H_over_delta)
    vars_ = {"kernel": kernel, "dx": dx, "m": m, "Delta": Delta, "H": f"{g['H']:.10g}",
             "L": f"{g['L']:.10g}", "a": f"{g['a']:.10g}", "E": E, "rho": RHO, "Gc": G_C,
             "offplane": OFF_PLANE_HORIZONS}
    output, wall = run_or_reuse(EXAMPLE, workdir, vars_, nprocs, RUN_TIMEOUT_S, reuse)
    uprime = float(output.split("STRIP-UPRIME: ")[-1].split()[0])
    words = output.split("STRIP: ")[-1].split("\n")[0].split()
    setup = dict(zip(words[0::2], words[1::2]))
    rows = np.loadtxt(workdir / "strip.dat", comments="#", ndmin=2)
    loop = re.findall(r"Loop time of ([0-9.eE+-]+) on (\d+) procs", output)[-1]    # the crack's run
    loop_s, ranks = float(loop[0]), int(loop[1])
    res = measure(rows, uprime, g, dx)
    res.update({"kernel": kernel, "m": m, "H_over_delta": H_over_delta, "dx": dx,
                "Delta": Delta, "Delta_model": uprime / G_C, "atoms": int(setup["atoms"]),
                "steps": int(rows[-1, 0]), "loop_s": loop_s, "wall_s": wall,
                "timing": f"{ranks} rank{'s' if ranks > 1 else ''}, {cpu()}",
                "t": rows[:, 1], "x": rows[:, 2]})
    return res


def write_csv(path, rows, provenance):
    """provenance: the 'made by' and 'rows added by' lines (csvfile.continue_csv)"""
    csvfile.write_csv(path, rows, list(provenance) + [
        "timing: LAMMPS loop time; its ranks and CPU in column timing"], CSV_COLUMNS, TEXT_COLUMNS,
        nan="nan")


def read_rows(path):
    """The CSV of write_csv as dicts (kernel, state and timing strings, crossed a bool, the rest
    floats)"""
    return csvfile.read_csv(path, TEXT_COLUMNS, ("crossed",))[1]


def timing_markdown(rows):
    """'Loop times: ...': which ranks and CPU timed which runs (appended runs may come from
    another machine)."""
    return csvfile.loop_times_note(rows, "timing", _case)


def kinetic_law(rows, kernel, m=5.0, H_over_delta=SWEEP_H_OVER_DELTA):
    """G_run/G_c against v/c_R of one kernel at (m, H/delta), from the runs that crossed:
    arrays (u, g) sorted by u, with G_run = U' (the model's) at the steady speed."""
    pts = sorted((r["v_ss_over_cR"], r["Delta_model"]) for r in rows
                 if r["kernel"] == kernel and r["m"] == m and r["H_over_delta"] == H_over_delta
                 and r["crossed"])
    return np.array([p[0] for p in pts]), np.array([p[1] for p in pts])


def main(argv=None):
    p = cli.parser(__doc__, "/tmp/strip", nprocs=1, kernels=["gaussian"], reuse=True,
                   csv="write (or, with --append, add to) this results CSV", append=True)
    p.add_argument("--Delta", nargs="+", type=float, default=[2.0])
    p.add_argument("--m", nargs="+", type=float, default=[M])
    p.add_argument("--H-over-delta", nargs="+", type=float, default=[H_OVER_DELTA])
    p.add_argument("--collect", action="store_true",
                   help="measure every run folder in --work (KERNEL-mM-HH-DD) again, run nothing")
    p.add_argument("--figure", help="draw the kinetic-law figure of the CSV's rows here")
    a = p.parse_args(argv)
    earlier, rows, made = csvfile.continue_csv(a.csv if a.append else None,
                                               cli.command("strip", argv), read_rows)
    if a.collect:
        rows = collect(a.work)
        a.kernels = []
    for kernel, m, hd, D in itertools.product(a.kernels, a.m, a.H_over_delta, a.Delta):
        wd = Path(a.work) / f"{kernel}-m{m:g}-H{hd:g}-D{D:g}"
        try:
            r = run(wd, kernel, D, DX * M / m, m, hd, nprocs=a.nprocs, reuse=a.reuse)
        except (LammpsError, subprocess.TimeoutExpired) as exc:    # one failed run must not end the sweep
            print(f"{wd.name}: FAILED: {exc}", flush=True)
            continue
        print(f"{kernel} m {m:g} H/delta {hd:g} Delta {D:g} (model {r['Delta_model']:.3f}): "
              f"crossed {r['crossed']} v_ss/c_R {r['v_ss_over_cR']:.3f} Gamma/Gc "
              f"{r['Gamma_over_Gc']:.3f} Phi/Gc {r['Phi_over_Gc']:.3f} closure "
              f"{r['closure_pct']:.2f} % balance {r['balance_pct']:.3f} % loop {r['loop_s']:.1f} s",
              flush=True)
        rows = [q for q in rows if (q["kernel"], q["m"], q["H_over_delta"], q["Delta"]) != (kernel, m, hd, D)]
        rows.append(r)
    rows.sort(key=lambda r: (r["kernel"], r["m"], r["H_over_delta"], r["Delta"]))
    if a.csv:
        write_csv(a.csv, rows, [*earlier, made])
    if a.figure:
        figure(rows, a.figure)
    return 0


RUN_FOLDER = re.compile(r"^(constant|triangular|gaussian)-m([0-9.]+)-H([0-9.]+)-D([0-9.]+)$")


def finished(log):
    """the crack's run (after the pre-stretch) ran to its end"""
    text = log.read_text(errors="replace")
    tail = text.split("STRIP-UPRIME: ")[-1] if "STRIP-UPRIME: " in text else ""
    return re.search(r"Loop time of \S+ on \d+ procs for [1-9]\d* steps", tail) is not None


def collect(work):
    """Every finished run under work, measured again from its outputs."""
    rows = []
    for d in sorted(Path(work).iterdir()):
        m = RUN_FOLDER.match(d.name)
        if not m or not (d / "log.lammps").is_file() or not finished(d / "log.lammps"):
            continue
        kernel, mm, hd, D = m.group(1), float(m.group(2)), float(m.group(3)), float(m.group(4))
        rows.append(run(d, kernel, D, DX * M / mm, mm, hd, reuse=True))
    return rows



# --------------------------------------------------------------------------- README blocks

def table_markdown(rows):
    """The README table of the strip runs (rows: dicts with the CSV's columns)."""
    def run(r):
        if r["crossed"]:
            return ["yes", f"{r['v_ss_over_cR']:.3f}", f"{r['Gamma_over_Gc']:.3f}",
                    f"{r['Phi_over_Gc']:.3f} ({r['Phi_behind_over_Gc']:.3f} + "
                    f"{r['Phi_ahead_over_Gc']:.3f})", f"{r['closure_pct']:+.1f}"]
        where = "" if math.isnan(r["left_plane_over_H"]) else f" at a + {r['left_plane_over_H']:.2f} H"
        return [f"no ({r['state']}{where})"] + [""] * 4
    table = md_table(
        ("kernel", "m", "H/delta", "Delta (CCM)", "Delta' = U'/G_c (model)", "crossed", "v_ss/c_R",
         "Gamma/G_c (bonds)", "Phi/G_c (waves: behind + ahead)", "closure (%)",
         "balance drift (% of bond energy)", "atoms", "loop time (s)"),
        ([r["kernel"], f"{r['m']:g}", f"{r['H_over_delta']:g}", f"{r['Delta']:g}",
          f"{r['Delta_model']:.3f}", *run(r), f"{r['balance_pct']:.2f}", int(r["atoms"]),
          f"{r['loop_s']:.0f}"] for r in rows))
    return table + "\n\n" + timing_markdown(rows) if rows else table


def threshold(rows, kernel, m=M, H_over_delta=SWEEP_H_OVER_DELTA):
    """(largest Delta that arrested, smallest that crossed) at (m, H/delta); None where none ran"""
    sel = [r for r in rows if r["kernel"] == kernel and r["m"] == m and r["H_over_delta"] == H_over_delta]
    stopped = [r["Delta"] for r in sel if r["state"] == "arrested"]
    crossed = [r["Delta"] for r in sel if r["crossed"]]
    return (max(stopped) if stopped else None, min(crossed) if crossed else None)


def speed_at(rows, kernel, m, H_over_delta, Delta):
    for r in rows:
        if (r["kernel"], r["m"], r["H_over_delta"], r["Delta"]) == (kernel, m, H_over_delta, Delta):
            return r["v_ss_over_cR"] if r["crossed"] else 0.0
    return None


CONVERGED_SPEED = 0.02    # v_ss/c_R between two refinements (issue's criterion)


def height_convergence(speeds):
    """The last refinement of a sequence [(H/delta, v_ss/c_R)]: {'last': its change, 'within':
    no more than CONVERGED_SPEED, 'before': the change before it (None for two heights),
    'alternate': the two changes alternate in sign, 'shrinks': the last is the smaller,
    'converged': within CONVERGED_SPEED and, with three heights, shrinking (a change that keeps
    its sign and size puts the limit about as far again beyond the last value)}; None for
    fewer than two heights"""
    if len(speeds) < 2:
        return None
    last = speeds[-1][1] - speeds[-2][1]
    before = speeds[-2][1] - speeds[-3][1] if len(speeds) >= 3 else None
    shrinks = before is None or abs(last) < abs(before)
    return dict(last=last, within=abs(last) <= CONVERGED_SPEED, before=before, shrinks=shrinks,
                alternate=before is not None and last * before < 0.0,
                converged=abs(last) <= CONVERGED_SPEED and shrinks)


def height_change_against_m(rows, kernel, h0=10.0, h1=20.0, Delta=2.0):
    """How doubling the strip's height from h0 to h1 horizons moves v_ss/c_R at each m with
    crossing runs at both: {'steps': [(m, change)], 'shrinks': at every step in m} (whether the
    height matters less as the bond family gets finer), None for fewer than two such m"""
    steps = []
    for m in sorted({r["m"] for r in rows if r["kernel"] == kernel}):
        a, b = speed_at(rows, kernel, m, h0, Delta), speed_at(rows, kernel, m, h1, Delta)
        if a and b:    # None: not run; 0.0: did not cross
            steps.append((m, b - a))
    if len(steps) < 2:
        return None
    sizes = [abs(d) for _, d in steps]
    return dict(steps=steps, shrinks=all(y < x for x, y in zip(sizes, sizes[1:])))


HEIGHTS = (10.0, 20.0, 40.0)    # H/delta of the sweep in the strip's height


def law_table(rows, Delta=2.0):
    """Per kernel and m: the threshold bracket of the load (H/delta = SWEEP_H_OVER_DELTA), the
    steady speed at Delta over the strip's heights, the last change in height and whether it
    converged (height_convergence), the runs at Delta that did not run steadily, and the grid's
    own c_R over c_R"""
    out = []
    for k in sorted({r["kernel"] for r in rows}):
        for m in sorted({r["m"] for r in rows if r["kernel"] == k}):
            lo, hi = threshold(rows, k, m)
            conv = height_convergence([(h, v) for h in HEIGHTS if (v := speed_at(rows, k, m, h, Delta))])
            lost = [r for r in rows if (r["kernel"], r["m"], r["Delta"]) == (k, m, Delta) and not r["crossed"]]
            out.append([k, f"{m:g}", f"{f(lo, 'g')} / {f(hi, 'g')}",
                        ", ".join(f(speed_at(rows, k, m, h, Delta) or None, ".3f") for h in HEIGHTS),
                        f"{conv['last']:+.4f}, {'yes' if conv['converged'] else 'no'}" if conv else "-",
                        ", ".join(f"{r['H_over_delta']:g} {r['state']}{_where(r)}" for r in lost) or "-",
                        f"{grid_rayleigh_ratio(k, m):.3f}"])
    return md_table(["kernel", "m", "Delta_c (arrests / crosses)", "v_ss/c_R at Delta = 2, H/delta = "
                     + ", ".join(f"{h:g}" for h in HEIGHTS), "last change in H, converged",
                     "not steady at Delta = 2 (H/delta)", "grid's c_R / c_R"], out)


def energy_closure(rows):
    """Gamma + Phi = U' over the runs that crossed: the worst closure's row, the largest drift
    of the energy balance among them, and the row of the largest drift of all runs"""
    crossed = [r for r in rows if r["crossed"]]
    if not crossed:
        return None
    return dict(n=len(crossed), worst=max(crossed, key=lambda r: abs(r["closure_pct"])),
                drift=max(r["balance_pct"] for r in crossed),
                drift_all=max(rows, key=lambda r: r["balance_pct"]))


def _case(r):
    return f"{r['kernel']} m = {r['m']:g}, H/delta = {r['H_over_delta']:g}, Delta = {r['Delta']:g}"


def _where(r):
    """', off the plane at a + 1.49 H' of a branched run that measured it, else ''"""
    x = r.get("left_plane_over_H", float("nan"))
    return "" if math.isnan(x) else f", off the plane at a + {x:.2f} H"


# --------------------------------------------------------------------------- REPORT.md

# the report's runs: by default the Gaussian kernel on a short strip (H = 10 horizons, a few
# tens of seconds each) at three loads; --full adds the converged strip (H = 20 horizons) for
# every kernel and the law at the Mode-I scene's m
REPORT_CASES = [("gaussian", D, M, 10.0) for D in (1.5, 2.0, 3.0)]
REPORT_CASES_FULL = REPORT_CASES + [(k, 2.0, M, H_OVER_DELTA) for k in ("constant", "triangular", "gaussian")] + \
    [(k, D, 5.0, H_OVER_DELTA) for k in ("constant", "triangular", "gaussian") for D in (1.5, 2.0, 3.0)]
REPORT_TITLE = "Steady crack in a pre-stretched strip: the kinetic law (examples/strip-steady-crack)"


def job(workdir, kernel, Delta, m, H_over_delta, nprocs=1):
    """One run for bbpd.jobs: the measured numbers, without the histories (JSON)."""
    r = run(workdir, kernel, Delta, DX * M / m, m, H_over_delta, nprocs=nprocs)
    r.pop("t")
    r.pop("x")
    r["workdir"] = str(workdir)
    return r


def jobs(full=False):
    """The report's strip runs as bbpd.report specs."""
    inputs = (EXAMPLE, Path(__file__), Path(freund.__file__))
    return jobmod.report_specs("strip", "bbpd.benchmarks.strip:job", inputs, (
        (kernel, DX * M / m, f"strip {kernel} m = {m:g} H/delta = {hd:g} Delta = {D:g}",
         {"kernel": kernel, "Delta": D, "m": m, "H_over_delta": hd},
         30.0 * (m / M) ** 3 * (hd / 10.0) ** 3)
        for kernel, D, m, hd in (REPORT_CASES_FULL if full else REPORT_CASES)))


def section(specs, results, figdir, notes):
    """The strip's section of report/REPORT.md."""
    return jobmod.section(
        REPORT_TITLE, "Soda-lime glass (E = 72 GPa, G_c = 3.8 J/m2), plane stress, delta = 1 mm, "
        "strip 8 H long with a seed crack H long, pre-stretched between fixed grips to U' = Delta "
        "G_c; steady speed, bond and wave energies over the middle of the strip. See "
        "examples/strip-steady-crack/README.md.", specs, results,
        lambda rows: table_markdown(rows) + "\n\n" + law_table(rows))


def figure(rows, path, H_over_delta=SWEEP_H_OVER_DELTA):
    """v_ss/c_R against Delta' (the model's U'/G_c) and Gamma/G_c against v_ss/c_R, one line
    per kernel and m at H/delta; runs that arrested drawn at 0, branched ones left out."""
    with plots.figure(path, 1, 2, figsize=(10, 4), dpi=110) as (fig, (a1, a2)):
        styles = {3.0: ":", 4.0: "-", 5.0: "--", 6.0: "-.", 8.0: (0, (1, 3))}
        for k in sorted({r["kernel"] for r in rows}):
            for m in sorted({r["m"] for r in rows if r["kernel"] == k}):
                sel = sorted((r for r in rows if r["kernel"] == k and r["m"] == m
                              and r["H_over_delta"] == H_over_delta
                              and r["state"] in ("crossed", "arrested")),
                             key=lambda r: r["Delta_model"])
                if len(sel) < 2:
                    continue
                ls = styles.get(m, "-")
                a1.plot([r["Delta_model"] for r in sel], [r["v_ss_over_cR"] for r in sel], ls=ls,
                        marker="o", color=COLORS[k], label=f"{k}, m = {m:g}")
                run = [r for r in sel if r["crossed"]]
                a2.plot([r["v_ss_over_cR"] for r in run], [r["Gamma_over_Gc"] for r in run], ls=ls,
                        marker="o", color=COLORS[k], label=f"{k}, m = {m:g}")
        a1.axvline(1.0, color="0.6", lw=0.8)
        a1.set(xlabel="Delta' = U'/G_c (model)", ylabel="v_ss / c_R",
               title=f"steady speed (H = {H_over_delta:g} delta; 0: arrested)")
        a2.axhline(1.0, color="0.6", lw=0.8)
        a2.set(xlabel="v_ss / c_R", ylabel="Gamma / G_c", title="energy the broken bonds take")
        for a in (a1, a2):
            a.grid(alpha=0.3)
            a.legend(fontsize=7)


def work_precision_markdown(rows, Delta=2.0, m=M):
    """Error of v_ss against run time: each kernel's runs at (Delta, m) by strip height, the
    error the difference from its tallest strip (which therefore has none)."""
    out, shown = [], []
    for k in sorted({r["kernel"] for r in rows}):
        sel = sorted((r for r in rows if r["kernel"] == k and r["m"] == m and r["Delta"] == Delta
                      and r["crossed"]), key=lambda r: r["H_over_delta"])
        if len(sel) > 1:
            out += [[k, f"{r['H_over_delta']:g}", int(r["atoms"]), f"{r['loop_s']:.0f}",
                     f"{r['v_ss_over_cR']:.3f}", "(reference)" if r is sel[-1] else
                     f"{r['v_ss_over_cR'] - sel[-1]['v_ss_over_cR']:+.3f}"] for r in sel]
            shown += sel
    table = md_table(["kernel", "H/delta", "atoms", "loop time (s)", "v_ss/c_R",
                      "difference from the tallest strip (c_R)"], out)
    return table + "\n\n" + timing_markdown(shown) if shown else table


if __name__ == "__main__":
    sys.exit(main())

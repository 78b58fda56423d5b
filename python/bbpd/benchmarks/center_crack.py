# SPDX-License-Identifier: GPL-2.0-or-later
"""Crack initiation in a centre-cracked plate under displacement-controlled tension: in.center-crack
relaxed by fix bbpd/relax, the far-field stress at which the pre-crack starts to grow against LEFM
(Tada's finite-width factor), the grip opening bisected with one LAMMPS run of one load step per
trial; --dynamic RAMPS: the same initiation from explicit dynamics, the grips opened to the LEFM
opening over RAMP transit times. examples/quasi-static/README.md ("Crack initiation in a
centre-cracked plate") has the reference, the bisection, the kernels and the commands.

    tools/python -m bbpd.benchmarks.center_crack [--full] [--kernels K1,K2] [--csv NAME]
"""
import argparse
import math
import re
import time
from pathlib import Path

from bbpd import csvfile, provenance

from bbpd.benchmarks.plate_hole import E, HERE, KERNELS, run_lammps

W, A, GC = 0.02, 0.004, 3.8    # in.center-crack: width, half crack length, glass
H_T = 1.0e-3                    # its thickness
CASES = ((2.0e-3, 4), (1.0e-3, 4))    # (delta, m); --full adds FULL_EXTRA
FULL_EXTRA = ((0.5e-3, 4), (1.0e-3, 3), (0.5e-3, 3))
REL_RES = 0.01         # the bracket's width relative to its lower end (the issue's ~1 %)
FIRST_GUESS = 1.0      # the first trial at this fraction of the LEFM opening
STEP = 1.1             # bracket search: multiply / divide the opening by this
CAP_FACTOR = 4         # iteration cap of a trial: this many elastic load steps' iterations
LPS_NU = 1.0 / 3.0     # Poisson's ratio of the state-based kernels (lps/KERNEL)
TIGHT_RES = 0.001      # --dynamic: the relaxed bracket it is compared with


def kernel_vars(kernel, delta):
    """in.center-crack's variables for a kernel: pair_coeff E nu Gc delta for the state-based
    ones; for pmb (bbpd/pmb, peri/pmb's numbers c delta s00 alpha) the constant micromodulus and
    critical stretch of 2D plane stress, c = 9 E / (pi h delta^3), s0 = sqrt(4 pi Gc / (9 E delta))
    (Ha & Bobaru 2010), with the horizon a hair above m Delta (peri/pmb's families are
    |xi| <= delta) and alpha = 0"""
    if kernel.startswith("lps/"):
        return {"kernel": kernel, "coeff": f"{E!r} {LPS_NU!r} {GC!r} {delta!r}"}
    if kernel == "pmb":
        c = 9.0 * E / (math.pi * H_T * delta ** 3)
        s0 = math.sqrt(4.0 * math.pi * GC / (9.0 * E * delta))
        return {"kernel": kernel, "coeff": f"{c!r} {delta * (1.0 + 1.0e-4)!r} {s0!r} 0.0"}
    return {"kernel": kernel}


def tada_factor(a_over_b):
    """finite-width factor of a centre crack in a strip under remote tension, 0.1 % for any a/b
    (Tada, Paris & Irwin, The Stress Analysis of Cracks Handbook, 3rd ed., 2000, Part II)"""
    r = a_over_b
    return (1.0 - 0.025 * r ** 2 + 0.06 * r ** 4) * math.sqrt(1.0 / math.cos(math.pi * r / 2))


def sigma_lefm():
    """far-field stress at initiation, plane stress"""
    return math.sqrt(E * GC) / (math.sqrt(math.pi * A) * tada_factor(2 * A / W))


def trial(kernel, delta, m, u, out, iters):
    dx = delta / m
    work = Path(out) / f"{kernel.replace('/', '-')}-d{delta * 1e3:g}mm-m{m}" / f"u{u:.6e}"
    start = time.perf_counter()
    proc = run_lammps(str(HERE / "in.center-crack"), work,
                      vars={**kernel_vars(kernel, delta), "dx": repr(dx), "m": m, "u": repr(u),
                            "iters": iters})
    r = re.search(r"CENTER-CRACK: u \S+ broken (\d+) stress (\S+) converged (\d) iterations (\d+)"
                  r" bottom \S+ elastic (\S+)", proc.output)
    atoms = int(re.search(r"CENTER-CRACK-SETUP: .* atoms (\d+)", proc.output).group(1))
    broken, converged = int(r.group(1)), r.group(3) == "1"
    if not converged and broken == 0:
        raise RuntimeError(f"{work}: the elastic relaxation did not converge in {iters} iterations")
    return {"broken": broken, "converged": converged, "stress": float(r.group(2)), "iterations": int(r.group(4)),
            "atoms": atoms, "elastic": float(r.group(5)), "wall_s": time.perf_counter() - start}


def initiation(kernel, delta, m, out, rel_res=REL_RES):
    """bisect the grip opening to rel_res; returns the row of the results table"""
    s_lefm = sigma_lefm()
    # stiffness from an opening well below initiation
    u0 = 1.0e-6
    first = trial(kernel, delta, m, u0, out, 1000000)
    assert first["broken"] == 0, first
    k = first["stress"] / u0
    iters = CAP_FACTOR * first["iterations"] + 100
    lo, hi, trials, wall, its = None, None, 1, first["wall_s"], first["iterations"]
    u = FIRST_GUESS * s_lefm / k
    # widen by STEP until a trial breaks bonds and one does not, then bisect
    while lo is None or hi is None or hi / lo - 1.0 > rel_res:
        r = trial(kernel, delta, m, u, out, iters)
        trials, wall, its = trials + 1, wall + r["wall_s"], its + r["iterations"]
        if r["broken"]:
            hi, at_hi = u, r
        else:
            lo, s_lo = u, r["stress"]
        u = u / STEP if lo is None else u * STEP if hi is None else 0.5 * (lo + hi)
    s_hi = s_lo * hi / lo
    s_c = 0.5 * (s_lo + s_hi)
    return {"kernel": kernel, "delta_mm": delta * 1e3, "m": m, "atoms": first["atoms"],
            "delta_over_a": delta / A, "sigma_lo_MPa": s_lo / 1e6, "sigma_hi_MPa": s_hi / 1e6,
            "sigma_c_MPa": s_c / 1e6, "sigma_lefm_MPa": s_lefm / 1e6,
            "error": s_c / s_lefm - 1.0, "u_lo": lo, "u_hi": hi, "broken_at_hi": at_hi["broken"],
            "arrested_at_hi": int(at_hi["converged"]), "trials": trials,
            "iterations": its, "elastic_iterations": first["iterations"], "wall_s": wall, "cpu": provenance.cpu()}


def dynamic(kernel, delta, m, ramp, row, out):
    """the first broken bond of a dynamic ramp over `ramp` transit times to the LEFM opening;
    row: initiation()'s row of the same plate (its stiffness and sigma_c)"""
    k = row["sigma_lo_MPa"] / row["u_lo"]
    u_ref = row["sigma_lefm_MPa"] / k
    work = Path(out) / f"{kernel.replace('/', '-')}-d{delta * 1e3:g}mm-m{m}" / f"ramp{ramp:g}"
    start = time.perf_counter()
    proc = run_lammps(str(HERE / "in.center-crack"), work,
                      vars={**kernel_vars(kernel, delta), "dx": repr(delta / m), "m": m,
                            "u": repr(u_ref), "solver": "dynamic", "ramp": ramp})
    r = re.search(r"CENTER-CRACK-DYNAMIC: step (\d+) time \S+ opening (\S+) stress (\S+) bottom (\S+) "
                  r"brokenenergy (\S+) away (\S+)", proc.output)
    steps = int(re.search(r"CENTER-CRACK-DYNAMIC-SETUP: .* steps (\d+)", proc.output).group(1))
    if float(r.group(5)) <= 0.0:
        raise RuntimeError(f"{work}: no bond broke in {steps} steps")
    u = float(r.group(2))
    return {"solver": "dynamic", "kernel": kernel, "delta_mm": delta * 1e3, "m": m,
            "ramp_transits": ramp, "bracket": 0.0, "steps": int(r.group(1)), "u_um": u * 1e6,
            "sigma_MPa": k * u, "sigma_grips_MPa": 0.5 * (float(r.group(3)) + float(r.group(4))) / 1e6,
            "error": k * u / row["sigma_lefm_MPa"] - 1.0,
            "vs_relax": k * u / row["sigma_c_MPa"] - 1.0, "away_from_tips": int(float(r.group(6))),
            "wall_s": time.perf_counter() - start, "cpu": provenance.cpu()}


def dynamic_study(kernel, delta, m, ramps, out, name):
    """results/NAME: the bisections to REL_RES and TIGHT_RES, then one dynamic ramp per ramp"""
    rows, tight = [], None
    for res in (REL_RES, TIGHT_RES):
        b = tight = initiation(kernel, delta, m, out, res)
        rows.append({"solver": "relax", "kernel": kernel, "delta_mm": delta * 1e3, "m": m,
                     "ramp_transits": 0, "bracket": res, "steps": b["iterations"],
                     "u_um": 0.5e6 * (b["u_lo"] + b["u_hi"]), "sigma_MPa": b["sigma_c_MPa"],
                     "sigma_grips_MPa": b["sigma_c_MPa"], "error": b["error"],
                     "vs_relax": 0.0, "away_from_tips": 0, "wall_s": b["wall_s"], "cpu": b["cpu"]})
    for ramp in ramps:
        rows.append(dynamic(kernel, delta, m, ramp, tight, out))
        rows[0]["vs_relax"] = rows[0]["sigma_MPa"] / tight["sigma_c_MPa"] - 1.0
        csvfile.write_csv(HERE / "results" / name, rows, nan="nan")
        r = rows[-1]
        print(f"{kernel} delta {delta * 1e3:g} mm ramp {ramp:g} transits: u = {r['u_um']:.5f} um, "
              f"sigma = {r['sigma_MPa']:.4f} MPa ({100 * r['vs_relax']:+.2f} % of relax, "
              f"{100 * r['error']:+.2f} % of LEFM), {r['steps']} steps, {r['wall_s']:.3g} s", flush=True)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="/tmp/bbpd-center-crack", help="work directory of the runs")
    ap.add_argument("--kernels", default=",".join(reversed(KERNELS)), help="comma-separated")
    ap.add_argument("--lps", action="store_true",
                    help="the state-based kernels lps/KERNEL of --kernels' kernels instead")
    ap.add_argument("--full", action="store_true", help="add delta = 0.5 mm and m = 3")
    ap.add_argument("--cases", help="instead: comma-separated delta:m pairs, e.g. 0.5e-3:4")
    ap.add_argument("--csv", default="center_crack.csv", help="file name under results/")
    ap.add_argument("--dynamic", help="instead: comma-separated ramps in transit times, on the "
                    "first kernel and case (default the first of CASES)")
    args = ap.parse_args(argv)
    cases = ([(float(c.split(":")[0]), int(c.split(":")[1])) for c in args.cases.split(",")]
             if args.cases else CASES + (FULL_EXTRA if args.full else ()))
    kernels = [f"lps/{k}" if args.lps else k for k in args.kernels.split(",")]
    if args.dynamic:
        return dynamic_study(kernels[0], *cases[0], [float(r) for r in args.dynamic.split(",")],
                             args.out, args.csv)
    rows = []
    for kernel in kernels:
        for delta, m in cases:
            rows.append(initiation(kernel, delta, m, args.out))
            r = rows[-1]
            print(f"{kernel:10s} delta {r['delta_mm']:g} mm m {m}: sigma_c = {r['sigma_c_MPa']:.4f}"
                  f" MPa [{r['sigma_lo_MPa']:.4f}, {r['sigma_hi_MPa']:.4f}] vs LEFM "
                  f"{r['sigma_lefm_MPa']:.4f} ({100 * r['error']:+.1f} %), {r['atoms']} atoms, "
                  f"{r['trials']} trials", flush=True)
            csvfile.write_csv(HERE / "results" / args.csv, rows, nan="nan")
    print(f"wrote {HERE / 'results' / args.csv}")


if __name__ == "__main__":
    main()

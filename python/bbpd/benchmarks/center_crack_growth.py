# SPDX-License-Identifier: GPL-2.0-or-later
"""Load-displacement through crack growth and the energy account of the centre-cracked plate:
in.center-crack with fix bbpd/relax, the grips opened step by step from below initiation until
the plate comes apart; per load step the opening, the grips' reaction, the elastic and
broken-bond energies, the work done on the body and what the account W = U + B + D leaves
(examples/quasi-static/README.md, "Load-displacement through crack growth, and the energy
account", derives the work and the account and has the commands).

    tools/python -m bbpd.benchmarks.center_crack_growth [--kernel K] [--delta D] [--m M]
        [--du FRACTION] [--csv NAME]
"""
import argparse
import re
from pathlib import Path

from bbpd import csvfile, provenance
from bbpd.benchmarks.center_crack import H_T, W, kernel_vars, sigma_lefm, trial
from bbpd.benchmarks.plate_hole import HERE, run_lammps

FIRST = 0.9           # the first load step, from rest, to this fraction of the LEFM opening
DU = 0.005            # each further load step opens the grips by this fraction of it
MAX_STEPS = 200
STOP = 0.05           # the path ends when the load falls below this fraction of LEFM's

LINE = re.compile(r"CENTER-CRACK: u (\S+) broken (\d+) stress (\S+) converged (\d) iterations "
                  r"(\d+) bottom (\S+) elastic (\S+) brokenenergy (\S+) tip (\S+) relaxations "
                  r"(\d+) step (\d+)")
RELAX = re.compile(r"^bbpd/relax: load step (\d+) (?:converged|NOT converged) at step \d+: .*, "
                   r"([0-9.e+-]+) s$", re.M)


def path(kernel, delta, m, out, du=DU, first=FIRST, tol=1.0e-6, max_steps=MAX_STEPS):
    """the load steps of one path: a list of dicts, one per load step"""
    dx = delta / m
    # the LEFM opening from the elastic stiffness (one elastic load step)
    probe = trial(kernel, delta, m, 1.0e-6, out, 1000000)
    u_lefm = sigma_lefm() * 1.0e-6 / probe["stress"]
    work = Path(out) / f"growth-{kernel.replace('/', '-')}-d{delta * 1e3:g}mm-m{m}-du{du:g}"
    vars = {**kernel_vars(kernel, delta), "dx": repr(dx), "m": m, "u": repr(first * u_lefm),
            "du": repr(du * u_lefm), "steps": max_steps, "tol": repr(tol),
            "stop": repr(STOP * sigma_lefm())}
    proc = run_lammps(str(HERE / "in.center-crack"), work, vars=vars, timeout=7200)
    walls = {int(s): float(t) for s, t in RELAX.findall(proc.output)}
    steps = []
    for g in LINE.findall(proc.output):
        u, stop, sbot = float(g[0]), float(g[2]), float(g[5])
        steps.append({"step": int(g[10]), "u_m": u, "load_N": 0.5 * (stop + sbot) * W * H_T,
                      "stress_MPa": 0.5 * (stop + sbot) / 1e6, "broken": int(g[1]),
                      "converged": int(g[3]), "iterations": int(g[4]), "relaxations": int(g[9]),
                      "U_J": float(g[6]), "B_J": float(g[7]), "tip_x_m": float(g[8]),
                      "wall_s": walls.get(int(g[10]), float("nan"))})
    rel = re.search(r"bbpd/relax: load step \d+ converged .*\(([0-9.e+-]+) of the reference",
                    proc.output)
    assert steps and rel, proc.output[-2000:]
    return account(steps), u_lefm, probe["atoms"]


def breaking_split(kernel, delta, m, u, out):
    """Where the energy released at initiation goes: one load step from rest to the opening u
    (the body is elastic until then: the state of the path) with thermo output at every step.
    A breaking evaluation does not move the atoms, so the elastic energy it takes out is the
    broken bonds' own energy at their stretch, against their energy at the critical stretch,
    which B books; the rest of the release is the relaxation after it. Returns (events, totals)."""
    work = Path(out) / f"split-{kernel.replace('/', '-')}-d{delta * 1e3:g}mm-m{m}"
    proc = run_lammps(str(HERE / "in.center-crack"), work,
                      vars={**kernel_vars(kernel, delta), "dx": repr(delta / m), "m": m,
                            "u": repr(u), "thermo": 1})
    rows = []    # step, bonds broken so far, U, B (thermo: step pe it broken rel stress U B tip)
    for line in proc.output.splitlines():
        f = line.split()
        if len(f) == 9 and f[0].isdigit():
            rows.append((int(f[0]), float(f[3]), float(f[6]), float(f[7])))
    events = [{"step": b[0], "bonds": int(b[1] - a[1]), "bond_energy_J": a[2] - b[2],
               "booked_J": b[3] - a[3]}
              for a, b in zip(rows, rows[1:]) if b[0] == a[0] + 1 and b[1] > a[1]]
    before = next(a for a, b in zip(rows, rows[1:]) if b[0] == a[0] + 1 and b[1] > a[1])
    released = before[2] - rows[-1][2]
    bonds = sum(e["bond_energy_J"] for e in events)
    booked = sum(e["booked_J"] for e in events)
    return events, {"released_J": released, "bond_energy_J": bonds, "booked_J": booked,
                    "overshoot_J": bonds - booked, "relaxation_J": released - bonds}


def account(steps):
    """add the work, the energy released at fixed opening and the account to each load step:
    the bonds are held between two converged states, so the load rises along the secant
    k_{k-1} = F_{k-1}/u_{k-1} and W = sum_k 1/2 k_{k-1} (u_k^2 - u_{k-1}^2) (W_trap: the
    trapezoid over the converged points, for comparison); U_k^- = 1/2 k_{k-1} u_k^2 before the
    bonds of step k break, D_k = (U_k^- - U_k) - (B_k - B_{k-1})"""
    w = w_trap = d = 0.0
    prev = None
    for s in steps:
        u, f = s["u_m"], s["load_N"]
        if prev is None:
            assert s["broken"] == 0, "the first load step must be elastic"
            k_prev, u_prev, f_prev, u_before, b_prev = f / u, 0.0, 0.0, 0.5 * f * u, 0.0
        else:
            k_prev, u_prev, f_prev, b_prev = prev["load_N"] / prev["u_m"], prev["u_m"], \
                prev["load_N"], prev["B_J"]
            u_before = 0.5 * k_prev * u * u
        w += 0.5 * k_prev * (u * u - u_prev * u_prev)
        w_trap += 0.5 * (f_prev + f) * (u - u_prev)
        released = u_before - s["U_J"]
        d += released - (s["B_J"] - b_prev)
        s.update({"load_before_break_N": k_prev * u, "W_J": w, "W_trap_J": w_trap,
                  "released_J": released, "dB_J": s["B_J"] - b_prev, "D_J": d,
                  "gap": (w - s["U_J"] - s["B_J"]) / w,
                  "clapeyron": s["U_J"] / (0.5 * f * u) - 1.0 if f > 0 else 0.0})
        prev = s
    return steps


def summary(steps):
    """the numbers of the README: peak, initiation, the account before and after the plate
    comes apart"""
    first = next(i for i, s in enumerate(steps) if s["broken"] > 0)
    peak = max(steps, key=lambda s: s["load_N"])
    last = steps[-1]
    # the last load step before the one that separates the plate (or the last of the path)
    before = max((s for s in steps if s["load_N"] > 0.5 * peak["load_N"]), key=lambda s: s["step"])
    return {"initiation_u_m": steps[first]["u_m"], "initiation_load_N": steps[first]["load_before_break_N"],
            "peak_load_N": peak["load_N"], "peak_u_m": peak["u_m"], "final_load_N": last["load_N"],
            "final_u_m": last["u_m"], "gap_before_separation": before["gap"],
            "B_over_W_before": before["B_J"] / before["W_J"], "u_before_m": before["u_m"],
            "gap_final": last["gap"], "B_final_J": last["B_J"], "W_final_J": last["W_J"],
            "clapeyron_max": max(abs(s["clapeyron"]) for s in steps if s["load_N"] > 1e-3 * peak["load_N"]),
            "steps": len(steps), "wall_s": sum(s["wall_s"] for s in steps)}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="/tmp/bbpd-center-crack", help="work directory of the runs")
    ap.add_argument("--kernel", default="gaussian")
    ap.add_argument("--delta", type=float, default=2.0e-3)
    ap.add_argument("--m", type=int, default=4)
    ap.add_argument("--du", type=float, default=DU, help="load step, fraction of the LEFM opening")
    ap.add_argument("--first", type=float, default=FIRST,
                    help="the first load step, fraction of the LEFM opening")
    ap.add_argument("--csv", default="center_crack_growth.csv", help="file name under results/")
    args = ap.parse_args(argv)
    steps, u_lefm, atoms = path(args.kernel, args.delta, args.m, args.out, du=args.du,
                                 first=args.first)
    cpu = provenance.cpu()
    out = HERE / "results" / args.csv
    csvfile.write_csv(out, [{"kernel": args.kernel, "delta_mm": args.delta * 1e3, "m": args.m,
                             "atoms": atoms, "u_lefm_m": u_lefm, "du_over_u_lefm": args.du, **s,
                             "cpu": cpu} for s in steps], nan="nan", digits=8)
    for s in steps:
        print(f"u {s['u_m'] * 1e6:.4f} um  F {s['load_N']:8.4f} N  broken {s['broken']:5d}  "
              f"U {s['U_J']:.4e}  B {s['B_J']:.4e}  W {s['W_J']:.4e}  gap {100 * s['gap']:+.2f} %  "
              f"it {s['iterations']}  {s['wall_s']:.2f} s")
    for k, v in summary(steps).items():
        print(f"{k}: {v:.6g}")
    first = next(s for s in steps if s["broken"] > 0)
    events, totals = breaking_split(args.kernel, args.delta, args.m, first["u_m"], args.out)
    split = out.with_name(out.stem + "_initiation_split.csv")
    csvfile.write_csv(split, [{"u_m": first["u_m"], **e, "cpu": cpu} for e in events], nan="nan",
                      digits=8)
    print("initiation: " + ", ".join(f"{k} {v:.6g}" for k, v in totals.items()))
    print(f"u_LEFM {u_lefm:.6g} m, {atoms} atoms, {cpu}; wrote {out}")


if __name__ == "__main__":
    main()

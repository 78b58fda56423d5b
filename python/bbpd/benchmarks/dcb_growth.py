# SPDX-License-Identifier: GPL-2.0-or-later
"""Stable crack growth and its energy account: in.dcb, a double cantilever beam opened at its
arms load step by load step with fix bbpd/relax.

    tools/python -m bbpd.benchmarks.dcb_growth [--dx DX] [--m M] [--u U] [--du DU] [--steps N]
        [--csv NAME]

At a fixed opening the energy release rate of a DCB falls as its crack grows, so the crack
grows stably, a little per load step, where the centre-cracked plate's runs (README.md). The
work, the energy released at fixed opening and the account W = U + B + D are those of
bbpd.benchmarks.center_crack_growth (account). Over the growth (from the last elastic state
on) the driver reports B over the energy the grips put in and the body did not keep: the part
of the release that the broken bonds book at their critical stretch.
"""
import argparse
import re
from pathlib import Path

from bbpd import csvfile, provenance
from bbpd.benchmarks.center_crack_growth import RELAX, account
from bbpd.benchmarks.plate_hole import HERE, run_lammps

LINE = re.compile(r"DCB: u (\S+) broken (\d+) F (\S+) U (\S+) B (\S+) iterations (\d+) "
                  r"converged (\d) step (\d+)")


def path(out, dx=0.5e-3, m=4, u=10e-6, du=0.5e-6, steps=24, kernel="gaussian"):
    """(the load steps as dicts with the account, the growth's totals, atoms)"""
    work = Path(out) / f"dcb-{kernel}-dx{dx * 1e3:g}mm-m{m}-du{du:g}"
    proc = run_lammps(str(HERE / "in.dcb"), work, timeout=7200,
                      vars={"kernel": kernel, "dx": repr(dx), "m": m, "u": repr(u),
                            "du": repr(du), "steps": steps})
    walls = {int(s): float(t) for s, t in RELAX.findall(proc.output)}
    rows = [{"step": int(g[7]), "u_m": float(g[0]), "load_N": float(g[2]), "broken": int(g[1]),
             "converged": int(g[6]), "iterations": int(g[5]), "U_J": float(g[3]),
             "B_J": float(g[4]), "wall_s": walls.get(int(g[7]), float("nan"))}
            for g in LINE.findall(proc.output)]
    atoms = int(re.search(r"DCB-SETUP: .* atoms (\d+)", proc.output).group(1))
    account(rows)
    first = next(k for k, r in enumerate(rows) if r["broken"] > 0)
    elastic, last = rows[first - 1], rows[-1]
    released = (last["W_J"] - elastic["W_J"]) - (last["U_J"] - elastic["U_J"])
    return rows, {"released_J": released, "B_J": last["B_J"], "B_over_released":
                  last["B_J"] / released, "bonds": sum(r["broken"] for r in rows),
                  "gap_final": last["gap"], "first_break_u_m": rows[first]["u_m"]}, atoms


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="/tmp/bbpd-dcb", help="work directory of the runs")
    ap.add_argument("--dx", type=float, default=0.5e-3)
    ap.add_argument("--m", type=int, default=4)
    ap.add_argument("--u", type=float, default=10e-6)
    ap.add_argument("--du", type=float, default=0.5e-6)
    ap.add_argument("--steps", type=int, default=24)
    ap.add_argument("--csv", default="dcb_growth.csv", help="file name under results/")
    args = ap.parse_args(argv)
    rows, totals, atoms = path(args.out, args.dx, args.m, args.u, args.du, args.steps)
    cpu = provenance.cpu()
    out = HERE / "results" / args.csv
    csvfile.write_csv(out, [{"dx_mm": args.dx * 1e3, "m": args.m, "atoms": atoms, **r, "cpu": cpu}
                            for r in rows], nan="nan", digits=8)
    for r in rows:
        print(f"u {r['u_m'] * 1e6:6.2f} um  F {r['load_N']:.4f} N  broken {r['broken']:4d}  "
              f"released {r['released_J']:.3e}  dB {r['dB_J']:.3e}  gap {100 * r['gap']:+.2f} %  "
              f"{r['iterations']} it  {r['wall_s']:.2f} s")
    print(", ".join(f"{k} {v:.6g}" for k, v in totals.items()))
    print(f"{atoms} atoms, {cpu}; wrote {out}")


if __name__ == "__main__":
    main()

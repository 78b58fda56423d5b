#!/usr/bin/python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""Mode-I semi-infinite crack with LAMMPS in this Python process, compared with Freund.

Runs examples/mode1-semi-infinite/in.mode1 through bbpd.lammps() (LAMMPS's own Python module
with bbpdplugin.so loaded), reads K_I(t) of `compute bbpd/dsif` after every step as NumPy
arrays through LAMMPS's numpy interface, and compares it with Freund's solution (paper eq. 42)
with the errors of eqs. 44-45. Run from the repository root:

    tools/python examples/python/mode1_freund.py --dx 0.1
"""
import argparse
import json
import os
import tempfile
from pathlib import Path

import numpy as np
from lammps import LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR

import bbpd
from bbpd.benchmarks import mode1
from bbpd.inprocess import QUIET

EXAMPLE = Path(__file__).resolve().parents[1] / "mode1-semi-infinite" / "in.mode1"


def run(kernel="gaussian", dx=0.1, t_end=mode1.T_END):
    """t, K_I (paper constants), K_I and K_II (consistent constants) after every step."""
    dt = mode1.default_dt(dx)
    variables = {"kernel": kernel, "dx": dx, "dt": dt, "E": mode1.E, "rho": mode1.RHO,
                 "H": mode1.H, "td": mode1.T_D, "sigma0": mode1.SIGMA0,
                 "nu_paper": mode1.NU_PAPER,
                 "tend": 0}    # the script's own run is a 'run 0': the steps are taken below
    cmdargs = list(QUIET)
    for name, value in variables.items():
        cmdargs += ["-var", name, str(value)]
    nsteps = int(np.ceil(t_end / dt))
    series = []
    cwd = os.getcwd()
    with tempfile.TemporaryDirectory() as scratch:    # in.mode1 also writes k.dat
        os.chdir(scratch)
        try:
            lmp = bbpd.lammps(cmdargs=cmdargs)
            lmp.file(str(EXAMPLE))
            for step in range(nsteps + 1):
                if step:
                    lmp.command("run 1 pre no post no")
                k_paper = lmp.numpy.extract_compute("kpaper", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR)
                k_cons = lmp.numpy.extract_compute("kcons", LMP_STYLE_GLOBAL, LMP_TYPE_VECTOR)
                series.append((lmp.get_thermo("time"), k_paper[0], k_cons[0], k_cons[1]))
            lmp.close()
        finally:
            os.chdir(cwd)
    t, k_paper, k_consistent, k_ii = np.array(series).T
    return t, k_paper, k_consistent, k_ii


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--kernel", default="gaussian", choices=mode1.KERNELS)
    ap.add_argument("--dx", type=float, default=0.1, help="grid spacing in m (default 0.1)")
    ap.add_argument("--json", type=Path, help="also write t and K(t) to this file")
    args = ap.parse_args()
    t, k_paper, k_consistent, k_ii = run(args.kernel, args.dx)
    err = mode1.errors(t, k_paper, k_consistent)
    for convention in mode1.CONVENTIONS:
        e = err[convention]
        print(f"{args.kernel} dx {args.dx:g} m, {convention} constants: peak error "
              f"{e['peak']:.2f} %, L2 error {e['l2']:.2f} % over t <= 3 t_c")
    if args.json:
        args.json.write_text(json.dumps({"t": t.tolist(), "k_paper": k_paper.tolist(),
                                         "k_consistent": k_consistent.tolist(),
                                         "k_ii": k_ii.tolist(), "errors": err}))


if __name__ == "__main__":
    main()

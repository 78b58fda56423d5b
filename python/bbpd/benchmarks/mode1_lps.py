# SPDX-License-Identifier: GPL-2.0-or-later
"""The stationary Mode-I crack with Poisson's ratio free: in.mode1 on the LPS styles at nu =
0.3, where the paper's convention and the model's are one, beside the bond-based runs
(examples/mode1-semi-infinite/README.md has the commands).
"""

import sys
from pathlib import Path

from bbpd import csvfile
from bbpd.benchmarks import mode1
from bbpd.provenance import cpu
from bbpd.kernels import KERNELS
from bbpd.markdown import table as md_table
from bbpd.benchmarks import cli

ROOT = Path(__file__).resolve().parents[3]
CSV = ROOT / "examples" / "mode1-semi-infinite" / "results" / "mode1_lps.csv"
NU = mode1.NU_PAPER                 # the paper's Poisson's ratio, now the model's own
MODEL = "plane/strain"              # eq. 42 is Freund's plane-strain solution
DXS = (0.1, 0.05, 0.025)
COLUMNS = ("kernel", "dx_m", "nu", "model", "peak_pct", "l2_pct", "j_peak_pct", "j_l2_pct",
           "kii_over_ki", "dt_s", "atoms", "loop_s")


def run_case(workdir, kernel, dx, nprocs=1):
    """One LPS run; its CSV row (errors of the consistent convention = the paper's here)."""
    r = mode1.run(Path(workdir) / f"{kernel}_{dx:g}", kernel, dx, MODEL, nprocs=nprocs,
                  family="lps", nu=NU)
    c, j = r["consistent"], r["jintegral"]["consistent"]
    return {"kernel": kernel, "dx_m": dx, "nu": NU, "model": MODEL, "peak_pct": c["peak"],
            "l2_pct": c["l2"], "j_peak_pct": j["peak"], "j_l2_pct": j["l2"],
            "kii_over_ki": r["kii_over_ki"], "dt_s": r["dt"], "atoms": r["atoms"],
            "loop_s": r["loop_time"]}


def read_rows(path=CSV):
    return csvfile.read_csv(path)[1]


def table(rows, bond_rows):
    def bond(r):    # the bond-based run of the same kernel and grid
        b = next((q for q in bond_rows if q["kernel"] == r["kernel"]
                  and abs(q["dx_m"] - r["dx_m"]) < 1e-12), None)
        return ([f"{b['consistent_peak']:.2f} / {b['consistent_l2']:.2f}",
                 f"{b['j_peak']:.2f} / {b['j_l2']:.2f}"] if b else ["-", "-"])
    return md_table(
        ("kernel", "dx (m)", "LPS nu = 0.3, plane strain: DSIF peak / L2 (%)",
         "J-integral peak / L2 (%)", "bond-based plane stress (nu = 1/3), consistent: DSIF peak / "
         "L2 (%)", "J-integral peak / L2 (%)", "LPS loop (s)"),
        ([r["kernel"], f"{r['dx_m']:g}", f"{r['peak_pct']:.2f} / {r['l2_pct']:.2f}",
          f"{r['j_peak_pct']:.2f} / {r['j_l2_pct']:.2f}", *bond(r), f"{r['loop_s']:.1f}"]
         for r in sorted(rows, key=lambda r: (KERNELS.index(r["kernel"]), -r["dx_m"]))))


def main(argv=None):
    a = cli.parser(__doc__, "/tmp/mode1-lps", nprocs=1, kernels=KERNELS, dx=DXS,
                   csv=True).parse_args(argv)
    rows = []
    cmd = cli.command("mode1_lps", argv)
    for kernel in a.kernels:
        for dx in a.dx:
            r = run_case(a.work, kernel, dx, a.nprocs)
            print(f"{kernel} dx {dx:g}: DSIF peak / L2 {r['peak_pct']:.2f} / {r['l2_pct']:.2f} %, "
                  f"J {r['j_peak_pct']:.2f} / {r['j_l2_pct']:.2f} %, loop {r['loop_s']:.1f} s",
                  flush=True)
            rows.append(r)
            if a.csv:
                csvfile.write_csv(a.csv, rows, comments=[
                    f"made by: {cmd}", f"timing: LAMMPS loop time, {cpu()}, shared machine"])
    return 0


if __name__ == "__main__":
    sys.exit(main())

# SPDX-License-Identifier: GPL-2.0-or-later
"""tools/reproduce: python -m bbpd.report [--full | --finer] [--out DIR] [--jobs N]"""
import argparse
import os
import sys

import bbpd.report as report
from bbpd.jobs import ROOT
from bbpd.report import make


def main(argv=None):
    ap = argparse.ArgumentParser(prog="tools/reproduce",
                                 description=report.__doc__.split("\n")[0])
    ap.add_argument("--full", action="store_true",
                    help="finer grids as well: Mode II 0.25 mm, Kalthoff-Winkler 0.5 mm, and "
                         "for the work-precision diagrams Mode I 0.0125 m and dispersion m = 20 "
                         "(about 12 more minutes on 2 cores), the Kalthoff-Winkler "
                         "loading study (32 runs, about 1 h of single-core run time), "
                         "Kalthoff-Winkler Gaussian at 0.25 mm (one run of about 20 min) "
                         "and the Mode-I propagation at 0.025 m, and the whole kink sweep "
                         "of examples/kink-mixed-mode (49 runs; its 18 fine-grid runs take "
                         "about 2 h of single-core run time), and the crack-branching sweep "
                         "of examples/crack-branching (12 runs, about 10 min)")
    ap.add_argument("--finer", action="store_true",
                    help="the finer grids of the benchmarks' tables alone (Mode II 0.25 mm, "
                         "Kalthoff-Winkler Gaussian 0.5 mm: 4 runs more than the default), "
                         "without the work-precision and loading-study runs of --full")
    ap.add_argument("--out", default=str(ROOT / "report"), help="report folder (default report/)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1,
                    help="runs at a time (default: all cores)")
    args = ap.parse_args(argv)
    if args.jobs < 1:
        ap.error("--jobs must be at least 1")
    if args.full and args.finer:
        ap.error("--full already runs the finer grids: give one of --full, --finer")
    _, n_failed = make.reproduce(args.out, make.job_list(args.full, args.finer), args.jobs,
                                 args.full, finer=args.finer)
    return 1 if n_failed else 0


if __name__ == "__main__":
    sys.exit(main())

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
                    help="the finer grids, the work-precision runs, the Kalthoff-Winkler studies "
                         "and the whole kink and crack-branching sweeps as well (hours of "
                         "single-core run time: report.runs.benchmark_specs lists them)")
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

# SPDX-License-Identifier: GPL-2.0-or-later
"""The command line of `tools/python -m bbpd.benchmarks.NAME`: the options every benchmark
spells alike, and the command line a results CSV names as what made it."""
import argparse
import sys

from bbpd.kernels import KERNELS

HELP = {"reuse": "measure the finished runs in --work again instead of running them",
        "csv": "write the rows here",
        "figures": "write the figures here",
        "append": "add the rows to --csv, keeping its rows and the commands that made them"}


def parser(doc, work, nprocs=None, kernels=None, dx=None, **flags):
    """A benchmark's parser: the first paragraph of doc as its description, --work (folder of
    the runs, default work), --nprocs (alias --np) with default nprocs, --kernels and --dx with
    the given default lists, and the flags reuse, csv, figures, append (True: with the help of
    HELP; a string: with that help)."""
    ap = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    ap.add_argument("--work", default=work, help="folder of the runs")
    if nprocs is not None:
        ap.add_argument("--nprocs", "--np", dest="nprocs", type=int, default=nprocs,
                        help=f"MPI ranks of each run (default {nprocs})")
    if kernels is not None:
        ap.add_argument("--kernels", nargs="+", default=list(kernels), choices=KERNELS)
    if dx is not None:
        ap.add_argument("--dx", nargs="+", type=float, default=list(dx))
    for name, text in flags.items():
        if text:
            helptext = HELP[name] if text is True else text
            if name in ("reuse", "append"):
                ap.add_argument(f"--{name}", action="store_true", help=helptext)
            else:
                ap.add_argument(f"--{name}", help=helptext)
    return ap


def command(name, argv, drop=()):
    """'tools/python -m bbpd.benchmarks.NAME ARGS' of this call (argv, or the command line's
    arguments), without the arguments in drop"""
    args = sys.argv[1:] if argv is None else argv
    return f"tools/python -m bbpd.benchmarks.{name} " + " ".join(a for a in args if a not in drop)

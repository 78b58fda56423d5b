# SPDX-License-Identifier: GPL-2.0-or-later
"""python -m bbpd.claims [--write] [--from REPORT_DIR] [--step-times COMMAND LOG NOTE...]"""
import argparse
import sys
from pathlib import Path

from . import check, times, write
from .data import STEP_TIMES, import_report


def main(argv=None):
    ap = argparse.ArgumentParser(prog="python -m bbpd.claims",
                                 description="Check (default) or regenerate the numbers of the "
                                             "READMEs and docs from the result files.")
    ap.add_argument("--write", action="store_true", help="regenerate every block from the data")
    ap.add_argument("--from", dest="report", metavar="REPORT_DIR",
                    help="copy REPORT_DIR/results/*.csv (tools/reproduce) over the committed "
                         "references, then regenerate")
    ap.add_argument("--step-times", nargs="+", metavar=("COMMAND", "LOG"),
                    help="COMMAND LOG [NOTE...]: the step times in LOG (the output of COMMAND, "
                         "e.g. tools/reproduce) into doc/results/quickstart_times.csv, with the "
                         "NOTEs (CPU, conditions) as its header, then regenerate")
    args = ap.parse_args(argv)
    if args.report:
        for path in import_report(args.report):
            print(f"claims: reference {path}")
    if args.step_times:
        if len(args.step_times) < 2:
            ap.error("--step-times needs COMMAND and LOG")
        command, log, *notes = args.step_times
        times.add(STEP_TIMES, command, Path(log).read_text(errors="replace"), notes)
    if args.write or args.report or args.step_times:
        for rel in write():
            print(f"claims: regenerated {rel}")
    problems = check()
    for p in problems:
        print(p)
    print(f"claims: {len(problems)} problem(s)" if problems else "claims: text and data agree")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

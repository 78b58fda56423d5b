# SPDX-License-Identifier: GPL-2.0-or-later
"""The numbers of the READMEs and docs, generated from result files and checked against them.

  tools/python -m bbpd.claims                  check: exit 1 and list every mismatch
  tools/python -m bbpd.claims --write          regenerate the blocks from the data
  tools/python -m bbpd.claims --from report/   take the result CSVs of a tools/reproduce call
                                               as the new references, then regenerate

Data: the reference CSVs committed under examples/<benchmark>/results/ (copies of what
tools/reproduce writes to report/results/, whose first lines name the command, builds and
CPU that made them), perf/results/ and doc/results/ (the quick start's step times).  Tables:
blocks between ``<!-- bbpd:table NAME -->`` and ``<!-- /bbpd:table -->``, each rendered from
the data by a function of blocks.BLOCKS, so a table whose text and data disagree is reported.
The sentences beside the tables are written by hand; the tests of each benchmark check the
numbers and verdicts they state against the same CSVs.  Outside the blocks, checks.py asks
every speed ratio to name its CPU.

Modules: bbpd.markers (find and replace blocks, below the benchmarks that write them too),
data (the reference CSVs), text (number formats), blocks (which table lives where, rendered
by mode1, mode2, kw, readme, crack, perf), checks (check and write a file's text).
"""
from .checks import check, check_text, write

__all__ = ["check", "check_text", "write"]

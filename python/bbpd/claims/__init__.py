# SPDX-License-Identifier: GPL-2.0-or-later
"""The numbers of the READMEs and docs, generated from result files and checked against them.

  tools/python -m bbpd.claims                  check: exit 1 and list every mismatch
  tools/python -m bbpd.claims --write          regenerate the blocks from the data
  tools/python -m bbpd.claims --from report/   take the result CSVs of a tools/reproduce call
                                               as the new references, then regenerate

Data: the reference CSVs under examples/<benchmark>/results/, perf/results/ and doc/results/.
Tables: blocks between ``<!-- bbpd:table NAME -->`` and ``<!-- /bbpd:table -->``, each rendered
from the data by a function of blocks.BLOCKS, so a table whose text and data disagree is
reported. The sentences beside the tables are written by hand; checks.py also asks every speed
ratio outside the blocks to name its CPU.
"""
from .checks import check, check_text, write

__all__ = ["check", "check_text", "write"]

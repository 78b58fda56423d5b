# SPDX-License-Identifier: GPL-2.0-or-later
"""Reproduce the paper's four benchmarks for the three kernels and write report/REPORT.md.

  tools/reproduce [--full] [--out DIR] [--jobs N]

Every benchmark run is a job of bbpd.jobs: single-rank LAMMPS runs, N at a time (default: all
cores), each cached under OUT/runs by its arguments, its input script, the Python that
analyses it and the plugin binary, so a second call reuses finished runs and reruns exactly
those whose inputs changed.  A failed run is listed as FAILED with its error; the others go on.

The report holds, per benchmark, our numbers beside the paper's with each run's wall time,
lines under each table that fill the numbers into fixed templates, the figures
(PNG) and the LAMMPS build, plugin version and machine that produced them.

Definitions follow the examples' READMEs (examples/*/README.md); the benchmark modules in
bbpd.benchmarks run and analyse each case.

Modules: runs (which runs, as bbpd.jobs jobs), tables (results -> rows and CSV), prose (the
lines under the tables), figures, sections (one per benchmark), provenance (LAMMPS, plugin, git, machine),
then work_precision (built on these), and on top document (REPORT.md), results (the
numbers as CSV, for bbpd.claims) and make (reproduce: the runs, then the document); __main__ is
the command.
"""
# The names callers use as bbpd.report.X, among them "bbpd.report:run_job" and
# "bbpd.report:dispersion_run" (part of every run's cache key). document, make and
# work_precision are not among them: they import the blocks (import them as
# bbpd.report.document, bbpd.report.make and bbpd.report.work_precision).
from bbpd.jobs import Job, Spec
from bbpd.kernels import KERNELS

from .prose import mode2_j, ranking
from .runs import dispersion_run, make_spec, run_job

__all__ = ["Job", "Spec", "KERNELS", "mode2_j", "ranking", "dispersion_run", "make_spec", "run_job"]

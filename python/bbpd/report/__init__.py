# SPDX-License-Identifier: GPL-2.0-or-later
"""Reproduce the paper's four benchmarks for the three kernels and write report/REPORT.md.

  tools/reproduce [--full] [--out DIR] [--jobs N]

Every run is a job of bbpd.jobs, cached under OUT/runs by its arguments, input script, analysis
code and plugin binary: a second call reuses finished runs and reruns exactly those whose inputs
changed; a failed run is listed as FAILED and the others go on. The report holds per benchmark
our numbers beside the paper's, lines with the numbers filled into fixed templates, the figures
and the builds and machine that made them. Its modules' layers: doc/architecture.rst.
"""
# The names callers use as bbpd.report.X, among them "bbpd.report:run_job" and
# "bbpd.report:dispersion_run" (part of every run's cache key); document, make and
# work_precision are imported as modules.
from bbpd.jobs import Job, Spec
from bbpd.kernels import KERNELS

from .sections import mode2_j
from .runs import dispersion_run, make_spec, run_job

__all__ = ["Job", "Spec", "KERNELS", "mode2_j", "dispersion_run", "make_spec", "run_job"]

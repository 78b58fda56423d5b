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
# The public names of the building blocks, here so that "bbpd.report:run_job" (part of every
# run's cache key) and the callers of bbpd.report.X keep working. document and make are not
# among them: they use work_precision, which imports the blocks (import them as
# bbpd.report.work_precision, bbpd.report.document and bbpd.report.make).
from bbpd.jobs import ROOT, Job
from bbpd.kernels import COLORS, KERNELS

from .figures import RESOLUTION_COLORS, _figure, plot_k
from .prose import MODE2_FIELD_SHARE, NEGATIVE_VG, mode2_j, ranking
from bbpd.provenance import git_revision, lammps_build, machine, plugin_version
from .runs import (BENCH, ESTIMATE_S, ESTIMATES_ENV, FREUND_PY, HEARTBEAT_S, KW_DX,
                   KW_GAUSSIAN_DX_FULL, METRICS_PY, MODE1_TABLE2_DX, MODE1_TABLE3_DX, MODE2_DX,
                   MODE2_DX_FULL, READERS_PY, Spec, _tools, benchmark_specs, build_of_run,
                   dispersion_run, make_spec, run_job, bench_inputs)
from .sections import (dispersion_section, kw_section, mode1_section,
                       mode2_section)
from .tables import (DISP_KDX, _arrays, _plain, f, failed, failed_row, failure_text, md_table,
                     run_time)

__all__ = ["ROOT", "Job", "COLORS", "KERNELS",
           "RESOLUTION_COLORS", "_figure", "plot_k",
           "MODE2_FIELD_SHARE", "NEGATIVE_VG", "mode2_j", "ranking", "git_revision",
           "lammps_build", "machine", "plugin_version", "BENCH", "ESTIMATE_S", "ESTIMATES_ENV",
           "FREUND_PY", "HEARTBEAT_S", "KW_DX", "KW_GAUSSIAN_DX_FULL", "METRICS_PY",
           "READERS_PY",
           "MODE1_TABLE2_DX", "MODE1_TABLE3_DX", "MODE2_DX", "MODE2_DX_FULL", "Spec", "_tools",
           "benchmark_specs", "build_of_run", "bench_inputs", "dispersion_run",
           "make_spec", "run_job",
           "dispersion_section", "kw_section", "mode1_section",
           "mode2_section", "DISP_KDX", "_arrays", "_plain", "f", "failed", "failed_row",
           "failure_text", "md_table", "run_time"]

# SPDX-License-Identifier: GPL-2.0-or-later
"""Blocks of the crack-growth examples (examples/mode1-propagation, examples/kink-mixed-mode,
examples/crack-branching,
the projectile, grid-pull and summary parts of examples/kalthoff-winkler), each rendered by its
benchmark module from the results it committed."""
import json

from bbpd import csvfile
from bbpd.benchmarks import kalthoff_winkler_3d as kw3d
from bbpd.benchmarks import kalthoff_winkler_deck as deck
from bbpd.benchmarks import kalthoff_winkler_grid as grid
from bbpd.benchmarks import kalthoff_winkler_projectile as projectile
from bbpd.benchmarks import (branching, kink, kink_convergence, kink_kalthoff_winkler,
                             mode1_propagation, strip, strip_closure)
from bbpd.jobs import ROOT

PROPAGATION_CSV = ROOT / "examples" / "mode1-propagation" / "results" / "mode1_propagation.csv"
PROJECTILE_CSV = ROOT / "examples" / "kalthoff-winkler" / "projectile.csv"
STRIP_CSV = ROOT / "examples" / "strip-steady-crack" / "results" / "strip.csv"
CLOSURE_CSV = ROOT / "examples" / "strip-steady-crack" / "results" / "closure.csv"
MADE_BY = "# made by: "


def _made_by(path):
    """The command on the CSV's 'made by' line."""
    for line in path.read_text().splitlines():
        if line.startswith(MADE_BY):
            return line[len(MADE_BY):]
    return None


def propagation_table(data):
    return mode1_propagation.table_markdown(mode1_propagation.read_rows(PROPAGATION_CSV),
                                            csvfile.provenance(PROPAGATION_CSV))


def kink_table(data):
    return kink.table(kink.read_rows(kink.RESULTS))


def branching_table(data):
    return branching.readme_table()


def branching_cost(data):
    return branching.readme_cost()


def kink_kw_table(data):
    return kink_kalthoff_winkler.table(json.loads(kink_kalthoff_winkler.SUMMARY.read_text()))


def projectile_table(data):
    return projectile.markdown(projectile.read_csv(PROJECTILE_CSV))


def grid_pull_table(data):
    comments, rows = grid.read_rows(grid.CSV)
    return grid.markdown(rows, comments)


def strip_table(data):
    return strip.table_markdown(strip.read_rows(STRIP_CSV),
                                [ln.split(": ", 1)[1] for ln in csvfile.provenance(STRIP_CSV)])


def strip_closure_table(data):
    return strip_closure.table_markdown(strip_closure.read_rows(CLOSURE_CSV), _made_by(CLOSURE_CSV))


def strip_work_precision(data):
    return strip.work_precision_markdown(strip.read_rows(STRIP_CSV))


def kw_deck_table(data):
    return deck.table(deck.read_rows()[1],
                      [ln.split(": ", 1)[1] for ln in csvfile.provenance(deck.CSV)])


def kw3d_table(data):
    return kw3d.table(kw3d.read_rows(), _made_by(kw3d.CSV))


def kink_convergence_table(data):
    return kink_convergence.table(kink_convergence.read_rows(),
                                  [ln.split(": ", 1)[1] for ln in csvfile.provenance(kink_convergence.CSV)])




def kink_sequences(data):
    return kink_convergence.sequences_table(kink_convergence.read_rows())


def kink_disk(data):
    return kink_convergence.disk_table(kink_convergence.read_rows())


def kink_sweeps(data):
    return kink_convergence.sweeps_table(kink_convergence.read_rows())


def kink_limits(data):
    return kink_convergence.limits_table(kink_convergence.read_rows())


def kink_kernels(data):
    return kink_convergence.kernels_table(kink_convergence.read_rows())


def kink_coverage(data):
    return kink_convergence.coverage_table(kink_convergence.read_rows())


def strip_law(data):
    return strip.law_table(strip.read_rows(STRIP_CSV))

# SPDX-License-Identifier: GPL-2.0-or-later
"""Tables of the crack-growth examples (examples/mode1-propagation, examples/kink-mixed-mode,
examples/strip-steady-crack, examples/crack-branching, the study, projectile, grid-pull, deck and
3D parts of examples/kalthoff-winkler): per README, block name -> render(data), each rendered by
its benchmark module from the results it committed."""
import json

from bbpd.benchmarks import kalthoff_winkler_3d as kw3d
from bbpd.benchmarks import kalthoff_winkler_deck as deck
from bbpd.benchmarks import kalthoff_winkler_grid as grid
from bbpd.benchmarks import kalthoff_winkler_projectile as projectile
from bbpd.benchmarks import kalthoff_winkler_study as study
from bbpd.benchmarks import kink_convergence as kc
from bbpd.benchmarks import (branching, kink, kink_kalthoff_winkler, mode1_propagation, strip,
                             strip_closure)
from bbpd import csvfile
from bbpd.jobs import ROOT
from bbpd.markdown import table as md_table

from .paper import made

PROPAGATION_CSV = ROOT / "examples" / "mode1-propagation" / "results" / "mode1_propagation.csv"
PROJECTILE_CSV = ROOT / "examples" / "kalthoff-winkler" / "projectile.csv"
STRIP_CSV = ROOT / "examples" / "strip-steady-crack" / "results" / "strip.csv"
CLOSURE_CSV = ROOT / "examples" / "strip-steady-crack" / "results" / "closure.csv"


PROPAGATION = {
    "mode1-propagation": made(PROPAGATION_CSV, lambda data: mode1_propagation.table_markdown(
        mode1_propagation.read_rows(PROPAGATION_CSV)))}
KINK = {
    "kink": lambda data: kink.table(kink.read_rows(kink.RESULTS)),
    "kink-verdict": lambda data: kink.verdict_table(kink.read_rows(kink.RESULTS)),
    "kink-kw": lambda data: kink_kalthoff_winkler.table(
        json.loads(kink_kalthoff_winkler.SUMMARY.read_text())),
    "kink-convergence": made(kc.CSV, lambda data: kc.table(kc.read_rows())),
    "kink-sequences": lambda data: kc.sequences_table(kc.read_rows()),
    "kink-disk": lambda data: kc.disk_table(kc.read_rows()),
    "kink-sweeps": lambda data: kc.sweeps_table(kc.read_rows()),
    "kink-limits": lambda data: kc.limits_table(kc.read_rows()),
    "kink-kernels": lambda data: kc.kernels_table(kc.read_rows()),
    "kink-coverage": lambda data: kc.coverage_table(kc.read_rows())}
STRIP = {
    "strip-runs": made(STRIP_CSV, lambda data: strip.table_markdown(strip.read_rows(STRIP_CSV))),
    "strip-work-precision": lambda data: strip.work_precision_markdown(strip.read_rows(STRIP_CSV)),
    "strip-closure": made(CLOSURE_CSV, lambda data: strip_closure.table_markdown(
        strip_closure.read_rows(CLOSURE_CSV))),
    "strip-law": lambda data: strip.law_table(strip.read_rows(STRIP_CSV))}
BRANCHING = {
    "branching": made(branching.RESULTS, lambda data: branching.table(branching.read_rows()),
                      timing=True),
    "branching-cost": lambda data: branching.cost_table(branching.read_rows())}
KW = {
    "kw-projectile": lambda data: projectile.markdown(csvfile.read_csv(PROJECTILE_CSV)[1]),
    "kw-study": made(study.CSV, lambda data: md_table(study.TABLE_HEADER, study.read_csv()[0])),
    "kw-grid-pull": lambda data: grid.markdown(*reversed(csvfile.read_csv(grid.CSV))),
    "kw-deck": made(deck.CSV, lambda data: deck.table(deck.read_rows()[1])),
    "kw-3d": made(kw3d.CSV, lambda data: kw3d.table(kw3d.read_rows()))}

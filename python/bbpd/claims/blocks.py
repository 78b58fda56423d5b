# SPDX-License-Identifier: GPL-2.0-or-later
"""Which generated table lives in which file, and the function that renders it from the data.
Sentences around the tables are written by hand."""
from bbpd.benchmarks import kalthoff_winkler as kw
from bbpd.benchmarks import mode1, mode2

from . import crack, paper, perf
from .paper import with_run_note

README = "README.md"
VERIFICATION = "doc/verification.md"
MODE1 = "examples/mode1-semi-infinite/README.md"
MODE2 = "examples/mode2-central-crack/README.md"
KW = "examples/kalthoff-winkler/README.md"
PROPAGATION = "examples/mode1-propagation/README.md"
KINK = "examples/kink-mixed-mode/README.md"
STRIP = "examples/strip-steady-crack/README.md"
BRANCHING = "examples/crack-branching/README.md"
PERFORMANCE = "doc/performance.md"

# file -> {block name: render(data) -> text}
BLOCKS = {
    README: {"zen5-readme": lambda data: perf.scene_table(perf.ZEN5_AUTO_FILES)},
    VERIFICATION: {"benchmarks": paper.benchmarks, "quickstart-times": paper.quickstart_times},
    MODE1: {"mode1-table2": with_run_note(mode1.table2, paper.MODE1),
            "mode1-table3": with_run_note(mode1.table3, paper.MODE1),
            "mode1-jtable": with_run_note(mode1.jtable, paper.MODE1),
            "mode1-tips": paper.tips_table, "mode1-lps": paper.lps_table},
    MODE2: {"mode2-table": with_run_note(mode2.table, paper.MODE2),
            "mode2-jtable": with_run_note(mode2.jtable, paper.MODE2)},
    KW: {"kw-table": with_run_note(kw.table, paper.KW), **crack.KW},
    PROPAGATION: crack.PROPAGATION,
    KINK: crack.KINK,
    STRIP: crack.STRIP,
    BRANCHING: crack.BRANCHING,
    PERFORMANCE: {"zen3-avx2": lambda data: perf.scene_table(perf.ZEN3_FILES),
                  "lps-cylinder": perf.lps_cylinder,
                  "zen5-simd": lambda data: perf.simd_table("zen5"),
                  "zen5-floor": lambda data: perf.floor_table("zen5"),
                  "spr-simd": lambda data: perf.simd_table("spr"),
                  "spr-floor": lambda data: perf.floor_table("spr"), "vs-bpm": perf.vs_bpm,
                  "vs-bpm-cylinder": perf.vs_bpm_cylinder, "vs-bpm-forced": perf.forced_table},
}

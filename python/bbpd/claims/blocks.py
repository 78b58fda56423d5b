# SPDX-License-Identifier: GPL-2.0-or-later
"""Which generated table lives in which file, and the function that renders it from the data.
Sentences around the tables are written by hand."""
from . import crack, kw, mode1, mode2, perf, readme

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
    README: {"zen5-readme": perf.zen5_readme},
    VERIFICATION: {"benchmarks": readme.benchmarks, "quickstart-times": readme.quickstart_times},
    MODE1: {"mode1-table2": mode1.table2, "mode1-table3": mode1.table3,
            "mode1-jtable": mode1.jtable, "mode1-tips": mode1.tips_table,
            "mode1-lps": mode1.lps_table},
    MODE2: {"mode2-table": mode2.table, "mode2-jtable": mode2.jtable},
    KW: {"kw-table": kw.table, **crack.KW},
    PROPAGATION: crack.PROPAGATION,
    KINK: crack.KINK,
    STRIP: crack.STRIP,
    BRANCHING: crack.BRANCHING,
    PERFORMANCE: {"zen3-avx2": perf.zen3_avx2, "lps-cylinder": perf.lps_cylinder,
                  "zen5-simd": perf.zen5_simd, "zen5-floor": perf.zen5_floor,
                  "spr-simd": perf.spr_simd, "spr-floor": perf.spr_floor,
                  "vs-bpm": perf.vs_bpm},
}

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
    KW: {"kw-table": kw.table, "kw-projectile": crack.projectile_table,
         "kw-grid-pull": crack.grid_pull_table, "kw-deck": crack.kw_deck_table,
         "kw-3d": crack.kw3d_table},
    PROPAGATION: {"mode1-propagation": crack.propagation_table},
    KINK: {"kink": crack.kink_table, "kink-kw": crack.kink_kw_table,
           "kink-convergence": crack.kink_convergence_table,
           "kink-sequences": crack.kink_sequences, "kink-disk": crack.kink_disk,
           "kink-sweeps": crack.kink_sweeps, "kink-limits": crack.kink_limits,
           "kink-kernels": crack.kink_kernels, "kink-coverage": crack.kink_coverage},
    STRIP: {"strip-runs": crack.strip_table, "strip-work-precision": crack.strip_work_precision,
            "strip-closure": crack.strip_closure_table, "strip-law": crack.strip_law},
    BRANCHING: {"branching": crack.branching_table, "branching-cost": crack.branching_cost},
    PERFORMANCE: {"zen3-avx2": perf.zen3_avx2, "lps-cylinder": perf.lps_cylinder,
                  "zen5-simd": perf.zen5_simd,
                  "zen5-floor": perf.zen5_floor, "spr-simd": perf.spr_simd,
                  "spr-floor": perf.spr_floor},
}

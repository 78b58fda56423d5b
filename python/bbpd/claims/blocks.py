# SPDX-License-Identifier: GPL-2.0-or-later
"""Which generated block lives in which file, and the function that renders it from the data."""
from . import crack, kw, mode1, mode2, perf, readme

README = "README.md"
VERIFICATION = "doc/verification.md"
MODE1 = "examples/mode1-semi-infinite/README.md"
MODE2 = "examples/mode2-central-crack/README.md"
KW = "examples/kalthoff-winkler/README.md"
JDOC = "doc/compute_bbpd_jintegral.rst"
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
            "mode1-findings": mode1.findings, "mode1-jtable": mode1.jtable,
            "mode1-jfindings": mode1.jfindings, "mode1-tips": mode1.tips_table,
            "mode1-tips-text": mode1.tips_text,
            "mode1-wrong-micromodulus": mode1.wrong_micromodulus,
            "mode1-lps": mode1.lps_table, "mode1-lps-findings": mode1.lps_findings},
    MODE2: {"mode2-table": mode2.table, "mode2-findings": mode2.findings,
            "mode2-symmetry": mode2.symmetry, "mode2-jtable": mode2.jtable,
            "mode2-conclusion": mode2.conclusion, "mode2-paper-verdict": mode2.paper_verdict},
    KW: {"kw-table": kw.table, "kw-initiation": kw.initiation, "kw-angle": kw.angle,
         "kw-speed": kw.speed, "kw-far-edge": kw.far_edge, "kw-other-far": kw.other_far,
         "kw-projectile": crack.projectile_table, "kw-grid-pull": crack.grid_pull_table,
         "kw-summary": crack.kw_summary, "kw-deck": crack.kw_deck_table,
         "kw-deck-summary": crack.kw_deck_summary, "kw-3d": crack.kw3d_table,
         "kw-3d-summary": crack.kw3d_summary},
    JDOC: {"jintegral-benchmarks": mode2.jintegral_doc},
    PROPAGATION: {"mode1-propagation": crack.propagation_table,
                  "mode1-propagation-findings": crack.propagation_findings},
    KINK: {"kink": crack.kink_table, "kink-kw": crack.kink_kw_table,
           "kink-kw-reading": crack.kink_kw_reading,
           "kink-k0-check": crack.kink_k0_check,
           "kink-convergence": crack.kink_convergence_table,
           "kink-convergence-verdict": crack.kink_convergence_verdict,
           "kink-convergence-sweep": crack.kink_convergence_sweep,
           "kink-convergence-trend": crack.kink_convergence_trend,
           "kink-convergence-subset": crack.kink_convergence_subset,
           "kink-convergence-kernels": crack.kink_convergence_kernels,
           "kink-convergence-coverage": crack.kink_convergence_coverage},
    STRIP: {"strip-runs": crack.strip_table, "strip-summary": crack.strip_summary,
            "strip-work-precision": crack.strip_work_precision,
            "strip-closure": crack.strip_closure_table,
            "strip-closure-verdict": crack.strip_closure_verdict},
    BRANCHING: {"branching": crack.branching_table,
                "branching-findings": crack.branching_findings,
                "branching-cost": crack.branching_cost},
    PERFORMANCE: {"zen3-avx2": perf.zen3_avx2, "lps-cylinder": perf.lps_cylinder, "row-driver": perf.row_driver,
                  "zen5-simd": perf.zen5_simd, "zen5-floor": perf.zen5_floor,
                  "spr-simd": perf.spr_simd, "spr-floor": perf.spr_floor},
}

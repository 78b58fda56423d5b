# SPDX-License-Identifier: GPL-2.0-or-later
"""The LPS Mode-I table (bbpd.benchmarks.mode1_lps) follows its rows."""
from bbpd.benchmarks import mode1_lps


def lps(kernel, dx, l2, jl2):
    return {"kernel": kernel, "dx_m": dx, "nu": 0.3, "model": "plane/strain", "peak_pct": 1.0,
            "l2_pct": l2, "j_peak_pct": 0.5, "j_l2_pct": jl2, "kii_over_ki": 0.0, "dt_s": 5e-6,
            "atoms": 100, "loop_s": 2.0}


BOND = [{"kernel": "gaussian", "dx_m": 0.05, "consistent_peak": 1.7, "consistent_l2": 2.33,
         "j_peak": 0.3, "j_l2": 0.27, "run_time_s": 23.4}]


def test_table_has_a_dash_where_no_bond_based_run_exists():
    table = mode1_lps.table([lps("constant", 0.025, 15.0, 0.7)], BOND)
    assert "| constant | 0.025 | 1.00 / 15.00 | 0.50 / 0.70 | - | - | 2.0 |" in table


def test_the_committed_runs_give_the_readme_lines():
    """examples/mode1-semi-infinite/README.md, 'Poisson's ratio free', by hand: the LPS DSIF L2
    per kernel and grid and the J-integral L2 at the finest grid"""
    rows = mode1_lps.read_rows()
    l2 = {k: [round(r["l2_pct"], 2) for r in sorted((r for r in rows if r["kernel"] == k), key=lambda r: -r["dx_m"])]
          for k in ("constant", "triangular", "gaussian")}
    assert l2 == {"constant": [21.10, 20.54, 14.99], "triangular": [11.09, 9.69, 9.00],
                  "gaussian": [6.98, 5.69, 4.59]}
    fine = {r["kernel"]: round(r["j_l2_pct"], 2) for r in rows if r["dx_m"] == 0.025}
    assert fine == {"constant": 0.68, "triangular": 0.32, "gaussian": 0.29}

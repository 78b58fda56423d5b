# SPDX-License-Identifier: GPL-2.0-or-later
"""The Mode-I propagation results CSV: rows added to it keep the earlier rows, their
provenance and their CPU, and the README's findings follow from the rows (synthetic
here, so the test needs no run)."""
import numpy as np

from bbpd import csvfile
from bbpd.benchmarks import mode1_propagation as mp
from bbpd.claims.paper import made


def row(kernel, dx, ext, cpu="CPU A", **kw):
    r = {c: 1.0 for c in mp.CSV_COLUMNS}
    r.update(kernel=kernel, dx=dx, ext_pd_3tc=ext, ext_toughness_3tc=0.77,
             ext_energy_3tc=0.98, Gc=mp.G_C, cpu=cpu, width_3tc_over_delta=1.0,
             ti_pd=0.5e-3, ti_theory=0.6e-3, ti_tip_pd=0.7e-3,
             t_tip=np.array([0.0, 1e-3]), l_pd=np.array([5.0, 5.0 + ext]))
    r.update(kw)
    return r


def test_append_keeps_rows_provenance_and_cpu(tmp_path):
    path = tmp_path / "results" / "m.csv"
    first = [row("gaussian", 0.1, 0.96), row("constant", 0.1, 1.01)]
    mp.write_csv(path, first, ["made by: first"])
    mp.write_histories(path.with_name("tip_histories.csv"), first)
    earlier = mp.read_rows(path, path.with_name("tip_histories.csv"))
    merged = mp.merge_rows(earlier, [row("gaussian", 0.05, 0.89, cpu="CPU B"),
                                     row("constant", 0.1, 1.00, cpu="CPU B")])
    mp.write_csv(path, merged, csvfile.provenance(path) + ["rows added by: second"])
    rows = mp.read_rows(path)
    assert [(r["kernel"], r["dx"]) for r in rows] == [("constant", 0.1), ("gaussian", 0.1),
                                                      ("gaussian", 0.05)]
    assert [r["cpu"] for r in rows] == ["CPU B", "CPU A", "CPU B"]
    assert rows[0]["ext_pd_3tc"] == 1.0          # the new run replaced the old one
    assert csvfile.provenance(path) == ["made by: first", "rows added by: second"]
    table = made(path, lambda data: mp.table_markdown(rows))(None)    # the README's block
    assert "Made by `first`. Rows added by `second`." in table
    assert "| CPU B | every other run |\n| CPU A | gaussian at dx = 0.1 m |" in table


def test_growth_verdict_settles_only_a_small_last_change():
    gap = 0.98 - 0.77
    small = mp.SETTLED_SHARE_OF_GAP * gap / 2
    rows = [row("gaussian", 0.05, 0.90), row("gaussian", 0.025, 0.78),
            row("gaussian", 0.0125, 0.78 - small),
            row("constant", 0.05, 0.93), row("constant", 0.025, 0.83),
            row("constant", 0.0125, 0.77)]
    v = mp.growth_verdict(rows)
    assert v["gaussian"]["settled"] and v["gaussian"]["nearest"] == "toughness"
    assert not v["constant"]["settled"] and abs(v["constant"]["last"] - 0.06) < 1e-9
    # negative control: the same last step for both kernels settles neither or both
    rows[5]["ext_pd_3tc"] = 0.83 - small
    assert mp.growth_verdict(rows)["constant"]["settled"]


def test_a_grid_run_by_one_kernel_is_that_kernels_finest():
    rows = [row("gaussian", 0.025, 0.78), row("gaussian", 0.0125, 0.77), row("gaussian", 0.00625, 0.74),
            row("constant", 0.025, 0.83), row("constant", 0.0125, 0.77)]
    assert [(r["kernel"], r["dx"]) for r in mp.finest_rows(rows)] == [("constant", 0.0125),
                                                                      ("gaussian", 0.00625)]
    v = mp.growth_verdict(rows)
    # the Gaussian's last change is its own halving to 0.00625 m, the constant's to 0.0125 m
    assert abs(v["gaussian"]["last"] - 0.03) < 1e-9 and abs(v["constant"]["last"] - 0.06) < 1e-9


def test_the_committed_runs_give_the_readme_findings():
    """examples/mode1-propagation/README.md, by hand: LEFM's t_i lies between the first broken
    bond and the tip's first grid step on every run; the last halving moves the extension at
    3 t_c by 0.017 m (constant), 0.013 m (triangular): settled, at the K_Ic form's value; by
    0.031 m for the Gaussian: not settled (gap 0.20 m); the band does not shrink with the horizon"""
    rows = mp.read_rows(mp.ROOT / "examples" / "mode1-propagation" / "results" / "mode1_propagation.csv")
    assert all(r["ti_pd"] <= r["ti_theory"] <= r["ti_tip_pd"] for r in rows)
    v = mp.growth_verdict(rows)
    assert {k: round(x["last"], 3) for k, x in v.items()} == {"constant": 0.017, "gaussian": 0.031,
                                                             "triangular": 0.013}
    assert {k: x["settled"] for k, x in v.items()} == {"constant": True, "gaussian": False, "triangular": True}
    assert v["constant"]["nearest"] == v["triangular"]["nearest"] == "toughness"
    assert round(v["gaussian"]["gap"], 2) == 0.20
    assert mp.band_kept(rows)
    for k, lo, hi in (("constant", -14.5, -14.0), ("triangular", -8.6, -6.4), ("gaussian", -4.7, -2.6)):
        assert all(lo <= r["ti_err_pct"] <= hi for r in rows if r["kernel"] == k)
    late = [max(r["ti_tip_err_pct"] for r in rows if r["dx"] == dx) for dx in sorted({r["dx"] for r in rows}, reverse=True)]
    assert min(late) > 0.0 and late == sorted(late, reverse=True)


def test_loop_times_name_the_cpu_of_each_run():
    from bbpd.benchmarks import mode1_propagation as mp
    rows = [{"kernel": k, "dx": dx, "cpu": "CPU A"} for dx in (0.1, 0.05) for k in ("constant", "gaussian")]
    assert "| CPU A | all |" in mp.cpu_markdown(rows)
    # one grid timed on two machines: each of the other machine's runs is named by kernel
    rows += [{"kernel": "gaussian", "dx": 0.00625, "cpu": "CPU B"},
             {"kernel": "triangular", "dx": 0.00625, "cpu": "CPU C"}]
    text = mp.cpu_markdown(rows)
    assert "| CPU A | every other run |" in text and "| CPU B | gaussian at dx = 0.00625 m |" in text
    assert "| CPU C | triangular at dx = 0.00625 m |" in text

"""The kink convergence runs (bbpd.benchmarks.kink_convergence) and their verdicts
(bbpd.benchmarks.kink_limit: sequences, sweep_stats, limits, limit, kernel_spread, coverage) follow their rows: each verdict is data
(the numbers, the criterion, settled or not), checked here against rows made for the purpose."""
import pytest


from bbpd.benchmarks import kink_convergence as kc
from bbpd.benchmarks import kink_limit as kl
from bbpd.markdown import cell


def row(m, rd, a2, a4, kernel="gaussian"):
    return {"kernel": kernel, "m": float(m), "R_over_delta": float(rd), "angle_2d": a2, "angle_4d": a4,
            "hoop_stress": -70.53, "hoop_strain": -63.61, "energy": -75.23}


def seq(rows, dist="2d", rd=10.0, kernel="gaussian", psi=90.0, alpha=0.0):
    found = [s for s in kl.sequences(rows) if (s["dist"], s["rd"], s["kernel"], s["psi"], s["alpha"])
             == (dist, rd, kernel, psi, alpha)]
    assert len(found) == 1
    return found[0]


def test_settled_sequence_names_its_criterion():
    rows = [row(5, 10, -90.0, -87.0), row(10, 10, -62.0, -63.8), row(15, 10, -63.0, -64.0),
            row(20, 10, -63.4, -64.2), row(10, 20, -62.5, -64.0)]
    s = seq(rows)
    # m = 20 at 2 horizons: atan(1 / 80) = 0.7 deg, and -63.4 lies 0.2 deg from hoop strain
    assert s["nearest"] == "hoop_strain" and s["offset"] == pytest.approx(0.21)
    assert s["bar"] == pytest.approx(0.716, abs=1e-3) and s["within_bar"]
    assert s["step"] == pytest.approx(-0.4) and s["settled"]
    moves = [d for d in kl.disk_moves(rows) if d["dist"] == "2d"]
    assert [(d["m"], round(d["move"], 6)) for d in moves] == [(10.0, -0.5)]


def test_moving_sequence_is_not_settled():
    rows = [row(10, 10, -62.0, -63.0), row(15, 10, -66.0, -67.0), row(20, 10, -69.5, -70.0)]
    s = seq(rows)
    assert s["nearest"] == "hoop_stress"
    assert not s["settled"] and s["beyond_bars"]
    s4 = seq(rows, "4d")
    assert not s4["settled"] and s4["beyond_bars"] and [round(b, 1) for b in s4["bars"]] == [0.5, 0.4]


def test_error_bars_are_the_grids_resolution_and_say_what_a_step_can_tell():
    # half a spacing across the path, n horizons = n m spacings out
    assert abs(kl.resolution_deg(10, "2d") - 1.432) < 1e-3
    assert abs(kl.resolution_deg(10, "4d") - 0.716) < 1e-3
    assert kl.resolution_deg(15, "4d") < kl.resolution_deg(15, "2d") < kl.resolution_deg(10, "2d")
    # a step of 1.5 deg between m = 10 and 15 at 2 horizons (bars 1.4 and 1.0) cannot be told apart
    rows = [row(10, 20, -62.0, -64.7), row(15, 20, -63.5, -64.8)]
    s = seq(rows, rd=20.0)
    assert s["step"] == pytest.approx(-1.5) and not s["settled"] and not s["beyond_bars"]
    assert [round(b, 1) for b in s["bars"]] == [1.4, 1.0]
    # 1.2 deg beyond hoop strain at 4 horizons, m = 15 (bar 0.5): outside
    s4 = seq(rows, "4d", rd=20.0)
    assert s4["offset"] == pytest.approx(-1.19) and not s4["within_bar"]
    full = [dict(r, dx_mm=5.0 / r["m"], atoms=1, steps=1, K_init_over_Kc=0.5, psi=90.0, alpha=0.0,
                 extension_over_delta=5.0, loop_s=1.0, nprocs=2) for r in rows]
    table = kc.table(full)
    assert "| -63.5 ± 1.0 | -64.8 ± 0.5 |" in table and kc.RESOLUTION_NOTE in table


def test_one_run_says_nothing():
    assert kl.sequences([row(5, 10, -90.0, -87.0)]) == []


def test_each_kernel_has_its_own_sequence_and_the_gaussians_comes_first():
    rows = [row(10, 10, -55.0, -56.0, "constant"), row(15, 10, -55.2, -56.1, "constant"),
            row(10, 10, -62.0, -63.8), row(15, 10, -63.0, -64.0)]
    assert [s["kernel"] for s in kl.sequences(rows)] == ["gaussian"] * 2 + ["constant"] * 2
    # the constant kernel's rows are not mixed into the Gaussian's sequence
    assert seq(rows)["angles"] == [-62.0, -63.0]
    assert seq(rows, kernel="constant")["angles"] == [-55.0, -55.2]


def test_time_step_rule_is_the_kink_tests():
    for m, factor in kc.kinkbench.DTFACTOR.items():
        assert float(kc.case_vars(m, 10)["dtfactor"]) == factor


def test_each_mix_is_a_sequence_of_its_own():
    rows = [row(10, 10, -62.0, -63.8), row(15, 10, -63.0, -64.0),
            dict(row(10, 20, -30.0, -31.0), psi=45.0, alpha=22.5),
            dict(row(15, 20, -30.5, -31.2), psi=45.0, alpha=22.5)]
    # the pure Mode II sequence keeps only its own rows, and comes first
    assert seq(rows)["angles"] == [-62.0, -63.0]
    mixed = seq(rows, rd=20.0, psi=45.0, alpha=22.5)
    assert mixed["angles"] == [-30.0, -30.5] and mixed["settled"]
    assert [(s["psi"], s["alpha"]) for s in kl.sequences(rows)][0] == (90.0, 0.0)
    full = [dict(r, dx_mm=5.0 / r["m"], atoms=1, steps=1, K_init_over_Kc=0.5,
                 extension_over_delta=5.0, loop_s=1.0, nprocs=2) for r in rows]
    assert "| gaussian | 45 | 22.5 | 10 | 20 |" in kc.table(full)
    assert kc.case_folder(10, 20, psi=45.0, alpha=22.5) == "m10-R20-psi45-alpha22.5"
    assert kc.case_folder(10, 20) == "m10-R20"    # the pure Mode II runs keep their folders


def test_a_larger_disk_with_two_values_of_m_has_its_own_sequence():
    rows = [row(5, 20, -66.0, -71.7), row(10, 20, -62.1, -64.7)]
    s = seq(rows, rd=20.0)
    assert s["ms"] == [5.0, 10.0] and s["angles"] == [-66.0, -62.1]
    assert s["step"] == pytest.approx(3.9) and not s["settled"]


def test_each_run_names_the_cpu_that_timed_it():
    rows = [dict(row(m, 10, -62.0, -63.8), cpu="Intel(R) Xeon(R) Processor, AVX-512") for m in (10, 15)]
    rows.append(dict(row(10, 20, -30.0, -31.0), psi=45.0, alpha=0.0, cpu="AMD EPYC (family 25 model 1), AVX2"))
    text = kc.loop_times(rows)
    assert "| Intel(R) Xeon(R) Processor, AVX-512 | every other run |" in text
    assert "| AMD EPYC (family 25 model 1), AVX2 | gaussian psi = 45, alpha = 0, m = 10, R/delta = 20 |" in text
    assert "| Intel(R) Xeon(R) Processor, AVX-512 | all |" in kc.loop_times(rows[:2])


def test_a_straight_crack_reads_zero_not_minus_zero():
    assert cell(-1e-15, ".1f") == "0.0" and cell(-0.04, ".1f") == "0.0" and cell(-0.06, ".1f") == "-0.1"
    assert cell(None, ".1f") == "-" and cell(-1e-15, "+.2f") == "0.00" and cell(-2.0, "g") == "-2"


def test_the_figure_draws_every_mix_with_its_error_bars(tmp_path):
    rows = [dict(row(10, 20, -62.1, -64.7), psi=90.0, alpha=0.0),
            dict(row(15, 20, -61.1, -64.8), psi=90.0, alpha=0.0),
            dict(row(10, 20, -47.1, -50.3), psi=45.0, alpha=22.5, hoop_stress=-53.1,
                 hoop_strain=-49.7, energy=-57.3),
            dict(row(5, 20, -56.7, None), psi=45.0, alpha=22.5, hoop_stress=-53.1,
                 hoop_strain=-49.7, energy=-57.3),
            dict(row(10, 20, 0.0, 0.0), psi=0.0, alpha=0.0)]   # pure Mode I: no panel
    out = tmp_path / "k.png"
    kc.figure(rows, out)
    assert out.stat().st_size > 10_000


def test_pure_mode_one_names_no_nearest_criterion():
    rows = [dict(row(5, 20, 0.0, 0.0), psi=0.0, alpha=0.0, hoop_stress=0.0, hoop_strain=0.0, energy=0.0),
            dict(row(10, 20, -1e-16, 0.0), psi=0.0, alpha=0.0, hoop_stress=0.0, hoop_strain=0.0, energy=0.0)]
    s = seq(rows, rd=20.0, psi=0.0)
    assert s["nearest"] is None and s["offset"] == pytest.approx(0.0) and s["within_bar"]


def test_the_whole_sweep_has_its_own_verdict_only_when_complete():
    crit = {90.0: (-70.53, -63.61, -75.23), 67.5: (-62.9, -57.6, -67.7), 45.0: (-53.13, -49.67, -57.33),
            22.5: (-36.1, -34.9, -39.0)}
    def mixed(psi, alpha, a2, a4, m=10):
        hs, hn, en = crit[psi]
        return dict(row(m, 20, a2, a4), psi=psi, alpha=alpha, hoop_stress=hs, hoop_strain=hn, energy=en)
    # every angle 0.5 deg beyond hoop strain along the rows and 1.5 deg at 22.5 deg
    rows = [mixed(p, a, crit[p][1] - 0.5 - a / 22.5, crit[p][1] - 0.5 - a / 22.5)
            for p in crit for a in (0.0, 22.5)]
    stats = kl.sweep_stats(rows)
    assert [(s["kernel"], s["m"], s["rd"], s["dist"], s["n"]) for s in stats] == \
        [("gaussian", 10.0, 20.0, "2d", 8), ("gaussian", 10.0, 20.0, "4d", 8)]
    s = stats[0]
    assert s["best"] == "hoop_strain"
    # four -0.5 and four -1.5: standard deviation 0.53 / sqrt(8)
    assert s["bias"]["hoop_strain"] == pytest.approx(-1.0) and s["se"]["hoop_strain"] == pytest.approx(0.189, abs=1e-3)
    assert s["pull_mean"] == pytest.approx(1.0) and s["pull_max"] == pytest.approx(1.0)
    # one run missing: no verdict for that group
    assert kl.sweep_stats(rows[1:]) == []
    # a pure Mode I run beside the sweep is left out of it
    assert kl.sweep_stats(rows + [dict(row(10, 20, 0.0, 0.0), psi=0.0, alpha=0.0)]) == stats


CRIT = {90.0: (-70.53, -63.61, -75.23), 67.5: (-62.9, -57.6, -67.7), 45.0: (-53.13, -49.67, -57.33),
        22.5: (-36.1, -34.9, -39.0)}


def sweep(m, offset, spread=0.5, criterion=1):
    """a whole mixed-mode sweep at m: every angle `offset` from the criterion CRIT[psi][criterion],
    +- spread alternately over the eight runs (so the mean is `offset`)"""
    out = []
    for k, (psi, alpha) in enumerate((p, a) for p in CRIT for a in (0.0, 22.5)):
        hs, hn, en = CRIT[psi]
        angle = CRIT[psi][criterion] + offset + (spread if k % 2 else -spread)
        out.append(dict(row(m, 20, angle, angle), psi=psi, alpha=alpha, hoop_stress=hs,
                        hoop_strain=hn, energy=en))
    return out


def settling(*ms_offsets):
    """whole sweeps at (m, offset) whose mixes scatter the other way at each next m, so that
    each mix's step differs and the mean step is within two of its standard errors"""
    return [r for k, (m, off) in enumerate(ms_offsets) for r in sweep(m, off, 0.5 * (-1) ** k)]


def test_the_trend_across_m_names_the_criterion_the_sweep_approaches():
    # 1.0 deg beyond hoop strain at m = 10, 0.3 deg at m = 15: nearest both times, RMS falling
    found = kl.limits(settling((10, -1.0), (15, -0.3)))
    assert [(t["kernel"], t["rd"], t["dist"], t["ms"]) for t in found] == \
        [("gaussian", 20.0, "2d", [10.0, 15.0]), ("gaussian", 20.0, "4d", [10.0, 15.0])]
    t = found[0]
    assert t["state"] == "approaches" and t["limit"] == "hoop_strain"
    assert [round(t["v"][m]["rms"]["hoop_strain"], 1) for m in t["ms"]] == [1.1, 0.6]
    assert round(t["step"][0], 1) == 0.7 and round(t["step"][1], 1) == 0.4 and not t["drifts"]
    # the finest m decides: a third, coarser sweep does not change the verdict
    assert [t["limit"] for t in kl.limits(settling((5, -4.0), (10, -1.0), (15, -0.3)))] == \
        ["hoop_strain", "hoop_strain"]


def test_a_sweep_that_still_drifts_is_not_settled():
    # every mix moves by the same +0.7 deg from m = 10 to 15: near hoop strain, its RMS falling
    # and admitted, but the whole sweep still moves, past any standard error
    rows = sweep(10, -1.0) + sweep(15, -0.3)
    t = kl.limits(rows)[0]
    assert t["state"] == "drifts" and t["limit"] is None and t["drifts"]
    assert t["step"][0] == pytest.approx(0.7) and t["step"][1] == pytest.approx(0.0, abs=1e-9)
    assert kl.limit(rows)["follows"] is None


def test_none_fits_names_the_criteria_the_kink_lies_between():
    # every run 2 deg beyond hoop strain, 2.5 deg short of a hoop stress that kinks more still:
    # the test admits neither, and the mean lies between the two
    rows = [dict(r, hoop_stress=r["angle_2d"] - 2.5, energy=r["angle_2d"] - 8.0)
            for r in sweep(10, -3.0, spread=0.1) + sweep(15, -2.0, spread=0.1)]
    t = kl.limits(rows)[0]
    assert t["state"] == "none fits" and t["between"] == ("hoop_strain", "hoop_stress")
    last = t["v"][15.0]
    assert last["bias"]["hoop_strain"] == pytest.approx(-2.0) and last["bias"]["hoop_stress"] == pytest.approx(2.5)
    assert [round(t["v"][m]["bias"]["hoop_strain"], 1) for m in t["ms"]] == [-3.0, -2.0]
    assert t["step"][0] == pytest.approx(1.0) and t["drifts"]
    assert kl.limit(rows)["at"]["4d"]["between"] == ("hoop_strain", "hoop_stress")
    # the same mean at both m: between the two, no drift
    still = [dict(r, hoop_stress=r["angle_2d"] - 2.5, energy=r["angle_2d"] - 8.0)
             for r in settling((10, -2.0), (15, -2.0))]
    assert all(t["between"] == ("hoop_strain", "hoop_stress") and not t["drifts"] for t in kl.limits(still))
    # kinking beyond every criterion: between none of them, nearest hoop stress by 1.0 deg
    beyond = [dict(r, hoop_stress=r["angle_2d"] + 1.0, energy=r["angle_2d"] + 5.0) for r in rows]
    t = kl.limits(beyond)[0]
    assert t["between"] is None and t["nearest_mean"] == "hoop_stress"
    assert t["v"][15.0]["bias"]["hoop_stress"] == pytest.approx(-1.0)


def test_the_trend_says_not_settled_and_why():
    # moving away from hoop strain: nearest both times, but the RMS grows
    grows = kl.limits(sweep(10, -0.3, spread=2.0) + sweep(15, -1.0, spread=2.0))[0]
    assert grows["state"] == "grows" and grows["v"][15.0]["best"] == "hoop_strain"
    # the nearest changes from hoop strain to hoop stress
    changes = kl.limits(sweep(10, -0.3) + sweep(15, 0.2, criterion=0))[0]
    assert changes["state"] == "changes" and changes["near_prev"] == ["hoop_strain"]
    assert changes["v"][15.0]["best"] == "hoop_stress"
    # every run 2.5 +- 0.1 deg beyond criteria that agree: a bias of 30 standard errors
    agree = [dict(r, hoop_stress=r["hoop_strain"], energy=r["hoop_strain"])
             for r in sweep(10, -3.0, spread=0.1) + sweep(15, -2.5, spread=0.1)]
    none = kl.limits(agree)[0]
    assert none["state"] == "none fits" and none["between"] is None and none["limit"] is None
    assert none["v"][15.0]["bias"][none["nearest_mean"]] == pytest.approx(-2.5)
    # nearest both times, its RMS falling, but excluded by the test at the finest m
    # (hoop strain 1.5 then 1.0 +- 0.2 deg away; hoop stress 3 deg either side, mean 0, so the
    # test admits it with the larger RMS)
    excluded = kl.limits([
        dict(r, hoop_stress=r["angle_2d"] + (3.0 if k % 4 < 2 else -3.0), energy=r["angle_2d"] + 10.0)
        for k, r in enumerate(sweep(10, -1.5, spread=0.2) + sweep(15, -1.0, spread=0.2))])[0]
    assert excluded["state"] == "excluded" and excluded["v"][15.0]["best"] == "hoop_strain"


def test_the_trend_needs_two_whole_sweeps():
    assert kl.limits(sweep(10, -1.0)) == []
    assert kl.limits(sweep(10, -1.0) + sweep(15, -0.3)[1:]) == []
    assert kl.limit(sweep(10, -1.0)) is None


def test_criteria_closer_than_the_grids_resolution_are_both_nearest():
    # at m = 15 hoop stress moved to within 0.4 deg of hoop strain in every run: their RMS values
    # lie closer than the grid's resolution (2 horizons: atan(1 / 60) = 0.95 deg), a tie
    rows = settling((10, -1.0), (15, -0.3))
    tied = [dict(r, hoop_stress=r["hoop_strain"] + (0.4 if k % 2 else -0.4)) if r["m"] == 15.0 else r
            for k, r in enumerate(rows)]
    t = kl.limits(tied)[0]
    assert t["state"] == "tied" and t["near"] == ["hoop_stress", "hoop_strain"] and t["limit"] is None
    # 2 horizons, m = 15: the RMS values lie closer than the resolution, 1.0 deg
    assert abs(t["v"][15.0]["rms"]["hoop_stress"] - t["v"][15.0]["rms"]["hoop_strain"]) <= kl.resolution_deg(15, "2d")


def test_kernel_comparison_holds_the_kernels_against_one_another_over_the_mixes_they_share():
    gauss = sweep(15, -0.3)                       # the whole sweep, near hoop strain
    near = [dict(r, kernel="constant", angle_2d=r["angle_2d"] - 0.5, angle_4d=r["angle_4d"] - 0.5)
            for r in sweep(15, -0.3) if r["alpha"] == 0.0 and r["psi"] in (90.0, 67.5)]
    found = kl.kernel_spread(gauss + near)
    # only the two mixes both kernels ran, the Gaussian first
    assert [(k["m"], k["rd"], k["dist"]) for k in found] == [(15.0, 20.0, "2d"), (15.0, 20.0, "4d")]
    k = found[0]
    assert k["kernels"] == ["gaussian", "constant"] and k["mixes"] == [(67.5, 0.0), (90.0, 0.0)]
    assert k["spread_mean"] == pytest.approx(0.5) and k["spread_max"] == pytest.approx(0.5)
    assert k["within_bars"] and round(k["bar"], 1) == 1.0
    assert all(x["common"] == ["hoop_strain"] for x in found)
    # a constant kernel at hoop stress instead: the nearest criterion differs, the spread is real
    far = [dict(r, kernel="constant", angle_2d=r["hoop_stress"], angle_4d=r["hoop_stress"]) for r in near]
    found = kl.kernel_spread(gauss + far)
    assert all(x["common"] == [] for x in found)
    assert not found[1]["within_bars"] and round(found[1]["bar"], 1) == 0.5


def test_kernel_comparison_needs_two_kernels_on_two_mixes():
    assert kl.kernel_spread(sweep(15, -0.3)) == []                 # one kernel
    lone = [dict(r, kernel="constant") for r in sweep(15, -0.3) if r["psi"] == 90.0 and r["alpha"] == 0.0]
    assert kl.kernel_spread(sweep(15, -0.3) + lone) == []          # pure Mode II alone
    other_m = [dict(r, kernel="constant", m=10.0) for r in sweep(15, -0.3)]
    assert kl.kernel_spread(sweep(15, -0.3) + other_m) == []       # not at one m


def test_an_exclusion_smaller_than_the_grid_resolves_is_said_to_be():
    # 0.5 deg beyond hoop strain with almost no scatter: the standard error excludes it, but
    # 0.5 deg is within one angle's bar at 2 horizons (m = 15: 1.0) and not at 4 (0.48)
    two, four = kl.sweep_stats(sweep(15, -0.5, spread=0.05))
    assert "hoop_stress" not in two["admitted"] and "hoop_strain" not in two["admitted"]
    assert two["unresolved"] == ["hoop_strain"] and four["unresolved"] == []
    # an exclusion by more than the bar, or a criterion the test admits, is not unresolved
    assert all(s["unresolved"] == [] for s in kl.sweep_stats(sweep(15, -2.0, spread=0.05)))
    assert all(s["unresolved"] == [] for s in kl.sweep_stats(sweep(15, -0.5, spread=2.0)))


def test_the_limit_names_a_criterion_only_where_every_distance_approaches_it():
    both = kl.limit(settling((10, -1.0), (15, -0.3)))
    assert (both["kernel"], both["rd"], both["ms"], both["follows"]) == ("gaussian", 20.0, [10.0, 15.0], "hoop_strain")
    assert [t["limit"] for t in both["at"].values()] == ["hoop_strain", "hoop_strain"]
    # tied at m = 15 (hoop stress within 0.4 deg of hoop strain in every run): no criterion named
    rows = settling((10, -1.0), (15, -0.3))
    tied = [dict(r, hoop_stress=r["hoop_strain"] + (0.4 if k % 2 else -0.4)) if r["m"] == 15.0 else r
            for k, r in enumerate(rows)]
    found = kl.limit(tied)
    assert found["at"]["2d"]["state"] == "tied" and found["follows"] is None
    # moving away from hoop strain: not settled either
    grows = kl.limit(sweep(10, -0.3, spread=2.0) + sweep(15, -1.0, spread=2.0))
    assert grows["follows"] is None and all(t["limit"] is None for t in grows["at"].values())
    # another kernel's sweeps say nothing about the Gaussian
    other = [dict(r, kernel="constant") for r in rows]
    assert kl.limit(other) is None
    assert kl.limit(other, "constant")["follows"] == "hoop_strain"


def test_the_coverage_lists_what_of_the_plan_is_left():
    rows = [dict(r, loop_s=100.0 + k, cpu="CPU A", nprocs=2.0) for k, r in enumerate(sweep(15, -0.3))]
    rows += [dict(r, kernel=k, loop_s=50.0, cpu="CPU B", nprocs=2.0) for k in ("constant", "triangular")
             for r in sweep(15, -0.3)]
    cov = kl.coverage(rows)
    g15 = cov["gaussian", 15]
    assert len(g15["done"]) == 8 and not g15["left"] and g15["machine"] == "CPU A, 2 ranks"
    assert (min(g15["loops"]), max(g15["loops"])) == (100.0, 107.0)
    assert not cov["gaussian", 10]["done"] and (90.0, 0.0) in cov["gaussian", 10]["left"]
    assert not cov["constant", 15]["left"] and not cov["triangular", 15]["left"]
    # the m = 20 sweep with one run missing, and a run on another machine: the majority's times
    part = [dict(r, loop_s=2000.0, cpu="CPU A", nprocs=2.0) for r in sweep(20, -0.3)[:7]]
    part[0] = dict(part[0], loop_s=9000.0, cpu="CPU C")
    g20 = kl.coverage(rows + part)["gaussian", 20]
    assert len(g20["done"]) == 7 and g20["left"] == {(22.5, 22.5)}
    assert g20["loops"] == [2000.0] * 6 and g20["machine"] == "CPU A, 2 ranks"
    whole = [dict(r, m=m, loop_s=1.0, cpu="CPU A", nprocs=2.0) for m in (10.0, 20.0) for r in sweep(15, -0.3)]
    assert not any(c["left"] for c in kl.coverage(rows + whole).values())


def test_the_report_section_carries_the_committed_limit():
    # the whole sweeps take days: REPORT.md states their limit from the committed CSV, run or not
    found = kl.limit(kc.read_rows())
    table = kc.section([], {}, None, [])["table"].splitlines()
    assert table[0] == "| kernel | R/delta | m | at | state | limit | follows |"
    cells = [[c.strip() for c in ln.split("|")[1:-1]] for ln in table[2:]]
    assert [c[:4] for c in cells] == [["gaussian", "20", "5, 10, 15, 20", d] for d in ("2d", "4d")]
    assert [c[4] for c in cells] == [found["at"][d]["state"] for d in ("2d", "4d")]
    assert [c[5] for c in cells] == [kc.NAMES["hoop_strain"], "-"]
    assert [c[6] for c in cells] == ["not settled"] * 2


def test_the_committed_sweeps_give_the_limit_the_readme_states():
    """examples/kink-mixed-mode/README.md and the top README state it by hand: Gaussian,
    R/delta = 20, m = 5 to 20: two horizons out it approaches max. hoop strain, four out none
    fits, between max. hoop strain and max. hoop stress; so not settled."""
    found = kl.limit(kc.read_rows())
    assert (found["rd"], found["ms"]) == (20.0, [5.0, 10.0, 15.0, 20.0])
    assert found["at"]["2d"]["limit"] == "hoop_strain"
    assert found["at"]["4d"]["state"] == "none fits"
    assert found["at"]["4d"]["between"] == ("hoop_strain", "hoop_stress")
    assert found["follows"] is None


def test_the_sequence_and_disk_tables_carry_the_verdict_fields():
    rows = [row(10, 10, -62.0, -63.8), row(15, 10, -63.0, -64.0), row(10, 20, -62.5, -64.0),
            row(15, 20, -64.0, -64.1)]
    table = kc.sequences_table(rows)
    assert "| gaussian | 90 | 0 | 2d | 10 | 10, 15 | -62.0, -63.0 | max. hoop strain: +0.6 ± 1.0 | -1.0 | yes | no |" in table
    assert "| gaussian | 90 | 0 | 2d | 15 | -1.0 |" in kc.disk_table(rows)


def test_the_committed_sweeps_give_the_readme_tables_and_reading():
    """examples/kink-mixed-mode/README.md, by hand: every finest m has run the whole sweep (every
    planned run is in); at m = 15 over the eight mixes all three
    kernels lie nearest hoop strain, their angles apart by more than the error bars"""
    rows = kc.read_rows()
    assert not any(c["left"] for c in kl.coverage(rows).values())
    k2, k4 = kl.kernel_spread(rows)
    assert len(k2["mixes"]) == 8 and k2["common"] == ["hoop_strain"] and k4["common"] == ["hoop_strain"]
    assert not k2["within_bars"] and not k4["within_bars"]
    assert "| gaussian | 20 | 2d | 5, 10, 15, 20 |" in kc.limits_table(rows)
    assert kc.sweeps_table(rows).count("\n") == 1 + len(kl.sweep_stats(rows))
    assert "| triangular | 15 | 8 of 8 | - |" in kc.coverage_table(rows)

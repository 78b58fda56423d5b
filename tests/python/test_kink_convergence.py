"""The kink convergence verdict (bbpd.benchmarks.kink_convergence.verdict) follows its rows."""
from bbpd.benchmarks import kink_convergence as kc


def row(m, rd, a2, a4, kernel="gaussian"):
    return {"kernel": kernel, "m": float(m), "R_over_delta": float(rd), "angle_2d": a2, "angle_4d": a4,
            "hoop_stress": -70.53, "hoop_strain": -63.61, "energy": -75.23}


def test_settled_sequence_names_its_criterion():
    rows = [row(5, 10, -90.0, -87.0), row(10, 10, -62.0, -63.8), row(15, 10, -63.0, -64.0),
            row(20, 10, -63.4, -64.2), row(10, 20, -62.5, -64.0)]
    text = kc.verdict(rows)
    # m = 20 at 2 horizons: atan(1 / 80) = 0.7 deg, and -63.4 lies 0.2 deg from hoop strain
    assert ("the finest (± 0.7°) lies nearest the max. hoop strain criterion (+0.2° from -63.6°: "
            "within its error bar)") in text
    assert "moves it by -0.4°: settled within 1°" in text
    assert "R/delta = 20 moves it by -0.5° at m = 10" in text


def test_moving_sequence_is_not_settled():
    rows = [row(10, 10, -62.0, -63.0), row(15, 10, -66.0, -67.0), row(20, 10, -69.5, -70.0)]
    text = kc.verdict(rows)
    assert "nearest the max. hoop stress criterion" in text
    assert "not settled (more than 1°, and more than the two error bars, ± 0.5 and ± 0.4°)" in text


def test_error_bars_are_the_grids_resolution_and_say_what_a_step_can_tell():
    # half a spacing across the path, n horizons = n m spacings out
    assert abs(kc.resolution_deg(10, "2d") - 1.432) < 1e-3
    assert abs(kc.resolution_deg(10, "4d") - 0.716) < 1e-3
    assert kc.resolution_deg(15, "4d") < kc.resolution_deg(15, "2d") < kc.resolution_deg(10, "2d")
    # a step of 1.5 deg between m = 10 and 15 at 2 horizons (bars 1.4 and 1.0) cannot be told apart
    rows = [row(10, 20, -62.0, -64.7), row(15, 20, -63.5, -64.8)]
    text = kc.verdict(rows)
    assert "moves it by -1.5°: not settled (more than 1°, within the two error bars, ± 1.4 and ± 1.0°)" in text
    # 1.2 deg beyond hoop strain at 4 horizons, m = 15 (bar 0.5): outside
    assert "(-1.2° from -63.6°: outside its error bar)" in text
    full = [dict(r, dx_mm=5.0 / r["m"], atoms=1, steps=1, K_init_over_Kc=0.5, psi=90.0, alpha=0.0,
                 extension_over_delta=5.0, loop_s=1.0, nprocs=2) for r in rows]
    table = kc.table(full)
    assert "| -63.5 ± 1.0 | -64.8 ± 0.5 |" in table and kc.RESOLUTION_NOTE in table


def test_one_run_says_nothing():
    assert kc.verdict([row(5, 10, -90.0, -87.0)]).startswith("Gaussian: no verdict")


def test_each_kernel_has_its_own_sentence_and_the_gaussians_comes_first():
    rows = [row(10, 10, -55.0, -56.0, "constant"), row(15, 10, -55.2, -56.1, "constant"),
            row(10, 10, -62.0, -63.8), row(15, 10, -63.0, -64.0)]
    text = kc.verdict(rows)
    g, c = text.index("Gaussian, at 2 horizons"), text.index("Constant, at 2 horizons")
    assert g < c
    # the constant kernel's rows are not mixed into the Gaussian's sequence
    assert "-62.0° at m = 10, -63.0° at m = 15;" in text
    assert "-55.0° at m = 10, -55.2° at m = 15;" in text


def test_time_step_rule_is_the_kink_tests():
    for m, factor in kc.kinkbench.DTFACTOR.items():
        assert float(kc.case_vars(m, 10)["dtfactor"]) == factor


def test_each_mix_is_a_sequence_of_its_own():
    rows = [row(10, 10, -62.0, -63.8), row(15, 10, -63.0, -64.0),
            dict(row(10, 20, -30.0, -31.0), psi=45.0, alpha=22.5),
            dict(row(15, 20, -30.5, -31.2), psi=45.0, alpha=22.5)]
    text = kc.verdict(rows)
    # the pure Mode II sequence keeps only its own rows, and comes first
    assert "Gaussian, at 2 horizons, R/delta = 10: -62.0° at m = 10, -63.0° at m = 15;" in text
    mixed = "Gaussian, psi = 45°, alpha = 22.5°, at 2 horizons, R/delta = 20: -30.0° at m = 10, -30.5° at m = 15;"
    assert mixed in text and text.index("Gaussian, at 2") < text.index(mixed)
    assert "moves it by -0.5°: settled within 1°" in text
    full = [dict(r, dx_mm=5.0 / r["m"], atoms=1, steps=1, K_init_over_Kc=0.5,
                 extension_over_delta=5.0, loop_s=1.0, nprocs=2) for r in rows]
    assert "| gaussian | 45 | 22.5 | 10 | 20 |" in kc.table(full)
    assert kc.case_folder(10, 20, psi=45.0, alpha=22.5) == "m10-R20-psi45-alpha22.5"
    assert kc.case_folder(10, 20) == "m10-R20"    # the pure Mode II runs keep their folders


def test_a_larger_disk_with_two_values_of_m_has_its_own_sentence():
    rows = [row(5, 20, -66.0, -71.7), row(10, 20, -62.1, -64.7)]
    text = kc.verdict(rows)
    assert "R/delta = 20: -66.0° at m = 5, -62.1° at m = 10" in text
    assert "moves it by +3.9°: not settled" in text


def test_each_run_names_the_cpu_that_timed_it():
    old = [dict(row(10, 10, -62.0, -63.8)), dict(row(15, 10, -63.0, -64.0))]
    comments = ["made by: x", "timing: LAMMPS loop time, Intel(R) Xeon(R) Processor, AVX-512, shared machine"]
    rows = kc.with_cpu(old, comments)
    assert {r["cpu"] for r in rows} == {"Intel(R) Xeon(R) Processor, AVX-512"}
    rows.append(dict(row(10, 20, -30.0, -31.0), psi=45.0, alpha=0.0, cpu="AMD EPYC (family 25 model 1), AVX2"))
    text = kc.loop_times(rows)
    assert text.startswith("Loop times: Intel(R) Xeon(R) Processor, AVX-512 (every run but these); ")
    assert "AMD EPYC (family 25 model 1), AVX2 (gaussian psi = 45, alpha = 0, m = 10, R/delta = 20)" in text
    assert kc.loop_times(rows[:2]) == "Loop times: Intel(R) Xeon(R) Processor, AVX-512."
    # a CSV without the line: unknown, never another machine's name
    assert kc.with_cpu(old, ["made by: x"])[0]["cpu"] == "unknown"


def test_a_straight_crack_reads_zero_not_minus_zero():
    assert kc._f(-1e-15) == "0.0" and kc._f(-0.04) == "0.0" and kc._f(-0.06) == "-0.1"
    assert kc._f(None) == "-"
    assert kc._signed(-0.04) == "+0.0" and kc._signed(-0.06) == "-0.1" and kc._signed(1.0) == "+1.0"


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
    text = kc.verdict(rows)
    assert "the three criteria agree (0.0°) and the finest (± 1.4°) lies +0.0° from them (within its error bar)" in text
    assert "nearest" not in text


def test_the_whole_sweep_has_its_own_verdict_only_when_complete():
    crit = {90.0: (-70.53, -63.61, -75.23), 67.5: (-62.9, -57.6, -67.7), 45.0: (-53.13, -49.67, -57.33),
            22.5: (-36.1, -34.9, -39.0)}
    def mixed(psi, alpha, a2, a4, m=10):
        hs, hn, en = crit[psi]
        return dict(row(m, 20, a2, a4), psi=psi, alpha=alpha, hoop_stress=hs, hoop_strain=hn, energy=en)
    # every angle 0.5 deg beyond hoop strain along the rows and 1.5 deg at 22.5 deg
    rows = [mixed(p, a, crit[p][1] - 0.5 - a / 22.5, crit[p][1] - 0.5 - a / 22.5)
            for p in crit for a in (0.0, 22.5)]
    text = kc.sweep_verdict(rows)
    assert text.startswith("Gaussian, m = 10, R/delta = 20, the whole mixed-mode sweep (8 runs: "
                           "psi = 22.5, 45, 67.5, 90°, both crack directions), at 2 horizons")
    assert "nearest by RMS max. hoop strain" in text
    assert "mean -1.0 ± 0.2" in text     # four -0.5 and four -1.5: standard deviation 0.53 / sqrt(8)
    assert "moves the angle by 1.0° on average (at most 1.0°)" in text
    # one run missing: no verdict for that group
    assert kc.sweep_verdict(rows[1:]).startswith("No (kernel, m, R/delta)")
    # a pure Mode I run beside the sweep is left out of it
    assert kc.sweep_verdict(rows + [dict(row(10, 20, 0.0, 0.0), psi=0.0, alpha=0.0)]) == text


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
    text = kc.sweep_trend(settling((10, -1.0), (15, -0.3)))
    assert text.startswith("Gaussian, R/delta = 20, the whole mixed-mode sweep at m = 10, 15, 2 "
                           "horizons out: nearest by RMS max. hoop strain, max. hoop strain")
    assert ("The sequence approaches max. hoop strain: among the nearest at m = 10 and the nearest "
            "at 15, its RMS falling from 1.1 to 0.6°, admitted by the test at m = 15; from m = 10 "
            "to 15 the mean moves by +0.7 ± 0.4° (paired by mix; positive: the crack kinks less), "
            "within two standard errors: no drift shown.") in text
    # the finest m decides: a third, coarser sweep does not change the sentence's verdict
    assert kc.sweep_trend(settling((5, -4.0), (10, -1.0), (15, -0.3))).count(
        "The sequence approaches max. hoop strain") == 2


def test_a_sweep_that_still_drifts_is_not_settled():
    # every mix moves by the same +0.7 deg from m = 10 to 15: near hoop strain, its RMS falling
    # and admitted, but the whole sweep still moves, past any standard error
    rows = sweep(10, -1.0) + sweep(15, -0.3)
    text = kc.sweep_trend(rows)
    assert ("Not settled: max. hoop strain stays the nearest with its RMS falling and the test "
            "admits it at m = 15, but from m = 10 to 15 the mean moves by +0.7 ± 0.0° (paired by "
            "mix; positive: the crack kinks less), more than two standard errors: the sequence "
            "still drifts.") in text
    assert "approaches" not in text
    assert kc.limit_sentence(rows).endswith("so which criterion the kink follows is not settled.")


def test_none_fits_names_the_criteria_the_kink_lies_between():
    # every run 2 deg beyond hoop strain, 2.5 deg short of a hoop stress that kinks more still:
    # the test admits neither, and the mean lies between the two
    rows = [dict(r, hoop_stress=r["angle_2d"] - 2.5, energy=r["angle_2d"] - 8.0)
            for r in sweep(10, -3.0, spread=0.1) + sweep(15, -2.0, spread=0.1)]
    text = kc.sweep_trend(rows)
    assert ("At m = 15 the two-standard-error test admits none of the criteria: none fits; the mean "
            "lies between max. hoop strain (BBPD kinks more by 2.0 ± 0.0°) and max. hoop stress "
            "(less by 2.5 ± 0.0°).") in text
    assert ("The mean deviation at m = 10, 15: from max. hoop strain -3.0, -2.0; from max. hoop "
            "stress +2.5, +2.5°; from m = 10 to 15 the mean moves by +1.0 ± 0.0°") in text
    assert ("4 horizons from the tip none of the criteria fits (the kink lies between max. hoop "
            "strain and max. hoop stress, still drifting)") in kc.limit_sentence(rows)
    # the same mean at both m: between the two, no drift
    still = [dict(r, hoop_stress=r["angle_2d"] - 2.5, energy=r["angle_2d"] - 8.0)
             for r in settling((10, -2.0), (15, -2.0))]
    assert ("(the kink lies between max. hoop strain and max. hoop stress);"
            in kc.limit_sentence(still))
    assert "within two standard errors: no drift shown." in kc.sweep_trend(still)
    # kinking beyond every criterion: between none of them
    beyond = [dict(r, hoop_stress=r["angle_2d"] + 1.0, energy=r["angle_2d"] + 5.0) for r in rows]
    assert "the kink lies between" not in kc.limit_sentence(beyond)
    assert "BBPD kinks more than every criterion, by 1.0 ± 0.0° than the nearest, max. hoop stress" \
        in kc.sweep_trend(beyond)


def test_the_trend_says_not_settled_and_why():
    # moving away from hoop strain: nearest both times, but the RMS grows
    grows = kc.sweep_trend(sweep(10, -0.3, spread=2.0) + sweep(15, -1.0, spread=2.0))
    assert "Not settled: max. hoop strain stays the nearest, but from m = 10 to 15 its RMS grows" in grows
    # the nearest changes from hoop strain to hoop stress
    changes = kc.sweep_trend(sweep(10, -0.3) + sweep(15, 0.2, criterion=0))
    assert ("Not settled: from m = 10 to 15 the nearest criterion changes from max. hoop strain to "
            "max. hoop stress.") in changes
    # every run 2.5 +- 0.1 deg beyond criteria that agree: a bias of 30 standard errors
    agree = [dict(r, hoop_stress=r["hoop_strain"], energy=r["hoop_strain"])
             for r in sweep(10, -3.0, spread=0.1) + sweep(15, -2.5, spread=0.1)]
    none = kc.sweep_trend(agree)
    assert ("At m = 15 the two-standard-error test admits none of the criteria: none fits; BBPD "
            "kinks more than every criterion, by 2.5 ± 0.0° than the nearest") in none
    assert "approaches" not in none
    # nearest both times, its RMS falling, but excluded by the test at the finest m
    # (hoop strain 1.5 then 1.0 +- 0.2 deg away; hoop stress 3 deg either side, mean 0, so the
    # test admits it with the larger RMS)
    excluded = kc.sweep_trend([
        dict(r, hoop_stress=r["angle_2d"] + (3.0 if k % 4 < 2 else -3.0), energy=r["angle_2d"] + 10.0)
        for k, r in enumerate(sweep(10, -1.5, spread=0.2) + sweep(15, -1.0, spread=0.2))])
    assert ("Not settled: max. hoop strain stays the nearest with its RMS falling, but at m = 15 "
            "the test excludes it.") in excluded


def test_the_trend_needs_two_whole_sweeps():
    assert kc.sweep_trend(sweep(10, -1.0)).startswith("No trend across m")
    assert kc.sweep_trend(sweep(10, -1.0) + sweep(15, -0.3)[1:]).startswith("No trend across m")


def test_criteria_closer_than_the_grids_resolution_are_both_nearest():
    # at m = 15 hoop stress moved to within 0.4 deg of hoop strain in every run: their RMS values
    # lie closer than the grid's resolution (2 horizons: atan(1 / 60) = 0.95 deg), a tie
    rows = settling((10, -1.0), (15, -0.3))
    tied = [dict(r, hoop_stress=r["hoop_strain"] + (0.4 if k % 2 else -0.4)) if r["m"] == 15.0 else r
            for k, r in enumerate(rows)]
    text = kc.sweep_trend(tied)
    assert "Not settled: at m = 15 max. hoop stress and max. hoop strain lie equally near" in text
    assert "closer than the grid's resolution, ± 1.0°" in text     # 2 horizons, m = 15
    assert "approaches" not in text


def test_a_partial_finest_sweep_is_followed_over_the_same_mixes():
    # whole sweeps at m = 10 and 15, and at m = 20 only psi = 90 and 45 along the rows, moving
    # from 0.3 deg beyond hoop strain (m = 15) to 2 deg beyond it
    part = [dict(r, angle_2d=r["hoop_strain"] - 2.0, angle_4d=r["hoop_strain"] - 2.0)
            for r in sweep(20, 0.0) if r["psi"] in (90.0, 45.0) and r["alpha"] == 0.0]
    rows = sweep(10, -1.0) + sweep(15, -0.3) + part
    text = kc.subset_trend(rows)
    assert text.startswith("Gaussian, R/delta = 20, the 2 mixes run so far at m = 20 (psi = 90° along "
                           "the rows, psi = 45° along the rows) followed over m = 10, 15, 20, 2 horizons out")
    # both mixes are even runs of sweep() (offset - spread): 1.5 deg beyond hoop strain at
    # m = 10, 0.8 at m = 15, 2.0 at m = 20 (over the whole sweep the RMS would be 1.1 and 0.6)
    assert "max. hoop strain 1.5, 0.8, 2.0" in text
    assert "From m = 15 to 20 the nearest at 20: max. hoop strain's RMS grows from 0.8 to 2.0°" in text
    assert "not the limit" in text and "approaches" not in text
    # the whole trend still reads the complete sweeps only
    assert "at m = 10, 15, 2 horizons out" in kc.sweep_trend(rows)


def test_the_subset_trend_needs_a_partial_finest_m_and_a_whole_coarser_sweep():
    nothing = "Every finest m has run the whole mixed-mode sweep or none of it."
    assert kc.subset_trend(sweep(10, -1.0) + sweep(15, -0.3)) == nothing     # finest m complete
    lone = [r for r in sweep(20, 0.0) if r["psi"] == 90.0] + [r for r in sweep(15, 0.0) if r["psi"] == 90.0]
    assert kc.subset_trend(lone) == nothing      # no coarser whole sweep to hold it against


def test_kernel_comparison_holds_the_kernels_against_one_another_over_the_mixes_they_share():
    gauss = sweep(15, -0.3)                       # the whole sweep, near hoop strain
    near = [dict(r, kernel="constant", angle_2d=r["angle_2d"] - 0.5, angle_4d=r["angle_4d"] - 0.5)
            for r in sweep(15, -0.3) if r["alpha"] == 0.0 and r["psi"] in (90.0, 67.5)]
    text = kc.kernel_comparison(gauss + near)
    # only the two mixes both kernels ran, the Gaussian first
    assert text.startswith("m = 15, R/delta = 20, the 2 mixes run by every kernel here (psi = 90° "
                           "along the rows, psi = 67.5° along the rows), 2 horizons out: RMS Gaussian")
    assert "The kernels' angles lie 0.5° apart on average and at most 0.5°" in text
    assert "within the two runs' error bars (± 1.0° each)" in text
    assert text.count("The kernel does not change the nearest criterion (max. hoop strain).") == 2
    # a constant kernel at hoop stress instead: the nearest criterion differs, the spread is real
    far = [dict(r, kernel="constant", angle_2d=r["hoop_stress"], angle_4d=r["hoop_stress"]) for r in near]
    text = kc.kernel_comparison(gauss + far)
    assert text.count("The kernel changes the nearest criterion.") == 2
    assert "beyond the two runs' error bars (± 0.5° each)" in text


def test_kernel_comparison_needs_two_kernels_on_two_mixes():
    nothing = "No (m, R/delta) has more than one kernel over more than one mixed mode."
    assert kc.kernel_comparison(sweep(15, -0.3)) == nothing                 # one kernel
    lone = [dict(r, kernel="constant") for r in sweep(15, -0.3) if r["psi"] == 90.0 and r["alpha"] == 0.0]
    assert kc.kernel_comparison(sweep(15, -0.3) + lone) == nothing          # pure Mode II alone
    other_m = [dict(r, kernel="constant", m=10.0) for r in sweep(15, -0.3)]
    assert kc.kernel_comparison(sweep(15, -0.3) + other_m) == nothing       # not at one m


def test_an_exclusion_smaller_than_the_grid_resolves_is_said_to_be():
    # 0.5 deg beyond hoop strain with almost no scatter: the standard error excludes it, but
    # 0.5 deg is within one angle's bar at 2 horizons (m = 15: 1.0) and not at 4 (0.48)
    text = kc.sweep_verdict(sweep(15, -0.5, spread=0.05))
    assert text.count("exclude max. hoop stress") == 2 and "and max. hoop strain (BBPD kinks more by 0.5" in text
    assert text.count("Of these, max. hoop strain's mean (-0.5°) lies within one angle's error bar "
                      "(± 1.0°): excluded by less than the grid resolves.") == 1
    # an exclusion by more than the bar, or a criterion the test admits, gets no such sentence
    assert "Of these" not in kc.sweep_verdict(sweep(15, -2.0, spread=0.05))
    assert "Of these" not in kc.sweep_verdict(sweep(15, -0.5, spread=2.0))


def test_the_limit_sentence_names_a_criterion_only_where_every_distance_approaches_it():
    both = kc.limit_sentence(settling((10, -1.0), (15, -0.3)))
    assert both == ("The kink test's whole mixed-mode sweep followed in m (Gaussian, R/delta = 20, "
                    "m = 10, 15): 2 horizons from the tip it approaches max. hoop strain; 4 horizons "
                    "from the tip it approaches max. hoop strain; so the kink follows max. hoop strain.")
    # tied at m = 15 (hoop stress within 0.4 deg of hoop strain in every run): no criterion named
    rows = settling((10, -1.0), (15, -0.3))
    tied = [dict(r, hoop_stress=r["hoop_strain"] + (0.4 if k % 2 else -0.4)) if r["m"] == 15.0 else r
            for k, r in enumerate(rows)]
    text = kc.limit_sentence(tied)
    assert "not settled (max. hoop stress and max. hoop strain equally near at m = 15)" in text
    assert text.endswith("so which criterion the kink follows is not settled.")
    assert "the kink follows max." not in text
    # moving away from hoop strain: not settled either
    grows = kc.limit_sentence(sweep(10, -0.3, spread=2.0) + sweep(15, -1.0, spread=2.0))
    assert grows.endswith("is not settled.") and "approaches" not in grows
    # another kernel's sweeps say nothing about the Gaussian
    other = [dict(r, kernel="constant") for r in rows]
    assert "no verdict on the limit for the gaussian kernel" in kc.limit_sentence(other)
    assert kc.limit_sentence(other, "constant").endswith("so the kink follows max. hoop strain.")


def test_the_kalthoff_winkler_summary_carries_the_kink_tests_limit():
    from bbpd.claims import crack
    text = crack.kw_summary(None)
    assert kc.limit_sentence(kc.read_rows()) in text
    assert "puts BBPD's critical stretch on" not in text


def test_the_coverage_lists_what_of_the_plan_is_left():
    rows = [dict(r, loop_s=100.0 + k, cpu="CPU A", nprocs=2.0) for k, r in enumerate(sweep(15, -0.3))]
    rows += [dict(r, kernel=k, loop_s=50.0, cpu="CPU B", nprocs=2.0) for k in ("constant", "triangular")
             for r in sweep(15, -0.3)]
    text = kc.coverage(rows)
    assert "Gaussian m = 15: whole (loop 100-107 s for the 8 of them on CPU A, 2 ranks)" in text
    assert "Gaussian m = 10: 0 of 8; Gaussian m = 15" in text
    assert "Left: Gaussian m = 10: psi = 90° along the rows" in text
    assert "Constant m = 15: whole" in text and "Triangular m = 15: whole" in text
    # the m = 20 sweep with one run missing, and a run on another machine: the majority's times
    part = [dict(r, loop_s=2000.0, cpu="CPU A", nprocs=2.0) for r in sweep(20, -0.3)[:7]]
    part[0] = dict(part[0], loop_s=9000.0, cpu="CPU C")
    text = kc.coverage(rows + part)
    assert "Gaussian m = 20: 7 of 8 (loop 2000-2000 s for the 6 of them on CPU A, 2 ranks)" in text
    assert "Gaussian m = 20: psi = 22.5° at 22.5°." in text
    whole = [dict(r, m=m, loop_s=1.0, cpu="CPU A", nprocs=2.0) for m in (10.0, 20.0) for r in sweep(15, -0.3)]
    assert kc.coverage(rows + whole).endswith("Every run of it is in.")


def test_an_rms_change_below_the_shown_digit_holds():
    assert kc._rms_move("X", 2.7403, 2.7372) == "X's RMS holds at 2.7°"
    assert kc._rms_move("X", 2.58, 2.64) == "X's RMS holds at 2.6°"     # the digits shown agree
    assert kc._rms_move("X", 1.4, 1.1) == "X's RMS falls from 1.4 to 1.1°"
    assert kc._rms_move("X", 0.8, 2.0) == "X's RMS grows from 0.8 to 2.0°"


def test_the_report_section_carries_the_committed_limit():
    # the whole sweeps take days: REPORT.md states their limit from the committed CSV, run or not
    sentence = kc.limit_sentence(kc.read_rows())
    assert sentence in kc.section([], {}, None, [])["setup"]

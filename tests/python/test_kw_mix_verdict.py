"""The Kalthoff-Winkler verdict at both mode mixes (kalthoff_winkler_grid.mix_verdict): it
names both mixes and states a criterion only where every mix and angle definition supports it."""
import json

import pytest

from bbpd.benchmarks import kalthoff_winkler_grid as grid
from bbpd.benchmarks import kink_kalthoff_winkler


def mix(first, band):
    """a mix record with the criteria's (negative, lower-crack) angles at the two instants"""
    out = {"psi": 113.0, "t_mix_us": 12.0, "psi_band": 97.0, "t_band_mix_us": 23.0}
    for (_, key), a, b in zip(grid.CRITERIA, first, band):
        out[key], out[key + "_band"] = -a, -b
    return out


ANGLES = {"initial": [64.0, 65.0, 66.0], "fit": [64.5, 65.0, 65.5]}


def test_both_mixes_agree_follows():
    text = grid.mix_verdict(mix((65.2, 73.0, 78.0), (64.8, 72.0, 77.0)), ANGLES, 1.0)
    assert "the first broken bond" in text and "the damage band" in text
    assert "the crack follows hoop strain." in text
    assert "not settled" not in text.split("The experiment")[0]


def test_agreement_at_one_mix_only_is_not_settled():
    text = grid.mix_verdict(mix((70.0, 79.0, 83.0), (65.2, 73.0, 78.0)), ANGLES, 1.0)
    assert "only at the damage band's mix" in text
    assert "the crack follows" not in text.replace("that the crack follows", "")


def test_nearest_criterion_changing_with_the_mix_singles_none_out():
    # hoop strain nearest at the first bond's mix, hoop stress at the band's
    text = grid.mix_verdict(mix((65.0, 75.0, 80.0), (58.0, 65.5, 75.0)), ANGLES, 1.0)
    assert "no criterion is singled out" in text


def test_experiment_angle_stated_only_when_both_mixes_agree():
    both = grid.mix_verdict(mix((69.5, 78.0, 82.0), (69.0, 77.0, 81.0)), ANGLES, 1.0)
    assert "70° lies nearest hoop strain at both mixes" in both
    split = grid.mix_verdict(mix((69.9, 78.9, 82.6), (65.4, 72.9, 77.4)), ANGLES, 1.0)
    assert "not settled by the mix" in split


def test_committed_mix_names_both_instants():
    rec = json.loads(kink_kalthoff_winkler.SUMMARY.read_text())
    text = grid.mix_verdict(rec, ANGLES, 1.0)
    for _, _, t, psi in grid.MIXES:
        assert f"psi = {rec[psi]:.1f}°" in text and f"{rec[t]:.1f} µs" in text


@pytest.mark.parametrize("bad", [{"initial": [60.0], "fit": [61.0, 62.0]}, {}])
def test_needs_two_setups_per_definition(bad):
    with pytest.raises(ValueError, match="at least two setups"):
        grid.mix_verdict(mix((65.0, 73.0, 78.0), (65.0, 73.0, 78.0)), bad, 1.0)


FINEST = {"kernel": "gaussian", "m": 20.0, "R_over_delta": 20.0, "angle_2d": -62.0, "angle_4d": -65.0}


def tips(ki, psi, psi_band):
    return {"KI": ki, "psi": psi, "psi_band": psi_band, "angle_deg": 59.0, "dx": 2e-3}


def test_the_kink_readme_reading_is_computed_from_the_mix():
    limit = "LIMIT SENTENCE."
    text = kink_kalthoff_winkler.reading(tips(-51e6, 113.0, 97.0), 5.0, FINEST, limit)
    assert "K_I -51.0 MPa m^1/2 (the notch faces are pressed together" in text
    assert "both beyond pure Mode II (psi = 90°)" in text and "(m = 5)" in text
    assert "kinks at 62.0 / 65.0° (2 / 4 horizons), against 59.0°" in text
    assert "at both instants and states only what both support" in text
    assert text.endswith(limit)
    # one instant inside the kink test's range, K_I opening: neither claim is made
    inside = kink_kalthoff_winkler.reading(tips(10e6, 113.0, 85.0), 5.0, FINEST, limit)
    assert "beyond pure Mode II" not in inside and "pressed together" not in inside
    assert "K_I +10.0 MPa m^1/2" in inside


def test_the_k0_check_sentence_reads_the_check_and_the_default_run():
    from bbpd.benchmarks import kink
    check = {"kernel": "gaussian", "psi": 90.0, "alpha": 0.0, "dx": 5e-4, "delta": 5e-3, "K0": 0.3,
             "K_init_over_Kc": 0.49, "angle_2d": -59.6, "angle_4d": -62.8}
    default = {"kernel": "gaussian", "psi": 90.0, "alpha": 0.0, "dx": 5e-4, "ncross": kink.NCROSS,
               "angle_2d": -62.1, "angle_4d": -63.8}
    other = dict(default, dx=1e-3, angle_2d=-90.0, angle_4d=-87.1)
    text = kink.k0_sentence(check, [other, default])
    assert "m = 10 psi = 90° case (crack along the rows) with K0 = 0.3 instead of 0.5" in text
    assert "during the slow ramp" in text and "(-62.1 / -63.8 with the default), 2.5 / 1.0 deg apart" in text
    assert "still on the fast ramp" in kink.k0_sentence(dict(check, K_init_over_Kc=0.25), [default])

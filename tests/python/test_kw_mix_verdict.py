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

"""The Kalthoff-Winkler verdict at both mode mixes (kalthoff_winkler_grid.mix_verdict): it
reads both instants' mixes and names a criterion only where every mix and angle definition
supports it."""
import json

import pytest

from bbpd.benchmarks import kalthoff_winkler_grid as grid
from bbpd.benchmarks import kink_kalthoff_winkler
from bbpd import csvfile
from bbpd.jobs import ROOT

FIRST, BAND = (m for m, _, _, _ in grid.MIXES)


def mix(first, band):
    """a mix record with the criteria's (negative, lower-crack) angles at the two instants"""
    out = {"psi": 113.0, "t_mix_us": 12.0, "psi_band": 97.0, "t_band_mix_us": 23.0}
    for (_, key), a, b in zip(grid.CRITERIA, first, band):
        out[key], out[key + "_band"] = -a, -b
    return out


ANGLES = {"initial": [64.0, 65.0, 66.0], "fit": [64.5, 65.0, 65.5]}


def test_both_mixes_agree_follows():
    v = grid.mix_verdict(mix((65.2, 73.0, 78.0), (64.8, 72.0, 77.0)), ANGLES)
    assert set(v["pred"]) == {FIRST, BAND} and v["pred"][FIRST]["hoop strain"] == pytest.approx(65.2)
    assert v["stats"]["initial"] == pytest.approx((65.0, 0.577), abs=1e-3)
    assert set(v["nearest"].values()) == {"hoop strain"} and all(v["agree"].values())
    assert v["follows"] == "hoop strain"


def test_agreement_at_one_mix_only_is_not_settled():
    v = grid.mix_verdict(mix((70.0, 79.0, 83.0), (65.2, 73.0, 78.0)), ANGLES)
    assert set(v["nearest"].values()) == {"hoop strain"}
    assert not any(v["agree"][FIRST, d] for d in ANGLES) and all(v["agree"][BAND, d] for d in ANGLES)
    assert v["follows"] is None


def test_nearest_criterion_changing_with_the_mix_singles_none_out():
    # hoop strain nearest at the first bond's mix, hoop stress at the band's
    v = grid.mix_verdict(mix((65.0, 75.0, 80.0), (58.0, 65.5, 75.0)), ANGLES)
    assert v["nearest"][FIRST, "fit"] == "hoop strain" and v["nearest"][BAND, "fit"] == "hoop stress"
    assert v["follows"] is None


def test_experiment_angle_nearest_per_mix():
    both = grid.mix_verdict(mix((69.5, 78.0, 82.0), (69.0, 77.0, 81.0)), ANGLES)
    assert both["experiment"] == {FIRST: "hoop strain", BAND: "hoop strain"}
    split = grid.mix_verdict(mix((69.9, 78.9, 82.6), (65.4, 72.9, 77.4)), ANGLES)
    assert split["experiment"] == {FIRST: "hoop strain", BAND: "hoop stress"}


@pytest.mark.parametrize("bad", [{"initial": [60.0], "fit": [61.0, 62.0]}, {}])
def test_needs_two_setups_per_definition(bad):
    with pytest.raises(ValueError, match="at least two setups"):
        grid.mix_verdict(mix((65.0, 73.0, 78.0), (65.0, 73.0, 78.0)), bad)


def test_the_committed_runs_give_the_readme_summary():
    """examples/kalthoff-winkler/README.md's summary, by hand: the 1 mm cracks (paper's G_c,
    every loading and grid) lie nearest hoop strain at both instants' mixes and by both
    definitions, below it by more than two standard errors at both: no criterion followed; the
    experiment's 70 deg lies nearest hoop strain at the first bond's mix, hoop stress at the
    band's"""
    rec = json.loads(kink_kalthoff_winkler.SUMMARY.read_text())
    proj = csvfile.read_csv(ROOT / "examples" / "kalthoff-winkler" / "projectile.csv")[1]
    fine, ang = grid.fine_angles(proj, csvfile.read_csv(grid.CSV)[1])
    assert fine == 1.0
    assert (round(min(ang["fit"]), 1), round(max(ang["fit"]), 1)) == (61.1, 67.1)
    assert (round(min(ang["chord"]), 1), round(max(ang["chord"]), 1)) == (62.3, 71.0)
    v = grid.mix_verdict(rec, {d: ang[d] for d in grid.MEASURED})
    assert [round(x, 1) for x in v["stats"]["initial"]] == [62.6, 0.6]
    assert [round(x, 1) for x in v["stats"]["fit"]] == [63.8, 0.5]
    assert set(v["nearest"].values()) == {"hoop strain"} and not any(v["agree"].values())
    assert v["follows"] is None
    assert v["experiment"] == {FIRST: "hoop strain", BAND: "hoop stress"}
    assert round(rec["psi"], 1) == 113.2 and round(rec["psi_band"], 1) == 97.0
    assert {c: round(a, 1) for c, a in v["pred"][FIRST].items()} == \
        {"hoop strain": 69.9, "hoop stress": 78.9, "maximum energy release rate": 82.6}
    assert {c: round(a, 1) for c, a in v["pred"][BAND].items()} == \
        {"hoop strain": 65.4, "hoop stress": 72.9, "maximum energy release rate": 77.4}


def test_the_committed_pulls_give_the_readme_line():
    """examples/kalthoff-winkler/README.md under the pull table: 17 of 24 pulls beyond two
    standard errors, the largest +9.7 deg (constant, prescribed, 2 mm, initial), off-grid
    standard deviations 1.0-8.9 deg"""
    p = grid.pull(csvfile.read_csv(grid.CSV)[1])
    assert len(p) == 24 and sum(grid.significant(q) for q in p.values()) == 17
    key, big = max(p.items(), key=lambda kq: abs(kq[1]["pull"]))
    assert key == ("prescribed", "constant", 2.0, "initial") and round(big["pull"], 1) == 9.7
    sd = [q["sd"] for q in p.values() if q["sd"] is not None]
    assert (round(min(sd), 1), round(max(sd), 1)) == (1.0, 8.9)


def test_the_kink_readme_reading_and_k0_check_follow_their_files():
    """examples/kink-mixed-mode/README.md, by hand: the Kalthoff-Winkler tip sees K_I -51.4
    MPa m^1/2 before the first broken bond, psi 113.2 / 97.0 deg at the two instants (both beyond
    pure Mode II), the run's angle 58.8 deg at 2 mm; the K0 check: first bond at 0.49 K_c, during
    the slow ramp (above K0 = 0.3), angles -59.6 / -62.8 deg"""
    from bbpd.benchmarks import kink
    rec = json.loads(kink_kalthoff_winkler.SUMMARY.read_text())
    assert round(rec["KI"] / 1e6, 1) == -51.4 and min(rec["psi"], rec["psi_band"]) > 90.0
    assert round(rec["angle_deg"], 1) == 58.8 and rec["dx"] == 2e-3
    check = json.loads(kink.K0_CHECK.read_text())
    assert round(check["K_init_over_Kc"], 2) == 0.49 and check["K_init_over_Kc"] > check["K0"] == 0.3
    assert (round(check["angle_2d"], 1), round(check["angle_4d"], 1)) == (-59.6, -62.8)

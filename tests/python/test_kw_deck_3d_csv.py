# SPDX-License-Identifier: GPL-2.0-or-later
"""The hand-written readings of examples/kalthoff-winkler/README.md on the standard deck and the
3D plate, checked against results/standard_deck.csv and results/kw3d.csv through the data the
report's lines rest on (kalthoff_winkler_deck.comparison, kalthoff_winkler_3d.against_2d)."""
from bbpd.benchmarks import kalthoff_winkler_3d as kw3d
from bbpd.benchmarks import kalthoff_winkler_deck as deck


def test_the_standard_deck_reading():
    c = deck.comparison(deck.read_rows()[1])
    assert c["fine"] == 0.5 and c["hits"] == []
    fit = {k: (round(a, 1), round(ch, 1)) for (d, k), (a, ch) in c["deck"].items() if d == "fit"}
    assert fit == {"constant": (63.3, 0.6), "triangular": (62.6, -0.2), "gaussian": (63.2, 0.8)}
    assert {k: round(v, 1) for k, v in c["grid"].items()} == {"constant": 2.5, "triangular": 1.4, "gaussian": 0.5}
    dx, lps = c["changes"]["paper-lps-nu025"]
    assert dx == 0.5 and {k: round(ch, 1) for k, (_, ch) in lps.items()} == \
        {"constant": -7.5, "triangular": -6.5, "gaussian": -5.7}
    dx, std = c["changes"]["standard-lps"]
    assert dx == 1.0 and {k: round(ch, 1) for k, (_, ch) in std.items()} == \
        {"constant": -10.7, "triangular": -11.0, "gaussian": -11.4}


def test_the_3d_plate_reading():
    """resolved through its thickness the crack crosses at the 2D angle of the same grid within a
    degree, mid-plane and faces agree"""
    pairs, refine = kw3d.against_2d(kw3d.read_rows())
    assert [round(diff, 1) for _, _, diff in pairs] == [0.8, 0.7]
    assert all(abs(d3["fit_face_lo_deg"] - d3["fit_deg"]) < 0.5 for d3, _, _ in pairs)
    assert [d3["horizons_through"] for d3, _, _ in pairs] == [3.0, 4.0]
    assert round(refine, 1) == -0.4

"""Tests for bbpd.crack_tip (the compute bbpd/crack/tip definition) on synthetic fields."""

import numpy as np
import pytest

from bbpd.crack_tip import crack_tip

DX = 0.1
LINK = 5 * DX
START = (5.0, 0.0)


def grid(nx=100, ny=20):
    i, j = np.meshgrid(np.arange(nx), np.arange(ny), indexing="ij")
    return ((i + 0.5) * DX).ravel(), ((j + 0.5) * DX - ny * DX / 2).ravel()


def band_damage(x, y, x_end, value=0.5):
    """Damage `value` on the two rows next to y = 0 from x = 0 up to x_end."""
    return np.where((np.abs(y) < DX) & (x <= x_end), value, 0.0)


def test_tip_is_the_end_of_the_longest_path():
    x, y = grid()
    xt, yt, ext = crack_tip(x, y, band_damage(x, y, 6.0), START, LINK)
    assert xt == pytest.approx(5.95) and yt == pytest.approx(-DX / 2)   # tie: smaller y
    # S -> (5.45, -0.05) -> (5.95, -0.05): slightly longer than the straight line
    assert ext == pytest.approx(np.hypot(0.45, 0.05) + 0.5, rel=1e-9)


def test_isolated_damage_ahead_is_not_the_tip():
    x, y = grid()
    dmg = band_damage(x, y, 6.0)
    lone = (np.abs(x - 8.05) < 1e-9) & (np.abs(y - 0.05) < 1e-9)    # 2 m ahead
    dmg[lone] = 0.9
    assert crack_tip(x, y, dmg, START, LINK)[0] == pytest.approx(5.95)
    # joined to the crack once the gap is no wider than the link
    dmg[(np.abs(x - 6.35) < 1e-9) & (np.abs(y - 0.05) < 1e-9)] = 0.9
    assert crack_tip(x, y, dmg, START, LINK)[0] == pytest.approx(6.35)


def test_notch_behind_the_start_and_weak_damage_do_not_count():
    x, y = grid()
    assert crack_tip(x, y, band_damage(x, y, 4.99), START, LINK) == (5.0, 0.0, 0.0)
    assert crack_tip(x, y, band_damage(x, y, 6.0, 0.2), START, LINK) == (5.0, 0.0, 0.0)
    assert crack_tip(x, y, band_damage(x, y, 6.0, 0.2), START, LINK, threshold=0.15)[0] == \
        pytest.approx(5.95)


def test_direction_and_bad_arguments():
    x, y = grid()
    dmg = band_damage(x, y, 6.0)
    xt, _, ext = crack_tip(x, y, dmg, START, LINK, direction=(-1.0, 0.0))
    assert xt == pytest.approx(0.05) and ext == pytest.approx(4.95, abs=0.01)
    with pytest.raises(ValueError):
        crack_tip(x, y, dmg, START, 0.0)
    with pytest.raises(ValueError):
        crack_tip(x, y, dmg, START, LINK, threshold=0.0)
    with pytest.raises(ValueError):
        crack_tip(x, y, dmg, START, LINK, direction=(0.0, 0.0))

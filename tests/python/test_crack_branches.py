"""Tests for bbpd.crack_branches (the branches of compute bbpd/crack/tip) on synthetic bands."""

import numpy as np
import pytest

from bbpd.crack_branches import branch_tips

DX = 1.0
LINK = 3.015 * DX
HALF_ANGLE = np.radians(15.0)


def grid(nx=90, ny=80):
    i, j = np.meshgrid(np.arange(-5, nx), np.arange(-ny // 2, ny // 2), indexing="ij")
    return ((i + 0.5) * DX).ravel(), ((j + 0.5) * DX).ravel()


def near(x, y, x0, y0, x1, y1, half_width=1.0):
    """points within half_width of the segment (x0, y0)-(x1, y1)"""
    dx, dy = x1 - x0, y1 - y0
    t = np.clip(((x - x0) * dx + (y - y0) * dy) / (dx * dx + dy * dy), 0.0, 1.0)
    return np.hypot(x - x0 - t * dx, y - y0 - t * dy) <= half_width


def test_straight_band_has_one_tip_and_a_fork_two_mirror_tips():
    x, y = grid()
    straight = near(x, y, 0, 0, 40, 0)
    tips = branch_tips(x, y, np.where(straight, 0.5, 0.0), (0.0, 0.0), LINK)
    assert len(tips) == 1 and tips[0]["split_length"] == 0.0
    leg = 25.0
    ends = [(20 + leg * np.cos(HALF_ANGLE), s * leg * np.sin(HALF_ANGLE)) for s in (1, -1)]
    forked = near(x, y, 0, 0, 20, 0) | near(x, y, 20, 0, *ends[0]) | near(x, y, 20, 0, *ends[1])
    tips = branch_tips(x, y, np.where(forked, 0.5, 0.0), (0.0, 0.0), LINK)
    assert len(tips) == 2
    assert tips[0]["y"] < 0.0 < tips[1]["y"]               # the tie goes to the lower one
    assert tips[0]["x"] == pytest.approx(tips[1]["x"], abs=DX)
    assert 20.0 <= tips[1]["split_x"] <= 32.0
    assert tips[1]["extension"] - tips[1]["split_length"] >= 2 * LINK


def test_short_side_bump_is_no_tip_and_no_damage_no_tip():
    x, y = grid()
    bumped = near(x, y, 0, 0, 40, 0) | near(x, y, 15, 0, 15, 3)
    assert len(branch_tips(x, y, np.where(bumped, 0.5, 0.0), (0.0, 0.0), LINK)) == 1
    assert len(branch_tips(x, y, np.where(bumped, 0.5, 0.0), (0.0, 0.0), LINK, 0.0)) > 1
    assert branch_tips(x, y, np.zeros_like(x), (0.0, 0.0), LINK) == []

# SPDX-License-Identifier: GPL-2.0-or-later
"""The crack that grows from a notch tip, from a damage snapshot (reference positions and
damage of every atom, e.g. a LAMMPS dump of f_ref[1] f_ref[2] c_dmg), and the direction it
took at stated distances from the tip.

Definitions (distances in the units of the positions)
    crack atoms   atoms with damage >= threshold (0.35 by default: with m = 5 the two rows that
                  flank a straight cut have damage ~0.44 and the next ones ~0.31, see
                  python/bbpd/benchmarks/kalthoff_winkler.py)
    grown crack   the crack atoms linked to the tip through crack atoms, a link joining two
                  atoms closer than `link` (1.5 dx: the 8-neighbourhood of a square grid), the
                  chain starting at a crack atom within `seed` (one horizon) of the tip
    angle(d)      in the crack-tip frame (x along the notch's extension line, theta as in
                  bbpd.kink: counter-clockwise, the notch faces at +-180 deg), the direction of
                  the centroid of the grown-crack atoms at distance d +- band from the tip (band
                  = dx: the band of two to three atoms across a crack straddles its path
                  symmetrically), excluding the notch's own flanks (|theta| > FLANK_DEG)
    spread(d)     the standard deviation of those atoms' angles: a few degrees for a single
                  crack, tens of degrees if the crack branched
    extension     the largest distance from the tip of a grown-crack atom ahead of the tip

`compute bbpd/crack/tip` follows the same connected crack in LAMMPS and
reports its tip, extension and newest direction; its tip position at the moment the
extension passes d gives angle(d) as atan2 of that position in the tip frame, without a dump.
"""

import math

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree

CRACK_DAMAGE = 0.35
LINK_DX = 1.5          # links within the 8-neighbourhood of a square grid
FLANK_DEG = 150.0      # atoms behind this angle belong to the notch's flanks


def tip_frame(x, y, tip, alpha_deg):
    """Coordinates (xt, yt) of points in the frame of a crack tip at `tip` whose extension line
    points at alpha_deg from +x."""
    a = math.radians(alpha_deg)
    dx, dy = np.asarray(x) - tip[0], np.asarray(y) - tip[1]
    return dx * math.cos(a) + dy * math.sin(a), -dx * math.sin(a) + dy * math.cos(a)


def clusters(points, link):
    """Connected-component label of each point, linking points closer than `link`."""
    n = len(points)
    if n == 0:
        return np.zeros(0, dtype=int)
    pairs = cKDTree(points).query_pairs(link, output_type="ndarray")
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    return connected_components(graph, directed=False)[1]


def grown_crack(x, y, damage, tip, dx, seed, threshold=CRACK_DAMAGE):
    """Boolean mask of the crack atoms linked to the tip (see the module's definitions)."""
    x, y, damage = map(np.asarray, (x, y, damage))
    crack = np.nonzero(damage >= threshold)[0]
    mask = np.zeros(len(x), dtype=bool)
    if len(crack) == 0:
        return mask
    pts = np.column_stack([x[crack], y[crack]])
    labels = clusters(pts, LINK_DX * dx)
    near = np.hypot(pts[:, 0] - tip[0], pts[:, 1] - tip[1]) <= seed
    mask[crack[np.isin(labels, np.unique(labels[near]))]] = True
    return mask


def kink_angles(x, y, damage, tip, alpha_deg, dx, distances, seed, threshold=CRACK_DAMAGE):
    """{'extension': ..., 'atoms': n, d: (angle_deg, spread_deg, count) or None per distance}
    of the crack grown from `tip` (module docstring)."""
    mask = grown_crack(x, y, damage, tip, dx, seed, threshold)
    xt, yt = tip_frame(np.asarray(x)[mask], np.asarray(y)[mask], tip, alpha_deg)
    r = np.hypot(xt, yt)
    theta = np.degrees(np.arctan2(yt, xt))
    ahead = np.abs(theta) <= FLANK_DEG
    out = {"extension": float(r[ahead].max()) if ahead.any() else 0.0,
           "atoms": int(ahead.sum())}
    for d in distances:
        sel = ahead & (np.abs(r - d) <= dx)
        if not sel.any():
            out[d] = None
            continue
        angle = math.degrees(math.atan2(yt[sel].mean(), xt[sel].mean()))
        out[d] = (angle, float(np.std(theta[sel])), int(sel.sum()))
    return out

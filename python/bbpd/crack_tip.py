# SPDX-License-Identifier: GPL-2.0-or-later
"""Crack tip from a damage field, in Python: the definition of `compute bbpd/crack/tip`
(doc/compute_bbpd_crack_tip.rst) applied to a dump, for runs without the compute and as an
independent check of it.

The nodes are the atoms with damage >= threshold at or ahead of the line through the start
point S normal to the crack direction d; two nodes are joined when they lie at most `link`
apart (the horizon), nodes within `link` of S are joined to S, each edge weighted by its
length.  The extension of a node is its shortest-path length from S; the tip is the node
with the largest one (ties within TIE link: smallest y, then smallest x).  Until a node is
connected to S the tip is S and the extension 0.  Positions are those of the dump (the
current ones: they differ from the reference positions by the displacement, far less than
a grid spacing in the benchmarks that use this).
"""

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import dijkstra
from scipy.spatial import cKDTree

from bbpd import readers

DEFAULT_THRESHOLD = 0.3   # the compute's default: the first row beside a grown crack, not
#                           the atoms ahead of a notch tip (damage table of its doc page)
TIE = 1e-9                # path lengths within TIE * link of the largest are a tie


def crack_graph(x, y, damage, start, link, threshold=DEFAULT_THRESHOLD, direction=(1.0, 0.0)):
    """(nodes N x 2 ordered by y then x, S, the linked node pairs, each node's path length from
    S: inf where it is not connected): the graph of the module docstring"""
    if not link > 0.0:
        raise ValueError(f"link must be > 0, got {link!r}")
    if not 0.0 < threshold <= 1.0:
        raise ValueError(f"threshold must lie in (0, 1], got {threshold!r}")
    d = np.asarray(direction, dtype=float)
    norm = np.hypot(d[0], d[1])
    if norm == 0.0:
        raise ValueError("direction must be non-zero")
    s = np.asarray(start, dtype=float)
    p = np.column_stack((np.asarray(x, dtype=float), np.asarray(y, dtype=float)))
    p = p[(np.asarray(damage, dtype=float) >= threshold) & ((p - s) @ (d / norm) >= 0.0)]
    p = p[np.lexsort((p[:, 0], p[:, 1]))]
    n = len(p)
    pairs = cKDTree(p).query_pairs(link, output_type="ndarray") if n else np.zeros((0, 2), int)
    seed = np.flatnonzero(np.hypot(*(p - s).T) <= link)
    both = np.vstack([p, s])          # node n is S itself
    i = np.concatenate([pairs[:, 0], pairs[:, 1], np.full(len(seed), n)])
    j = np.concatenate([pairs[:, 1], pairs[:, 0], seed])
    w = np.hypot(*(both[i] - both[j]).T)
    length = dijkstra(coo_matrix((w, (i, j)), shape=(n + 1, n + 1)).tocsr(), indices=n)[:n]
    return p, s, pairs, length


def crack_tip(x, y, damage, start, link, threshold=DEFAULT_THRESHOLD, direction=(1.0, 0.0)):
    """(tip x, tip y, extension) of one damage field (see the module docstring)."""
    p, s, _, length = crack_graph(x, y, damage, start, link, threshold, direction)
    reached = np.isfinite(length)
    if not reached.any():
        return float(s[0]), float(s[1]), 0.0
    tied = np.flatnonzero(reached & (length >= length[reached].max() - TIE * link))
    k = min(tied, key=lambda q: (p[q, 1], p[q, 0]))
    return float(p[k, 0]), float(p[k, 1]), float(length[k])


def tip_history(dump_path, dt, start, link, threshold=DEFAULT_THRESHOLD, direction=(1.0, 0.0)):
    """Tip of every snapshot of a dump with columns x y c_damage -> (t, x, y, extension)."""
    rows = []
    for step, cols in readers.dump_snapshots(dump_path):
        rows.append((step * dt,) + crack_tip(cols["x"], cols["y"], cols["c_damage"], start,
                                             link, threshold, direction))
    t, x, y, ext = np.array(rows).T
    return t, x, y, ext

# SPDX-License-Identifier: GPL-2.0-or-later
"""Every tip of a branched crack from a damage field, in Python: the definition of
`compute bbpd/crack/tip ... branches yes` (doc/compute_bbpd_crack_tip.rst), written again with
SciPy as an independent check of the compute and for runs without it.

The crack graph is that of bbpd.crack_tip (nodes: damage >= threshold at or ahead of the start
line; edges: at most `link` apart; path length l from S by Dijkstra).  The tips are the peaks
of l counted by prominence: nodes are taken from the largest l down (the longest tip first,
then by l, ties in the order of reference positions, y then x); where two sets of taken nodes
meet at node v, the one with the lower peak ends; its peak is a tip if it stands at least
`min_length` above l(v), v being its split point.  Sets that meet only at S end there (split
point S, l = 0).
"""

import functools

import numpy as np
from bbpd.crack_tip import DEFAULT_THRESHOLD, TIE, crack_graph

BRANCH_DEFAULT = 2.0      # the compute's default min_length, in units of the link


def branch_tips(x, y, damage, start, link, min_length=None, threshold=DEFAULT_THRESHOLD,
                direction=(1.0, 0.0)):
    """The tips of one damage field, longest first: a list of dicts with x, y, extension
    (path length), split_x, split_y, split_length; [] if no node is connected to S."""
    min_length = BRANCH_DEFAULT * link if min_length is None else min_length
    p, s, pairs, length = crack_graph(x, y, damage, start, link, threshold, direction)
    n = len(p)
    reached = np.flatnonzero(np.isfinite(length))
    if len(reached) == 0:
        return []
    tie = TIE * link
    top = int(reached[length[reached] >= length[reached].max() - tie].min())

    def better(a, b):
        if a == top or b == top:
            return a == top and b != top
        if abs(length[a] - length[b]) <= tie:
            return a < b
        return length[a] > length[b]

    neighbours = [[] for _ in range(n)]
    for a, b in pairs:
        neighbours[a].append(b)
        neighbours[b].append(a)
    order = sorted(reached.tolist(), key=lambda k: (k != top, -length[k], k))
    parent, peak = {}, {}

    def root(k):
        while parent[k] != k:
            parent[k] = parent[parent[k]]
            k = parent[k]
        return k

    ends = []
    for v in order:
        parent[v] = peak[v] = v
        for nb in neighbours[v]:
            if nb not in parent:
                continue
            a, b = root(v), root(nb)
            if a == b:
                continue
            elder, younger = (a, b) if better(peak[a], peak[b]) else (b, a)
            if length[peak[younger]] - length[v] >= min_length:
                ends.append((peak[younger], v))
            parent[younger] = elder
    roots = sorted({root(v) for v in order},
                   key=functools.cmp_to_key(lambda a, b: -1 if better(peak[a], peak[b]) else 1))
    ends += [(peak[r], None) for r in roots[1:] if length[peak[r]] >= min_length]
    ends.sort(key=functools.cmp_to_key(lambda a, b: -1 if better(a[0], b[0]) else 1))

    def tip(k, at):
        sx, sy = (s if at is None else p[at])
        return {"x": float(p[k, 0]), "y": float(p[k, 1]), "extension": float(length[k]),
                "split_x": float(sx), "split_y": float(sy),
                "split_length": 0.0 if at is None else float(length[at])}
    return [tip(top, None)] + [tip(k, at) for k, at in ends]

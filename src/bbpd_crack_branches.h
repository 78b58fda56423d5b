// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: every tip of a branched crack, for compute bbpd/crack/tip with
   `branches yes`, with no LAMMPS dependency (unit-tested in
   tests/unit/test_crack_branches.cpp).

   The tips are the peaks of the path length l over the crack graph of
   bbpd_crack_tip.h, counted by their prominence (0-dimensional persistence of
   the sets {l >= h}): the nodes are taken from the largest l down, each joins
   the sets of the nodes it is linked to, and where two sets meet, at node v,
   the one with the lower peak ends there; its peak is a tip if it stands at
   least `min_length` above l(v), and v is its split point. Sets that meet only
   at S end there (split point S, l = 0). Two face rows of one crack are linked
   across it at every level, so they are one set; two branches become two sets
   above the level where they lie more than a link apart. A side bump shorter
   than `min_length` is no tip.

   The first tip is always find_tip's; the others follow by decreasing path
   length (ties as in find_tip: within TIE_FRACTION * link, node order). Every
   step is sequential in node order, so the same nodes give the same bits.

   BranchTracker follows the tips from one call to the next: a tip grows from
   the previous tip nearest to its shortest path; of several tips grown from
   one, the nearest continues it and each other one is a split, recorded with
   the time of the call and its split point. Each tip's speed is that of its
   path length over the window, the history of a split branch starting from
   its parent's.
------------------------------------------------------------------------- */

#ifndef BBPD_CRACK_BRANCHES_H
#define BBPD_CRACK_BRANCHES_H

#include "bbpd_crack_tip.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace BBPD::CrackTip {

// a tip of the crack and where its branch leaves a longer one
struct Branch {
  Result tip;                       // as find_tip reports one
  std::size_t index = 0;            // node of the tip in the graph
  double split[2] = {0.0, 0.0};     // split point (S for the first tip and branches from S)
  double split_length = 0.0;        // its path length (0 at S)
};

/* every tip of the searched graph g standing at least min_length above its split point: the
   tip of find_tip first, then by decreasing path length; none if no node is reached */
inline std::vector<Branch> find_branches(const Graph &g, const Params &p, double min_length)
{
  const std::size_t n = g.node.size();
  std::vector<Branch> out;
  const std::size_t top = tip_index(g, p);
  if (top == n) return out;
  const double tie = TIE_FRACTION * p.link;
  // the higher peak (find_tip's tip above all; ties within `tie` to the first in node order)
  auto better = [&](std::size_t a, std::size_t b) {
    if (a == top || b == top) return a == top && b != top;
    if (std::abs(g.len[a] - g.len[b]) <= tie) return a < b;
    return g.len[a] > g.len[b];
  };
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < n; i++)
    if (g.done[i]) order.push_back(i);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (a == top || b == top) return a == top && b != top;
    if (g.len[a] != g.len[b]) return g.len[a] > g.len[b];
    return a < b;
  });

  // union-find over the nodes taken so far (parent n: not yet taken); peak: a set's highest
  std::vector<std::size_t> parent(n, n), peak(n, n);
  auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  struct End {
    std::size_t peak, at;    // at == n: S
  };
  std::vector<End> ends;
  for (const std::size_t v : order) {
    parent[v] = peak[v] = v;
    for (std::size_t k = g.row[v]; k < g.row[v + 1]; k++) {
      const std::size_t j = g.col[k];
      if (parent[j] == n) continue;
      const std::size_t a = root(v), b = root(j);
      if (a == b) continue;
      const bool a_elder = better(peak[a], peak[b]);
      const std::size_t elder = a_elder ? a : b, younger = a_elder ? b : a;
      if (g.len[peak[younger]] - g.len[v] >= min_length) ends.push_back({peak[younger], v});
      parent[younger] = elder;
    }
  }
  // sets that never met meet at S
  std::vector<std::size_t> roots;
  for (const std::size_t v : order)
    if (root(v) == v) roots.push_back(v);
  std::sort(roots.begin(), roots.end(),
            [&](std::size_t a, std::size_t b) { return better(peak[a], peak[b]); });
  for (std::size_t k = 1; k < roots.size(); k++)
    if (g.len[peak[roots[k]]] >= min_length) ends.push_back({peak[roots[k]], n});

  std::sort(ends.begin(), ends.end(), [&](const End &a, const End &b) { return better(a.peak, b.peak); });
  auto branch = [&](std::size_t tip, std::size_t at) {
    Branch b;
    b.tip = tip_at(g, tip, p);
    b.index = tip;
    b.split[0] = at == n ? p.start[0] : g.node[at].x;
    b.split[1] = at == n ? p.start[1] : g.node[at].y;
    b.split_length = at == n ? 0.0 : g.len[at];
    return b;
  };
  out.push_back(branch(top, n));
  for (const End &e : ends) out.push_back(branch(e.peak, e.at));
  return out;
}

/* distance from (x, y) to the nearest node on the shortest path of node i */
inline double distance_to_path(const Graph &g, std::size_t i, double x, double y)
{
  double best = HUGE_VAL;
  for (std::size_t k = i; k != g.node.size(); k = g.pred[k])
    best = std::min(best, std::hypot(g.node[k].x - x, g.node[k].y - y));
  return best;
}

struct Split {
  double x = 0.0, y = 0.0;    // split point
  double time = -1.0;         // of the call that first saw the branch (-1: none)
  double length = 0.0;        // path length of the split point
};

/* the tips of successive calls, matched; one track per tip of the last call, in its order */
class BranchTracker {
 public:
  struct Track {
    History history;
    double x, y;    // the tip
    Split split;    // where this branch left its parent (time -1: it did not)
  };

  explicit BranchTracker(double window) : window_(window) {}
  void clear()
  {
    tracks_.clear();
    before_.clear();
    splits_.clear();
    splits_before_ = 0;
    time_ = -HUGE_VAL;
  }

  void record(double t, const Graph &g, const std::vector<Branch> &tips)
  {
    if (t < time_) clear();
    if (t == time_) {    // the same time again: match against the call before
      tracks_ = before_;
      splits_.resize(splits_before_);
    }
    before_ = tracks_;
    splits_before_ = splits_.size();
    time_ = t;

    // each tip's parent: the previous tip nearest to its path (ties: the earlier track)
    const std::size_t none = before_.size();
    std::vector<std::size_t> parent(tips.size(), none);
    std::vector<double> dist(tips.size(), HUGE_VAL);
    for (std::size_t i = 0; i < tips.size(); i++)
      for (std::size_t o = 0; o < before_.size(); o++) {
        const double d = distance_to_path(g, tips[i].index, before_[o].x, before_[o].y);
        if (d < dist[i]) {
          dist[i] = d;
          parent[i] = o;
        }
      }
    // of a parent's children, the one nearest to it continues it (ties: the earlier tip)
    std::vector<std::size_t> heir(before_.size(), tips.size());
    for (std::size_t i = 0; i < tips.size(); i++) {
      const std::size_t o = parent[i];
      if (o != none && (heir[o] == tips.size() || dist[i] < dist[heir[o]])) heir[o] = i;
    }
    tracks_.clear();
    for (std::size_t i = 0; i < tips.size(); i++) {
      const std::size_t o = parent[i];
      Track tr = o == none ? Track{History(window_), 0.0, 0.0, Split()} : before_[o];
      if (o != none && heir[o] != i) {
        tr.split = {tips[i].split[0], tips[i].split[1], t, tips[i].split_length};
        splits_.push_back(tr.split);
      }
      tr.x = tips[i].tip.x;
      tr.y = tips[i].tip.y;
      tr.history.record(t, tips[i].tip.extension);
      tracks_.push_back(tr);
    }
  }

  const std::vector<Track> &tracks() const { return tracks_; }
  const std::vector<Split> &splits() const { return splits_; }    // every split so far

 private:
  double window_;
  double time_ = -HUGE_VAL;
  std::vector<Track> tracks_, before_;
  std::vector<Split> splits_;
  std::size_t splits_before_ = 0;
};

}    // namespace BBPD::CrackTip

#endif

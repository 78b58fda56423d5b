// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the crack-tip tracker of compute bbpd/crack/tip, with no LAMMPS
   dependency (unit-tested in tests/unit/test_crack_tip.cpp).

   The crack graph: its nodes are the damaged atoms, damage >= threshold, at or
   ahead of the start line (the line through the start point S = (X, Y) normal
   to the direction d the crack runs in: (x0 - S).d >= 0), so that the notch
   behind S is not part of it; its edges join nodes whose reference positions
   x0 lie at most `link` apart, weighted by that distance. Nodes within `link`
   of S start with the distance |x0 - S|. The path length of a node is its
   shortest distance from S through the graph (Dijkstra); the tip is the
   reached node of the largest path length, ties (within TIE_FRACTION * link)
   going to the first node in the order of reference positions: smallest y,
   then smallest x (then smallest tag, for coincident atoms). The extension is
   the tip's path length; the direction is that of the chord to the tip from
   the first node on its path at least `span` behind it, or from S if the path
   is shorter.

   Nodes are taken in the order of their reference positions and every step is
   sequential, so equal sets of atoms give the same bits whatever order they
   were gathered in and however the atoms are numbered (create_atoms numbers
   them differently on different numbers of ranks).
------------------------------------------------------------------------- */

#ifndef BBPD_CRACK_TIP_H
#define BBPD_CRACK_TIP_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace BBPD::CrackTip {

constexpr double PI = 3.14159265358979323846;
// path lengths closer than this fraction of the link distance are a tie (round-off of equal
// paths summed in a different order)
constexpr double TIE_FRACTION = 1.0e-9;

// a damaged atom: its tag (identity), reference position and damage
struct Node {
  std::int64_t tag;
  double x, y;
  double damage;
};

struct Params {
  double start[2];     // S = (X, Y), the notch tip
  double dir[2];       // unit direction the crack runs in at S
  double threshold;    // smallest damage of a node
  double link;         // longest edge
  double span;         // chord length behind the tip for the direction
};

struct Result {
  bool found = false;             // some node is connected to S
  std::size_t nodes = 0;          // nodes reached from S
  std::int64_t tag = -1;          // the tip atom (-1: none)
  double x = 0.0, y = 0.0;        // tip position (S if none)
  double extension = 0.0;         // path length of the tip
  double back[2] = {0.0, 0.0};    // start of the direction chord
  double direction = 0.0;         // degrees, atan2 of the chord (or of d if none)
};

/* may the atom be a node? (used to select what is gathered, and again by the search) */
inline bool candidate(const Params &p, double x, double y, double damage)
{
  return damage >= p.threshold && (x - p.start[0]) * p.dir[0] + (y - p.start[1]) * p.dir[1] >= 0.0;
}

inline double degrees(double dx, double dy)
{
  return std::atan2(dy, dx) * 180.0 / PI;
}

/* the order nodes are taken in: reference position, y first (then the tag, for coincident
   atoms) */
inline bool before(const Node &a, const Node &b)
{
  if (a.y != b.y) return a.y < b.y;
  if (a.x != b.x) return a.x < b.x;
  return a.tag < b.tag;
}

/* the crack graph searched from S: the candidates in node order, their edges (compressed
   rows), path lengths and shortest-path predecessors */
struct Graph {
  std::vector<Node> node;
  std::vector<std::size_t> row, col;    // edges of node i: col[row[i] .. row[i + 1])
  std::vector<double> length;           // edge lengths
  std::vector<double> len;              // path length from S (HUGE_VAL: not reached)
  std::vector<std::size_t> pred;        // predecessor on the shortest path (size: from S)
  std::vector<char> done;               // reached from S
  std::size_t reached = 0;
};

/* the crack graph of `all` (any order; atoms that are not candidates are skipped) */
inline Graph search(std::vector<Node> all, const Params &p)
{
  Graph g;
  std::vector<Node> &node = g.node;
  std::sort(all.begin(), all.end(), before);
  for (const Node &a : all)
    if (candidate(p, a.x, a.y, a.damage)) node.push_back(a);
  const std::size_t n = node.size();
  if (n == 0) return g;

  // cells of side `link`: the neighbours of a node lie in its own and the 8 adjacent cells
  using Cell = std::pair<std::int64_t, std::int64_t>;
  auto cell_of = [&](const Node &a) {
    return Cell(static_cast<std::int64_t>(std::floor((a.x - p.start[0]) / p.link)),
                static_cast<std::int64_t>(std::floor((a.y - p.start[1]) / p.link)));
  };
  std::vector<std::pair<Cell, std::size_t>> binned(n);
  for (std::size_t i = 0; i < n; i++) binned[i] = {cell_of(node[i]), i};
  std::sort(binned.begin(), binned.end());

  // edges as compressed rows with their lengths; a row lists the cells in a fixed order and
  // each cell in node order, so the same nodes give the same rows
  std::vector<std::size_t> &row = g.row, &col = g.col;
  std::vector<double> &length = g.length;
  row.assign(n + 1, 0);
  const double wide = p.link * p.link * (1.0 + 1.0e-12);    // beyond it no d <= link
  for (std::size_t i = 0; i < n; i++) {
    const Cell c = cell_of(node[i]);
    for (std::int64_t cx = c.first - 1; cx <= c.first + 1; cx++)
      for (std::int64_t cy = c.second - 1; cy <= c.second + 1; cy++) {
        auto it = std::lower_bound(binned.begin(), binned.end(),
                                   std::make_pair(Cell(cx, cy), std::size_t(0)));
        for (; it != binned.end() && it->first == Cell(cx, cy); ++it) {
          const std::size_t j = it->second;
          const double dx = node[j].x - node[i].x, dy = node[j].y - node[i].y;
          if (j == i || dx * dx + dy * dy > wide) continue;    // the square root only near
          const double d = std::sqrt(dx * dx + dy * dy);
          if (d <= p.link) {
            col.push_back(j);
            length.push_back(d);
          }
        }
      }
    row[i + 1] = col.size();
  }

  // Dijkstra from S; equal keys leave the queue in node order
  const double inf = HUGE_VAL;
  std::vector<double> &len = g.len;
  std::vector<std::size_t> &pred = g.pred;
  len.assign(n, inf);
  pred.assign(n, n);    // n: reached from S directly
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (std::size_t i = 0; i < n; i++) {
    const double dx = node[i].x - p.start[0], dy = node[i].y - p.start[1];
    const double d = std::sqrt(dx * dx + dy * dy);
    if (d <= p.link) {
      len[i] = d;
      queue.push({d, i});
    }
  }
  std::vector<char> &done = g.done;
  done.assign(n, 0);
  while (!queue.empty()) {
    const auto [d, i] = queue.top();
    queue.pop();
    if (done[i]) continue;
    done[i] = 1;
    g.reached++;
    for (std::size_t k = row[i]; k < row[i + 1]; k++) {
      const std::size_t j = col[k];
      const double dj = d + length[k];
      if (dj < len[j]) {
        len[j] = dj;
        pred[j] = i;
        queue.push({dj, j});
      }
    }
  }
  return g;
}

/* nothing found: the tip is S, the direction d */
inline Result no_tip(const Params &p, std::size_t nodes = 0)
{
  Result r;
  r.nodes = nodes;
  r.x = p.start[0];
  r.y = p.start[1];
  r.back[0] = p.start[0];
  r.back[1] = p.start[1];
  r.direction = degrees(p.dir[0], p.dir[1]);
  return r;
}

/* the result for reached node `tip` of the graph: its position, path length and the chord
   from the first node on its path at least `span` behind it */
inline Result tip_at(const Graph &g, std::size_t tip, const Params &p)
{
  const std::size_t n = g.node.size();
  Result r = no_tip(p, g.reached);
  r.found = true;
  r.tag = g.node[tip].tag;
  r.x = g.node[tip].x;
  r.y = g.node[tip].y;
  r.extension = g.len[tip];
  std::size_t k = tip;
  while (k != n && g.len[tip] - g.len[k] < p.span) k = g.pred[k];
  if (k != n) {
    r.back[0] = g.node[k].x;
    r.back[1] = g.node[k].y;
  }
  if (r.x != r.back[0] || r.y != r.back[1]) r.direction = degrees(r.x - r.back[0], r.y - r.back[1]);
  return r;
}

/* the node index of the tip of a searched graph (the size of the graph if none is reached) */
inline std::size_t tip_index(const Graph &g, const Params &p)
{
  const std::size_t n = g.node.size();
  if (g.reached == 0) return n;
  double longest = -HUGE_VAL;
  for (std::size_t i = 0; i < n; i++)
    if (g.done[i]) longest = std::max(longest, g.len[i]);
  std::size_t tip = n;
  for (std::size_t i = 0; i < n && tip == n; i++)    // the first in node order within the tie
    if (g.done[i] && g.len[i] >= longest - TIE_FRACTION * p.link) tip = i;
  return tip;
}

/* the tip of the crack graph of `all` (any order; atoms that are not candidates are skipped) */
inline Result find_tip(std::vector<Node> all, const Params &p)
{
  const Graph g = search(std::move(all), p);
  const std::size_t tip = tip_index(g, p);
  return tip == g.node.size() ? no_tip(p, g.reached) : tip_at(g, tip, p);
}

/* (time, extension) of past evaluations, for the speed over a time window */
class History {
 public:
  explicit History(double window) : window_(window) {}
  void clear() { rec_.clear(); }

  // a record at the time of the newest one replaces it; an earlier time starts afresh
  void record(double t, double extension)
  {
    if (!rec_.empty() && t < rec_.back().first) rec_.clear();
    if (!rec_.empty() && t == rec_.back().first) rec_.pop_back();
    rec_.emplace_back(t, extension);
    // keep the newest earlier record at least a window old (else the oldest) and everything
    // after it: that record is then the first
    while (rec_.size() > 2 && rec_[1].first <= t - window_) rec_.pop_front();
  }

  // (l(t) - l(t0)) / (t - t0), t0 the newest earlier record at least a window before t, else
  // the oldest; 0 with fewer than two records
  double speed() const
  {
    if (rec_.size() < 2) return 0.0;
    return (rec_.back().second - rec_.front().second) / (rec_.back().first - rec_.front().first);
  }
  std::size_t size() const { return rec_.size(); }

 private:
  double window_;
  std::deque<std::pair<double, double>> rec_;
};

}    // namespace BBPD::CrackTip

#endif

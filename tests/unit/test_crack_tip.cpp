// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_crack_tip.h on synthetic damage fields: a straight crack beside a notch
   (the notch behind the start line and undamaged atoms are left out), a kinked
   path (extension = polyline length, direction of the newest leg), a branch
   (the longer one wins, whichever it is), gaps wider than the link (the far part
   is ignored), ties (smallest reference y, then x, whatever the input order and
   the atom numbering), random fields against a brute-force shortest path, and the
   speed history. */

#include "bbpd_crack_tip.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace BBPD::CrackTip;

namespace {

constexpr double DAMAGED = 0.45;    // a node's damage in the synthetic fields
constexpr double THRESHOLD = 0.3;

Params params(double link, double span = 2.0)
{
  return Params{{0.0, 0.0}, {1.0, 0.0}, THRESHOLD, link, span};
}

// nodes along a polyline from `from`, `count` steps of length `step` at angle `deg`
void add_leg(std::vector<Node> &nodes, double from[2], int count, double step, double deg,
             std::int64_t &tag)
{
  const double c = std::cos(deg * PI / 180.0), s = std::sin(deg * PI / 180.0);
  for (int k = 0; k < count; k++) {
    from[0] += step * c;
    from[1] += step * s;
    nodes.push_back({tag++, from[0], from[1], DAMAGED});
  }
}

// a crack between two rows of a unit grid, atoms at (i + 1/2, +-1/2), i = 0..n-1, upper row
// first; a damaged notch of the same shape behind the start point (x < 0) and undamaged atoms
// ahead of the crack
std::vector<Node> straight_crack(int n)
{
  std::vector<Node> nodes;
  std::int64_t tag = 1;
  for (double y : {0.5, -0.5})
    for (int i = 0; i < n; i++) nodes.push_back({tag++, i + 0.5, y, DAMAGED});
  for (double y : {0.5, -0.5})
    for (int i = 1; i <= 40; i++) nodes.push_back({tag++, -i + 0.5, y, DAMAGED});
  for (double y : {0.5, -0.5})
    for (int i = n; i < n + 10; i++) nodes.push_back({tag++, i + 0.5, y, 0.9 * THRESHOLD});
  return nodes;
}

}    // namespace

TEST(CrackTip, NoNodesGivesTheStartPointAndTheGivenDirection)
{
  Params p = params(3.0);
  p.start[0] = 2.0;
  p.start[1] = -1.0;
  p.dir[0] = 0.0;
  p.dir[1] = -1.0;
  for (const auto &nodes : {std::vector<Node>{}, std::vector<Node>{{7, 2.0, -5.0, DAMAGED}}}) {
    const Result r = find_tip(nodes, p);    // the second node lies 4 > link away from S
    EXPECT_FALSE(r.found);
    EXPECT_EQ(r.nodes, 0u);
    EXPECT_EQ(r.x, 2.0);
    EXPECT_EQ(r.y, -1.0);
    EXPECT_EQ(r.extension, 0.0);
    EXPECT_EQ(r.direction, -90.0);
  }
}

TEST(CrackTip, StraightCrackIgnoresTheNotchAndUndamagedAtoms)
{
  constexpr int N = 20;
  constexpr double LINK = 3.015;    // a horizon of 3 grid spacings
  const Result r = find_tip(straight_crack(N), params(LINK, 5.0));
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.nodes, 2u * N);
  // both rows end at x = N - 1/2: a tie, which goes to the lower row (smaller y)
  EXPECT_EQ(r.tag, 2 * N);
  EXPECT_EQ(r.x, N - 0.5);
  EXPECT_EQ(r.y, -0.5);
  // shortest path: from S straight to the farthest lower atom within the link, (2.5, -0.5),
  // then along the row
  EXPECT_NEAR(r.extension, std::sqrt(2.5 * 2.5 + 0.25) + (N - 3), 1e-12);
  EXPECT_EQ(r.direction, 0.0);
}

TEST(CrackTip, NodesBelowTheThresholdOrBehindTheStartLineAreNotNodes)
{
  const Params p = params(1.0);
  EXPECT_TRUE(candidate(p, 0.0, 5.0, THRESHOLD));
  EXPECT_FALSE(candidate(p, 0.0, 5.0, std::nextafter(THRESHOLD, 0.0)));
  EXPECT_FALSE(candidate(p, -1e-12, 0.0, 1.0));
}

TEST(CrackTip, AnEdgeOfExactlyTheLinkCounts)
{
  std::vector<Node> nodes;
  for (int k = 1; k <= 6; k++) nodes.push_back({k, 0.25 * k, 0.0, DAMAGED});
  const Result r = find_tip(nodes, params(0.25));    // 0.25 k: exact in binary
  EXPECT_EQ(r.nodes, 6u);
  EXPECT_EQ(r.extension, 1.5);
  EXPECT_EQ(find_tip(nodes, params(std::nextafter(0.25, 0.0))).nodes, 0u);
}

TEST(CrackTip, KinkedPathLengthAndNewestDirection)
{
  // legs of 10 steps, the step a little shorter than the link: no edge skips a node, and none
  // cuts the 60 degree corner (its neighbours are 2 sin 60 = 1.73 steps apart)
  constexpr double STEP = 1.0, LINK = 1.01, KINK = 60.0;
  std::vector<Node> nodes;
  std::int64_t tag = 100;
  double at[2] = {0.0, 0.0};
  add_leg(nodes, at, 10, STEP, 0.0, tag);
  add_leg(nodes, at, 10, STEP, KINK, tag);
  const Result r = find_tip(nodes, params(LINK, 4.0));
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.tag, 119);
  EXPECT_NEAR(r.x, 10.0 + 10.0 * std::cos(KINK * PI / 180.0), 1e-12);
  EXPECT_NEAR(r.y, 10.0 * std::sin(KINK * PI / 180.0), 1e-12);
  EXPECT_NEAR(r.extension, 20.0 * STEP, 1e-12);
  EXPECT_NEAR(r.direction, KINK, 1e-9);

  // a span across the kink: the chord from the first node 11.5 or more back, (8, 0)
  const Result across = find_tip(nodes, params(LINK, 11.5));
  EXPECT_EQ(across.back[0], nodes[7].x);
  EXPECT_EQ(across.back[1], nodes[7].y);
  EXPECT_NEAR(across.direction, degrees(r.x - 8.0, r.y), 1e-12);
  // a span longer than the path: the chord from the start point
  const Result whole = find_tip(nodes, params(LINK, 50.0));
  EXPECT_EQ(whole.back[0], 0.0);
  EXPECT_EQ(whole.back[1], 0.0);
  EXPECT_NEAR(whole.direction, degrees(r.x, r.y), 1e-12);
}

TEST(CrackTip, TheLongerBranchWins)
{
  constexpr double LINK = 1.01;
  for (int longer : {0, 1}) {
    std::vector<Node> nodes;
    std::int64_t tag = 1;
    double at[2] = {0.0, 0.0};
    add_leg(nodes, at, 5, 1.0, 0.0, tag);
    const double fork[2] = {at[0], at[1]};
    double up[2] = {fork[0], fork[1]}, down[2] = {fork[0], fork[1]};
    add_leg(nodes, up, longer == 0 ? 8 : 6, 1.0, 45.0, tag);
    add_leg(nodes, down, longer == 1 ? 8 : 6, 1.0, -30.0, tag);
    const Result r = find_tip(nodes, params(LINK));
    ASSERT_TRUE(r.found);
    EXPECT_NEAR(r.extension, 13.0, 1e-12);
    EXPECT_EQ(r.x, longer == 0 ? up[0] : down[0]);
    EXPECT_EQ(r.y, longer == 0 ? up[1] : down[1]);
    EXPECT_NEAR(r.direction, longer == 0 ? 45.0 : -30.0, 1e-9);
    EXPECT_EQ(r.nodes, 19u);
  }
}

TEST(CrackTip, PartsBeyondAGapWiderThanTheLinkAreIgnored)
{
  constexpr double LINK = 1.5;
  std::vector<Node> nodes;
  std::int64_t tag = 1;
  double at[2] = {0.0, 0.0};
  add_leg(nodes, at, 6, 1.0, 0.0, tag);    // ends at x = 6
  const double end = at[0];
  at[0] += 1.6 - 1.0;    // next node 1.6 > link after the last
  add_leg(nodes, at, 30, 1.0, 0.0, tag);
  for (int k = 0; k < 50; k++) nodes.push_back({tag++, 3.0 + k, 10.0, 1.0});    // far band
  Result r = find_tip(nodes, params(LINK));
  ASSERT_TRUE(r.found);
  EXPECT_EQ(r.x, end);
  EXPECT_NEAR(r.extension, end, 1e-12);
  EXPECT_EQ(r.nodes, 6u);

  // the same gap within the link joins both parts
  r = find_tip(nodes, params(1.7));
  EXPECT_EQ(r.x, at[0]);
  EXPECT_EQ(r.nodes, 36u);
}

TEST(CrackTip, TiesGoToTheSmallestYThenXWhateverTheOrderAndNumbering)
{
  // two mirror branches of equal length: the lower one wins, whichever has the smaller tags
  std::vector<Node> nodes;
  std::int64_t tag = 50;
  double up[2] = {0.0, 0.0}, down[2] = {0.0, 0.0};
  add_leg(nodes, up, 7, 1.0, 20.0, tag);       // tags 50..56
  add_leg(nodes, down, 7, 1.0, -20.0, tag);    // tags 57..63
  Params p = params(1.01);
  EXPECT_EQ(find_tip(nodes, p).tag, 63);
  std::vector<Node> swapped = nodes;
  for (auto &a : swapped) a.tag = a.y > 0.0 ? a.tag + 100 : a.tag - 100;
  EXPECT_EQ(find_tip(swapped, p).y, down[1]);
  EXPECT_EQ(find_tip(swapped, p).tag, -37);

  // the same branches turned to run along +y: both ends at the same y, the smaller x wins
  for (auto &a : nodes) a = {a.tag, -a.y, a.x, a.damage};
  p.dir[0] = 0.0;
  p.dir[1] = 1.0;
  const Result r = find_tip(nodes, p);
  EXPECT_EQ(r.y, up[0]);
  EXPECT_EQ(r.x, -up[1]);
  EXPECT_EQ(r.tag, 56);

  // any input order and any numbering: the same bits
  std::mt19937 rng(12345);
  const Result ref = find_tip(straight_crack(30), params(3.015, 4.0));
  for (int trial = 0; trial < 10; trial++) {
    std::vector<Node> shuffled = straight_crack(30);
    std::vector<std::int64_t> tags(shuffled.size());
    for (std::size_t k = 0; k < tags.size(); k++) tags[k] = 1000 + k;
    std::shuffle(tags.begin(), tags.end(), rng);
    for (std::size_t k = 0; k < tags.size(); k++) shuffled[k].tag = tags[k];
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const Result a = find_tip(shuffled, params(3.015, 4.0));
    EXPECT_EQ(a.x, ref.x);
    EXPECT_EQ(a.y, ref.y);
    EXPECT_EQ(a.extension, ref.extension);
    EXPECT_EQ(a.direction, ref.direction);
    EXPECT_EQ(a.nodes, ref.nodes);
  }
}

TEST(CrackTip, RandomFieldsAgreeWithBruteForceShortestPaths)
{
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> pos(0.0, 12.0), dmg(0.0, 1.0);
  constexpr double LINK = 1.3;
  for (int trial = 0; trial < 20; trial++) {
    std::vector<Node> nodes;
    for (int k = 0; k < 150; k++) nodes.push_back({k + 1, pos(rng), pos(rng) - 6.0, dmg(rng)});
    const Params p = params(LINK);
    const Result r = find_tip(nodes, p);

    // Bellman-Ford on the full graph of candidates, no cells, no queue
    std::vector<Node> c;
    for (const auto &a : nodes)
      if (candidate(p, a.x, a.y, a.damage)) c.push_back(a);
    std::vector<double> len(c.size(), HUGE_VAL);
    for (std::size_t i = 0; i < c.size(); i++)
      if (std::hypot(c[i].x, c[i].y) <= LINK) len[i] = std::hypot(c[i].x, c[i].y);
    for (bool changed = true; changed;) {
      changed = false;
      for (std::size_t i = 0; i < c.size(); i++)
        for (std::size_t j = 0; j < c.size(); j++) {
          const double d = std::hypot(c[i].x - c[j].x, c[i].y - c[j].y);
          if (d <= LINK && len[i] + d < len[j]) {
            len[j] = len[i] + d;
            changed = true;
          }
        }
    }
    double longest = 0.0;
    std::size_t reached = 0;
    for (double l : len)
      if (l < HUGE_VAL) {
        longest = std::max(longest, l);
        reached++;
      }
    EXPECT_EQ(r.nodes, reached);
    EXPECT_NEAR(r.extension, longest, 1e-12);
    if (reached > 0) {
      ASSERT_TRUE(r.found);
      EXPECT_GE(r.extension, std::hypot(r.x, r.y) - 1e-12);    // never shorter than the chord
    }
  }
}

TEST(CrackTipHistory, SpeedOverTheWindow)
{
  History h(2.0);
  EXPECT_EQ(h.speed(), 0.0);
  h.record(0.0, 1.0);
  EXPECT_EQ(h.speed(), 0.0);
  // extension 1 + t^2: the speed over [t - 2, t] is (t^2 - (t - 2)^2) / 2 = 2 t - 2
  for (int t = 1; t <= 10; t++) {
    h.record(t, 1.0 + t * t);
    const double t0 = std::max(0, t - 2);
    EXPECT_DOUBLE_EQ(h.speed(), (t * t - t0 * t0) / (t - t0)) << "t = " << t;
  }
  EXPECT_LE(h.size(), 3u);    // only what the window needs is kept

  // a record at the same time replaces the last one
  h.record(10.0, 101.0 + 4.0);
  EXPECT_DOUBLE_EQ(h.speed(), (105.0 - 65.0) / 2.0);
  // an earlier time (a reset of the clock) starts afresh
  h.record(3.0, 7.0);
  EXPECT_EQ(h.size(), 1u);
  EXPECT_EQ(h.speed(), 0.0);

  // window 0: the previous record
  History last(0.0);
  last.record(0.0, 0.0);
  last.record(0.5, 1.0);
  last.record(1.5, 4.0);
  EXPECT_DOUBLE_EQ(last.speed(), 3.0);
  EXPECT_EQ(last.size(), 2u);

  // irregular records: the newest one at least a window old
  History irregular(1.0);
  for (double t : {0.0, 0.3, 0.9, 1.2, 1.35}) irregular.record(t, 10.0 * t);
  EXPECT_DOUBLE_EQ(irregular.speed(), 10.0);    // from t0 = 0.3 (1.35 - 1 = 0.35)
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_crack_branches.h on synthetic damage bands of a unit grid: a straight crack two rows
   wide has one tip (find_tip's); a fork into two mirror legs has two, split where the legs
   separate; a side bump counts only if it stands min_length above the crack; the same bits
   whatever the input order and numbering; random fields keep find_tip's tip first; and the
   tracker follows a growing fork: one track, then two, one split, speeds over the window. */

#include "bbpd_crack_branches.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace BBPD::CrackTip;

namespace {

constexpr double DAMAGED = 0.45;
constexpr double THRESHOLD = 0.3;
constexpr double LINK = 3.015;            // a horizon of 3 grid spacings
constexpr double MIN_LENGTH = 2.0 * LINK;
constexpr double HALF_WIDTH = 1.0;        // the band: grid points within 1 of its centre line

Params params()
{
  return Params{{0.0, 0.0}, {1.0, 0.0}, THRESHOLD, LINK, 2.0 * LINK};
}

struct Segment {
  double x0, y0, x1, y1;
};

double distance(const Segment &s, double x, double y)
{
  const double dx = s.x1 - s.x0, dy = s.y1 - s.y0;
  const double t = std::clamp(((x - s.x0) * dx + (y - s.y0) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(x - s.x0 - t * dx, y - s.y0 - t * dy);
}

// the points (i + 1/2, j + 1/2) of a unit grid within HALF_WIDTH of any segment
std::vector<Node> band(const std::vector<Segment> &segments)
{
  std::vector<Node> nodes;
  std::int64_t tag = 1;
  for (int j = -40; j < 40; j++)
    for (int i = -5; i < 80; i++) {
      const double x = i + 0.5, y = j + 0.5;
      for (const Segment &s : segments)
        if (distance(s, x, y) <= HALF_WIDTH) {
          nodes.push_back({tag++, x, y, DAMAGED});
          break;
        }
    }
  return nodes;
}

constexpr double FORK = 20.0, LEG = 25.0, HALF_ANGLE = 15.0;

std::vector<Segment> forked(double leg = LEG)
{
  const double c = std::cos(HALF_ANGLE * PI / 180.0), s = std::sin(HALF_ANGLE * PI / 180.0);
  return {{0.0, 0.0, FORK, 0.0},
          {FORK, 0.0, FORK + leg * c, leg * s},
          {FORK, 0.0, FORK + leg * c, -leg * s}};
}

std::vector<Branch> branches(const std::vector<Node> &nodes, double min_length = MIN_LENGTH)
{
  return find_branches(search(nodes, params()), params(), min_length);
}

}    // namespace

TEST(CrackBranches, NoNodeNoTip)
{
  EXPECT_TRUE(branches({}).empty());
  EXPECT_TRUE(branches({{1, 0.0, 10.0, DAMAGED}}).empty());    // not linked to S
}

TEST(CrackBranches, AStraightCrackTwoRowsWideHasOneTip)
{
  const std::vector<Node> nodes = band({{0.0, 0.0, 40.0, 0.0}});
  const std::vector<Branch> b = branches(nodes);
  ASSERT_EQ(b.size(), 1u);
  const Result r = find_tip(nodes, params());
  EXPECT_EQ(b[0].tip.tag, r.tag);
  EXPECT_EQ(b[0].tip.extension, r.extension);
  EXPECT_EQ(b[0].tip.direction, r.direction);
  EXPECT_EQ(b[0].split[0], 0.0);
  EXPECT_EQ(b[0].split_length, 0.0);
}

TEST(CrackBranches, AForkHasTwoMirrorTipsSplitWhereTheLegsSeparate)
{
  const std::vector<Node> nodes = band(forked());
  const std::vector<Branch> b = branches(nodes);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_EQ(b[0].tip.tag, find_tip(nodes, params()).tag);
  // the lower leg wins the tie (smallest y); the other is its mirror image on the grid
  EXPECT_LT(b[0].tip.y, 0.0);
  EXPECT_GT(b[1].tip.y, 0.0);
  EXPECT_NEAR(b[0].tip.x, b[1].tip.x, 1.0 + 1e-12);
  EXPECT_NEAR(b[0].tip.y, -b[1].tip.y, 1.0 + 1e-12);
  EXPECT_NEAR(b[0].tip.extension, b[1].tip.extension, 1.0);
  EXPECT_NEAR(b[0].tip.direction, -HALF_ANGLE, 5.0);
  EXPECT_NEAR(b[1].tip.direction, HALF_ANGLE, 5.0);
  // the split point: on the centre line, past the fork by about where the legs' bands are a
  // link apart ((link + 2 half-widths) / (2 sin 15) = 9.7 along a leg)
  EXPECT_GE(b[1].split[0], FORK);
  EXPECT_LE(b[1].split[0], FORK + 12.0);
  EXPECT_LE(std::abs(b[1].split[1]), 4.0);
  EXPECT_GE(b[1].tip.extension - b[1].split_length, MIN_LENGTH);
}

TEST(CrackBranches, ASideBumpCountsOnlyIfItStandsMinLengthAbove)
{
  for (double height : {3.0, 12.0}) {
    const std::vector<Node> nodes = band({{0.0, 0.0, 40.0, 0.0}, {15.0, 0.0, 15.0, height}});
    const std::vector<Branch> b = branches(nodes);
    EXPECT_EQ(b.size(), height < MIN_LENGTH ? 1u : 2u) << "height " << height;
    if (b.size() == 2) {
      EXPECT_NEAR(b[1].tip.x, 15.0, 1.0);
      EXPECT_NEAR(b[1].tip.y, height, 1.0);
      EXPECT_NEAR(b[1].split[0], 15.0, LINK);
    }
  }
  // min_length 0: every peak of the path length is a tip
  EXPECT_GT(branches(band(forked()), 0.0).size(), 2u);
}

TEST(CrackBranches, TheSameBitsWhateverTheOrderAndNumbering)
{
  const std::vector<Node> nodes = band(forked());
  const std::vector<Branch> ref = branches(nodes);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; trial++) {
    std::vector<Node> shuffled = nodes;
    std::vector<std::int64_t> tags(shuffled.size());
    for (std::size_t k = 0; k < tags.size(); k++) tags[k] = 5000 + k;
    std::shuffle(tags.begin(), tags.end(), rng);
    for (std::size_t k = 0; k < tags.size(); k++) shuffled[k].tag = tags[k];
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const std::vector<Branch> b = branches(shuffled);
    ASSERT_EQ(b.size(), ref.size());
    for (std::size_t k = 0; k < b.size(); k++) {
      EXPECT_EQ(b[k].tip.x, ref[k].tip.x);
      EXPECT_EQ(b[k].tip.y, ref[k].tip.y);
      EXPECT_EQ(b[k].tip.extension, ref[k].tip.extension);
      EXPECT_EQ(b[k].tip.direction, ref[k].tip.direction);
      EXPECT_EQ(b[k].split[0], ref[k].split[0]);
      EXPECT_EQ(b[k].split[1], ref[k].split[1]);
    }
  }
}

TEST(CrackBranches, RandomFieldsKeepFindTipFirstAndEveryTipProminent)
{
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> pos(0.0, 30.0), dmg(0.0, 1.0);
  for (int trial = 0; trial < 20; trial++) {
    std::vector<Node> nodes;
    for (int k = 0; k < 400; k++) nodes.push_back({k + 1, pos(rng), pos(rng) - 15.0, dmg(rng)});
    const Graph g = search(nodes, params());
    const std::vector<Branch> b = find_branches(g, params(), LINK);
    const Result r = find_tip(nodes, params());
    ASSERT_EQ(b.empty(), !r.found);
    if (b.empty()) continue;
    EXPECT_EQ(b[0].tip.tag, r.tag);
    EXPECT_EQ(b[0].tip.extension, r.extension);
    for (std::size_t k = 1; k < b.size(); k++) {
      EXPECT_GE(b[k].tip.extension - b[k].split_length, LINK);
      EXPECT_LE(b[k].tip.extension, b[k - 1].tip.extension + TIE_FRACTION * LINK);
    }
  }
}

TEST(CrackBranchTracker, AGrowingForkGivesOneSplitAndBothSpeeds)
{
  // the crack grows by 1 per unit time: straight to the fork, then both legs
  BranchTracker tracker(2.0);
  const Params p = params();
  std::size_t most = 0;
  for (int t = 5; t <= 45; t++) {
    const double grown = t;
    const std::vector<Segment> s =
        grown <= FORK ? std::vector<Segment>{{0.0, 0.0, grown, 0.0}} : forked(grown - FORK);
    const Graph g = search(band(s), p);
    const std::vector<Branch> b = find_branches(g, p, MIN_LENGTH);
    tracker.record(t, g, b);
    ASSERT_EQ(tracker.tracks().size(), b.size());
    most = std::max(most, b.size());
    if (t >= 10) {
      for (const auto &tr : tracker.tracks()) EXPECT_NEAR(tr.history.speed(), 1.0, 0.6) << t;
    }
  }
  EXPECT_EQ(most, 2u);
  ASSERT_EQ(tracker.splits().size(), 1u);
  const Split s = tracker.splits()[0];
  EXPECT_GT(s.time, FORK);
  EXPECT_LT(s.time, FORK + 25.0);
  EXPECT_GE(s.x, FORK);
  // the split is carried by the branch that left, not by the one that continued
  const auto &tr = tracker.tracks();
  EXPECT_EQ(tr[0].split.time, -1.0);
  EXPECT_EQ(tr[1].split.time, s.time);

  // the same time again replaces the last record; an earlier time starts afresh
  const Graph g = search(band(forked()), p);
  tracker.record(45.0, g, find_branches(g, p, MIN_LENGTH));
  EXPECT_EQ(tracker.splits().size(), 1u);
  tracker.record(1.0, g, find_branches(g, p, MIN_LENGTH));
  EXPECT_TRUE(tracker.splits().empty());
  EXPECT_EQ(tracker.tracks()[0].history.speed(), 0.0);
}

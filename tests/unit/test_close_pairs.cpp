// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_close_pairs.h: the candidates of the short-range forces and the skip of may_be_close.
   Whatever the atoms do within half the skin, an atom that has a pair closer than its
   distance is never skipped; an atom at rest whose pairs all lie beyond it is, also while
   another atom moves. */

#include "bbpd_close_pairs.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

constexpr double LC = 1.0;            // lattice constant
constexpr double D = 0.9 * LC;        // the pairs' distance (peri/pmb's 0.9 |xi0| for neighbours)
constexpr double SKIN = 0.6 * LC;
constexpr int N = 6;                   // a cubic block of N^3 atoms, all local

std::vector<double> block()
{
  std::vector<double> x;
  for (int a = 0; a < N; a++)
    for (int b = 0; b < N; b++)
      for (int c = 0; c < N; c++) x.insert(x.end(), {a * LC, b * LC, c * LC});
  return x;
}

bool has_close_pair(const BBPD::ClosePairs &cp, const std::vector<double> &x, int i)
{
  for (int m = cp.first[i]; m < cp.first[i + 1]; m++) {
    const int j = cp.pairs[m];
    const double dx = x[3 * i] - x[3 * j], dy = x[3 * i + 1] - x[3 * j + 1],
                 dz = x[3 * i + 2] - x[3 * j + 2];
    if (std::sqrt(dx * dx + dy * dy + dz * dz) < cp.dist[m]) return true;
  }
  return false;
}

// at positions x, no atom with a close pair is skipped; counts those and the atoms skipped
void expect_no_close_pair_skipped(BBPD::ClosePairs &cp, const std::vector<double> &x, int n,
                                  int &close_seen, int &skipped)
{
  for (int i = 0; i < n; i++) {
    const bool close = has_close_pair(cp, x, i);
    close_seen += close;
    skipped += !cp.may_be_close(i);
    if (close) {
      EXPECT_TRUE(cp.may_be_close(i)) << "atom " << i;
    }
  }
}

}    // namespace

TEST(ClosePairs, AtomsAtRestAreSkipped)
{
  std::vector<double> x = block();
  const int n = static_cast<int>(x.size() / 3);
  BBPD::ClosePairs cp;
  ASSERT_TRUE(cp.build(x.data(), n, n, D, SKIN, [](int, int) { return D; }));
  ASSERT_TRUE(cp.current(x.data(), n, n));
  for (int i = 0; i < n; i++) EXPECT_FALSE(cp.may_be_close(i)) << i;
}

TEST(ClosePairs, AnAtomWithAClosePairIsNeverSkipped)
{
  std::mt19937 gen(7);
  const std::vector<double> x0 = block();
  const int n = static_cast<int>(x0.size() / 3);
  int close_seen = 0, skipped = 0;
  for (double amplitude : {0.01, 0.05, 0.1, 0.2}) {
    BBPD::ClosePairs cp;
    ASSERT_TRUE(cp.build(x0.data(), n, n, D, SKIN, [](int, int) { return D; }));
    // every atom moves at most amplitude (under half the skin): the candidates stay current
    std::uniform_real_distribution<double> u(-amplitude / std::sqrt(3.0), amplitude / std::sqrt(3.0));
    for (int round = 0; round < 20; round++) {
      std::vector<double> x = x0;
      for (double &v : x) v += u(gen);
      ASSERT_TRUE(cp.current(x.data(), n, n));
      SCOPED_TRACE(amplitude);
      expect_no_close_pair_skipped(cp, x, n, close_seen, skipped);
    }
  }
  EXPECT_GT(close_seen, 0);    // the largest amplitude brings neighbours within D
  EXPECT_GT(skipped, 0);       // the smallest leaves atoms to skip
}

TEST(ClosePairs, AtomsAtRestAreSkippedWhileAnotherMoves)
{
  // the nearest pairs lie LC - D = 0.1 beyond their distance. One atom moves 0.06: a bound of
  // twice the largest displacement (0.12) would skip none; displacements from their centre
  // (0.03) skip every atom, the moving one too (it came 0.06 nearer at most). Moving 0.12, it
  // may reach a pair: the atoms within the search's reach of it (D + SKIN) are not skipped,
  // but the atoms two bins away (a bin is at least that reach) are.
  for (double step : {0.06 * LC, 0.12 * LC}) {
    std::vector<double> x = block();
    const std::vector<double> x0 = x;
    const int n = static_cast<int>(x.size() / 3);
    BBPD::ClosePairs cp;
    ASSERT_TRUE(cp.build(x.data(), n, n, D, SKIN, [](int, int) { return D; }));
    const int moving = n / 2;    // at (3, 0, 0)
    x[3 * moving] += step;
    ASSERT_TRUE(cp.current(x.data(), n, n));
    int skipped = 0;
    for (int i = 0; i < n; i++) {
      const double dx = x0[3 * i] - x0[3 * moving], dy = x0[3 * i + 1] - x0[3 * moving + 1],
                   dz = x0[3 * i + 2] - x0[3 * moving + 2];
      skipped += !cp.may_be_close(i);
      if (step <= LC - D) {
        EXPECT_FALSE(cp.may_be_close(i)) << i << " " << step;
      } else if (std::sqrt(dx * dx + dy * dy + dz * dz) < D + SKIN) {
        EXPECT_TRUE(cp.may_be_close(i)) << i << " " << step;
      }
    }
    if (step > LC - D) {
      EXPECT_FALSE(cp.may_be_close(n - 1));    // at (5, 5, 5)
      EXPECT_GT(skipped, 0);
      EXPECT_LT(skipped, n);
    }
  }
}

TEST(ClosePairs, FastAtomsAmongSlowOnes)
{
  // a few atoms move up to half the skin, the others little: whatever they do, an atom with a
  // pair closer than its distance is never skipped, and the atoms far from the fast ones are
  std::mt19937 gen(11);
  const std::vector<double> x0 = block();
  const int n = static_cast<int>(x0.size() / 3);
  std::uniform_int_distribution<int> pick(0, n - 1);
  std::uniform_real_distribution<double> slow(-0.01, 0.01), fast(-0.14, 0.14);
  int close_seen = 0, skipped = 0;
  for (int round = 0; round < 200; round++) {
    BBPD::ClosePairs cp;
    ASSERT_TRUE(cp.build(x0.data(), n, n, D, SKIN, [](int, int) { return D; }));
    std::vector<double> x = x0;
    for (double &v : x) v += slow(gen);
    for (int f = 0; f < 3; f++) {
      const int a = pick(gen);
      for (int m = 0; m < 3; m++) x[3 * a + m] += fast(gen);
    }
    ASSERT_TRUE(cp.current(x.data(), n, n));
    SCOPED_TRACE(round);
    expect_no_close_pair_skipped(cp, x, n, close_seen, skipped);
  }
  EXPECT_GT(close_seen, 0);
  EXPECT_GT(skipped, 0);
}

TEST(ClosePairs, ABodyMovingAsAWholeKeepsItsCandidates)
{
  // a translation by twice the skin brings no pair nearer: no search, every atom skipped;
  // the same shift of half the block moves it 0.6 from the other half: searched again
  constexpr double SHIFT = 2.0 * SKIN;
  const std::vector<double> x0 = block();
  const int n = static_cast<int>(x0.size() / 3);
  BBPD::ClosePairs cp;
  ASSERT_TRUE(cp.build(x0.data(), n, n, D, SKIN, [](int, int) { return D; }));
  std::vector<double> x = x0;
  for (int i = 0; i < n; i++) x[3 * i + 1] += SHIFT;
  ASSERT_TRUE(cp.current(x.data(), n, n));
  for (int i = 0; i < n; i++) EXPECT_FALSE(cp.may_be_close(i)) << i;
  x = x0;
  for (int i = 0; i < n / 2; i++) x[3 * i + 1] += SHIFT;
  EXPECT_FALSE(cp.current(x.data(), n, n));
}

TEST(ClosePairs, AGhostThatMovesHalfTheSkinMakesTheCandidatesStale)
{
  // the last 7 atoms are ghosts; each in turn (in a block of 4 atoms of the bounding-box pass or
  // in its tail) moves 1.0 or 0.8 skins along z while the rest stays: it is then half that from
  // the centre of the displacements' box, beyond or within current()'s sqrt(0.2) skins
  const std::vector<double> x0 = block();
  const int nall = static_cast<int>(x0.size() / 3) - 1, nlocal = nall - 7;    // 215: a tail of 3
  for (int g = nlocal; g < nall; g++) {
    BBPD::ClosePairs cp;
    ASSERT_TRUE(cp.build(x0.data(), nlocal, nall, D, SKIN, [](int, int) { return D; }));
    std::vector<double> x = x0;
    x[3 * g + 2] += 1.0 * SKIN;
    EXPECT_FALSE(cp.current(x.data(), nlocal, nall)) << "ghost " << g;
    x[3 * g + 2] = x0[3 * g + 2] + 0.8 * SKIN;
    EXPECT_TRUE(cp.current(x.data(), nlocal, nall)) << "ghost " << g;
  }
}

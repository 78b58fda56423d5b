// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_pmb_rules.h: peri/pmb's volume ramp, short-range distance and the
   Silling-Askari critical stretch. */

#include "bbpd_pmb_rules.h"
#include "bbpd_silling_askari.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace PMB = BBPD::PMB;
using BBPD::SillingAskariRule;

namespace {

constexpr double LC = 0.5e-3;
constexpr double DELTA = 1.5001e-3;

TEST(PMBRules, FamilyIncludesTheHorizon)
{
  EXPECT_TRUE(PMB::in_family(DELTA * DELTA, DELTA));
  EXPECT_FALSE(PMB::in_family(DELTA * DELTA * (1.0 + 1e-15), DELTA));
}

TEST(PMBRules, VolumeRampFromOneToHalf)
{
  // 1 up to delta - lc/2, linear down to 1/2 at delta, then 1 again beyond lc/2 past the horizon
  EXPECT_DOUBLE_EQ(PMB::volume_scale(DELTA - 0.5 * LC, DELTA, LC), 1.0);
  EXPECT_DOUBLE_EQ(PMB::volume_scale(DELTA, DELTA, LC), 0.5);
  EXPECT_DOUBLE_EQ(PMB::volume_scale(DELTA - 0.25 * LC, DELTA, LC), 0.75);
  EXPECT_EQ(PMB::volume_scale(DELTA - 0.6 * LC, DELTA, LC), 1.0);
  EXPECT_EQ(PMB::volume_scale(2.0 * LC, DELTA, LC), 1.0);
}

TEST(PMBRules, ShortRangeDistance)
{
  EXPECT_DOUBLE_EQ(PMB::short_range_distance(LC, LC), 0.9 * LC);
  EXPECT_DOUBLE_EQ(PMB::short_range_distance(1.4 * LC, LC), 0.9 * 1.4 * LC);
  EXPECT_DOUBLE_EQ(PMB::short_range_distance(3.0 * LC, LC), 1.35 * LC);
}

TEST(PMBRules, CriticalStretchFollowsTheLargerSmallestStretch)
{
  const double s00 = 5e-4, alpha = 0.25;
  // compression of both atoms raises s0 by alpha times the milder one
  EXPECT_DOUBLE_EQ(SillingAskariRule<false>::critical_stretch(s00, alpha, -0.01, -0.002), s00 + alpha * 0.002);
  EXPECT_DOUBLE_EQ(SillingAskariRule<true>::critical_stretch(s00, alpha, -0.01, -0.002), s00 + alpha * 0.002);
  // peri/pmb: tension lowers s0; the clamped rule keeps s00
  EXPECT_DOUBLE_EQ(SillingAskariRule<false>::critical_stretch(s00, alpha, 4e-4, -0.01), s00 - alpha * 4e-4);
  EXPECT_EQ(SillingAskariRule<true>::critical_stretch(s00, alpha, 4e-4, -0.01), s00);
  // an atom without bonds never lowers its partner's critical stretch
  EXPECT_GT(SillingAskariRule<false>::critical_stretch(s00, alpha, PMB::NO_BOND_STRETCH, PMB::NO_BOND_STRETCH), 1e300);
  EXPECT_EQ(SillingAskariRule<false>::critical_stretch(s00, 0.0, PMB::NO_BOND_STRETCH, -0.01), s00);
}

// peri/pmb reads a round-off elongation as zero, and only that; the other rules read it as it is
TEST(PMBRules, PeriPmbRuleZeroesRoundOffElongations)
{
  EXPECT_EQ(BBPD::PeriPmbRule::settled_elongation(0.5 * PMB::NEAR_ZERO), 0.0);
  EXPECT_EQ(BBPD::PeriPmbRule::settled_elongation(-0.5 * PMB::NEAR_ZERO), 0.0);
  EXPECT_EQ(BBPD::PeriPmbRule::settled_elongation(2.0 * PMB::NEAR_ZERO), 2.0 * PMB::NEAR_ZERO);
  EXPECT_EQ(SillingAskariRule<true>::settled_elongation(0.5 * PMB::NEAR_ZERO), 0.5 * PMB::NEAR_ZERO);
  EXPECT_TRUE(BBPD::PeriPmbRule::FORCE_IN_BREAKING_STEP);
  EXPECT_FALSE(SillingAskariRule<true>::FORCE_IN_BREAKING_STEP);
}

// the SIMD rows test a bond only when the row's largest stretch reaches this floor: it must lie
// below the critical stretch of every partner whose smallest stretch is at most the cap, for each
// rule (the clamped one of bbpd/KERNEL/alpha and peri/pmb's)
template <class Rule> void expect_floor_below_every_critical_stretch()
{
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1e-2, 1e-2);
  for (int t = 0; t < 10000; t++) {
    const double s00 = 1e-3 + std::fabs(u(gen)), alpha = 0.25 + 10.0 * std::fabs(u(gen));
    const double smin_i = u(gen), smin_j = u(gen), cap = smin_j + std::fabs(u(gen)) * (t % 2);
    ASSERT_LE(BBPD::critical_stretch_floor<Rule>(s00, alpha, smin_i, cap),
              Rule::critical_stretch(s00, alpha, smin_i, smin_j));
  }
  // a negative alpha: no floor, every bond tested
  EXPECT_EQ(BBPD::critical_stretch_floor<Rule>(1e-3, -0.25, 0.0, 1.0),
            -std::numeric_limits<double>::infinity());
}

TEST(PMBRules, CriticalStretchFloorIsBelowEveryBondsCriticalStretch)
{
  expect_floor_below_every_critical_stretch<SillingAskariRule<false>>();
  expect_floor_below_every_critical_stretch<SillingAskariRule<true>>();
  expect_floor_below_every_critical_stretch<BBPD::PeriPmbRule>();
}

TEST(PMBRules, LargestOfEveryLength)
{
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n = 0; n < 12; n++) {
    std::vector<double> v(n);
    for (double &x : v) x = u(gen);
    double expect = std::numeric_limits<double>::lowest();
    for (double x : v) expect = std::max(expect, x);
    EXPECT_EQ(BBPD::largest_of(v.data(), n), expect) << n;
    if (n > 0) {
      v[n - 1] = 2.0;    // the last element (the loop's remainder) counts too
      EXPECT_EQ(BBPD::largest_of(v.data(), n), 2.0) << n;
    }
  }
}

}    // namespace

// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_pmb_rules.h: peri/pmb's volume ramp, short-range distance and the
   Silling-Askari critical stretch. */

#include "bbpd_pmb_rules.h"

#include <gtest/gtest.h>

#include <cfloat>

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

}    // namespace

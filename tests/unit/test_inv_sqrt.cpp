// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_inv_sqrt.h: 1/sqrt(x) from a bit-level guess and Newton steps, as the bond loop uses it. */

#include "bbpd_inv_sqrt.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>

namespace {

// the Newton steps end at the rounding error of their last step: a few ulps
constexpr double MAX_ULPS = 4.0;

double ulps_off(double got, double x)
{
  const long double exact = 1.0L / std::sqrt((long double) x);
  return (double) (std::fabs((long double) got - exact) / exact) / DBL_EPSILON;
}

TEST(InvSqrt, FewUlpsOverTheWholeRange)
{
  std::mt19937_64 gen(20260704);
  std::uniform_real_distribution<double> expo(-300.0, 300.0), mant(1.0, 10.0);
  double worst = 0.0;
  for (int n = 0; n < 200000; n++) {
    const double x = mant(gen) * std::pow(10.0, expo(gen));
    worst = std::max(worst, ulps_off(BBPD::inv_sqrt(x), x));
  }
  EXPECT_LT(worst, MAX_ULPS);
}

TEST(InvSqrt, BondLengthsAndPowersOfTwo)
{
  // squared bond lengths of a 1 mm grid, stretched a little, and both sides of a binade
  for (int k = 1; k < 2000; k++) {
    const double x = 1e-6 * k * (1.0 + 1e-4 * std::sin(k));
    EXPECT_LT(ulps_off(BBPD::inv_sqrt(x), x), MAX_ULPS) << x;
  }
  for (int e = -60; e <= 60; e++) {
    const double x = std::ldexp(1.0, e);
    EXPECT_LT(ulps_off(BBPD::inv_sqrt(x), x), MAX_ULPS) << x;
    EXPECT_LT(ulps_off(BBPD::inv_sqrt(std::nextafter(x, 0.0)), std::nextafter(x, 0.0)), MAX_ULPS);
  }
}

TEST(InvSqrt, ZeroGivesInfinityAndNaNStaysNaN)
{
  // coincident atoms must give a non-finite force, which the pair style reports
  EXPECT_TRUE(std::isinf(BBPD::inv_sqrt(0.0)));
  EXPECT_TRUE(std::isnan(BBPD::inv_sqrt(std::nan(""))));
  EXPECT_FALSE(std::isfinite(BBPD::inv_sqrt(INFINITY) * INFINITY));
}

}    // namespace

// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_exact_sum.h: exact against cancellation, independent of order and of how the terms are
   split into partial sums, and rounded like the exact rational sum. */

#include "bbpd_exact_sum.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using BBPD::ExactSum;

namespace {

double exact_sum(const std::vector<double> &v)
{
  ExactSum s;
  for (double x : v) s.add(x);
  return s.value();
}

TEST(ExactSum, SurvivesCancellation)
{
  // naive summation gives 0 for both
  EXPECT_EQ(exact_sum({1.0e100, 1.0, -1.0e100}), 1.0);
  EXPECT_EQ(exact_sum({1.0, 1.0e-30, -1.0}), 1.0e-30);
  EXPECT_EQ(exact_sum({}), 0.0);
  EXPECT_EQ(exact_sum({-2.5, 0.5}), -2.0);
}

TEST(ExactSum, WholeRange)
{
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double huge = std::numeric_limits<double>::max();
  EXPECT_EQ(exact_sum({tiny, tiny, tiny}), 3 * tiny);
  EXPECT_EQ(exact_sum({huge, -huge, tiny}), tiny);
  EXPECT_EQ(exact_sum({huge, huge, -huge}), huge);    // the intermediate 2 huge does not overflow
}

TEST(ExactSum, SameBitsInAnyOrderAndSplit)
{
  std::mt19937_64 gen(20261202);
  std::uniform_real_distribution<double> mant(-1.0, 1.0);
  std::uniform_int_distribution<int> expo(-60, 60);
  std::vector<double> v(20000);
  for (auto &x : v) x = std::ldexp(mant(gen), expo(gen));
  const double ref = exact_sum(v);
  double naive_forward = 0.0, naive_backward = 0.0;
  for (double x : v) naive_forward += x;
  for (auto it = v.rbegin(); it != v.rend(); ++it) naive_backward += *it;
  EXPECT_NE(naive_forward, naive_backward);    // the set is one where order matters
  for (int trial = 0; trial < 5; trial++) {
    std::shuffle(v.begin(), v.end(), gen);
    EXPECT_EQ(exact_sum(v), ref);
    // split into 'ranks' partial sums, combined as MPI would (limbs added as integers)
    const int nparts = 2 + trial;
    std::vector<ExactSum> parts(nparts);
    for (size_t i = 0; i < v.size(); i++) parts[i % nparts].add(v[i]);
    ExactSum total;
    for (auto &p : parts) {
      p.normalize();
      total.combine(p);
    }
    EXPECT_EQ(total.value(), ref);
  }
}

TEST(ExactSum, WithinAnUlpOfTheExactSum)
{
  // 2^53 + 1 + 2^-40: the exact sum is just above a midpoint; the result is one of its two
  // neighbours (rounding the long-double sum of the limbs may round twice)
  const double two53 = std::ldexp(1.0, 53);
  const double r = exact_sum({two53, 1.0, std::ldexp(1.0, -40)});
  EXPECT_TRUE(r == two53 || r == two53 + 2.0) << r;
  // a million terms 0.1 (as a double, 0.1 + 5.55e-18): exactly 1e5 + 5.55e-12, which rounds to 1e5
  ExactSum s;
  for (int i = 0; i < 1000000; i++) s.add(0.1);
  EXPECT_EQ(s.value(), 100000.0);
  double naive = 0.0;
  for (int i = 0; i < 1000000; i++) naive += 0.1;
  EXPECT_NE(naive, 100000.0);    // what the exact sum avoids
}

}    // namespace

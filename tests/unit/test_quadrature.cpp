// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_quadrature.h: exactness degree, smooth and oscillatory integrands. */

#include "bbpd_quadrature.h"
#include "bbpd_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

using BBPD::GaussLegendre;
using BBPD::test::rel_near;

namespace {

TEST(GaussLegendre, ExactForDegree2nMinus1)
{
  for (int n : {1, 2, 5, 12, 20}) {
    const GaussLegendre gl(n);
    const int deg = 2 * n - 1;
    // int_{-0.3}^{1.7} x^deg dx
    const double exact = (std::pow(1.7, deg + 1) - std::pow(-0.3, deg + 1)) / (deg + 1);
    EXPECT_TRUE(rel_near(gl.integrate([&](double x) { return std::pow(x, deg); }, -0.3, 1.7), exact,
                         1.0e-13))
        << "n = " << n;
  }
}

TEST(GaussLegendre, WeightsSumToTwo)
{
  const GaussLegendre gl(20);
  EXPECT_TRUE(rel_near(gl.integrate([](double) { return 1.0; }, -1.0, 1.0), 2.0, 1.0e-14));
}

TEST(GaussLegendre, CompositeOscillatory)
{
  const GaussLegendre gl(20);
  const double k = 150.0;
  const double q = gl.integrate([&](double x) { return std::cos(k * x) * std::exp(-x); }, 0.0, 2.0,
                                 60);
  // int_0^2 e^-x cos(kx) dx = [e^-x (k sin kx - cos kx)]_0^2 / (1 + k^2)
  const double exact =
      (std::exp(-2.0) * (k * std::sin(2 * k) - std::cos(2 * k)) + 1.0) / (1.0 + k * k);
  EXPECT_TRUE(rel_near(q, exact, 1.0e-12));
}

TEST(GaussLegendre, RejectsEmptyRule) { EXPECT_THROW(GaussLegendre(0), std::invalid_argument); }

}    // namespace

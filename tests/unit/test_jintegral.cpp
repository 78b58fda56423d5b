// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_jintegral.h: Williams fields against each other (displacement, gradient,
   Hooke, the printed stresses), the weight q, the least-squares gradient, and
   the domain integrals on a fine grid: J = (K_I^2 + K_II^2)/E' and both K from
   the interaction integral on several annuli; a plane elastic wave (no crack)
   gives J = 0 only with the inertia terms. */

#include "bbpd_jintegral.h"
#include "bbpd_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>
#include <array>
#include <functional>

using namespace BBPD::JIntegral;
using BBPD::test::rel_near;

namespace {

const Elastic STRESS{2.1, 1.0 / 3.0, true};
const Elastic STRAIN{0.7, 0.25, false};
constexpr double KI = 1.3, KII = -0.6;

// sample points around the tip, off the crack line
std::vector<std::array<double, 2>> ring_points()
{
  std::vector<std::array<double, 2>> pts;
  for (double r : {0.3, 1.0, 2.7})
    for (int k = 0; k < 12; k++) {
      const double th = -PI + (k + 0.5) * 2.0 * PI / 12.0;
      pts.push_back({r * std::cos(th), r * std::sin(th)});
    }
  return pts;
}

TEST(Williams, GradientMatchesFiniteDifferences)
{
  constexpr double H = 1.0e-6, TOL = 1.0e-7;
  for (const Elastic &el : {STRESS, STRAIN})
    for (auto p : ring_points()) {
      double g[2][2], up[2], um[2];
      williams_gradient(KI, KII, p[0], p[1], el, g);
      for (int j = 0; j < 2; j++) {
        double a[2] = {p[0], p[1]}, b[2] = {p[0], p[1]};
        a[j] += H;
        b[j] -= H;
        williams_displacement(KI, KII, a[0], a[1], el, up);
        williams_displacement(KI, KII, b[0], b[1], el, um);
        for (int i = 0; i < 2; i++) EXPECT_NEAR(g[i][j], (up[i] - um[i]) / (2.0 * H), TOL);
      }
    }
}

TEST(Williams, HookeOfTheGradientIsThePrintedStress)
{
  for (const Elastic &el : {STRESS, STRAIN})
    for (auto p : ring_points()) {
      double g[2][2], sig[2][2], ref[3];
      williams_gradient(KI, KII, p[0], p[1], el, g);
      hooke(g, el, sig);
      williams_stress(KI, KII, p[0], p[1], ref);
      EXPECT_NEAR(sig[0][0], ref[0], 1.0e-12);
      EXPECT_NEAR(sig[1][1], ref[1], 1.0e-12);
      EXPECT_NEAR(sig[0][1], ref[2], 1.0e-12);
    }
}

TEST(Williams, FacesAreTractionFreeAndJumpHasTheSignOfK)
{
  constexpr double R = 0.8, EPS = 1.0e-12;
  for (const Elastic &el : {STRESS, STRAIN}) {
    double sup[3], slo[3], uup[2], ulo[2];
    williams_stress(KI, KII, -R, EPS, sup);
    williams_stress(KI, KII, -R, -EPS, slo);
    EXPECT_NEAR(sup[1], 0.0, 1.0e-9);
    EXPECT_NEAR(sup[2], 0.0, 1.0e-9);
    EXPECT_NEAR(slo[1], 0.0, 1.0e-9);
    williams_displacement(KI, KII, -R, EPS, el, uup);
    williams_displacement(KI, KII, -R, -EPS, el, ulo);
    // opening and sliding jumps: 8 K sqrt(r/2pi)/(E'(1+kappa)/... ) = (kappa+1) K sqrt(r/2pi)/mu
    const double f = (el.kappa() + 1.0) * std::sqrt(R / (2.0 * PI)) / el.mu();
    EXPECT_NEAR(uup[1] - ulo[1], f * KI, 1.0e-9);
    EXPECT_NEAR(uup[0] - ulo[0], f * KII, 1.0e-9);
  }
}

TEST(QWeight, EndsAndSlope)
{
  constexpr double RIN = 0.5, ROUT = 2.0, H = 1.0e-7;
  double q, dq;
  q_weight(0.1, RIN, ROUT, q, dq);
  EXPECT_EQ(q, 1.0);
  EXPECT_EQ(dq, 0.0);
  q_weight(2.5, RIN, ROUT, q, dq);
  EXPECT_EQ(q, 0.0);
  q_weight(RIN + 1.0e-12, RIN, ROUT, q, dq);
  EXPECT_NEAR(q, 1.0, 1.0e-12);
  EXPECT_NEAR(dq, 0.0, 1.0e-9);
  q_weight(ROUT - 1.0e-12, RIN, ROUT, q, dq);
  EXPECT_NEAR(q, 0.0, 1.0e-12);
  for (double r : {0.7, 1.25, 1.9}) {
    double qp, qm, d;
    q_weight(r + H, RIN, ROUT, qp, d);
    q_weight(r - H, RIN, ROUT, qm, d);
    q_weight(r, RIN, ROUT, q, dq);
    EXPECT_NEAR(dq, (qp - qm) / (2.0 * H), 1.0e-7);
    EXPECT_LT(dq, 0.0);
  }
}

TEST(CrackCrossing, OnlyBehindTheTip)
{
  const double a[2] = {-1.0, 0.5}, b[2] = {-1.2, -0.5}, c[2] = {1.0, 0.5}, d[2] = {1.0, -0.5},
               e[2] = {-1.0, 0.7};
  EXPECT_TRUE(crosses_crack(a, b));
  EXPECT_TRUE(crosses_crack(b, a));
  EXPECT_FALSE(crosses_crack(c, d));
  EXPECT_FALSE(crosses_crack(a, e));
  const double f[2] = {-0.2, 0.5}, g[2] = {0.6, -0.5};    // crosses x2 = 0 at x1 = 0.2
  EXPECT_FALSE(crosses_crack(f, g));
}

TEST(LeastSquares, ExactForLinearFields)
{
  const double G[2][2] = {{0.3, -1.1}, {0.7, 2.2}};
  Moment m;
  double b[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  const double xis[4][2] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.3}, {0.4, -1.5}};
  for (auto xi : xis) {
    const double w = 0.5 + xi[0] * xi[0];
    m.add(xi, w);
    for (int i = 0; i < 2; i++)
      for (int n = 0; n < 2; n++) b[i][n] += w * (G[i][0] * xi[0] + G[i][1] * xi[1]) * xi[n];
  }
  double ki[3], g[2][2];
  ASSERT_TRUE(m.inverse(ki));
  apply_inverse(b, ki, g);
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) EXPECT_NEAR(g[i][j], G[i][j], 1.0e-13);
  Moment line;
  const double x1[2] = {1.0, 1.0}, x2[2] = {-2.0, -2.0};
  line.add(x1, 1.0);
  line.add(x2, 1.0);
  EXPECT_FALSE(line.inverse(ki));
}

// midpoint quadrature of the three integrals on a square grid of cell h around the tip
std::array<double, 3> domain_integrals(const Elastic &el, double rin, double rout, double h,
                                       const std::function<void(Point &)> &fields)
{
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  const int n = static_cast<int>(std::ceil(rout / h));
  for (int i = -n; i < n; i++)
    for (int j = -n; j < n; j++) {
      Point p{};
      p.x[0] = (i + 0.5) * h;
      p.x[1] = (j + 0.5) * h;
      p.rho = 1.7;
      p.area = h * h;
      fields(p);
      double out[3];
      integrand(p, el, rin, rout, out);
      for (int k = 0; k < 3; k++) sum[k] += out[k];
    }
  return sum;
}

TEST(DomainIntegral, StaticWilliamsFieldOnThreeAnnuli)
{
  for (const Elastic &el : {STRESS, STRAIN}) {
    const double jref = (KI * KI + KII * KII) / el.e_prime();
    for (auto ann : {std::array<double, 2>{0.5, 1.5}, {1.0, 3.0}, {0.2, 2.5}}) {
      auto s = domain_integrals(el, ann[0], ann[1], 0.01, [&](Point &p) {
        williams_gradient(KI, KII, p.x[0], p.x[1], el, p.gu);
      });
      EXPECT_TRUE(rel_near(s[0], jref, 1.0e-3));
      EXPECT_TRUE(rel_near(k_from_interaction(s[1], el), KI, 1.0e-3));
      EXPECT_TRUE(rel_near(k_from_interaction(s[2], el), KII, 1.0e-3));
    }
  }
}

// a plane P or S wave along x1 satisfies rho a = div sigma and has no crack: J = 0, but
// each of the two integrals alone is not zero
TEST(DomainIntegral, PlaneWaveGivesZeroOnlyWithInertia)
{
  for (const Elastic &el : {STRESS, STRAIN})
    for (int pol = 0; pol < 2; pol++) {
      constexpr double RHO = 1.7, U = 0.01, K = 2.3, T = 0.37;
      const double modulus = pol == 0 ? el.lambda() + 2.0 * el.mu() : el.mu();
      const double w = K * std::sqrt(modulus / RHO);
      auto wave = [&](Point &p) {
        const double ph = K * p.x[0] - w * T;
        p.gu[pol][0] = U * K * std::cos(ph);
        p.v[pol] = -U * w * std::cos(ph);
        p.gv[pol][0] = U * w * K * std::sin(ph);
        p.a[pol] = -U * w * w * std::sin(ph);
      };
      auto full = domain_integrals(el, 0.4, 2.0, 0.01, wave);
      auto nodyn = domain_integrals(el, 0.4, 2.0, 0.01, [&](Point &p) {
        wave(p);
        p.v[pol] = p.a[pol] = p.gv[pol][0] = 0.0;
      });
      const double scale = std::fabs(nodyn[0]);
      ASSERT_GT(scale, 1.0e-5);
      EXPECT_LT(std::fabs(full[0]), 1.0e-3 * scale);
    }
}

}    // namespace

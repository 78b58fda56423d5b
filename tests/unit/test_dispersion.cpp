// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_dispersion.h: continuous (eq. 29), discrete (eq. 31) and
   time-discrete dispersion of a 1D bar, against the paper's closed forms
   (eqs. 32-34, 36-38), series solutions, finite differences and limits. */

#include "bbpd_dispersion.h"
#include "bbpd_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

using namespace BBPD;
using BBPD::test::rel_near;

namespace {

// Fig. 4-6 setting: m = 5, delta = 1 mm; E and rho chosen so v = 2
constexpr double M_PAPER = 5.0;
constexpr double DELTA = 1.0e-3;
constexpr double E = 4.0;
constexpr double RHO = 1.0;
constexpr double V = 2.0;    // sqrt(E/rho)

DispersionBar make_bar(const std::string &kernel, double m, bool cv = false)
{
  DispersionBar bar{kernel_by_name(kernel), m, DELTA};
  bar.E = E;
  bar.rho = RHO;
  bar.volume_correction = cv;
  return bar;
}

// wave numbers spanning the first Brillouin zone, k dx in [0.05, pi]
std::vector<double> k_samples(double dx)
{
  std::vector<double> k;
  for (double kdx : {0.05, 0.3, 0.77, 1.2, 1.9, 2.5, 3.0, PI}) k.push_back(kdx / dx);
  return k;
}

/* ---------------------------------------------------------------------- */
// closed forms of the paper equal the general sum with C_v off

TEST(PaperClosedForms, OmegaEqs32to34)
{
  for (double m : {M_PAPER, 3.0, 3.6, 12.0}) {
    const double dx = DELTA / m;
    for (double k : k_samples(dx)) {
      EXPECT_TRUE(rel_near(omega2_discrete(make_bar("constant", m), k),
                           paper::omega2_eq32_constant(m, dx, V, k), 1.0e-12));
      EXPECT_TRUE(rel_near(omega2_discrete(make_bar("gaussian", m), k),
                           paper::omega2_eq33_gaussian(m, dx, V, k), 1.0e-12));
      EXPECT_TRUE(rel_near(omega2_discrete(make_bar("triangular", m), k),
                           paper::omega2_eq34_triangular(m, dx, V, k), 1.0e-12));
    }
  }
}

TEST(PaperClosedForms, GroupVelocityEqs36to38)
{
  for (double m : {M_PAPER, 3.0, 3.6, 12.0}) {
    const double dx = DELTA / m;
    for (double k : k_samples(dx)) {
      // group velocity vanishes at the zone edge: compare on the scale of v
      EXPECT_NEAR(dispersion_discrete(make_bar("constant", m), k).group_velocity,
                  paper::group_velocity_eq36_constant(m, dx, V, k), 1.0e-12 * V);
      EXPECT_NEAR(dispersion_discrete(make_bar("gaussian", m), k).group_velocity,
                  paper::group_velocity_eq37_gaussian(m, dx, V, k), 1.0e-12 * V);
      EXPECT_NEAR(dispersion_discrete(make_bar("triangular", m), k).group_velocity,
                  paper::group_velocity_eq38_triangular(m, dx, V, k), 1.0e-12 * V);
    }
  }
}

/* ---------------------------------------------------------------------- */
// continuous relation against series solutions, term by term (no cancellation):
//   int_0^d (1 - cos k xi)/xi dxi           = sum_n (-1)^(n+1) x^(2n)/(2n)! / (2n)
//   int_0^d (1 - xi/d)(1 - cos k xi)/xi dxi = sum_n (-1)^(n+1) x^(2n)/(2n)! / (2n (2n+1))
// with x = k d (the first is Cin(x)); summed in long double

double series(double x, bool triangular)
{
  long double term = 1.0L, sum = 0.0L;    // term = x^(2n)/(2n)!
  const long double x2 = static_cast<long double>(x) * x;
  for (int n = 1; n < 200; ++n) {
    term *= x2 / ((2.0L * n - 1.0L) * (2.0L * n));
    const long double den = triangular ? 2.0L * n * (2.0L * n + 1.0L) : 2.0L * n;
    sum += (n % 2 ? 1.0L : -1.0L) * term / den;
    if (term < 1.0e-30L) break;
  }
  return static_cast<double>(sum);
}

TEST(Continuous, ConstantAndTriangularSeries)
{
  for (double kd : {1.0e-3, 0.1, 1.0, 5.0, PI * M_PAPER}) {
    const double k = kd / DELTA;
    const double cA_const = 2.0 * E / (DELTA * DELTA);    // Table 1, times A
    const double cA_tri = 6.0 * E / (DELTA * DELTA);
    EXPECT_TRUE(rel_near(omega2_continuous(make_bar("constant", M_PAPER), k),
                         2.0 * cA_const / RHO * series(kd, false), 1.0e-12))
        << "k delta = " << kd;
    EXPECT_TRUE(rel_near(omega2_continuous(make_bar("triangular", M_PAPER), k),
                         2.0 * cA_tri / RHO * series(kd, true), 1.0e-12))
        << "k delta = " << kd;
  }
}

/* ---------------------------------------------------------------------- */
// analytic group velocity against central differences of omega(k)

TEST(GroupVelocity, MatchesFiniteDifferences)
{
  for (const auto &name : BBPD::test::kernel_names()) {
    for (bool cv : {false, true}) {
      for (double m : {M_PAPER, 3.6}) {
        const DispersionBar bar = make_bar(name, m, cv);
        const double dx = bar.dx();
        const double h = 1.0e-5 / dx;
        for (double k : k_samples(dx)) {
          const double fd_d = (std::sqrt(omega2_discrete(bar, k + h)) -
                               std::sqrt(omega2_discrete(bar, k - h))) / (2 * h);
          EXPECT_NEAR(dispersion_discrete(bar, k).group_velocity, fd_d, 1.0e-8 * V)
              << name << " m=" << m << " cv=" << cv << " k dx=" << k * dx;
          const double fd_c = (std::sqrt(omega2_continuous(bar, k + h)) -
                               std::sqrt(omega2_continuous(bar, k - h))) / (2 * h);
          EXPECT_NEAR(dispersion_continuous(bar, k).group_velocity, fd_c, 1.0e-8 * V)
              << name << " continuous k dx=" << k * dx;
        }
      }
    }
  }
}

/* ---------------------------------------------------------------------- */
// long waves

TEST(LongWaves, ContinuousPhaseAndGroupVelocityTendToV)
{
  for (const auto &name : BBPD::test::kernel_names()) {
    const DispersionBar bar = make_bar(name, M_PAPER);
    const DispersionPoint p0 = dispersion_continuous(bar, 0.0);
    EXPECT_TRUE(rel_near(p0.phase_velocity, V, 1.0e-12)) << name;
    EXPECT_TRUE(rel_near(p0.group_velocity, V, 1.0e-12)) << name;
    // dispersion is O(k^2 delta^2)
    const DispersionPoint p = dispersion_continuous(bar, 1.0e-4 / DELTA);
    EXPECT_TRUE(rel_near(p.phase_velocity, V, 1.0e-8)) << name;
    EXPECT_TRUE(rel_near(p.group_velocity, V, 1.0e-8)) << name;
    EXPECT_LT(p.phase_velocity, V);
  }
}

TEST(LongWaves, DiscreteLimitIsTheBondSum)
{
  for (const auto &name : BBPD::test::kernel_names()) {
    for (bool cv : {false, true}) {
      const DispersionBar bar = make_bar(name, M_PAPER, cv);
      const double v0 = long_wave_speed_discrete(bar);
      const DispersionPoint p = dispersion_discrete(bar, 1.0e-5 / bar.dx());
      EXPECT_TRUE(rel_near(p.phase_velocity, v0, 1.0e-8)) << name << " cv=" << cv;
      EXPECT_TRUE(rel_near(p.group_velocity, v0, 1.0e-8)) << name << " cv=" << cv;
      EXPECT_EQ(dispersion_discrete(bar, 0.0).phase_velocity, v0);
    }
  }
  // closed forms of sum_j j W(j/m): constant m(m+1)/2, triangular (m^2 - 1)/6;
  // with C_v the outer bond (j = m) has weight 1/2 and the constant kernel
  // gives exactly m^2/2, i.e. v
  const double m = M_PAPER;
  EXPECT_TRUE(rel_near(long_wave_speed_discrete(make_bar("constant", m)), V * std::sqrt(1 + 1 / m),
                       1.0e-12));
  EXPECT_TRUE(rel_near(long_wave_speed_discrete(make_bar("triangular", m)),
                       V * std::sqrt(1 - 1 / (m * m)), 1.0e-12));
  EXPECT_TRUE(rel_near(long_wave_speed_discrete(make_bar("constant", m, true)), V, 1.0e-12));
}

TEST(LongWaves, DiscreteLimitTendsToVOnFineGrids)
{
  for (const auto &name : BBPD::test::kernel_names())
    for (bool cv : {false, true})
      EXPECT_TRUE(rel_near(long_wave_speed_discrete(make_bar(name, 2000.0, cv)), V, 1.0e-3))
          << name << " cv=" << cv;
}

/* ---------------------------------------------------------------------- */
// eq. 31 -> eq. 29 as dx -> 0 at fixed delta: first order without C_v (the
// outer bond has full weight, a one-sided Riemann sum), second order with
// C_v and integer m (trapezoidal rule)

double discrete_error(const std::string &name, double m, bool cv, double kd)
{
  const DispersionBar bar = make_bar(name, m, cv);
  const double k = kd / DELTA;
  return std::fabs(omega2_discrete(bar, k) / omega2_continuous(bar, k) - 1.0);
}

TEST(Convergence, DiscreteToContinuous)
{
  constexpr double KD = 3.0;    // k delta, fixed while dx -> 0
  for (const auto &name : BBPD::test::kernel_names()) {
    for (bool cv : {false, true}) {
      const double e1 = discrete_error(name, 40.0, cv, KD);
      const double e2 = discrete_error(name, 400.0, cv, KD);
      const double e3 = discrete_error(name, 4000.0, cv, KD);
      EXPECT_LT(e2, e1) << name << " cv=" << cv;
      EXPECT_LT(e3, e2) << name << " cv=" << cv;
      EXPECT_LT(e3, 1.0e-3) << name << " cv=" << cv;
      // observed order over a decade of refinement
      const double order = std::log10(e2 / e3);
      const bool second = cv || name == "triangular";    // W(1) = 0: no endpoint error
      EXPECT_GT(order, second ? 1.9 : 0.95) << name << " cv=" << cv;
    }
  }
}

/* ---------------------------------------------------------------------- */
// time-discrete relation of central differences / velocity Verlet

TEST(TimeDiscrete, ReducesToSpatialAsDtVanishes)
{
  const DispersionBar bar = make_bar("gaussian", M_PAPER);
  for (double k : k_samples(bar.dx())) {
    const DispersionPoint p = dispersion_discrete(bar, k);
    const double dt = 1.0e-4 / p.omega;
    const DispersionPoint t = time_discrete(p, k, dt);
    EXPECT_TRUE(rel_near(t.omega, p.omega, 1.0e-8));    // error (dt omega)^2/24
    EXPECT_TRUE(rel_near(t.phase_velocity, p.phase_velocity, 1.0e-8));
    EXPECT_NEAR(t.group_velocity, p.group_velocity, 1.0e-8 * V);
    EXPECT_GT(t.omega, p.omega);    // central differences raise the frequency
    EXPECT_EQ(omega_time_discrete(p.omega, 0.0), p.omega);
  }
}

TEST(TimeDiscrete, SatisfiesCentralDifferenceRelation)
{
  const double omega = 3.0, dt = 0.5;
  const double wt = omega_time_discrete(omega, dt);
  // (u^{n+1} - 2u^n + u^{n-1})/dt^2 = -omega^2 u^n with u = exp(-i wt t)
  EXPECT_TRUE(rel_near((2.0 - 2.0 * std::cos(wt * dt)) / (dt * dt), omega * omega, 1.0e-14));
  EXPECT_TRUE(std::isnan(omega_time_discrete(omega, 2.0 / omega * 1.000001)));
  EXPECT_FALSE(time_step_stable(omega, 2.0 / omega * 1.000001));
  EXPECT_TRUE(time_step_stable(omega, 2.0 / omega));
}

TEST(TimeDiscrete, GroupVelocityMatchesFiniteDifferences)
{
  const DispersionBar bar = make_bar("triangular", M_PAPER, true);
  const double dx = bar.dx();
  const double dt = 0.8 * 2.0 / dispersion_discrete(bar, PI / dx).omega;
  const double h = 1.0e-5 / dx;
  auto wt = [&](double k) { return omega_time_discrete(dispersion_discrete(bar, k).omega, dt); };
  for (double k : k_samples(dx)) {
    if (k + h > PI / dx) continue;
    const double fd = (wt(k + h) - wt(k - h)) / (2 * h);
    EXPECT_NEAR(time_discrete(dispersion_discrete(bar, k), k, dt).group_velocity, fd, 1.0e-8 * V);
  }
}

// sum_j V_j c(xi_j)/|xi_j| of eq. 26 on a 1D grid of unit cross-section
double bond_stiffness_sum(const DispersionBar &bar)
{
  const int jmax = static_cast<int>(std::floor(bar.m + 0.5)) + 1;
  double sum = 0.0;
  for (int j = 1; j <= jmax; ++j) {
    double w = bar.kernel.shape(j / bar.m);
    w *= bar.volume_correction ? partial_volume(j * bar.dx(), bar.horizon, bar.dx())
                               : (j <= bar.m ? 1.0 : 0.0);
    sum += 2.0 * bar.dx() * bar.bond_constant() * w / (j * bar.dx());
  }
  return sum;
}

// Silling & Askari's time step sqrt(2 rho / sum) bounds the von Neumann limit
// 2/max omega; with one neighbour on each side it is exactly that limit.
TEST(TimeDiscrete, SillingTimeStepIsStable)
{
  for (const auto &name : BBPD::test::kernel_names()) {
    for (bool cv : {false, true}) {
      const DispersionBar bar = make_bar(name, M_PAPER, cv);
      const double dt = stable_timestep_silling(RHO, bond_stiffness_sum(bar));
      for (int i = 0; i <= 400; ++i) {
        const double k = PI / bar.dx() * i / 400.0;
        EXPECT_TRUE(time_step_stable(dispersion_discrete(bar, k).omega, dt)) << name;
      }
      EXPECT_LT(stable_timestep_paper(RHO, bond_stiffness_sum(bar)), dt);
    }
  }
  const DispersionBar nn = make_bar("constant", 1.0);
  const double dt = stable_timestep_silling(RHO, bond_stiffness_sum(nn));
  const double omega_max = dispersion_discrete(nn, PI / nn.dx()).omega;
  EXPECT_TRUE(rel_near(0.5 * dt * omega_max, 1.0, 1.0e-14));
}

}    // namespace

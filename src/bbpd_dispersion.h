// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: kernel-weighted bond-based peridynamics for LAMMPS.

   Dispersion of longitudinal waves in a 1D bar (Bouaraquia & Mabssout 2026,
   section 4.1), no LAMMPS dependency. For u = u0 exp(i(k x - omega t)):

     continuous (eq. 29)  omega^2 = 2 cA/rho int_0^delta W(xi/delta) (1 - cos k xi)/xi dxi
     discrete   (eq. 31)  omega^2 = 2 cA/rho sum_{j>=1} w_j (1 - cos j k dx)/j
     time step  (CD/VV)   omega_t = (2/dt) asin(dt omega / 2)

   with cA = c0 A = E/(delta^2 M1) (the 1D micromodulus of bbpd_kernel.h
   times the cross-section, which cancels), m = delta/dx and the bond weight
     w_j = W(j/m)                              for j <= m        (paper, eq. 31)
     w_j = W(j/m) C_v(j dx)                    with C_v of eq. 19 (pair bbpd)
   Group velocities are the analytic derivatives
     d omega/dk = (d omega^2/dk) / (2 omega),
     d omega^2/dk = 2 cA/rho int_0^delta W sin(k xi) dxi   or   2 cA/rho dx sum w_j sin(j k dx).
   At k = 0 phase and group velocity take their common limit
     sqrt(cA delta^2 M1/rho) = v   and   sqrt(cA dx^2 sum_j j w_j / rho).

   The paper's closed forms (eqs. 32-34 and 36-38) are kept verbatim in
   namespace BBPD::paper so the tests can compare them with the general sums.
------------------------------------------------------------------------- */

#ifndef BBPD_DISPERSION_H
#define BBPD_DISPERSION_H

#include "bbpd_kernel.h"
#include "bbpd_quadrature.h"

#include <cmath>
#include <limits>

namespace BBPD {

// A uniform 1D bar: horizon delta = m dx, classical wave speed v = sqrt(E/rho)
struct DispersionBar {
  KernelInfo kernel;
  double m;                           // horizon ratio delta/dx, may be non-integer
  double horizon;                     // delta
  double E = 1.0;                     // Young's modulus
  double rho = 1.0;                   // mass density
  bool volume_correction = false;     // weight bonds by C_v (eq. 19) as pair bbpd does

  double dx() const { return horizon / m; }
  double wave_speed() const { return std::sqrt(E / rho); }
  // c0 A: the cross-section cancels from the 1D equation of motion (eq. 27)
  double bond_constant() const { return micromodulus(kernel, Model::Bar1D, E, horizon, 1.0); }
};

struct DispersionPoint {
  double omega;             // angular frequency, NaN if the time step is unstable
  double phase_velocity;    // omega/k (eq. 35)
  double group_velocity;    // d omega/dk (eq. 35)
};

namespace detail {

  // Gauss-Legendre order and panels per wavelength for eq. 29: 2 panels of
  // 20 nodes per period of cos(k xi) give ~1e-15 relative error.
  constexpr int QUAD_ORDER = 20;
  constexpr int QUAD_MIN_PANELS = 4;
  constexpr int QUAD_PANELS_PER_PERIOD = 2;
  // m = delta/dx computed in floating point may fall just below an integer
  constexpr double M_ROUND_TOL = 1.0e-9;

  inline const GaussLegendre &rule()
  {
    static const GaussLegendre gl(QUAD_ORDER);
    return gl;
  }

  inline int panels_for(double k_delta)
  {
    return QUAD_MIN_PANELS +
        QUAD_PANELS_PER_PERIOD * static_cast<int>(std::ceil(std::fabs(k_delta) / (2.0 * PI)));
  }

  // 1 - cos x without cancellation at small x
  inline double one_minus_cos(double x)
  {
    const double s = std::sin(0.5 * x);
    return 2.0 * s * s;
  }

  // largest neighbour index j with a nonzero bond weight
  inline int max_neighbour(const DispersionBar &bar)
  {
    if (bar.volume_correction) return static_cast<int>(std::ceil(bar.m + 0.5));
    return static_cast<int>(std::floor(bar.m + M_ROUND_TOL));
  }

  // w_j of the header comment (j >= 1)
  inline double bond_weight(const DispersionBar &bar, int j)
  {
    const double W = bar.kernel.shape(j / bar.m);
    if (!bar.volume_correction) return j <= bar.m + M_ROUND_TOL ? W : 0.0;
    const double dx = bar.dx();
    return W * partial_volume(j * dx, bar.horizon, dx);
  }

  inline DispersionPoint make_point(double omega2, double domega2_dk, double k, double v0)
  {
    const double omega = std::sqrt(omega2);
    if (k == 0.0) return {0.0, v0, v0};
    const double vg = omega > 0.0 ? 0.5 * domega2_dk / omega : 0.0;
    return {omega, omega / k, vg};
  }

}    // namespace detail

/* ---------------------------------------------------------------------- */
// continuous relation, eq. 29

inline double omega2_continuous(const DispersionBar &bar, double k)
{
  const double kd = k * bar.horizon;
  auto f = [&](double r) {
    return r > 0.0 ? bar.kernel.shape(r) * detail::one_minus_cos(kd * r) / r : 0.0;
  };
  return 2.0 * bar.bond_constant() / bar.rho *
      detail::rule().integrate(f, 0.0, 1.0, detail::panels_for(kd));
}

inline double domega2_dk_continuous(const DispersionBar &bar, double k)
{
  const double kd = k * bar.horizon;
  auto f = [&](double r) { return bar.kernel.shape(r) * std::sin(kd * r); };
  return 2.0 * bar.bond_constant() / bar.rho * bar.horizon *
      detail::rule().integrate(f, 0.0, 1.0, detail::panels_for(kd));
}

inline DispersionPoint dispersion_continuous(const DispersionBar &bar, double k)
{
  const double v0 =
      std::sqrt(bar.bond_constant() * bar.horizon * bar.horizon * bar.kernel.moment(1) / bar.rho);
  return detail::make_point(omega2_continuous(bar, k), domega2_dk_continuous(bar, k), k, v0);
}

/* ---------------------------------------------------------------------- */
// discrete relation, eq. 31 (optionally with the C_v weights of eq. 19)

inline double omega2_discrete(const DispersionBar &bar, double k)
{
  const double kdx = k * bar.dx();
  double sum = 0.0;
  for (int j = 1; j <= detail::max_neighbour(bar); ++j)
    sum += detail::bond_weight(bar, j) * detail::one_minus_cos(j * kdx) / j;
  return 2.0 * bar.bond_constant() / bar.rho * sum;
}

inline double domega2_dk_discrete(const DispersionBar &bar, double k)
{
  const double dx = bar.dx();
  double sum = 0.0;
  for (int j = 1; j <= detail::max_neighbour(bar); ++j)
    sum += detail::bond_weight(bar, j) * std::sin(j * k * dx);
  return 2.0 * bar.bond_constant() / bar.rho * dx * sum;
}

// k -> 0 limit of omega/k on the grid: not exactly v unless the bond sum
// reproduces the second moment, e.g. constant kernel with C_v and integer m
inline double long_wave_speed_discrete(const DispersionBar &bar)
{
  double sum = 0.0;
  for (int j = 1; j <= detail::max_neighbour(bar); ++j) sum += j * detail::bond_weight(bar, j);
  const double dx = bar.dx();
  return std::sqrt(bar.bond_constant() * dx * dx * sum / bar.rho);
}

inline DispersionPoint dispersion_discrete(const DispersionBar &bar, double k)
{
  return detail::make_point(omega2_discrete(bar, k), domega2_dk_discrete(bar, k), k,
                            long_wave_speed_discrete(bar));
}

/* ---------------------------------------------------------------------- */
// central differences / velocity Verlet: 4 sin^2(omega_t dt/2) = dt^2 omega^2

inline bool time_step_stable(double omega, double dt) { return 0.5 * dt * omega <= 1.0; }

inline double omega_time_discrete(double omega, double dt)
{
  if (dt == 0.0) return omega;
  const double x = 0.5 * dt * omega;
  if (x > 1.0) return std::numeric_limits<double>::quiet_NaN();
  return 2.0 / dt * std::asin(x);
}

// p is a spatial point (continuous or discrete) at wave number k
inline DispersionPoint time_discrete(const DispersionPoint &p, double k, double dt)
{
  const double x = 0.5 * dt * p.omega;
  if (x > 1.0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan};
  }
  const double omega = omega_time_discrete(p.omega, dt);
  if (k == 0.0) return {0.0, p.phase_velocity, p.group_velocity};
  return {omega, omega / k, p.group_velocity / std::sqrt(1.0 - x * x)};
}

/* ---------------------------------------------------------------------- */
// The paper's closed forms as printed, sums over j in [-m, m], j != 0.
// v is the classical wave speed, dx the grid spacing.

namespace paper {

  inline int jmax(double m) { return static_cast<int>(std::floor(m + detail::M_ROUND_TOL)); }

  // Gaussian prefactor of eqs. 33 and 37: c = 8 v^2 e^4 / (m^2 dx^2 (e^4 - 1))
  inline double gaussian_c(double m, double dx, double v)
  {
    const double e4 = std::exp(4.0);
    return 8.0 * v * v * e4 / (m * m * dx * dx * (e4 - 1.0));
  }

  // eq. 32, constant kernel
  inline double omega2_eq32_constant(double m, double dx, double v, double k)
  {
    double sum = 0.0;
    for (int j = -jmax(m); j <= jmax(m); ++j)
      if (j != 0) sum += (1.0 - std::cos(j * k * dx)) / std::abs(j);
    return 2.0 * v * v / (m * m * dx * dx) * sum;
  }

  // eq. 33, Gaussian kernel
  inline double omega2_eq33_gaussian(double m, double dx, double v, double k)
  {
    double sum = 0.0;
    for (int j = -jmax(m); j <= jmax(m); ++j)
      if (j != 0)
        sum += (1.0 - std::cos(j * k * dx)) / std::abs(j) * std::exp(-std::pow(2.0 * j / m, 2));
    return gaussian_c(m, dx, v) * sum;
  }

  // eq. 34, triangular kernel
  inline double omega2_eq34_triangular(double m, double dx, double v, double k)
  {
    double sum = 0.0;
    for (int j = -jmax(m); j <= jmax(m); ++j)
      if (j != 0) sum += (1.0 - std::cos(j * k * dx)) / std::abs(j) * (1.0 - std::abs(j) / m);
    return 6.0 * v * v / (m * m * dx * dx) * sum;
  }

  inline double sign(int j) { return j > 0 ? 1.0 : -1.0; }

  // eq. 36, constant kernel
  inline double group_velocity_eq36_constant(double m, double dx, double v, double k)
  {
    double num = 0.0, den = 0.0;
    for (int j = -jmax(m); j <= jmax(m); ++j) {
      if (j == 0) continue;
      num += sign(j) * std::sin(j * k * dx);
      den += (1.0 - std::cos(j * k * dx)) / std::abs(j);
    }
    return v / (m * std::sqrt(2.0)) * num / std::sqrt(den);
  }

  // eq. 37, Gaussian kernel
  inline double group_velocity_eq37_gaussian(double m, double dx, double v, double k)
  {
    double sum = 0.0;
    for (int j = -jmax(m); j <= jmax(m); ++j)
      if (j != 0) sum += sign(j) * std::sin(j * k * dx) * std::exp(-std::pow(2.0 * j / m, 2));
    const double omega = std::sqrt(omega2_eq33_gaussian(m, dx, v, k));
    return gaussian_c(m, dx, v) * dx / (2.0 * omega) * sum;
  }

  // eq. 38, triangular kernel
  inline double group_velocity_eq38_triangular(double m, double dx, double v, double k)
  {
    double sum = 0.0;
    for (int j = -jmax(m); j <= jmax(m); ++j)
      if (j != 0) sum += sign(j) * std::sin(j * k * dx) * (1.0 - std::abs(j) / m);
    const double omega = std::sqrt(omega2_eq34_triangular(m, dx, v, k));
    return 3.0 * v * v / (omega * m * m * dx) * sum;
  }

}    // namespace paper
}    // namespace BBPD

#endif

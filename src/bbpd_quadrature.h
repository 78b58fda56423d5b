// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: kernel-weighted bond-based peridynamics for LAMMPS.

   Composite Gauss-Legendre quadrature, no LAMMPS dependency. Used for the
   continuous dispersion relation (eq. 29) and by the unit tests to integrate
   the energy-equivalence and fracture-energy integrals numerically.

   An n-point rule is exact for polynomials of degree 2n-1; splitting [a,b]
   into panels keeps oscillatory integrands (1 - cos k xi) resolved.
------------------------------------------------------------------------- */

#ifndef BBPD_QUADRATURE_H
#define BBPD_QUADRATURE_H

#include <cmath>
#include <stdexcept>
#include <vector>

namespace BBPD {

class GaussLegendre {
 public:
  // Nodes are the roots of P_n, found by Newton's method from the
  // Tricomi estimate cos(pi (i - 1/4) / (n + 1/2)).
  explicit GaussLegendre(int n) : node(n), weight(n)
  {
    if (n < 1) throw std::invalid_argument("GaussLegendre needs at least one node");
    constexpr double PI_ = 3.14159265358979323846;
    constexpr int MAX_NEWTON = 100;
    constexpr double NEWTON_TOL = 1.0e-15;    // |dx| near machine precision on [-1,1]
    for (int i = 0; i < n; ++i) {
      double x = std::cos(PI_ * (i + 0.75) / (n + 0.5));
      double dp = 1.0;
      for (int it = 0; it < MAX_NEWTON; ++it) {
        double p = legendre(n, x, dp);
        double step = p / dp;
        x -= step;
        if (std::fabs(step) < NEWTON_TOL) break;
      }
      legendre(n, x, dp);
      node[i] = x;
      weight[i] = 2.0 / ((1.0 - x * x) * dp * dp);
    }
  }

  int size() const { return static_cast<int>(node.size()); }

  // int_a^b f(x) dx with the rule applied on `panels` equal sub-intervals
  template <class F> double integrate(F &&f, double a, double b, int panels = 1) const
  {
    if (panels < 1) panels = 1;
    const double width = (b - a) / panels;
    const double half = 0.5 * width;
    double sum = 0.0;
    for (int p = 0; p < panels; ++p) {
      const double mid = a + (p + 0.5) * width;
      double part = 0.0;
      for (std::size_t i = 0; i < node.size(); ++i) part += weight[i] * f(mid + half * node[i]);
      sum += half * part;
    }
    return sum;
  }

 private:
  std::vector<double> node, weight;

  // P_n(x) by the three-term recurrence; dp returns P_n'(x)
  static double legendre(int n, double x, double &dp)
  {
    double p0 = 1.0, p1 = x;
    if (n == 0) {
      dp = 0.0;
      return 1.0;
    }
    for (int k = 2; k <= n; ++k) {
      double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    dp = n * (x * p1 - p0) / (x * x - 1.0);
    return p1;
  }
};

}    // namespace BBPD

#endif

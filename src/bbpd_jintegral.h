// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the math of compute bbpd/jintegral, with no LAMMPS dependency.

   Domain form of the dynamic J-integral of a stationary crack (Moran & Shih
   1987, Eng. Fract. Mech. 27:615), in crack-tip coordinates (x1 ahead of the
   tip along the crack line, x2 normal to it):

     J = int_A [ sigma_ij u_i,1 - (W + T) delta_1j ] q,j dA
       + int_A [ rho a_i u_i,1 - rho v_i v_i,1 ] q dA

   and the interaction integral with a static auxiliary Williams field
   (u^a, eps^a, sigma^a) of unit K_I or K_II (Yau, Wang & Corten 1980):

     I = int_A [ sigma_ij u^a_i,1 + sigma^a_ij u_i,1 - sigma^a_ik eps_ik delta_1j ] q,j dA
       + int_A rho a_i u^a_i,1 q dA,          K = E' I / 2.

   W = sigma_ij eps_ij / 2 (linear elasticity, plane stress or strain),
   T = rho v_i v_i / 2, q = 1 for r <= rin, 0 for r >= rout, C1 in between.
------------------------------------------------------------------------- */

#ifndef BBPD_JINTEGRAL_H
#define BBPD_JINTEGRAL_H

#include <cmath>

namespace BBPD::JIntegral {

constexpr double PI = 3.14159265358979323846;

// isotropic linear elasticity in a plane
struct Elastic {
  double E, nu;
  bool plane_stress;
  double mu() const { return E / (2.0 * (1.0 + nu)); }
  // Kolosov constant
  double kappa() const { return plane_stress ? (3.0 - nu) / (1.0 + nu) : 3.0 - 4.0 * nu; }
  // in-plane Lame constant: lambda, or 2 mu lambda/(lambda + 2 mu) in plane stress
  double lambda() const
  {
    return plane_stress ? E * nu / (1.0 - nu * nu) : E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  }
  // J = (K_I^2 + K_II^2) / E'
  double e_prime() const { return plane_stress ? E : E / (1.0 - nu * nu); }
};

/* Williams near-tip displacement (leading term) at (x1, x2), u[i] */
inline void williams_displacement(double KI, double KII, double x1, double x2, const Elastic &el,
                                  double u[2])
{
  const double r = std::hypot(x1, x2), th = std::atan2(x2, x1);
  const double s = std::sin(0.5 * th), c = std::cos(0.5 * th), k = el.kappa();
  const double f = std::sqrt(r / (2.0 * PI)) / (2.0 * el.mu());
  u[0] = f * (KI * c * (k - 1.0 + 2.0 * s * s) + KII * s * (k + 1.0 + 2.0 * c * c));
  u[1] = f * (KI * s * (k + 1.0 - 2.0 * c * c) - KII * c * (k - 1.0 - 2.0 * s * s));
}

/* its gradient g[i][j] = du_i/dx_j: u = sqrt(r) f(theta), so du/dr = u/(2r),
   du/dtheta = sqrt(r) f'(theta) */
inline void williams_gradient(double KI, double KII, double x1, double x2, const Elastic &el,
                              double g[2][2])
{
  const double r = std::hypot(x1, x2), th = std::atan2(x2, x1);
  const double s = std::sin(0.5 * th), c = std::cos(0.5 * th), k = el.kappa();
  const double f = std::sqrt(r / (2.0 * PI)) / (2.0 * el.mu());
  const double u[2] = {
      f * (KI * c * (k - 1.0 + 2.0 * s * s) + KII * s * (k + 1.0 + 2.0 * c * c)),
      f * (KI * s * (k + 1.0 - 2.0 * c * c) - KII * c * (k - 1.0 - 2.0 * s * s))};
  const double dth[2] = {
      f * (KI * (-0.5 * s * (k - 1.0 + 2.0 * s * s) + 2.0 * s * c * c) +
           KII * (0.5 * c * (k + 1.0 + 2.0 * c * c) - 2.0 * s * s * c)),
      f * (KI * (0.5 * c * (k + 1.0 - 2.0 * c * c) + 2.0 * s * s * c) -
           KII * (-0.5 * s * (k - 1.0 - 2.0 * s * s) - 2.0 * s * c * c))};
  const double ct = std::cos(th), st = std::sin(th);
  for (int i = 0; i < 2; i++) {
    const double dr = u[i] / (2.0 * r);
    g[i][0] = ct * dr - st / r * dth[i];
    g[i][1] = st * dr + ct / r * dth[i];
  }
}

/* Williams near-tip stress (leading term): {sigma_11, sigma_22, sigma_12} */
inline void williams_stress(double KI, double KII, double x1, double x2, double sig[3])
{
  const double r = std::hypot(x1, x2), th = std::atan2(x2, x1);
  const double s = std::sin(0.5 * th), c = std::cos(0.5 * th);
  const double s3 = std::sin(1.5 * th), c3 = std::cos(1.5 * th);
  const double f = 1.0 / std::sqrt(2.0 * PI * r);
  sig[0] = f * (KI * c * (1.0 - s * s3) - KII * s * (2.0 + c * c3));
  sig[1] = f * (KI * c * (1.0 + s * s3) + KII * s * c * c3);
  sig[2] = f * (KI * s * c * c3 + KII * c * (1.0 - s * s3));
}

/* in-plane Hooke's law from the displacement gradient: sig[i][j] */
inline void hooke(const double g[2][2], const Elastic &el, double sig[2][2])
{
  const double mu = el.mu(), tr = el.lambda() * (g[0][0] + g[1][1]);
  sig[0][0] = tr + 2.0 * mu * g[0][0];
  sig[1][1] = tr + 2.0 * mu * g[1][1];
  sig[0][1] = sig[1][0] = mu * (g[0][1] + g[1][0]);
}

/* weight q(r) = 1 - 3 s^2 + 2 s^3, s = (r - rin)/(rout - rin): 1 inside rin,
   0 outside rout, continuous slope (zero at both radii) */
inline void q_weight(double r, double rin, double rout, double &q, double &dqdr)
{
  if (r <= rin) {
    q = 1.0;
    dqdr = 0.0;
  } else if (r >= rout) {
    q = 0.0;
    dqdr = 0.0;
  } else {
    const double w = rout - rin, s = (r - rin) / w;
    q = 1.0 - s * s * (3.0 - 2.0 * s);
    dqdr = -6.0 * s * (1.0 - s) / w;
  }
}

/* true if the segment p-q (crack-tip coordinates) crosses the crack line
   x2 = 0 behind the tip (x1 < 0): the crack faces do not see each other */
inline bool crosses_crack(const double p[2], const double q[2])
{
  if ((p[1] >= 0.0) == (q[1] >= 0.0)) return false;
  const double x1 = p[0] + (q[0] - p[0]) * (-p[1]) / (q[1] - p[1]);
  return x1 < 0.0;
}

/* Least-squares gradient over a neighbourhood: G = B K^-1 with
   K = sum w xi (x) xi, B = sum w (f_j - f_i) (x) xi (exact for linear fields). */
struct Moment {
  double k[3] = {0.0, 0.0, 0.0};    // K11, K22, K12
  void add(const double xi[2], double w)
  {
    k[0] += w * xi[0] * xi[0];
    k[1] += w * xi[1] * xi[1];
    k[2] += w * xi[0] * xi[1];
  }
  double det() const { return k[0] * k[1] - k[2] * k[2]; }
  // inverse {Ki11, Ki22, Ki12}; false if the neighbours are (nearly) collinear
  bool inverse(double ki[3]) const
  {
    const double d = det();
    if (!(d > 1.0e-12 * (k[0] + k[1]) * (k[0] + k[1]))) return false;
    ki[0] = k[1] / d;
    ki[1] = k[0] / d;
    ki[2] = -k[2] / d;
    return true;
  }
};

// g[i][j] = sum_n B[i][n] Kinv[n][j]; B[i][n] = sum w df_i xi_n
inline void apply_inverse(const double b[2][2], const double ki[3], double g[2][2])
{
  for (int i = 0; i < 2; i++) {
    g[i][0] = b[i][0] * ki[0] + b[i][1] * ki[2];
    g[i][1] = b[i][0] * ki[2] + b[i][1] * ki[1];
  }
}

/* fields at one integration point, in crack-tip coordinates */
struct Point {
  double x[2];          // position relative to the tip
  double gu[2][2];      // du_i/dx_j
  double gv[2][2];      // dv_i/dx_j
  double v[2], a[2];    // velocity, acceleration
  double rho, area;     // mass density, area of the point
};

/* what depends on the position only: the weight q, its gradient and the gradients of the
   unit auxiliary Williams fields (mode I, mode II); zero at the tip itself, where the
   auxiliary field is singular */
struct Aux {
  double q, dq[2];
  double ga[2][2][2];
};

inline void aux_fields(const double x[2], const Elastic &el, double rin, double rout, Aux &a)
{
  const double r = std::hypot(x[0], x[1]);
  double dqdr;
  q_weight(r, rin, rout, a.q, dqdr);
  a.dq[0] = r > 0.0 ? dqdr * x[0] / r : 0.0;
  a.dq[1] = r > 0.0 ? dqdr * x[1] / r : 0.0;
  for (int mode = 0; mode < 2; mode++) {
    if (r == 0.0 || a.q == 0.0) {
      for (int i = 0; i < 2; i++) a.ga[mode][i][0] = a.ga[mode][i][1] = 0.0;
      continue;
    }
    williams_gradient(mode == 0 ? 1.0 : 0.0, mode == 0 ? 0.0 : 1.0, x[0], x[1], el, a.ga[mode]);
  }
}

/* the three integrands, times the area: out = {J, I(aux K_I = 1), I(aux K_II = 1)} */
inline void integrand(const Point &p, const Elastic &el, const Aux &a, double out[3])
{
  out[0] = out[1] = out[2] = 0.0;
  if (a.q == 0.0) return;
  const double q = a.q, *dq = a.dq;

  double sig[2][2];
  hooke(p.gu, el, sig);
  const double eps[2][2] = {{p.gu[0][0], 0.5 * (p.gu[0][1] + p.gu[1][0])},
                            {0.5 * (p.gu[0][1] + p.gu[1][0]), p.gu[1][1]}};
  double w = 0.0;
  for (int i = 0; i < 2; i++)
    for (int j = 0; j < 2; j++) w += 0.5 * sig[i][j] * eps[i][j];
  const double t = 0.5 * p.rho * (p.v[0] * p.v[0] + p.v[1] * p.v[1]);

  double jq = -(w + t) * dq[0], jd = 0.0;
  for (int i = 0; i < 2; i++) {
    for (int j = 0; j < 2; j++) jq += sig[i][j] * p.gu[i][0] * dq[j];
    jd += p.rho * (p.a[i] * p.gu[i][0] - p.v[i] * p.gv[i][0]);
  }
  out[0] = p.area * (jq + jd * q);

  for (int mode = 0; mode < 2; mode++) {
    const double(*ga)[2] = a.ga[mode];
    double sa[2][2];
    hooke(ga, el, sa);
    double iq = 0.0, id = 0.0, cross = 0.0;
    for (int i = 0; i < 2; i++) {
      for (int j = 0; j < 2; j++) {
        iq += (sig[i][j] * ga[i][0] + sa[i][j] * p.gu[i][0]) * dq[j];
        cross += sa[i][j] * eps[i][j];
      }
      id += p.rho * p.a[i] * ga[i][0];
    }
    iq -= cross * dq[0];
    out[1 + mode] = p.area * (iq + id * q);
  }
}

inline void integrand(const Point &p, const Elastic &el, double rin, double rout, double out[3])
{
  Aux a;
  aux_fields(p.x, el, rin, rout, a);
  integrand(p, el, a, out);
}

/* K from the interaction integral with a unit auxiliary field */
inline double k_from_interaction(double I, const Elastic &el)
{
  return 0.5 * el.e_prime() * I;
}

}    // namespace BBPD::JIntegral

#endif

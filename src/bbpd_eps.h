// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the elastic-plastic family (EPS) of LAMMPS's pair style peri/eps
   (src/PERI/pair_peri_eps.cpp; Mitchell, "A nonlocal, ordinary, state-based plasticity model
   for peridynamics", SAND2011-3166), used by pair style bbpd/eps (pair_bbpd_lps.h) through
   the history row of bbpd_lps_history_row.h. No LAMMPS header, so that the unit tests can
   use it on plain numbers.

   The LPS state of bbpd_lps.h; the force state of a bond (atom i's end, partner j,
   w V = omega V_j ramp) is
     t_ij = 3K w V (theta_i / m_i + theta_j / m_j) xi0 + td_ij V_j ramp,
     td_ij = 15 G omega (1 / m_i + 1 / m_j) (ed - edp)             (the trial state)
   with ed = e - theta_i xi0 / 3 and edp the plastic deviatoric extension of the bond end.
   Per step and atom, with the pointwise yield value psi0 = 25 Y^2 / (8 pi delta^5) (Y the
   yield stress, delta the horizon of atom i's type) and the norm
   |td|^2 = sum_j td_ij^2 V_j ramp over atom i's bonds:
     |td|^2 / 2 <= psi0   elastic: td as is, and edp = 0 for the next step (*)
     otherwise            plastic: td scaled onto the yield surface, sqrt(2 psi0) / |td|;
                          delta_lambda = (|td| / sqrt(2 psi0) - 1) m_i / (15 G) is added to
                          atom i's lambda, and edp += td delta_lambda xi0 / 2
   (*) peri/eps collects the new edp in a zeroed array that only plastic atoms write, so an
   atom's plastic extensions return to zero at its first elastic step; bbpd/eps does the same
   (doc/pair_bbpd_ves_eps.rst). The energy density of atom i is K theta_i^2 / 2 plus, per bond,
   15 G / (2 m_i) w V (ed - edp)^2 (the trial state's, as peri/eps tallies it).
   History: per bond end (edp used in this step, edp after it), per atom (lambda, |td| of the
   last evaluation), so that a second evaluation of a step repeats its forces.
------------------------------------------------------------------------- */

#ifndef BBPD_EPS_H
#define BBPD_EPS_H

#include <cmath>

namespace BBPD {
namespace EPS {

  constexpr double PI = 3.14159265358979323846;
  // psi0 = 25 Y^2 / (8 pi delta^5): the pointwise yield value of peri/eps (Mitchell 2011)
  constexpr double YIELD_NUMERATOR = 25.0;
  constexpr double YIELD_DENOMINATOR = 8.0;
  // edp grows by td delta_lambda xi0 / 2 (peri/eps: the 1/length influence function)
  constexpr double PLASTIC_LENGTH_SHARE = 0.5;

  inline double pointwise_yield_value(double yield_stress, double delta)
  {
    const double d2 = delta * delta;
    return YIELD_NUMERATOR / YIELD_DENOMINATOR / PI / (d2 * d2 * delta) *
        (yield_stress * yield_stress);
  }

  // the coefficients of atom i's type and its weighted volume
  struct Coeffs {
    double deviatoric;    // 15 G of the force state (Moduli::deviatoric, bbpd_lps.h)
    double psi0;          // pointwise yield value
    double m;             // weighted volume m_i
  };

  /* the family as the history row uses it (bbpd_lps_history_row.h) */
  struct Family {
    static constexpr int BOND_HISTORY = 2;    // edp used in this step, edp after it
    static constexpr int ATOM_HISTORY = 2;    // lambda, |td| of the last evaluation
    static constexpr int LAMBDA = 0, NORM = 1;
    static constexpr bool NEEDS_NORM = true;
    struct Plan {
      bool plastic;
      double scale;    // sqrt(2 psi0) / |td| when plastic
      double delta_lambda;
    };

    Coeffs c;

    /* a bond end's term of |td|^2, td^2 V_j ramp (= td omega-free times td with w V); ROLL
       (the first evaluation of a step): the last step's new edp becomes this step's */
    template <bool ROLL>
    double norm_term(double wv, double omega, double ed, double inv_sum, double *h) const
    {
      return norm_term_v<ROLL>(wv, omega, ed, inv_sum, h[0], h[1]);
    }
    // the same over any width V (double, Vec4, Vec8: bbpd_simd.h), the history in h0, h1
    template <bool ROLL, class V> V norm_term_v(V wv, V omega, V ed, V inv_sum, V &h0, V &h1) const
    {
      if (ROLL) h0 = h1;
      const V s = V(c.deviatoric) * inv_sum * (ed - h0);
      return (s * omega) * (s * wv);
    }
    // elastic or plastic from the norm of the row
    Plan plan(double norm) const
    {
      const double fsurf = 0.5 * (norm * norm) - c.psi0;
      if (!(fsurf > 0.0)) return {false, 1.0, 0.0};
      const double root = std::sqrt(2.0 * c.psi0);
      return {true, root / norm, (norm / root - 1.0) * c.m / c.deviatoric};
    }
    /* the deviatoric force state of a bond end with w V (the td V_j ramp term of t_ij); COMMIT
       writes the new edp into h[1]; energy: w V (ed - edp)^2 */
    template <bool COMMIT>
    double deviatoric(const Plan &p, double wv, double omega, double xi0, double ed, double inv_sum,
                      double *h, double &energy) const
    {
      return deviatoric_v<COMMIT>(p, wv, omega, xi0, ed, inv_sum, h[0], h[1], energy);
    }
    // the same over any width V, the history in h0, h1
    template <bool COMMIT, class V>
    V deviatoric_v(const Plan &p, V wv, V omega, V xi0, V ed, V inv_sum, V &h0, V &h1,
                   V &energy) const
    {
      const V d = ed - h0;
      const V k = V(c.deviatoric) * inv_sum * d;
      energy = wv * (d * d);
      if (!p.plastic) {
        if (COMMIT) h1 = V(0.0);
        return k * wv;
      }
      if (COMMIT)
        h1 = h0 + (V(p.scale) * (k * omega)) * V(p.delta_lambda) * (V(PLASTIC_LENGTH_SHARE) * xi0);
      return V(p.scale) * (k * wv);
    }
  };

}    // namespace EPS
}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the viscoelastic family (VES) of LAMMPS's pair style peri/ves
   (src/PERI/pair_peri_ves.cpp; Mitchell, "A non-local, ordinary-state-based viscoelasticity
   model for peridynamics", SAND2011-8064), used by pair style bbpd/ves
   (pair_bbpd_lps.h) through the history row of bbpd_lps_history_row.h. No LAMMPS header, so
   that the unit tests can use it on plain numbers.

   The LPS state of bbpd_lps.h with two changes in the force state of a bond (atom i's end,
   partner j, w V = omega V_j ramp):
     t_ij = 3K w V (theta_i / m_i + theta_j / m_j) xi0
          + 15 G w V (1 / m_i + 1 / m_j) ((1 - lambda) ed + lambda (ed - edb))
   (in d dimensions d K and d (d + 2) G, split_dilatational and Moduli::deviatoric of
   bbpd_lps.h: the kernel styles bbpd/ves/KERNEL in plane strain and plane stress)
   ed = e - theta_i xi0 / d is the deviatoric extension (atom i's dilatation only), edb the
   back extension of the bond end, a dashpot of relaxation time tau in series with a spring:
   per step dt, from the last step's ed_n and edb_n,
     edb = ed_n (1 - decay) + edb_n decay + beta (ed - ed_n),
     decay = exp(-dt / tau),  beta = 1 - (tau / dt) (1 - decay)
   (the exact integral of the dashpot over a step with ed linear in time). lambda in [0, 1]
   is the share of the shear modulus that relaxes. The energy density of atom i is
   K theta_i^2 / 2 plus, per bond, 15 G / (2 m_i) w V ((1 - lambda) ed^2 + lambda (ed - edb)^2).
   The history of a bond end is the pair (ed_n, edb_n), BOND_HISTORY doubles.
------------------------------------------------------------------------- */

#ifndef BBPD_VES_H
#define BBPD_VES_H

#include <cmath>

namespace BBPD {
namespace VES {

  // the coefficients of atom i's type for a time step dt
  struct Coeffs {
    double deviatoric;    // d (d + 2) G of the force state (Moduli::deviatoric, bbpd_lps.h)
    double lambda;        // relaxing share of G
    double decay;     // exp(-dt / tau)
    double beta;      // 1 - (tau / dt) (1 - decay)
  };
  inline Coeffs coeffs(double deviatoric, double lambda, double tau, double dt)
  {
    const double c1 = tau / dt;    // peri/ves's names
    const double decay = std::exp(-1.0 / c1);
    return {deviatoric, lambda, decay, 1.0 - c1 * (1.0 - decay)};
  }

  // the back extension of this step from the bond end's history (ed_n, edb_n) and ed, over any
  // width V (double, Vec4, Vec8: bbpd_simd.h)
  template <class V> inline V back_extension(const Coeffs &c, V ed, V ed_last, V edb_last)
  {
    return ed_last * V(1.0 - c.decay) + edb_last * V(c.decay) + V(c.beta) * (ed - ed_last);
  }

  /* the family as the history row uses it (bbpd_lps_history_row.h) */
  struct Family {
    static constexpr int BOND_HISTORY = 2;    // ed and edb of the last evaluation
    static constexpr int ATOM_HISTORY = 0;
    static constexpr bool NEEDS_NORM = false;
    struct Plan {};    // nothing over the row

    Coeffs c;

    /* the deviatoric force state of a bond end (the 15 G term of t_ij) for w V (wv), the
       deviatoric extension ed and 1 / m_i + 1 / m_j (inv_sum); h its history. COMMIT: the
       first evaluation of a step advances the history; otherwise h already holds this step's
       back extension (a second evaluation of the step). energy: its w V ((1 - lambda) ed^2 +
       lambda (ed - edb)^2) (15 G / (2 m_i) times it is atom i's energy density). */
    template <bool COMMIT>
    double deviatoric(const Plan &p, double wv, double omega, double xi0, double ed, double inv_sum,
                      double *h, double &energy) const
    {
      return deviatoric_v<COMMIT>(p, wv, omega, xi0, ed, inv_sum, h[0], h[1], energy);
    }
    // the same over any width V, the history (h0, h1) = (ed_n, edb_n) in and out
    template <bool COMMIT, class V>
    V deviatoric_v(const Plan &, V wv, V, V, V ed, V inv_sum, V &h0, V &h1, V &energy) const
    {
      V edb = h1;
      if (COMMIT) {
        edb = back_extension(c, ed, h0, h1);
        h0 = ed;
        h1 = edb;
      }
      const V k = V(c.deviatoric) * wv * inv_sum;
      const V eb = ed - edb;
      energy = wv * (V(1.0 - c.lambda) * (ed * ed) + V(c.lambda) * (eb * eb));
      return V(1.0 - c.lambda) * k * ed + V(c.lambda) * k * eb;
    }
  };

}    // namespace VES
}    // namespace BBPD

#endif

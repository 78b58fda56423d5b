// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the bond loop of one row of an LPS state whose deviatoric part has a history, for
   a family policy F (bbpd_ves.h, bbpd_eps.h), with no LAMMPS dependency, summed with one
   accumulator: the reference of the unit tests (test_ves_eps.cpp) and the force state of a
   breaking bond (pair_bbpd_lps_history.cpp); the rows run its lanes form,
   bbpd_lps_history_lanes.h.

   A family F provides
     F::BOND_HISTORY, F::ATOM_HISTORY   doubles of history per bond end and per atom
     F::NEEDS_NORM, F::Plan             what the family decides once per row before its bonds
                                        (EPS: elastic or plastic from the norm of the trial
                                        state, norm_term() per bond, plan(norm)); else Plan is
                                        empty
     deviatoric<COMMIT>(plan, wV, omega, xi0, ed, 1/m_i + 1/m_j, h, energy), and
     deviatoric_v over any width V with the history as (h0, h1) (bbpd_lps_history_lanes.h)
                                        the deviatoric force state of a bond end with
                                        history h; COMMIT (the first evaluation of a step)
                                        advances h; energy: its term of atom i's deviatoric
                                        energy before the factor 15 G / (2 m_i)
   so the force state of bond i-j is
     t_ij = d K wV (theta_i / m_i + theta_j / m_j) xi0 + deviatoric(...),
   d K the split dilatational coefficient (split_dilatational, bbpd_lps.h: 3K for peri/ves and
   peri/eps), ed = e - theta_i xi0 / d; zero unless both ends have a weighted volume (as
   bbpd_lps.h).
   Bond k of the row (its k-th intact bond) keeps its history in slot slot[k] of the row's
   blocks hist (bbpd_history_blocks.h).
------------------------------------------------------------------------- */

#ifndef BBPD_LPS_HISTORY_ROW_H
#define BBPD_LPS_HISTORY_ROW_H

#include "bbpd_history_blocks.h"
#include "bbpd_lps_row.h"

#include <cmath>

namespace BBPD {
namespace LPS {

  // the force state of one bond end of a family with history (see above)
  template <class F, bool COMMIT>
  inline double history_force_state(double dilatational, const F &fam, const typename F::Plan &plan,
                                    double wv, double xi0, double e, double theta_third_i,
                                    const AtomState &a, const AtomState &b, double &h0,
                                    double &h1, double &energy)
  {
    energy = 0.0;
    if (!(a.inv_m > 0.0 && b.inv_m > 0.0)) return 0.0;
    const double ed = deviatoric_extension(e, xi0, theta_third_i);
    return dilatational * wv * (a.theta_over_m + b.theta_over_m) * xi0 +
        fam.template deviatoric_v<COMMIT>(plan, wv, influence(xi0), xi0, ed, a.inv_m + b.inv_m, h0,
                                          h1, energy);
  }

  /* the norm of the row's trial deviatoric state (F::NEEDS_NORM), sqrt of the sum of
     norm_term over its bonds; ROLL: the first evaluation of a step. Arguments as row_sums
     (bbpd_lps_row.h), with the row's history (hist, slot). */
  template <class F, bool ROLL, bool CACHED, class Idx, class Values>
  inline double history_row_norm(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                                 const double *r_row, const AtomState *states, double theta_third_i,
                                 const F &fam, const int *slot, double *hist)
  {
    const double xi = xx[3 * i], yi = xx[3 * i + 1], zi = xx[3 * i + 2];
    const AtomState si = states[i];
    double sum = 0.0;
    for (int k = 0; k < n; k++) {
      const int j = partner_index(bj, i, k);
      const double xi0 = vals.xi0_at(k, j), wv = vals.coef_at(k, j);
      const double dx = xx[3 * j] - xi, dy = xx[3 * j + 1] - yi, dz = xx[3 * j + 2] - zi;
      const double r = CACHED ? r_row[k] : std::sqrt(dx * dx + dy * dy + dz * dz);
      const double ed = deviatoric_extension(elongation(r, xi0), xi0, theta_third_i);
      constexpr int B = F::BOND_HISTORY;
      sum += fam.template norm_term_v<ROLL>(wv, influence(xi0), ed, si.inv_m + states[j].inv_m,
                                            history_value<B>(hist, slot[k], 0),
                                            history_value<B>(hist, slot[k], 1));
    }
    return std::sqrt(sum);
  }

  /* row_sums of bbpd_lps_row.h for a family with history: the same sums and breaking check,
     the force state of history_force_state with the row's plan; COMMIT as there */
  template <class F, bool EV, bool CHECK, bool CACHED, bool COMMIT, class Idx, class Values,
            class Check>
  inline bool history_row_sums(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                               const double *r_row, const AtomState *states, double dilatational,
                               const F &fam, const typename F::Plan &plan, double theta_third_i,
                               const int *slot, double *hist, Check check, RowSums &out)
  {
    const double xi = xx[3 * i], yi = xx[3 * i + 1], zi = xx[3 * i + 2];
    const AtomState si = states[i];
    double ax = 0.0, ay = 0.0, az = 0.0;
    double eng = 0.0, v0 = 0.0, v1 = 0.0, v2 = 0.0, v3 = 0.0, v4 = 0.0, v5 = 0.0;
    bool past = false;
    for (int k = 0; k < n; k++) {
      const int j = partner_index(bj, i, k);
      const double xi0 = vals.xi0_at(k, j), wv = vals.coef_at(k, j);
      const double dx = xx[3 * j] - xi, dy = xx[3 * j + 1] - yi, dz = xx[3 * j + 2] - zi;
      const double r = CACHED ? r_row[k] : std::sqrt(dx * dx + dy * dy + dz * dz);
      const double e = elongation(r, xi0);
      double energy;
      constexpr int B = F::BOND_HISTORY;
      const double t = history_force_state<F, COMMIT>(
          dilatational, fam, plan, wv, xi0, e, theta_third_i, si, states[j],
          history_value<B>(hist, slot[k], 0), history_value<B>(hist, slot[k], 1), energy);
      const double fpl = r > 0.0 ? t / r : 0.0;
      ax += fpl * dx;
      ay += fpl * dy;
      az += fpl * dz;
      if (EV) {
        eng += energy;
        v0 += fpl * dx * dx;
        v1 += fpl * dy * dy;
        v2 += fpl * dz * dz;
        v3 += fpl * dx * dy;
        v4 += fpl * dx * dz;
        v5 += fpl * dy * dz;
      }
      if (CHECK) past |= check(j, e, xi0);
    }
    out.f[0] = ax;
    out.f[1] = ay;
    out.f[2] = az;
    out.wv_ed2 = eng;
    const double v[6] = {v0, v1, v2, v3, v4, v5};
    for (int c = 0; c < 6; c++) out.fdd[c] = v[c];
    return past;
  }

}    // namespace LPS
}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the bond loop of one row of the linear peridynamic solid (bbpd_lps.h), with no LAMMPS
   dependency (tests/unit/test_lps_row.cpp runs it on plain arrays): the force density on
   atom i from the force states of its bonds, the sums its energy and virial are made of, and,
   with CHECK, the breaking test of each bond. The rows of the pair styles run its lanes form
   (bbpd_lps_lanes.h, whose unit test takes this loop as reference); the families with history
   take RowSums (bbpd_lps_history_row.h).

   The bonds are summed in row order with one accumulator per sum. The force state reads the
   state (theta / m, 1 / m) of both ends, so a bond's force is not a function of the bond alone,
   as the bond models of bbpd_bond_model.h are: this loop is the LPS family's, beside the
   bond-based row kernels of bbpd_row.h.
------------------------------------------------------------------------- */

#ifndef BBPD_LPS_ROW_H
#define BBPD_LPS_ROW_H

#include "bbpd_lps.h"
#include "bbpd_partner_index.h"

#include <cmath>

namespace BBPD {
namespace LPS {

  // what one pass over a row sums
  struct RowSums {
    double f[3];      // force density on atom i
    double wv_ed2;    // sum of w V ed^2 over the bonds (the deviatoric energy before its factor)
    double fdd[6];    // sums of (t / |y|) d_a d_b, xx yy zz xy xz yz (the virial before its factor)
  };

  /* The n bonds of atom i: partners bj (local indices or offsets, bbpd_partner_index.h),
     reference length and weighted partner volume of bond k from vals (xi0_at, coef_at), the
     positions xx (3 per atom), the states of all atoms (states), atom i's moduli and theta_i / d
     (theta_third_i). With CACHED the current lengths are read from r_row (a pass over the
     same row that computed them with the same operations, the dilatation pass), else computed.
     With EV the energy and virial sums are filled. With CHECK, check(j, e, xi0) is called for
     every bond (partner j, elongation e) and says whether it is past breaking; the return
     value is whether any is. */
  template <bool EV, bool CHECK, bool CACHED, class Idx, class Values, class Check>
  inline bool row_sums(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                       const double *r_row, const AtomState *states, const Moduli &mod,
                       double theta_third_i, Check check, RowSums &out)
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
      const double t = force_state(mod, wv, xi0, e, si, states[j]);
      const double fpl = r > 0.0 ? t / r : 0.0;
      ax += fpl * dx;
      ay += fpl * dy;
      az += fpl * dz;
      if (EV) {    // sums of the bonds' terms: the factors are applied once per row
        const double ed = deviatoric_extension(e, xi0, theta_third_i);
        eng += wv * (ed * ed);
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

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: one bond of the bond-based model, with no LAMMPS dependency.

   What a bond does with its current length r, reference length xi0 and
   coefficient coef = c(xi0) C_v V_j / xi0 (bbpd_bond_law.h): its elongation,
   force, share of the energy and virial, and whether it breaks. Every bond loop
   calls these and nothing else for it: the portable loop with V = double, the
   AVX2 and AVX-512 kernels with Vec4 and Vec8 (bbpd_simd.h), the canonical test
   both ends of a bond agree on, and the Silling-Askari loop. A new bond model or
   breaking rule is a new struct with these members, passed to the loops as their
   Model parameter (doc/architecture.rst, "Adding a bond model"); the unit test
   tests/unit/test_bond_model.cpp runs a toy one through every width.
------------------------------------------------------------------------- */

#ifndef BBPD_BOND_MODEL_H
#define BBPD_BOND_MODEL_H

#include "bbpd_simd.h"

namespace BBPD {

/* the prototype microelastic brittle bond (eqs. 6, 9, 21, 22): a linear spring in the
   elongation that breaks, for good, once its stretch exceeds the critical stretch s0 */
struct CriticalStretchBond {
  template <class V> static V elongation(V r, V xi0) { return r - xi0; }
  // force on atom i per unit of the difference x_j - x_i: c (r - xi0) / r (eq. 21)
  template <class V> static V force_per_length(V coef, V elong, V r) { return coef * elong / r; }
  // each end tallies half of the bond's micropotential (eq. 6), 1/4 c elong^2 (with the
  // coefficient's 1/xi0 and the partner volume)
  template <class V> static V energy_share(V coef, V elong) { return V(0.25) * coef * elong * elong; }
  // each end's share of the energy the bond carries away as it breaks: its share at the critical
  // elongation s0 xi0, which its stretch crossed within the step. (At the stretch it has at the
  // end of the step, the overshoot of that step would enter the energy balance as an error of
  // first order in the time step: compute bbpd/energy, doc/compute_bbpd_energy.rst.)
  template <class V> static V broken_energy_share(V coef, V xi0, V s0)
  {
    return energy_share(coef, s0 * xi0);
  }
  // and half of its virial (x_i - x_j) (x) f_i, component a b, with the sign of f_i = f (x_j - x_i)
  template <class V> static V virial_share(V fpl, V da, V db) { return V(0.5) * fpl * da * db; }
  // past the critical stretch s0 (eq. 22), or within 'margin' (a length) of it
  template <class V> static auto past_critical(V elong, V xi0, V s0, V margin)
  {
    return elong + margin > s0 * xi0;
  }
};

/* the Silling-Askari critical stretch of peri/pmb and of the bbpd/KERNEL/alpha styles: bond i-j breaks
   when its stretch exceeds min(s0_i, s0_j), s0_a = s00 - alpha smin_a, smin_a the smallest
   stretch of atom a's bonds at the previous step; with CLAMP only compression counts
   (s0_a = s00 - alpha min(0, smin_a)), so a body in pure tension keeps the calibrated s00 */
template <bool CLAMP> struct SillingAskariRule {
  // a bond that breaks is dropped at once: no force in that step, its energy booked at its
  // critical stretch (CriticalStretchBond::broken_energy_share)
  static constexpr bool FORCE_IN_BREAKING_STEP = false;
  // the elongation a stretch is read from: the bond model's, as it is
  template <class V> static V settled_elongation(V elong) { return elong; }
  template <class V> static V critical_stretch(V s00, V alpha, V smin_i, V smin_j)
  {
    const V smax = vmax(smin_i, smin_j);
    return s00 - alpha * (CLAMP ? vmin(V(0.0), smax) : smax);
  }
  template <class V> static V stretch(V elong, V xi0) { return elong / xi0; }
  // past s0 or within 'margin' (a stretch) of it
  template <class V> static auto past_critical(V s, V s0, V margin) { return s + margin > s0; }
};

}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the rules of LAMMPS's pair style peri/pmb (src/PERI/pair_peri_pmb.cpp,
   fix_peri_neigh.cpp; Parks et al., Comput. Phys. Commun. 179 (2008) 777), used by
   pair style bbpd/pmb (pair_bbpd_pmb.h), and the Silling-Askari critical stretch
   (Silling & Askari, Comput. Struct. 83 (2005) 1526, eq. 40) that also backs the
   styles bbpd/KERNEL/alpha (pair_bbpd_alpha.h). Free of LAMMPS so unit tests can use it.
------------------------------------------------------------------------- */

#ifndef LMP_BBPD_PMB_RULES_H
#define LMP_BBPD_PMB_RULES_H

#include "bbpd_bond_model.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace BBPD {
namespace PMB {

  // short-range forces act between any two atoms closer than
  // min(SHORT_RANGE_BOND_FACTOR |xi0|, SHORT_RANGE_LATTICE_FACTOR lc) (peri/pmb's constants)
  constexpr double SHORT_RANGE_BOND_FACTOR = 0.9;
  constexpr double SHORT_RANGE_LATTICE_FACTOR = 1.35;
  // their stiffness is 15 c V_j / delta: Silling, EMU theory manual (12 May 2005), p. 18
  constexpr double SHORT_RANGE_STIFFNESS_FACTOR = 15.0;
  // the short-range force keeps its own list of candidate pairs, rebuilt when an atom has
  // moved half this many lattice constants (a performance choice: it must be > 0)
  constexpr double SHORT_RANGE_CANDIDATE_SKIN = 0.6;
  // peri/pmb sets an elongation below this to zero ("avoid roundoff errors")
  constexpr double NEAR_ZERO = 2.2204e-16;
  // smallest stretch of an atom without intact bonds: it never lowers a partner's s0
  constexpr double NO_BOND_STRETCH = -DBL_MAX;

  // the family: every atom within the horizon, boundary included
  inline bool in_family(double rsq, double delta) { return rsq <= delta * delta; }

  /* volume fraction of a partner at reference distance xi0: a linear ramp from 1 at
     delta - lc/2 to 1/2 at delta (fix_peri_neigh / pair_peri_pmb, written as there) */
  inline double volume_scale(double xi0, double delta, double lc)
  {
    const double half_lc = 0.5 * lc;
    if (std::abs(xi0 - delta) <= half_lc)
      return (-1.0 / (2 * half_lc)) * xi0 + (1.0 + ((delta - half_lc) / (2 * half_lc)));
    return 1.0;
  }

  inline double short_range_distance(double xi0, double lc)
  {
    return std::min(SHORT_RANGE_BOND_FACTOR * xi0, SHORT_RANGE_LATTICE_FACTOR * lc);
  }

}    // namespace PMB

/* peri/pmb's own Silling-Askari rule (bbpd/pmb): smin as is (no clamp), an elongation below
   NEAR_ZERO read as zero, and a bond that breaks still acts in that step, its energy then
   being what it carries away (pair_peri_pmb.cpp). The Silling-Askari loop takes it, or
   SillingAskariRule<true> (bbpd/KERNEL/alpha), as its Rule parameter. */
struct PeriPmbRule : SillingAskariRule<false> {
  static constexpr bool FORCE_IN_BREAKING_STEP = true;
  template <class V> static V settled_elongation(V elong)
  {
    return vdrop(vabs(elong) < V(PMB::NEAR_ZERO), elong);
  }
};
}    // namespace BBPD

#endif

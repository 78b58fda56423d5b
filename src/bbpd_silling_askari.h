// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the coefficients of the Silling-Askari breaking rules per type pair (s00 and alpha of
   pair_coeff) and the critical stretch of a bond from them, written once for every style with
   these rules (bbpd/KERNEL/alpha, bbpd/pmb, bbpd/lps, bbpd/ves, bbpd/eps); how s00, alpha and
   the smallest stretches combine is the Rule parameter (SillingAskariRule<CLAMP> of
   bbpd_bond_model.h, PeriPmbRule of bbpd_pmb_rules.h). No LAMMPS header.
------------------------------------------------------------------------- */

#ifndef BBPD_SILLING_ASKARI_H
#define BBPD_SILLING_ASKARI_H

#include <algorithm>
#include <limits>

namespace BBPD {

/* a lower bound of Rule's critical stretch s0 = s00 - alpha f(max(smin_i, smin_j)) for every
   partner j of atom i whose smallest stretch smin_j is at most smin_cap: with alpha >= 0, s0
   falls as smin_j rises (f: the identity, or min(0, .) for SillingAskariRule<true>), and
   rounding keeps that order (each operation is monotonic); else -infinity, which has every
   bond tested. The SIMD rows test a bond against its own s0 only when the row's largest
   stretch reaches this floor. */
template <class Rule>
inline double critical_stretch_floor(double s00, double alpha, double smin_i, double smin_cap)
{
  if (!(alpha >= 0.0)) return -std::numeric_limits<double>::infinity();
  return Rule::critical_stretch(s00, alpha, smin_i, smin_cap);
}

// the largest of v[0..n-1] (the smin_cap of critical_stretch_floor), lowest() if n is 0; four
// running maxima, so that an element's comparison need not wait for the last one's
inline double largest_of(const double *v, int n)
{
  double m[4] = {std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest(),
                 std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  int i = 0;
  for (; i + 3 < n; i += 4)
    for (int l = 0; l < 4; l++) m[l] = std::max(m[l], v[i + l]);
  for (; i < n; i++) m[0] = std::max(m[0], v[i]);
  return std::max(std::max(m[0], m[1]), std::max(m[2], m[3]));
}

/* s00 and alpha per type pair; with one s00 and alpha for every type pair (multi false) no
   per-bond lookup */
struct SillingAskariCoefficients {
  bool multi;    // s00 or alpha differ between type pairs
  double s00_one, alpha_one;
  double *const *s00, *const *alpha;    // [itype][jtype], types 1..ntypes

  static SillingAskariCoefficients of(double *const *s00, double *const *alpha, int ntypes)
  {
    SillingAskariCoefficients c{false, s00[1][1], alpha[1][1], s00, alpha};
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++)
        if (s00[i][j] != c.s00_one || alpha[i][j] != c.alpha_one) c.multi = true;
    return c;
  }

  // the critical stretch of the bond of atom i to j (types from 'type'), with the smallest
  // stretches smin_i and smin_j of the two atoms at the previous step
  template <class Rule>
  double critical_stretch(const int *type, int i, int j, double smin_i, double smin_j) const
  {
    if (!multi) return Rule::critical_stretch(s00_one, alpha_one, smin_i, smin_j);
    return Rule::critical_stretch(s00[type[i]][type[j]], alpha[type[i]][type[j]], smin_i, smin_j);
  }
};

}    // namespace BBPD

#endif

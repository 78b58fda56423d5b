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

namespace BBPD {

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

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: pair styles bbpd/constant/alpha, bbpd/triangular/alpha,
   bbpd/gaussian/alpha: the kernel styles with the Silling-Askari critical
   stretch (Silling & Askari, Comput. Struct. 83 (2005) 1526, eq. 40),
     s0 = s00 - alpha min(0, smallest bond stretch of the atom at the last step),
   'alpha A' in pair_coeff. A bond past it breaks and exerts no force (the bbpd
   order). Its loop also serves pair style bbpd/pmb (pair_bbpd_pmb.h), whose
   bonds act in the step they break and whose smin is not clamped.

   smin lives in the per-atom s0 of atom_style peri, which LAMMPS already sends
   to ghost atoms every step and carries through migration and restart files;
   fix bbpd/alpha keeps what a second evaluation of the same step needs
   (fix_bbpd_alpha.h).
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_ALPHA_H
#define LMP_PAIR_BBPD_ALPHA_H

#include "pair_bbpd.h"

namespace LAMMPS_NS {

class PairBBPDAlpha : public PairBBPD {
 public:
  PairBBPDAlpha(class LAMMPS *, BBPD::KernelInfo, const char *style = nullptr,
                Rules = Rules{true, false, false});
  ~PairBBPDAlpha() override;

 protected:
  int nmax_smin;
  double *smin_new;                   // smallest bond stretch of each local atom in this step
  class FixBBPDAlpha *alpha_state;    // what a second evaluation of the same step needs

  void eval_bonds() override;
  void init_rules() override;
  std::string report_rules() const override;

  // PMB: peri/pmb's order (a bond acts in the step it breaks, round-off elongations are zero,
  // smin is not clamped to compression)
  template <int EVFLAG, class Rule> void eval_silling_askari();
  template <int EVFLAG> double broken_bond_force(int i, int k, double *fb, double *acc);
};

}    // namespace LAMMPS_NS

#endif

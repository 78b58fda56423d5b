// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: pair styles bbpd/constant/alpha, bbpd/triangular/alpha,
   bbpd/gaussian/alpha: the kernel styles with the Silling-Askari critical
   stretch (Silling & Askari, Comput. Struct. 83 (2005) 1526, eq. 40),
     s0 = s00 - alpha min(0, smallest bond stretch of the atom at the last step),
   'alpha A' in pair_coeff. A bond past it breaks and exerts no force (the bbpd
   order). The style holds its state (pair_bbpd_silling_askari_state.h) and calls
   PairBBPD's Silling-Askari loop (pair_bbpd_silling_askari.cpp), which pair style
   bbpd/pmb calls with peri/pmb's rule (pair_bbpd_pmb.h).
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_ALPHA_H
#define LMP_PAIR_BBPD_ALPHA_H

#include "pair_bbpd.h"
#include "pair_bbpd_silling_askari_state.h"

namespace LAMMPS_NS {

class PairBBPDAlpha : public PairBBPD {
 public:
  PairBBPDAlpha(class LAMMPS *, BBPD::KernelInfo);
  ~PairBBPDAlpha() override;

 protected:
  SillingAskariState silling_askari;    // smin of this step and fix bbpd/alpha

  void eval_bonds() override;
  void init_rules() override;
  std::string report_rules() const override;
};

}    // namespace LAMMPS_NS

#endif

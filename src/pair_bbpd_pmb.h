// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: pair style bbpd/pmb, the rules of LAMMPS's peri/pmb in the bbpd
   loops (bbpd_pmb_rules.h).

   'pair_style bbpd/pmb MODEL' takes 'pair_coeff I J c delta s00 alpha' as
   peri/pmb does and follows its rules: families |xi| <= delta, the volume ramp
   within lc/2 of the horizon, short-range forces between all atoms closer than
   min(0.9 |xi|, 1.35 lc), and in each step: all intact bonds exert their force,
   then a bond breaks when its stretch exceeds s00 - alpha max(smin_i, smin_j),
   smin being the smallest stretch of each atom's bonds at the previous step
   (PairBBPD's Silling-Askari loop, pair_bbpd_silling_askari.cpp, with peri/pmb's
   rule and order; the short-range forces of pair_bbpd_peri_rules.cpp).
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_PMB_H
#define LMP_PAIR_BBPD_PMB_H

#include "pair_bbpd.h"
#include "pair_bbpd_silling_askari_state.h"

namespace LAMMPS_NS {

class PairBBPDPMB : public PairBBPD {
 public:
  explicit PairBBPDPMB(class LAMMPS *);
  ~PairBBPDPMB() override;

  void settings(int, char **) override;
  void coeff(int, char **) override;

 protected:
  SillingAskariState silling_askari;    // smin of this step and fix bbpd/alpha
  double lattice_constant;              // lc of the lattice command, as in peri/pmb

  void eval_bonds() override;
  void init_rules() override;
  std::string report_type_pair(int i, int j) const override;
  std::string report_rules() const override;
};

}    // namespace LAMMPS_NS

#endif

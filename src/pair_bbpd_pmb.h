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
   (the Silling-Askari loop of pair_bbpd_alpha.h, in peri/pmb's order).
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_PMB_H
#define LMP_PAIR_BBPD_PMB_H

#include "bbpd_pmb_rules.h"
#include "pair_bbpd_alpha.h"

namespace LAMMPS_NS {

class PairBBPDPMB : public PairBBPDAlpha {
 public:
  PairBBPDPMB(class LAMMPS *, const char *style = "bbpd/pmb");
  // a style on peri/pmb's rules whose bonds carry a kernel (bbpd/lps/KERNEL)
  PairBBPDPMB(class LAMMPS *, BBPD::KernelInfo, const char *style);

  void settings(int, char **) override;
  void coeff(int, char **) override;

 protected:
  double lattice_constant;    // lc of the lattice command, as in peri/pmb

  void eval_bonds() override;
  void init_rules() override;
  std::string report_type_pair(int i, int j) const override;
  std::string report_rules() const override;
  void compute_short_range();
  // the short-range stiffness of types i j per partner volume (peri/pmb: 15 c)
  virtual double short_range_stiffness(int itype, int jtype) const
  {
    return BBPD::PMB::SHORT_RANGE_STIFFNESS_FACTOR * micromodulus[itype][jtype];
  }
};

}    // namespace LAMMPS_NS

#endif

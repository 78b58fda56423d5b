// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: pair styles bbpd/lps/constant, bbpd/lps/triangular, bbpd/lps/gaussian: the
   linear peridynamic solid of pair style bbpd/lps (pair_bbpd_lps.h) with the kernel shape
   W(|xi| / delta) of bbpd_kernel.h as influence function and the engineering constants of
   the bond-based styles (bbpd_lps_kernel.h):
     pair_style bbpd/lps/KERNEL MODEL [thickness h] [keywords of bbpd/lps]
     pair_coeff I J E nu Gc|none delta
   MODEL is 3d, plane/strain or plane/stress (the 2D LPS of Le, Chan & Schwartz 2014). The
   bond storage, dilatation pass, ghost exchange, force loop, short-range forces, fix
   bbpd/lps state and restart are those of bbpd/lps; a bond breaks past the s0 derived from
   G_c (Silling-Askari alpha 0), 'none' never.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_LPS_KERNEL_H
#define LMP_PAIR_BBPD_LPS_KERNEL_H

#include "pair_bbpd_lps.h"

namespace LAMMPS_NS {

class PairBBPDLPSKernel : public PairBBPDLPS {
 public:
  PairBBPDLPSKernel(class LAMMPS *, BBPD::KernelInfo);

  void settings(int, char **) override;
  void coeff(int, char **) override;
  // the E and nu of pair_coeff (in 2D kappa' is not the 3D bulk modulus of the base class)
  double youngs_modulus(int itype) const override { return youngs[itype][itype]; }
  double poisson_ratio(int itype) const override
  {
    return youngs[itype][itype] / (2.0 * shear[itype][itype]) - 1.0;    // G = E / (2 (1 + nu))
  }

 protected:
  void init_rules() override;
  double bond_stiffness(int i, int k) const override;
  std::string report_type_pair(int i, int j) const override;
  std::string report_rules() const override;
};

}    // namespace LAMMPS_NS

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: compute bbpd/damage/atom -- local damage phi of eq. 17,
   phi_i = 1 - sum_{intact j} C_v V_j / sum_{all j} C_v V_j
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_BBPD_DAMAGE_ATOM_H
#define LMP_COMPUTE_BBPD_DAMAGE_ATOM_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeBBPDDamageAtom : public Compute {
 public:
  ComputeBBPDDamageAtom(class LAMMPS *, int, char **);
  ~ComputeBBPDDamageAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  int nmax;
  double *damage;
  class FixBBPDBonds *bonds;
};

}    // namespace LAMMPS_NS

#endif

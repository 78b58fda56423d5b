// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: compute bbpd/plasticity/atom -- the plastic multiplier lambda of every atom
   of pair style bbpd/eps (the sum of its plastic increments, bbpd_eps.h): LAMMPS's compute
   plasticity/atom for peri/eps. Atoms outside the group get 0.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_BBPD_PLASTICITY_ATOM_H
#define LMP_COMPUTE_BBPD_PLASTICITY_ATOM_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeBBPDPlasticityAtom : public Compute {
 public:
  ComputeBBPDPlasticityAtom(class LAMMPS *, int, char **);
  ~ComputeBBPDPlasticityAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  int nmax;
  double *values;
};

}    // namespace LAMMPS_NS

#endif

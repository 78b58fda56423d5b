// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: compute bbpd/dilatation/atom -- the dilatation theta of every atom at the
   last force evaluation, for the state-based styles (bbpd/lps, bbpd/lps/KERNEL, bbpd/ves,
   bbpd/eps): LAMMPS's compute dilatation/atom for peri/lps, peri/ves and peri/eps. Atoms
   outside the group get 0.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_BBPD_DILATATION_ATOM_H
#define LMP_COMPUTE_BBPD_DILATATION_ATOM_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeBBPDDilatationAtom : public Compute {
 public:
  ComputeBBPDDilatationAtom(class LAMMPS *, int, char **);
  ~ComputeBBPDDilatationAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

 private:
  int nmax;
  double *values;
};

}    // namespace LAMMPS_NS

#endif

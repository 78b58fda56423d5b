// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: compute bbpd/energy -- the energy account of a group, in
   energy units of the body as modelled (LAMMPS's peridynamic pe and ke are
   sums of densities; these are densities times atom volumes):
     [1] elastic energy of the pair style (intact bonds, and contact when on)
     [2] kinetic energy
     [3] energy that broken bonds carried away when they broke, since the bonds
         were made (fix bbpd/bonds keeps it per atom, in restart files)
     [4] work done on the group by everything but the pair style (fix bbpd/work)
     [5] [1] + [2] + [3] - [4]: constant to the time integrator's error
   Each is an exact sum over the atoms (bbpd_exact_sum.h): the same bits on any
   number of ranks.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_BBPD_ENERGY_H
#define LMP_COMPUTE_BBPD_ENERGY_H

#include "compute.h"

#include <string>

namespace LAMMPS_NS {

class ComputeBBPDEnergy : public Compute {
 public:
  ComputeBBPDEnergy(class LAMMPS *, int, char **);
  ~ComputeBBPDEnergy() override;
  void init() override;
  void compute_vector() override;

  static constexpr int NTERMS = 4;

 private:
  std::string work_id;
  class FixBBPDWork *work;
  class FixBBPDBonds *bonds;
};

}    // namespace LAMMPS_NS

#endif

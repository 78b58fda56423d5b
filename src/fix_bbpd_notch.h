// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: fix bbpd/notch -- pre-cracks made of broken bonds.

   fix ID group bbpd/notch segment x1 y1 x2 y2 [segment ...]          (2D)
   fix ID group bbpd/notch rectangle cx cy cz ax ay az bx by bz [...]  (3D)
   fix ID group bbpd/notch groups G1 G2 [...]                         (any dimension)

   Every bond of an atom in the group whose reference segment crosses a notch
   starts broken (paper sec. 4.2.3). An endpoint lying exactly on the notch
   counts as being on its positive side, so a notch through a row of atoms
   cuts that row from the negative side instead of leaking. 'groups G1 G2'
   cuts every bond between an atom of G1 and one of G2 (a pre-crack between
   two bodies); both ends of a bond decide alike because LAMMPS sends the
   group masks of ghost atoms.

   The cut is made at every run setup (setup_pre_force: the families exist and
   their cache is fresh), through the interface of fix bbpd/bonds (remove_bonds_if);
   cutting is idempotent.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_NOTCH_H
#define LMP_FIX_BBPD_NOTCH_H

#include "fix.h"

#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class FixBBPDNotch : public Fix {
 public:
  FixBBPDNotch(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_force(int) override;

  // pure geometry, public for unit tests
  struct Cut {
    double p[3], a[3], b[3];    // origin and edge vectors (b = 0 for a 2D segment)
  };
  static bool crosses(const Cut &, const double *xa, const double *xb, int dim);
  static double plane_distance(const Cut &, const double *x, int dim);

 private:
  std::vector<Cut> cuts;
  // group pairs by name: looked up again at init, as a group may be redefined after this fix
  std::vector<std::pair<std::string, std::string>> group_names;
  std::vector<std::pair<int, int>> group_bits;
  class FixBBPDBonds *bonds;
};

}    // namespace LAMMPS_NS

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the per-atom state of pair style bbpd/lps (pair_bbpd_lps.h).

   Created by the pair style (ID BBPD_LPS); not meant for input scripts.
   Persistent per-atom data, carried through atom migration and restart files (the three
   columns of FixBBPDAtomState, kept as per-atom arrays: the dilatations are extract("theta")):
     weighted_volume[i]   m_i of bbpd_lps.h, summed once over the bonds of the atom at the
                          first force evaluation after its family was built (as peri/lps
                          fixes wvolume when it builds the families) and kept while bonds break
     dilatation[i]        theta_i of the last force evaluation
     lost[i]              bonds the atom lost at that evaluation: a second evaluation of the
                          same step (setup of a run, read_restart) reuses dilatation[i] for such
                          an atom, whose broken bonds counted in it, and sums it again for
                          the others
   Global (in restart files): whether the weighted volumes exist.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_LPS_H
#define LMP_FIX_BBPD_LPS_H

#include "fix_bbpd_atom_state.h"

namespace LAMMPS_NS {

class FixBBPDLPS : public FixBBPDAtomState {
 public:
  FixBBPDLPS(class LAMMPS *, int, char **);
  int setmask() override { return 0; }

  void write_restart(FILE *) override;
  void restart(char *) override;

  static constexpr int VALUES = 3;    // per atom: weighted volume, dilatation, lost bonds
  int ready;                          // the weighted volumes have been summed
  // the columns, [i] (they follow the arrays as these grow)
  double *&weighted_volume = columns[0];
  double *&dilatation = columns[1];
  double *&lost = columns[2];
};

}    // namespace LAMMPS_NS

#endif

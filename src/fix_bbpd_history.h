// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the history of the state-based families with memory, bbpd/ves and bbpd/eps
   (pair_bbpd_lps.h; the families in bbpd_ves.h and bbpd_eps.h).

   Created by the pair style (ID BBPD_HISTORY); not meant for input scripts.
   Persistent per-atom data, carried through atom migration, 'balance' and restart files:
     values[i][0 .. A-1]                 the family's per-atom history (A = ATOM_HISTORY)
     values[i][A + B m .. A + B m + B-1]  the history of the bond to partner slot m of fix
                                          bbpd/bonds (partner[i][m], B = BOND_HISTORY): the
                                          slots keep their order for the life of the bond
   width = A + B maxpartner doubles per atom (FixBBPDAtomState), set by the pair style once the
   families exist (and read back from a restart file). Global data: none.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_HISTORY_H
#define LMP_FIX_BBPD_HISTORY_H

#include "fix_bbpd_atom_state.h"

namespace LAMMPS_NS {

class FixBBPDHistory : public FixBBPDAtomState {
 public:
  FixBBPDHistory(class LAMMPS *, int, char **);
  int setmask() override { return 0; }
};

}    // namespace LAMMPS_NS

#endif

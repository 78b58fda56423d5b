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
   width = A + B maxpartner doubles per atom, set by the pair style once the families exist
   (and read back from a restart file). Global data: none.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_HISTORY_H
#define LMP_FIX_BBPD_HISTORY_H

#include "fix.h"

namespace LAMMPS_NS {

class FixBBPDHistory : public Fix {
 public:
  FixBBPDHistory(class LAMMPS *, int, char **);
  ~FixBBPDHistory() override;
  int setmask() override { return 0; }

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override { return 1 + width; }
  int maxsize_restart() override { return 1 + width; }

  // w doubles per atom from now on: the first min(w, width) kept, the others zero
  void set_width(int w);
  int width;
  double **values;

 private:
  int nmax_values;
};

}    // namespace LAMMPS_NS

#endif

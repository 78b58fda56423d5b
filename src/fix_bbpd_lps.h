// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the per-atom state of pair style bbpd/lps (pair_bbpd_lps.h).

   Created by the pair style (ID BBPD_LPS); not meant for input scripts.
   Persistent per-atom data, carried through atom migration and restart files:
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

#include "fix.h"

namespace LAMMPS_NS {

class FixBBPDLPS : public Fix {
 public:
  FixBBPDLPS(class LAMMPS *, int, char **);
  ~FixBBPDLPS() override;
  int setmask() override { return 0; }

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override { return 1 + VALUES; }
  int maxsize_restart() override { return 1 + VALUES; }

  static constexpr int VALUES = 3;    // per atom: weighted volume, dilatation, lost bonds
  int ready;                          // the weighted volumes have been summed
  double *weighted_volume, *dilatation, *lost;
};

}    // namespace LAMMPS_NS

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: what the Silling-Askari bond loop (bbpd/pmb, bbpd/KERNEL/alpha) needs to evaluate
   a time step again, e.g. at the setup after read_restart or of a second 'run'.

   Created by the pair style (ID BBPD_ALPHA); not meant for input scripts.
     last_step      time step of the last force evaluation (global, in restart files)
     fbroken[i]     with bbpd/pmb:  force density on atom i from the bonds that broke
                    at that step (they act in the step they break, as in peri/pmb): the
                    three per-atom values of FixBBPDAtomState
   A second evaluation of the same step neither breaks bonds nor updates the smallest
   stretches, and adds fbroken: the forces, and so the run, are bitwise those of a run
   without the interruption.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_ALPHA_H
#define LMP_FIX_BBPD_ALPHA_H

#include "fix_bbpd_atom_state.h"

namespace LAMMPS_NS {

class FixBBPDAlpha : public FixBBPDAtomState {
 public:
  FixBBPDAlpha(class LAMMPS *, int, char **);
  int setmask() override { return 0; }

  void write_restart(FILE *) override;
  void restart(char *) override;

  bigint last_step;
  double **&fbroken = values;    // [i][0..2]
};

}    // namespace LAMMPS_NS

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: what the Silling-Askari bond loop (bbpd/pmb, bbpd/KERNEL/alpha) needs to evaluate
   a time step again, e.g. at the setup after read_restart or of a second 'run'.

   Created by the pair style (ID BBPD_ALPHA); not meant for input scripts.
     last_step      time step of the last force evaluation (global, in restart files)
     fbroken[i]     with bbpd/pmb:  force density on atom i from the bonds that broke
                    at that step (they act in the step they break, as in peri/pmb)
   A second evaluation of the same step neither breaks bonds nor updates the smallest
   stretches, and adds fbroken: the forces, and so the run, are bitwise those of a run
   without the interruption.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_ALPHA_H
#define LMP_FIX_BBPD_ALPHA_H

#include "fix.h"

namespace LAMMPS_NS {

class FixBBPDAlpha : public Fix {
 public:
  FixBBPDAlpha(class LAMMPS *, int, char **);
  ~FixBBPDAlpha() override;
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
  int size_restart(int) override { return 4; }
  int maxsize_restart() override { return 4; }

  bigint last_step;
  double **fbroken;
};

}    // namespace LAMMPS_NS

#endif

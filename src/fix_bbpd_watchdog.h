// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the run-explosion watchdog of the bbpd pair styles.

   Created by the pair style (ID BBPD_WATCHDOG); not meant for input scripts.
   Before atoms migrate (pre_exchange, once per reneighboring) it stops a run in
   which an atom moves more than a few grid spacings per step or the bonded body
   has grown far beyond its size when the bonds were made, with an ERROR that
   names the cause (the timestep, or imposed velocities), before LAMMPS bins an
   exploded box. A pair style has no hook at that point, hence a fix. It reads
   the bonded atoms from fix bbpd/bonds and the limits the pair style sends.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_WATCHDOG_H
#define LMP_FIX_BBPD_WATCHDOG_H

#include "bbpd_bond_storage.h"
#include "fix.h"

namespace LAMMPS_NS {

class FixBBPDWatchdog : public Fix {
 public:
  FixBBPDWatchdog(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void pre_exchange() override;

  // the pair style, at every init and whenever a limit changes
  void set_limits(const BBPD::RunLimits &r) { limits = r; }

 private:
  class FixBBPDBonds *bonds;
  BBPD::RunLimits limits;
};

}    // namespace LAMMPS_NS

#endif

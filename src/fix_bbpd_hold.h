// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the log of the bonds a minimize holds.

   Created by the pair style (ID BBPD_HOLD); not meant for input scripts. While
   LAMMPS minimizes, the bbpd pair styles break no bond (bbpd_bond_hold.h): a
   minimizer's line search evaluates trial states that are not equilibria, and a
   bond broken there would stay broken. At the setup of a minimize with fracture
   on it says so in the log; at its end it reports how many bonds are past
   breaking in the minimized state (held, not broken), with a WARNING if any
   are. A pair style has no hook at the end of a minimize, hence a fix.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_HOLD_H
#define LMP_FIX_BBPD_HOLD_H

#include "fix.h"

namespace LAMMPS_NS {

class FixBBPDHold : public Fix {
 public:
  FixBBPDHold(class LAMMPS *, int, char **);
  int setmask() override;
  void min_setup(int) override;
  void post_run() override;

  // the bonds past breaking in the pair style's last force evaluation (held), on all ranks
  bigint held_bonds();

 private:
  class PairBBPD *fracturing_pair();    // the bbpd pair style, if fracture is on
};

}    // namespace LAMMPS_NS

#endif

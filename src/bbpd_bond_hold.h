// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: when a pair style holds its bonds, with no LAMMPS dependency.

   Breaking is irreversible: a bond that breaks in a state the solver later
   rejects stays broken. LAMMPS's minimizers evaluate forces at trial states
   (line-search moves) that are not equilibria, so while LAMMPS minimizes the
   bbpd pair styles hold every bond, and fix bbpd/relax holds them while it
   iterates towards an equilibrium, letting go for one force evaluation in each
   converged state. A held evaluation breaks nothing; it counts the bond ends
   past breaking (fix bbpd/hold reports them after a minimize).
------------------------------------------------------------------------- */

#ifndef BBPD_BOND_HOLD_H
#define BBPD_BOND_HOLD_H

#include <cstdint>

namespace BBPD {

struct BondHold {
  static constexpr int MINIMIZE = 2;    // LAMMPS's update->whichflag while it minimizes
  bool by_fix = false;                  // fix bbpd/relax holds the bonds
  int64_t held_ends = 0;    // bond ends past breaking in the last held evaluation, this rank
  bool holds(int whichflag) const { return by_fix || whichflag == MINIMIZE; }
};

}    // namespace BBPD

#endif

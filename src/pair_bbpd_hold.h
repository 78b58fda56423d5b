// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: PairBBPD::count_held, what the row driver (pair_bbpd_rows.h)
   does with a row that has a bond past breaking while the bonds are held
   (bbpd_bond_hold.h): nothing breaks, and the bonds that would are counted.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_HOLD_H
#define LMP_PAIR_BBPD_HOLD_H

#include "pair_bbpd.h"

#include "fix_bbpd_bonds.h"

namespace LAMMPS_NS {

/* the bonds of row i that would break now, counted in hold.held_ends. A style's breaks(k) also
   books what a breaking bond carries away (fix bbpd/bonds' ebroken, the energy and virial
   tallies, the force a rule applies in the breaking step): a copy of the row asks it, with its
   tallies sent to a scratch array, and atom i's booked values are put back */
template <class Row> void PairBBPD::count_held(int i, Row row)
{
  double scratch[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  row.acc = scratch;
  const double ebroken = bonds->ebroken[i];
  const double e_atom = eflag_atom ? eatom[i] : 0.0;
  double v_atom[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  for (int m = 0; m < 6 && vflag_atom; m++) v_atom[m] = vatom[i][m];
  int n = 0;
  for (int k = bonds->bond_start[i]; k < bonds->bond_start[i] + bonds->nbond[i]; k++)
    if (row.breaks(k)) n++;
  bonds->ebroken[i] = ebroken;
  if (eflag_atom) eatom[i] = e_atom;
  for (int m = 0; m < 6 && vflag_atom; m++) vatom[i][m] = v_atom[m];
  if (n > 0) {
#if defined(_OPENMP)
#pragma omp atomic
#endif
    hold.held_ends += n;
  }
}

}    // namespace LAMMPS_NS

#endif

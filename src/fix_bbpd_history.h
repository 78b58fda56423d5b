// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the history of the state-based families with memory, bbpd/ves and bbpd/eps
   (pair_bbpd_lps.h; the families in bbpd_ves.h and bbpd_eps.h).

   Created by the pair style (ID BBPD_HISTORY); not meant for input scripts.
   Persistent per-atom data, carried through atom migration, 'balance' and restart files, one
   row per local atom (bbpd_partner_rows.h), as long as the atom's own family:
     row(i)[0 .. A-1]                 the family's per-atom history (A = ATOM_HISTORY)
     row(i)[A + B m .. A + B m + B-1] the history of the bond to partner slot m of fix
                                      bbpd/bonds (partner[i][m], B = BOND_HISTORY): the slots
                                      keep their order for the life of the bond
   A ghost slot holds no row (peri/ves's per-atom arrays of maxpartner slots, local and ghost,
   cost 4-5 times the history itself on LAMMPS's benchmark deck). Restart files hold
   {1 + length, row...} per atom, the layout of the files written when every row was
   A + B maxpartner long, which read back as longer rows. Global data: none.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_HISTORY_H
#define LMP_FIX_BBPD_HISTORY_H

#include "fix.h"

#include "bbpd_partner_rows.h"

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
  int size_restart(int i) override { return 1 + rows.room(i); }
  int maxsize_restart() override { return 1 + max_length; }

  // every local atom's row at least atom_width + bond_width npartner[i] long, the values held
  // kept and the new ones zero; rows are never longer than atom_width + bond_width maxpartner
  void fit(int atom_width, int bond_width, const int *npartner, int maxpartner);
  double *row(int i) { return rows[i]; }
  int length(int i) const { return rows.room(i); }
  // the bytes of the rows once fit() has sized those of the local atoms
  double bytes_when_fit(int atom_width, int bond_width, const int *npartner) const;

 private:
  BBPD::PartnerRows<double> rows;
  int max_length;    // the longest row an atom may bring (exchange, restart)
  void resize_keep(int i, int n);
  void allow_length(int n);
  void take_row(int i, int n, const double *src);
};

}    // namespace LAMMPS_NS

#endif

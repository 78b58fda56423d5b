// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the history of the state-based families with memory, bbpd/ves and bbpd/eps
   (pair_bbpd_lps.h; the families in bbpd_ves.h and bbpd_eps.h).

   Created by the pair style as  fix BBPD_HISTORY all bbpd/history A B  (A, B: the family's
   ATOM_HISTORY and BOND_HISTORY); not meant for input scripts.
   Persistent per-atom data, carried through atom migration, 'balance' and restart files, one
   row per local atom (bbpd_partner_rows.h), as long as the atom's own family:
     row(i)[0 .. A-1]   the family's per-atom history
     row(i)[A ..]       the history of the bonds, B values per partner slot m of fix
                        bbpd/bonds (partner[i][m]) in blocks of slots (bbpd_history_blocks.h):
                        the slots keep their order for the life of the bond
   A ghost slot holds no row (peri/ves's per-atom arrays of maxpartner slots, local and ghost,
   cost 4-5 times the history itself on LAMMPS's benchmark deck). Restart files hold
   {1 + length, row...} per atom with a slot's B values side by side, the layout of the files
   written before the blocks and when every row was A + B maxpartner long (such rows read back
   as longer rows). Global data: none.
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

  // every local atom's row long enough for npartner[i] slots, the values held kept and the new
  // ones zero; no row longer than maxpartner slots need
  void fit(const int *npartner, int maxpartner);
  double *row(int i) { return rows[i]; }
  int length(int i) const { return rows.room(i); }
  // the bytes of the rows once fit() has sized those of the local atoms
  double bytes_when_fit(const int *npartner) const;
  int atom_width() const { return atom_values; }
  int bond_width() const { return bond_values; }

 private:
  BBPD::PartnerRows<double> rows;
  int atom_values, bond_values;    // A and B
  int max_length;                  // the longest row an atom may bring (exchange, restart)
  int row_length(int nslots) const;
  void resize_keep(int i, int n);
  void allow_length(int n);
  void take_row(int i, int n, const double *src);
};

}    // namespace LAMMPS_NS

#endif

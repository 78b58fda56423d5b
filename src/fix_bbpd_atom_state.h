// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the base of the internal fixes that carry per-atom state of one width for
   every atom (fix bbpd/alpha, bbpd/work, bbpd/lps; fix bbpd/history keeps rows as long as
   each atom's family instead): width doubles per atom, grown with the atom arrays, set
   to zero for a new atom, carried through atom migration ('balance' included) and, the first
   'saved' of them (all by default), through restart files as {1 + saved, values...}. A
   subclass says what the columns mean and adds what else it keeps (global restart data, fix
   hooks). The values are kept in one of two layouts:
     ROWS      values[i][0 .. width-1], one row per atom; set_width() changes the width (a
               restart file written with another width)
     COLUMNS   columns[c][0 .. nmax-1], one array per column, for a state handed out as
               per-atom arrays (fix bbpd/lps: its dilatations are extract("theta"), as
               peri/lps's); the width is fixed at construction
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_ATOM_STATE_H
#define LMP_FIX_BBPD_ATOM_STATE_H

#include "fix.h"

namespace LAMMPS_NS {

class FixBBPDAtomState : public Fix {
 public:
  static constexpr int ALL = -1;
  enum class Layout { ROWS, COLUMNS };
  // created_by: the command that creates the fix (for the error on extra arguments)
  FixBBPDAtomState(class LAMMPS *, int, char **, const char *created_by, int width,
                   int saved = ALL, Layout = Layout::ROWS);
  ~FixBBPDAtomState() override;

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override { return 1 + saved_width(); }
  int maxsize_restart() override { return 1 + saved_width(); }

  // ROWS: w doubles per atom from now on: the first min(w, width) kept, the others zero
  void set_width(int w);
  int width;
  double **values;     // ROWS: [i][c]
  double **columns;    // COLUMNS: [c][i]; growing may move a column: keep a reference to columns[c]

 protected:
  const Layout layout;
  int saved;    // columns in restart files, ALL for every one
  int saved_width() const { return saved == ALL ? width : saved; }
  double &value(int i, int c) { return layout == Layout::ROWS ? values[i][c] : columns[c][i]; }

 private:
  int nmax_values;
};

}    // namespace LAMMPS_NS

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the base of the internal fixes that carry per-atom state (fix bbpd/alpha,
   bbpd/history, bbpd/work): width doubles per atom, values[i][0 .. width-1], grown with the
   atom arrays, set to zero for a new atom, carried through atom migration ('balance'
   included) and, the first 'saved' of them (all by default), through restart files as
   {1 + saved, values...}. A subclass says what the columns mean and adds what else it
   keeps (global restart data, fix hooks).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_ATOM_STATE_H
#define LMP_FIX_BBPD_ATOM_STATE_H

#include "fix.h"

namespace LAMMPS_NS {

class FixBBPDAtomState : public Fix {
 public:
  static constexpr int ALL = -1;
  // created_by: the command that creates the fix (for the error on extra arguments)
  FixBBPDAtomState(class LAMMPS *, int, char **, const char *created_by, int width,
                   int saved = ALL);
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

  // w doubles per atom from now on: the first min(w, width) kept, the others zero
  void set_width(int w);
  int width;
  double **values;

 protected:
  int saved;    // columns in restart files, ALL for every one
  int saved_width() const { return saved == ALL ? width : saved; }

 private:
  int nmax_values;
};

}    // namespace LAMMPS_NS

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: where the history of each intact bond of a row lies, with no LAMMPS dependency. Bond k
   of row i (its k-th intact bond) keeps its history in partner slot of(i)[k] of fix
   bbpd/bonds (bbpd_history_blocks.h: the slot's place in the row's history). The slots rise
   with k. A row that lost no partner has its bonds in slots 0 .. n-1: it stores nothing and
   reads a shared 0, 1, 2, ... (dense_slots, bbpd_lps_history_lanes.h). Only a row with lost
   partners keeps slots of its own: on LAMMPS's benchmark deck no row does, where an int per
   bond end cost 8 bytes per bond. A row that breaks bonds in a step writes its new slots
   (fewer than before) where it kept them, or at the end if it had none.
------------------------------------------------------------------------- */

#ifndef BBPD_BOND_SLOTS_H
#define BBPD_BOND_SLOTS_H

#include <numeric>
#include <vector>

namespace BBPD {

class BondSlots {
 public:
  // nrows rows, none with slots of its own, rows of up to longest bonds
  void reset(int nrows, int longest)
  {
    start.assign(nrows, DENSE);
    pool.clear();
    if ((int) identity.size() < longest) {
      identity.resize(longest);
      std::iota(identity.begin(), identity.end(), 0);
    }
  }
  // the slots of row i's bonds
  const int *of(int i) const { return start[i] == DENSE ? identity.data() : pool.data() + start[i]; }
  // room for row i's own n slots, to be written by the caller (n no more than it had, if it
  // had slots of its own)
  int *own(int i, int n)
  {
    if (start[i] == DENSE) {
      start[i] = (int) pool.size();
      pool.resize(pool.size() + n);
    }
    return pool.data() + start[i];
  }
  bool dense(int i) const { return start[i] == DENSE; }
  double bytes() const
  {
    return (double) (start.capacity() + pool.capacity() + identity.capacity()) * sizeof(int);
  }

 private:
  static constexpr int DENSE = -1;
  std::vector<int> start;    // per row: its first slot in pool, or DENSE
  std::vector<int> pool;     // the slots of the rows with lost partners
  std::vector<int> identity;
};

}    // namespace BBPD

#endif

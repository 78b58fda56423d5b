// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the partner tags of every atom's bond family, one row per atom slot, each row exactly
   as long as the atom's family.

   LAMMPS's per-atom 2D arrays have one width for every slot: an atom on a free surface (a
   third of a full family in 3D) or a ghost slot would pay for the largest family on any
   rank, about 2 bytes per bond on a thin 3D plate. Here the rows lie in one pool, each slot
   holding where its row starts and how long it may grow (8 bytes per slot). The rows follow
   LAMMPS's per-atom callbacks: copy (a sort: the source slot is read again), move (migration:
   the source slot is deleted), clear (a slot taken by a new atom). A row that does not fit
   where it was goes to the pool's end; the pool is compacted when what no slot uses is as
   large as what the slots use. Pointers into rows are valid until the next change of a row.
   No LAMMPS dependency.
------------------------------------------------------------------------- */

#ifndef BBPD_PARTNER_ROWS_H
#define BBPD_PARTNER_ROWS_H

#include <algorithm>
#include <cstddef>
#include <vector>

namespace BBPD {

template <class Tag> class PartnerRows {
 public:
  Tag *operator[](int i) { return pool.data() + slots[i].start; }
  const Tag *operator[](int i) const { return pool.data() + slots[i].start; }

  // at least n slots; the rows of the slots kept are untouched
  void grow(int n)
  {
    if (n > static_cast<int>(slots.size())) slots.resize(n);
  }
  // slot i holds room for n partners (their values are the caller's to write; a row that keeps
  // its room keeps its values)
  void resize(int i, int n)
  {
    if (n <= slots[i].cap) return;
    release(i);
    slots[i] = {append(n), n};
  }
  void clear(int i) { release(i); }
  // the partners slot i has room for
  int room(int i) const { return slots[i].cap; }
  // room for n more partners at the pool's end, allocated once (before a family build)
  void reserve_more(std::size_t n) { pool.reserve(pool.size() + n); }
  // slot j becomes a copy of the first n partners of slot i (LAMMPS's copy with delflag 0: slot
  // i is still in use)
  void copy(int i, int j, int n)
  {
    if (i == j) return;
    resize(j, n);
    std::copy_n(pool.data() + slots[i].start, n, pool.data() + slots[j].start);
  }
  // slot j takes slot i's row, which is left empty (a copy whose source is deleted)
  void move(int i, int j)
  {
    if (i == j) return;
    release(j);
    slots[j] = slots[i];
    slots[i] = {};
  }

  // bytes held: the slots and the pool
  double bytes() const
  {
    return static_cast<double>(slots.capacity()) * sizeof(Slot) +
        static_cast<double>(pool.capacity()) * sizeof(Tag);
  }

 private:
  struct Slot {
    std::size_t start = 0;
    int cap = 0;
  };
  std::vector<Slot> slots;
  std::vector<Tag> pool;
  std::size_t unused = 0;    // pool entries no slot holds

  void release(int i)
  {
    unused += slots[i].cap;
    slots[i] = {};
  }
  // room for n more at the pool's end, after compacting it if half of it is unused
  std::size_t append(int n)
  {
    if (unused > 0 && unused >= pool.size() - unused) compact();
    const std::size_t at = pool.size();
    pool.resize(at + n);
    return at;
  }
  // the rows moved to the front of the pool in slot order, without gaps
  void compact()
  {
    std::vector<Tag> packed;
    packed.reserve(pool.size() - unused);
    for (auto &s : slots) {
      const std::size_t at = packed.size();
      packed.insert(packed.end(), pool.begin() + s.start, pool.begin() + s.start + s.cap);
      s.start = at;
    }
    pool.swap(packed);
    unused = 0;
  }
};

}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: what the pair style tells its bond storage (fix bbpd/bonds) besides
   the bond law: how much of each bond to cache, and the limits of a stable
   run. No LAMMPS dependency.
------------------------------------------------------------------------- */

#ifndef BBPD_BOND_STORAGE_H
#define BBPD_BOND_STORAGE_H

namespace BBPD {

/* What the per-bond cache holds besides the partner (a 2-byte offset, or a 4-byte index where
   a partner is out of an offset's reach: bbpd_partner_index.h): FAST also keeps the reference
   length and the coefficient, as a class into the rank's table of distinct pairs
   (bbpd_bond_table.h, 16 bytes per bond) or per bond where a rank has too many distinct pairs
   (44 bytes per bond); COMPACT recomputes both from x0 when needed, with the same operations,
   so the same bits (12 bytes per bond). 4 bytes more per bond with indices. */
class BondStorage {
 public:
  enum Kind { FAST, COMPACT };
  constexpr BondStorage(Kind k = FAST) : kind(k) {}
  constexpr bool caches_geometry() const { return kind == FAST; }
  constexpr bool operator==(BondStorage o) const { return kind == o.kind; }
  constexpr bool operator!=(BondStorage o) const { return kind != o.kind; }
  // restart files hold the policy as an int: 0 fast, 1 compact
  constexpr int code() const { return kind == FAST ? 0 : 1; }
  static constexpr BondStorage from_code(int c) { return c ? COMPACT : FAST; }

 private:
  Kind kind;
};

/* The storage stops a run that has blown up (before LAMMPS bins an exploded box) and names
   the cause with these numbers; in a periodic box with breaking bonds both ends of a bond
   must see their owners' unshifted positions. */
struct RunLimits {
  bool breaks_bonds = false;       // some type pair has a finite critical stretch
  double grid_spacing = 0.0;
  double stable_timestep = 0.0;    // velocity-Verlet bound, 0 until the first setup report
  double timestep_safety = 1.0;    // fraction of the bound a run may use without a warning
};

}    // namespace BBPD

#endif

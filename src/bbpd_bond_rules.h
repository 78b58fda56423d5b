// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: what the bond-family storage (fix bbpd/bonds) asks of the material,
   and how much of each bond it keeps. No LAMMPS dependency.

   The storage builds families and caches per-bond data, but knows no physics:
   the pair style hands it a BondRules (which pairs are bonded, the coefficient
   and volume of a bond, the limits a stable run keeps) and a BondStorage (what
   the cache holds). Dependencies then run one way: pair -> storage -> rules.
------------------------------------------------------------------------- */

#ifndef BBPD_BOND_RULES_H
#define BBPD_BOND_RULES_H

namespace BBPD {

class BondRules {
 public:
  // is a pair of types itype, jtype at squared reference distance rsq in a family?
  virtual bool in_family(int itype, int jtype, double rsq) const = 0;
  // force density per unit elongation of a bond of reference length xi0 to a partner of
  // volume vj: c(xi0) C_v V_j / xi0 (eqs. 9, 19, 21)
  virtual double bond_coef(int itype, int jtype, double xi0, double vj) const = 0;
  // the partner volume the bond counts for the damage (eq. 17): C_v V_j
  virtual double bond_volume(int itype, int jtype, double xi0, double vj) const = 0;
  // dimension of the family integral (1, 2 or 3) and the grid spacing an atom volume implies:
  // they bound the number of partners an atom can have
  virtual int family_dimension() const = 0;
  virtual double grid_spacing_of(double vfrac) const = 0;
  // can bonds break? (then both ends of a bond across a periodic boundary need the same view)
  virtual bool breaks_bonds() const = 0;
  // grid spacing, stable timestep and the fraction of it a run may use: an unstable run is
  // stopped with these numbers before LAMMPS bins an exploded box
  virtual double grid_spacing() const = 0;
  virtual double stable_timestep() const = 0;
  virtual double timestep_safety() const = 0;

 protected:
  ~BondRules() = default;
};

/* What the per-bond cache holds besides the partner index: with FAST also the reference
   length and the coefficient (48 bytes per bond); COMPACT recomputes both from x0 when needed,
   with the same operations, so the same bits (16 bytes per bond). */
class BondStorage {
 public:
  enum Kind { FAST, COMPACT };
  constexpr BondStorage(Kind k = FAST) : kind(k) {}
  constexpr bool caches_geometry() const { return kind == FAST; }
  constexpr bool operator==(BondStorage o) const { return kind == o.kind; }
  constexpr bool operator!=(BondStorage o) const { return kind != o.kind; }
  constexpr const char *name() const { return kind == FAST ? "fast" : "compact"; }
  // restart files store the policy as an int (0 fast, 1 compact)
  constexpr int code() const { return kind == FAST ? 0 : 1; }
  static constexpr BondStorage from_code(int c) { return c ? COMPACT : FAST; }
  // cached bytes per bond end besides the partner index: reference length and coefficient
  constexpr double cached_bytes() const { return caches_geometry() ? 2.0 * sizeof(double) : 0.0; }

 private:
  Kind kind;
};

}    // namespace BBPD

#endif

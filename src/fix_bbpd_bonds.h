// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: bond families of the bbpd pair styles.

   Created by the pair style (ID BBPD_BONDS); not meant for input scripts.
   Persistent per-atom data, carried through atom migration and restart files:
     npartner[i]       number of bonds the atom started with
     partner[i][k]     tag of partner k; negative = broken (rows of their own length,
                       bbpd_partner_rows.h). Partners are kept in
                       the order of their reference offset x0_j - x0_i (compared
                       exactly: z, then y, then x): the summation order then
                       depends on the geometry only, not on the atom numbering
     vinit[i]          sum of C_v V_j over the initial family (damage, eq. 17)
     ebroken[i]        energy (not a density) that atom i's halves of its broken bonds
                       held when they broke, summed since the bonds were made (term 3 of
                       compute bbpd/energy; booked by the pair style's breaking rules)
   Cached per intact bond, rebuilt only when LAMMPS reneighbors (post_neighbor),
   one flat structure-of-arrays row per local atom, partners in that order:
     bond_start[i], nbond[i]  first entry and number of intact bonds of atom i
     bdelta[k]               partner's local/ghost index minus i, 2 bytes, for a row whose
                             partners are all within that reach (bbpd_partner_index.h); else
     bj[jstart[i] + k - bond_start[i]]  local/ghost index of the partner, 4 bytes (rows near a
                             rank's ghosts, or beyond the reach of an offset in memory order;
                             every row when the pair style's loop reads indices: then bdelta
                             and jstart are null and bj is indexed like bclass). partner_of(i, k)
                             and visit_row() read either
     bclass[k]               class of the bond in the rank's table 'classes' of distinct
                             (reference length, coefficient) pairs (bbpd_bond_table.h):
       classes.xi0(c)        reference bond length |x0_j - x0_i|
       classes.coef(c)       c(xi0) C_v V_j / xi0: force density per unit elongation
     vintact[i]              sum of C_v V_j over the intact bonds (damage, eq. 17)
   A bond that breaks is removed from its row at once (the row shifts), so the
   force loop has no per-bond branch. 16 bytes per bond with offsets, 20 with indices.
   Should a rank have more distinct pairs than a class can address, the pairs are kept
   per bond instead (bxi0[k], bcoef[k]; bclass null), 44 or 48 bytes per bond. With the
   COMPACT storage policy (bbpd_bond_storage.h, 'bond/storage compact' of the pair
   style) only the partner is cached; reference length and coefficient are recomputed
   from x0 when needed (same operations, so the same bits), for 12 or 16 bytes per bond.

   The fix owns storage only. What a bond is and what it costs come from the
   BBPD::BondLaw (bbpd_bond_law.h, no LAMMPS dependency) the pair style passes
   with set_rules() at every init, once it has calibrated c0 and s0: a value
   holding its own copy of the calibrated numbers, no pointer into the pair's
   tables. With it come the storage policy and the run limits (whether bonds break,
   and the stable step for messages); the fix includes no pair-style header. The
   run-explosion watchdog is fix bbpd/watchdog (fix_bbpd_watchdog.h).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_BONDS_H
#define LMP_FIX_BBPD_BONDS_H

#include "atom.h"
#include "bbpd_bond_law.h"
#include "bbpd_bond_storage.h"
#include "bbpd_bond_table.h"
#include "bbpd_bond_values.h"
#include "bbpd_partner_index.h"
#include "bbpd_partner_rows.h"
#include "bbpd_row_paths.h"
#include "fix.h"

#include <atomic>
#include <vector>

namespace LAMMPS_NS {

class FixBBPDBonds : public Fix {
 public:
  FixBBPDBonds(class LAMMPS *, int, char **);
  ~FixBBPDBonds() override;
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup_post_neighbor() override;
  void post_neighbor() override;
  void min_post_neighbor() override { post_neighbor(); }
  void setup_pre_force(int) override;
  void pre_force(int) override;
  void min_pre_force(int vflag) override { pre_force(vflag); }
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  // the pair style, at every init after its calibration and before the fix's own init: the
  // bond law (calibrated values, copied), the storage policy and the run limits (again whenever
  // a limit changes)
  void set_rules(const BBPD::BondLaw &l, BBPD::BondStorage s)
  {
    law = l;
    policy = s;
    have_rules = true;
    coef_epoch = next_coef_epoch();    // coefficients recomputed with the old law are stale
  }
  void set_limits(const BBPD::RunLimits &r) { limits = r; }
  BBPD::BondStorage storage() const { return policy; }

  // used by the pair style, the computes and fix bbpd/notch
  bool families_built() const { return !first; }
  int maxpartner;
  int *npartner;
  BBPD::PartnerRows<tagint> partner;    // partner[i][k], npartner[i] of them (bbpd_partner_rows.h)
  double *vinit;
  double *ebroken;
  int *bond_start, *nbond;
  BBPD::PartnerOffset *bdelta;    // null when every row stores indices
  int *jstart;                    // per row: its first entry in bj, or -1 (offsets); null with bdelta
  int *bj;
  bool index_row(int i) const { return !bdelta || jstart[i] >= 0; }
  int partner_of(int i, int k) const
  {
    if (!bdelta) return bj[k];
    return jstart[i] < 0 ? i + bdelta[k] : bj[jstart[i] + k - bond_start[i]];
  }
  BBPD::BondClass *bclass;    // null unless the table holds the pairs
  BBPD::BondClassTable classes;
  double *bxi0, *bcoef;        // null unless the pairs are kept per bond
  double *vintact;
  // local damage of eq. 17, phi_i = 1 - vintact_i / vinit_i (0 before the families exist and
  // for an atom that never had a bond): what compute bbpd/damage/atom and bbpd/crack/tip report
  double damage(int i) const { return first || vinit[i] <= 0.0 ? 0.0 : 1.0 - vintact[i] / vinit[i]; }
  // compact storage: the type and volume of every local and ghost atom if they have one
  // (uniform_type 0 if not)
  int uniform_type;
  double uniform_vfrac;

  // the coefficients of the bonds of an atom of type itype (compact storage's cache misses)
  struct RowLaw {
    const BBPD::BondLaw *law;
    int itype;
    static double coefficient(const void *self, int jtype, double xi0, double vj)
    {
      const RowLaw &r = *static_cast<const RowLaw *>(self);
      return r.law->coefficient(r.itype, jtype, xi0, vj);
    }
  };
  /* Row i of the cache as the bond loops read it, whatever the layout: returns
     fn(partners, values), the partners as 2-byte offsets or 4-byte indices
     (bbpd_partner_index.h), the reference lengths and coefficients by class, per bond, or
     (compact storage) recomputed from x0 with this fix's bond law through 'cache', the calling
     thread's (bbpd_bond_values.h): the same doubles in every layout. */
  template <class Fn> auto visit_row(int i, BBPD::CoefCache &cache, Fn &&fn) const
  {
    const int beg = bond_start[i];
    auto with_values = [&](const auto *row_partners) {
      if (bclass)
        return fn(row_partners, BBPD::ClassValues{bclass + beg, classes.data()});
      if (bxi0) return fn(row_partners, BBPD::PerBondValues{bxi0 + beg, bcoef + beg});
      const RowLaw row_law{&law, atom->type[i]};
      const BBPD::CoefFunction coef_fn{&RowLaw::coefficient, &row_law};
      cache.start(coef_epoch);
      const int t_uniform = uniform_type * BBPD::CoefCache::TYPE_STRIDE + uniform_type;
      const double *x0 = atom->x0 ? atom->x0[0] : nullptr;
      // every atom in reach of one type and volume, and so every cache entry: lengths alone key it
      if (uniform_type > 0 && cache.holds_only(uniform_vfrac, t_uniform))
        return fn(row_partners, BBPD::UniformCompactValues{
                                    x0, i, atom->vfrac, atom->type, &cache, coef_fn, uniform_type, uniform_vfrac});
      return fn(row_partners, BBPD::CompactValues{
                                  x0, i, atom->vfrac, atom->type, &cache, coef_fn, uniform_type, uniform_vfrac});
    };
    if (!bdelta) return with_values(bj + beg);
    return jstart[i] < 0 ? with_values(bdelta + beg) : with_values(bj + jstart[i]);
  }

  /* the one way bonds break (the pair styles' breaking rules, fix bbpd/notch): remove every
     bond k of local atom i for which broken(k) is true, in row order, for good; returns how
     many. broken(k) sees the row as it is then: the bonds before k are the kept ones. */
  template <class Broken> int remove_bonds_if(int i, Broken &&broken)
  {
    int k = bond_start[i], removed = 0;
    while (k < bond_start[i] + nbond[i]) {
      if (broken(k)) {
        remove_bond(i, k);
        removed++;
      } else {
        k++;
      }
    }
    // summed again rather than decremented: the same bits as after the next reneighboring
    if (removed) {
      vintact[i] = intact_volume(i);
      removals.fetch_add(1, std::memory_order_relaxed);    // rows run in threads
    }
    return removed;
  }
  double xi0_of(int i, int k) const;                // reference length of bond k of atom i
  double coef_of(int i, int k, double xi0) const;    // its coefficient
  bigint count_broken() const;
  double bytes_per_bond() const;
  // unshifted position of atom j (local, or a ghost: its owner's coordinates) in a periodic box
  const double *raw_x(int j) const;
  // (false if no force evaluation has sent them yet, e.g. a pair computed outside a run)
  bool raw_positions() const
  {
    return need_raw && (owners_local || nmax_raw >= atom->nlocal + atom->nghost);
  }
  // shortest reference length of this rank's bonds at the last rebuild of the cache
  double min_reference_length() const { return xi0_min; }
  // counts the rebuilds of the cache: unchanged while every local index keeps its meaning
  bigint cache_generation() const { return generation; }
  // counts the rows that lost bonds: unchanged while every row keeps its bonds
  long row_removals() const { return removals.load(std::memory_order_relaxed); }
  // for fix bbpd/watchdog: the body's size now (atoms with bonds) and when the bonds were made
  double bonded_extent();
  double initial_extent() const { return extent0; }

 protected:
  int first;    // 1 until bond families exist
  int nlocal_cache, nbond_cache;    // allocated sizes of the per-atom and per-bond cache
  class NeighList *list;
  BBPD::BondLaw law;
  bool have_rules;
  BBPD::BondStorage policy;
  BBPD::RunLimits limits;
  double extent0;    // size of the body when the families were built (in restart files)
  int need_raw;       // periodic box with fracture: ghosts carry their owner's position
  int nmax_raw;
  double **xraw;      // owner's (unshifted) position of each ghost
  bool owners_local = false;    // one rank with an atom map: raw_x reads the owner itself
  bigint generation;
  std::atomic<long> removals{0};
  double xi0_min;
  std::vector<tagint> tags_cached;    // tag of every local and ghost index at the last rebuild
  bool same_atoms_at_same_indices();

  void size_family_neighbor_list();
  void set_maxexchange() { maxexchange = maxpartner + 3; }

  // entries past the last bond of bclass and bdelta: a whole SIMD vector may be read at a row end
  static constexpr int LANES_PAD = 8;
  void free_bond_values();
  void free_partners();
  int nbj_cache;           // allocated size of bj
  bigint nindex_ends;      // bond ends of the index rows at the last rebuild (storage report)
  void reserve_indices(int n);
  double sort_binsize = 0.0;    // the atom sort's bin size this fix chose (0: none chosen)
  void choose_sort_bins();
  void all_indices();
  void store_bond_values(int m, double xi, double coef);

  void remove_bond(int i, int k);
  unsigned coef_epoch = 0;    // of the law the compact coefficients are computed with
  static unsigned next_coef_epoch();
  void build_families();
  void release_family_list();
  void refresh_cache();
  double intact_volume(int i) const;
};

}    // namespace LAMMPS_NS

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: where the bond loops find a bond's reference length and coefficient, with no
   LAMMPS dependency. Three layouts of the bond cache of fix bbpd/bonds: a class into
   the rank's table of distinct pairs (bbpd_bond_table.h), per bond, or recomputed from
   the reference positions (bond/storage compact). FixBBPDBonds::visit_row() hands a
   row's view to a loop, so that no loop branches on the layout; the SIMD kernels read
   each view with their own loads (bbpd_row.h), the portable loops with xi0_at() and
   coef_at().
------------------------------------------------------------------------- */

#ifndef BBPD_BOND_VALUES_H
#define BBPD_BOND_VALUES_H

#include "bbpd_bond_table.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace BBPD {

/* where a row finds the reference length and coefficient of its bond k: per bond, or through
   the bond's class in the rank's table (the same doubles either way) */
struct PerBondValues {
  const double *xi0, *coef;
  double xi0_of(int k) const { return xi0[k]; }
  double coef_of(int k) const { return coef[k]; }
  // of bond k of the row, partner j: what the portable loops read, whatever the layout
  double xi0_at(int k, int) const { return xi0[k]; }
  double coef_at(int k, int) const { return coef[k]; }
};
struct ClassValues {
  const BBPD::BondClass *cls;    // readable LANES entries past the row's end
  const double *values;          // per class c: reference length values[2c], coefficient values[2c + 1]
  double xi0_of(int k) const { return values[2 * cls[k]]; }
  double coef_of(int k) const { return values[2 * cls[k] + 1]; }
  double xi0_at(int k, int) const { return xi0_of(k); }
  double coef_at(int k, int) const { return coef_of(k); }
};

/* bond/storage compact: the reference length and the coefficient recomputed from x0 with the
   operations of FixBBPDBonds::xi0_of() and coef_of(), through a per-thread cache keyed by
   everything they depend on (the squared reference length, the partner volume and the two
   types, compared exactly): a grid has a few hundred distinct keys, so the cache nearly always
   holds the pair, and gives the same bits as computing it (a square root and a coefficient
   saved per bond end). */
struct CoefCache {
  static constexpr int SLOT_BITS = 11;
  static constexpr int SIZE = 1 << SLOT_BITS;    // entries: a few times the keys of a grid
  std::vector<double> rsq0, vj;         // per entry, key: squared reference length (NaN: empty), partner volume
  std::vector<int> types;               // and itype * TYPE_STRIDE + jtype
  std::vector<double> xi0, coef;        // per entry, value
  unsigned epoch = 0;                   // of the pair settings the coefficients were computed with
  static constexpr int TYPE_STRIDE = 1 << 15;
  // where the partner volume's and the types' bits enter the slot (slot() and the SIMD copies
  // in load_values must agree, or the vector lookups miss every time)
  static constexpr int VOLUME_SHIFT = 7, TYPES_SHIFT = 45;
  // the partner volume and types of every entry so far, unless mixed
  bool filled = false, mixed = false;
  double only_v = 0.0;
  int only_t = -1;
  void start(unsigned e)
  {
    if (rsq0.empty() || e != epoch) {
      rsq0.assign(SIZE, std::numeric_limits<double>::quiet_NaN());
      vj.assign(SIZE, 0.0);
      types.assign(SIZE, -1);
      xi0.assign(SIZE, 0.0);
      coef.assign(SIZE, 0.0);
      filled = mixed = false;
      epoch = e;
    }
  }
  void note(double v, int t)
  {
    if (!filled) {
      filled = true;
      only_v = v;
      only_t = t;
    } else if (!(v == only_v && t == only_t)) {
      mixed = true;
    }
  }
  // does every entry have partner volume v and types t (then a key is its length alone)?
  bool holds_only(double v, int t) const { return !mixed && (!filled || (v == only_v && t == only_t)); }
  static std::uint64_t slot(std::uint64_t qb, std::uint64_t vb, std::uint64_t t)
  {
    // every bit of the key folded into the slot: round-off variants of a length differ in the
    // low mantissa bits, grid lengths in the high ones and in the exponent (xi and 2 xi)
    const std::uint64_t h = qb ^ (vb >> VOLUME_SHIFT) ^ (t << TYPES_SHIFT);
    std::uint64_t s = 0;
    for (int b = 0; b < 64; b += SLOT_BITS) s ^= h >> b;
    return s & (SIZE - 1);
  }
};

/* the coefficient of a bond of a compact row, computed on a cache miss (rare): called through a
   pointer, so that the SIMD kernels, each compiled for its own instruction set
   (bbpd_row_paths.h), reach the one copy compiled with the plugin's flags */
struct CoefFunction {
  double (*fn)(const void *context, int jtype, double xi0, double vj);
  const void *context;
  double operator()(int jtype, double xi0, double vj) const { return fn(context, jtype, xi0, vj); }
};

template <class CoefFn, bool UNIFORM = false> struct RecomputedValues {
  const double *x0;       // reference positions, 3 per atom
  int i;
  const double *vfrac;
  const int *type;
  CoefCache *cache;
  CoefFn coef_fn;          // coefficient of (partner type, reference length, partner volume)
  // UNIFORM: every atom a bond of i can reach has type uniform_type and volume uniform_v, and
  // so has every cache entry: the SIMD kernel then reads and compares lengths alone
  int uniform_type;
  double uniform_v;
  double rsq0_of(int j) const
  {
    const double d[3] = {x0[3 * j] - x0[3 * i], x0[3 * j + 1] - x0[3 * i + 1],
                         x0[3 * j + 2] - x0[3 * i + 2]};
    return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  }
  double xi0_of(int j) const { return std::sqrt(rsq0_of(j)); }
  // coefficient (and reference length) of a bond of squared reference length q to a partner of
  // type jtype and volume v
  double lookup(int jtype, double q, double v, double &xi0) const
  {
    CoefCache &c = *cache;
    std::uint64_t qb, vb;
    std::memcpy(&qb, &q, sizeof qb);
    std::memcpy(&vb, &v, sizeof vb);
    const int t = type[i] * CoefCache::TYPE_STRIDE + jtype;
    const std::uint64_t s = CoefCache::slot(qb, vb, t);
    if (!(c.rsq0[s] == q && c.vj[s] == v && c.types[s] == t)) {
      c.rsq0[s] = q;
      c.vj[s] = v;
      c.types[s] = t;
      c.xi0[s] = std::sqrt(q);
      c.coef[s] = coef_fn(jtype, c.xi0[s], v);
      c.note(v, t);
    }
    xi0 = c.xi0[s];
    return c.coef[s];
  }
  double coef_of(int j) const
  {
    double xi0;
    return lookup(type[j], rsq0_of(j), vfrac[j], xi0);
  }
  double xi0_at(int, int j) const { return xi0_of(j); }
  double coef_at(int, int j) const { return coef_of(j); }
};

}    // namespace BBPD

#endif

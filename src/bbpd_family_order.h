// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: a bond family in the order of its reference offsets (z, then y, then x, compared
   exactly; ties by tag, only for partners at one reference position), so that a row's
   summation order depends on the geometry alone.

   A comparison sort of every family is most of a large 3D setup (300 partners per atom and
   half a million atoms: seconds). On a grid the offsets fall on a few cells of the grid
   spacing h: a counting sort by cell (the multiples of h nearest z, y, x, which never
   decrease as the offset grows) puts the entries in order but for entries that share a cell, and an insertion
   sort with the exact comparison then finishes it (on a grid it finds nothing to move). Any
   h gives the exact order; h only sets how much is left to the insertion sort. When the cells
   would be too many (a tiny h, non-finite offsets) the comparison sort does it all.
   No LAMMPS dependency.
------------------------------------------------------------------------- */

#ifndef BBPD_FAMILY_ORDER_H
#define BBPD_FAMILY_ORDER_H

#include <algorithm>
#include <cmath>
#include <vector>

namespace BBPD {

template <class Tag> struct FamilyEntry {
  double z, y, x;    // reference offset of the partner
  Tag tag;
  bool operator<(const FamilyEntry &o) const
  {
    if (z != o.z) return z < o.z;
    if (y != o.y) return y < o.y;
    if (x != o.x) return x < o.x;
    return tag < o.tag;
  }
};

// more cells than this per family and the comparison sort is cheaper than counting
constexpr long FAMILY_ORDER_MAX_CELLS = 1L << 16;

template <class Tag> class FamilyOrder {
 public:
  // sorts f in place; h > 0 the cell size (the grid spacing)
  void sort(std::vector<FamilyEntry<Tag>> &f, double h)
  {
    const std::size_t n = f.size();
    if (n < 2) return;
    if (!(h > 0.0) || !cells_of(f, h)) {
      std::sort(f.begin(), f.end());
      return;
    }
    count.assign(ncell + 1, 0);
    for (std::size_t e = 0; e < n; e++) count[cell[e] + 1]++;
    for (long c = 0; c < ncell; c++) count[c + 1] += count[c];
    out.resize(n);
    for (std::size_t e = 0; e < n; e++) out[count[cell[e]]++] = f[e];
    for (std::size_t e = 1; e < n; e++) {
      if (!(out[e] < out[e - 1])) continue;
      FamilyEntry<Tag> v = out[e];
      std::size_t p = e;
      do {
        out[p] = out[p - 1];
        p--;
      } while (p > 0 && v < out[p - 1]);
      out[p] = v;
    }
    f.swap(out);
  }

 private:
  std::vector<long> cell;
  std::vector<long> count;
  std::vector<FamilyEntry<Tag>> out;
  long ncell = 0;

  // the nearest integer below v + 1/2 (v finite and within the cells, which cells_of checked):
  // a cast and a compare, where std::floor may be a library call
  static long nearest(double v)
  {
    const double t = v + 0.5;
    const long c = static_cast<long>(t);
    return t < static_cast<double>(c) ? c - 1 : c;
  }
  // the cell index of every entry, z slowest; false if the cells would be too many
  bool cells_of(const std::vector<FamilyEntry<Tag>> &f, double h)
  {
    double lo[3] = {f[0].z, f[0].y, f[0].x}, hi[3] = {lo[0], lo[1], lo[2]};
    for (const auto &e : f) {
      const double v[3] = {e.z, e.y, e.x};
      for (int d = 0; d < 3; d++) {
        lo[d] = std::min(lo[d], v[d]);
        hi[d] = std::max(hi[d], v[d]);
      }
    }
    long base[3], span[3];
    double cells = 1.0;
    for (int d = 0; d < 3; d++) {
      const double a = std::floor(lo[d] / h + 0.5), b = std::floor(hi[d] / h + 0.5);
      if (!std::isfinite(a) || !std::isfinite(b)) return false;
      cells *= b - a + 1.0;
      if (cells > FAMILY_ORDER_MAX_CELLS) return false;
      base[d] = static_cast<long>(a);
      span[d] = static_cast<long>(b - a) + 1;
    }
    ncell = span[0] * span[1] * span[2];
    cell.resize(f.size());
    for (std::size_t e = 0; e < f.size(); e++) {
      const long cz = nearest(f[e].z / h) - base[0];
      const long cy = nearest(f[e].y / h) - base[1];
      const long cx = nearest(f[e].x / h) - base[2];
      cell[e] = (cz * span[1] + cy) * span[2] + cx;
    }
    return true;
  }
};

}    // namespace BBPD

#endif

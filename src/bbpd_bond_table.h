// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the distinct (reference length, coefficient) pairs of a rank's bonds.

   On a regular grid a bond's reference length and coefficient depend only on its lattice
   offset and the partner's type and volume, so a rank holds a few hundred to a few thousand
   distinct pairs however many bonds it has. Each bond end then stores a 2-byte class index
   into this table instead of 16 bytes. Pairs are compared by their bits: the table hands back
   exactly the doubles it was given, so forces are the same bits as with per-bond storage.
   When a rank has more distinct pairs than a class index can address (an irregular
   discretisation), add() says so and the caller keeps per-bond values.
   A class's two doubles sit side by side (values[2c], values[2c + 1]): the SIMD rows read them
   with one 16-byte load per bond, as they read a partner's position (bbpd_row.h).
------------------------------------------------------------------------- */

#ifndef BBPD_BOND_TABLE_H
#define BBPD_BOND_TABLE_H

#include <cstdint>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <vector>

namespace BBPD {

using BondClass = std::uint16_t;

class BondClassTable {
 public:
  // every index of a BondClass is a valid class
  static constexpr std::size_t MAX_CLASSES = std::size_t(std::numeric_limits<BondClass>::max()) + 1;

  void clear()
  {
    values.clear();
    index.clear();
  }
  // class of (xi0, coef), added if new; false if the table is full
  bool add(double x, double c, BondClass &cls)
  {
    const Key key{bits(x), bits(c)};
    const auto it = index.find(key);
    if (it != index.end()) {
      cls = it->second;
      return true;
    }
    if (size() >= MAX_CLASSES) return false;
    cls = static_cast<BondClass>(size());
    index.emplace(key, cls);
    values.push_back(x);
    values.push_back(c);
    return true;
  }
  std::size_t size() const { return values.size() / 2; }
  double xi0(std::size_t c) const { return values[2 * c]; }
  double coef(std::size_t c) const { return values[2 * c + 1]; }
  const double *data() const { return values.data(); }

 private:
  std::vector<double> values;    // per class: reference length, coefficient

  struct Key {
    std::uint64_t a, b;
    bool operator==(const Key &o) const { return a == o.a && b == o.b; }
  };
  struct Hash {
    std::size_t operator()(const Key &k) const
    {
      // splitmix64 finaliser of the two words: nearby doubles differ in their low bits
      std::uint64_t h = k.a ^ (k.b * 0x9e3779b97f4a7c15ULL);
      h ^= h >> 30;
      h *= 0xbf58476d1ce4e5b9ULL;
      h ^= h >> 27;
      h *= 0x94d049bb133111ebULL;
      h ^= h >> 31;
      return static_cast<std::size_t>(h);
    }
  };
  static std::uint64_t bits(double v)
  {
    std::uint64_t u;
    std::memcpy(&u, &v, sizeof u);
    return u;
  }
  std::unordered_map<Key, BondClass, Hash> index;
};

}    // namespace BBPD

#endif

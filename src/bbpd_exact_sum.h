// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: an exact sum of doubles, with no LAMMPS dependency.

   The sum of floating-point numbers depends on the order they are added in, and so
   on how the atoms are split between ranks. ExactSum adds every double exactly into a
   fixed-point accumulator that spans the whole double range (limbs of 32 bits with
   signed slack: a long accumulator in the manner of Kulisch), so the result depends
   on the set of numbers only: the same bits on any rank count and in any order.
   Partial sums of several ranks are combined by adding their limbs as integers
   (MPI_Allreduce of MPI_INT64_T with MPI_SUM on limbs(), then normalize()).
   compute bbpd/energy sums its per-atom energies with it.
------------------------------------------------------------------------- */

#ifndef BBPD_EXACT_SUM_H
#define BBPD_EXACT_SUM_H

#include <cmath>
#include <cstdint>

namespace BBPD {

class ExactSum {
 public:
  static constexpr int LIMB_BITS = 32;
  // bit 0 of limb 0 weighs 2^LOWEST_EXPONENT: below the smallest subnormal, 2^-1074, less
  // the 53 bits of a mantissa, rounded down to a whole limb
  static constexpr int LOWEST_EXPONENT = -36 * LIMB_BITS;
  // 2^1024 (above the largest double) plus 64 bits for the count of terms, in whole limbs
  static constexpr int NLIMBS = (1024 + 64 - LOWEST_EXPONENT) / LIMB_BITS + 1;

  ExactSum() { clear(); }
  void clear()
  {
    for (auto &l : limb) l = 0;
    pending = 0;
  }

  // add x exactly (x finite)
  void add(double x)
  {
    if (x == 0.0) return;
    int e;
    const double f = std::frexp(x, &e);    // x = f 2^e, 0.5 <= |f| < 1
    const int64_t mant = static_cast<int64_t>(std::ldexp(f, 53));    // exact: 53 bits
    const int pos = e - 53 - LOWEST_EXPONENT;                            // weight of bit 0 of mant
    const int l = pos / LIMB_BITS, s = pos % LIMB_BITS;
    const uint64_t mag = static_cast<uint64_t>(mant < 0 ? -mant : mant);
    // |mant| 2^s < 2^85 spans three limbs
    const unsigned __int128 v = static_cast<unsigned __int128>(mag) << s;
    const int64_t part[3] = {static_cast<int64_t>(v & LIMB_MASK),
                             static_cast<int64_t>((v >> LIMB_BITS) & LIMB_MASK),
                             static_cast<int64_t>(v >> (2 * LIMB_BITS))};
    for (int k = 0; k < 3; k++) limb[l + k] += mant < 0 ? -part[k] : part[k];
    // each limb can take 2^31 more terms of at most 2^32 before it could overflow
    if (++pending == MAX_PENDING) normalize();
  }

  // carry into canonical form: every limb but the top one in [0, 2^32)
  void normalize()
  {
    for (int k = 0; k + 1 < NLIMBS; k++) {
      const int64_t carry = limb[k] >> LIMB_BITS;    // arithmetic shift: the floor
      limb[k] -= carry * (int64_t(1) << LIMB_BITS);
      limb[k + 1] += carry;
    }
    pending = 0;
  }

  // the sum, rounded to a double (from the canonical form, so the same bits for the same set)
  double value()
  {
    normalize();
    // the top limb carries the sign; the value is sum limb[k] 2^(32 k + LOWEST_EXPONENT),
    // added from the top in long double (64-bit mantissa): the lower limbs change only
    // bits that the rounding to double drops, and they are the same for the same set
    long double s = 0.0L;
    for (int k = NLIMBS - 1; k >= 0; k--)
      if (limb[k] != 0) s += std::ldexp(static_cast<long double>(limb[k]), LIMB_BITS * k + LOWEST_EXPONENT);
    return static_cast<double>(s);
  }

  // the sum with the opposite sign, exactly
  void negate()
  {
    for (auto &l : limb) l = -l;
    normalize();
  }

  // the limbs, for combining partial sums (add them as integers, then normalize())
  int64_t *limbs() { return limb; }
  void combine(const ExactSum &o)
  {
    normalize();
    for (int k = 0; k < NLIMBS; k++) limb[k] += o.limb[k];    // both canonical: no overflow
    normalize();
  }

 private:
  static constexpr uint64_t LIMB_MASK = (uint64_t(1) << LIMB_BITS) - 1;
  static constexpr int64_t MAX_PENDING = int64_t(1) << 30;
  int64_t limb[NLIMBS];
  int64_t pending;
};

}    // namespace BBPD

#endif

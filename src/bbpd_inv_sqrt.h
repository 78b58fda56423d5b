// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: 1/sqrt(x) from additions and multiplications only.

   The bond loop needs 1/|y| and |y| per bond end; a square root and a division per bond end
   keep the divider busy for most of the loop. A first guess from the bits of x and Newton
   steps y <- y (3/2 - (x/2) y y) use the adders and multipliers instead, in IEEE operations
   whose results do not depend on the CPU (no hardware estimate, no FMA), so the AVX-512, AVX2
   and portable loops give the same bits on every machine. Relative error of the first guess
   below 3.5e-2, then about 1.5 e^2 per step: 4 steps reach the rounding error (a few ulps).
   The bond length |y| = x w then gets one more Newton step (sqrt_from_inv).
------------------------------------------------------------------------- */

#ifndef LMP_BBPD_INV_SQRT_H
#define LMP_BBPD_INV_SQRT_H

#include <cstdint>
#include <cstring>
#include <limits>

namespace BBPD {

// first guess of 1/sqrt(x) from the bits of x: C. Lomont, "Fast inverse square root" (2003)
constexpr std::uint64_t INV_SQRT_MAGIC = 0x5fe6eb50c7b537a9ULL;
constexpr int INV_SQRT_NEWTON_STEPS = 4;

/* 1/sqrt(x) for x > 0; +inf for x = 0 (coincident atoms: a non-finite force, reported) */
inline double inv_sqrt(double x)
{
  std::uint64_t u;
  std::memcpy(&u, &x, sizeof u);
  u = INV_SQRT_MAGIC - (u >> 1);
  double y;
  std::memcpy(&y, &u, sizeof y);
  const double h = 0.5 * x;
  for (int n = 0; n < INV_SQRT_NEWTON_STEPS; n++) y = y * (1.5 - h * y * y);
  return x == 0.0 ? std::numeric_limits<double>::infinity() : y;
}

/* sqrt(x) from w = inv_sqrt(x): r = x w is a few ulps off; one Newton step on r^2 = x brings it
   within about an ulp (the bond elongation r - xi0 is a small difference of two lengths, so
   the error of r is amplified by 1/stretch) */
inline double sqrt_from_inv(double x, double w)
{
  const double r = x * w;
  return r + (x - r * r) * (0.5 * w);
}

}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* The family the LPS unit tests share: atom 0 at the origin of peri/lps's example lattice
   (lc = 0.5 mm, delta = 3.0002 lc: 122 partners). */

#ifndef BBPD_TEST_FAMILY_H
#define BBPD_TEST_FAMILY_H

#include "bbpd_pmb_rules.h"

#include <cmath>

namespace BBPD::test {

constexpr double LC = 0.5e-3;
constexpr double DELTA = 1.5001e-3;
constexpr double VOLUME = LC * LC * LC;
constexpr double K = 14.9e9, G = 9.3e9;    // the example's bulk and shear moduli (Pa)

// fn(p, xi0) for every partner of atom 0, in lattice order: p its reference position, xi0 = |p|
template <class Fn> void for_each_partner(Fn fn)
{
  for (int a = -3; a <= 3; a++)
    for (int b = -3; b <= 3; b++)
      for (int c = -3; c <= 3; c++) {
        const double p[3] = {a * LC, b * LC, c * LC};
        const double xi0 = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        if (xi0 > 0.0 && PMB::in_family(xi0 * xi0, DELTA)) fn(p, xi0);
      }
}

}    // namespace BBPD::test

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: differences between the LAMMPS versions we support
   (4 Feb 2025 and 4 Jul 2026), resolved at compile time by overload
   detection rather than version numbers.
------------------------------------------------------------------------- */

#ifndef LMP_BBPD_COMPAT_H
#define LMP_BBPD_COMPAT_H

#include "domain.h"

#include <string>

namespace LAMMPS_NS {
namespace BBPDCompat {

  // LAMMPS 2026 takes the caller's file and line; 2025 does not
  template <class D>
  auto minimum_image_impl(D *domain, double *delta, int)
      -> decltype(domain->minimum_image(__FILE__, __LINE__, delta), void())
  {
    // the file name made a std::string once, not at every call (a heap allocation per bond end
    // when the families and the bond cache are built in a periodic box)
    static const std::string here(__FILE__);
    domain->minimum_image(here, __LINE__, delta);
  }
  template <class D> void minimum_image_impl(D *domain, double *delta, long)
  {
    domain->minimum_image(delta);
  }
  inline void minimum_image(Domain *domain, double *delta)
  {
    minimum_image_impl(domain, delta, 0);
  }

}    // namespace BBPDCompat
}    // namespace LAMMPS_NS

#endif

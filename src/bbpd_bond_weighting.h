// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: how a model family weights its bonds, with no LAMMPS dependency.

   A weighting says which pairs are in a family, the partner volume a bond counts and the
   coefficient the bond storage keeps per bond. Each family is one small value type with the
   same four members; the bond law (bbpd_bond_law.h) holds one of them, set by the pair style,
   and no loop or storage asks which. A new family is a new struct here and an entry of
   BondWeighting (doc/architecture.rst, "Adding a model family").
------------------------------------------------------------------------- */

#ifndef BBPD_BOND_WEIGHTING_H
#define BBPD_BOND_WEIGHTING_H

#include "bbpd_kernel.h"
#include "bbpd_lps.h"
#include "bbpd_lps_kernel.h"
#include "bbpd_pmb_rules.h"

#include <variant>

namespace BBPD {

/* the kernel-weighted bond-based styles bbpd/KERNEL: every pair closer than delta + dx/2,
   the partial volume C_v V_j (eq. 19), coefficient c0 W(xi0 / delta) C_v V_j / xi0 (eq. 21) */
struct KernelWeighting {
  double cutoff(double delta, double spacing) const { return delta + 0.5 * spacing; }
  bool in_family(double rsq, double delta, double spacing) const
  {
    const double rc = cutoff(delta, spacing);
    return rsq < rc * rc;
  }
  double partner_volume(double xi0, double delta, double spacing, double vj) const
  {
    return partial_volume(xi0, delta, spacing) * vj;
  }
  double coefficient(const KernelInfo &kernel, double c0, double xi0, double delta,
                     double spacing, double vj) const
  {
    return c0 * kernel.shape(xi0 / delta) * partner_volume(xi0, delta, spacing, vj) / xi0;
  }
};

/* LAMMPS's peri/pmb (bbpd/pmb): every atom within the horizon, boundary included, whole
   volumes, coefficient c V_j times the lattice ramp / xi0 (bbpd_pmb_rules.h) */
struct PmbWeighting {
  double lattice_constant = 0.0;    // the ramp's width
  double cutoff(double delta, double) const { return delta; }
  bool in_family(double rsq, double delta, double) const { return PMB::in_family(rsq, delta); }
  double partner_volume(double, double, double, double vj) const { return vj; }
  double coefficient(const KernelInfo &, double c0, double xi0, double delta, double,
                     double vj) const
  {
    return c0 * vj * PMB::volume_scale(xi0, delta, lattice_constant) / xi0;
  }
};

/* LAMMPS's peri/lps (bbpd/lps): peri/pmb's family; the coefficient is the bond's weighted
   partner volume omega V_j ramp with omega = 1 / |xi0| (bbpd_lps.h) */
struct LpsWeighting : PmbWeighting {
  double coefficient(const KernelInfo &, double, double xi0, double delta, double,
                     double vj) const
  {
    return LPS::weighted_partner_volume(xi0, delta, lattice_constant, vj);
  }
};

/* the kernel-weighted LPS styles bbpd/lps/KERNEL: the same with omega the kernel's shape
   (bbpd_lps_kernel.h) */
struct LpsKernelWeighting : PmbWeighting {
  double coefficient(const KernelInfo &kernel, double, double xi0, double delta, double,
                     double vj) const
  {
    return LPS::weighted_partner_volume_with(LPS::influence_function(kernel, xi0, delta), xi0,
                                             delta, lattice_constant, vj);
  }
};

using BondWeighting = std::variant<KernelWeighting, PmbWeighting, LpsWeighting, LpsKernelWeighting>;

}    // namespace BBPD

#endif

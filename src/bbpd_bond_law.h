// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the bond law of the bbpd pair styles, with no LAMMPS dependency.

   Which pairs of atoms are bonded (the family), and per bond the partner
   volume C_v V_j (eq. 19) and the force density per unit elongation
   c(xi0) C_v V_j / xi0 (eqs. 9, 19, 21), as the family's weighting
   (bbpd_bond_weighting.h: the kernel styles', peri/pmb's, peri/lps's) gives them. The pair style fills one BondLaw with
   copies of its calibrated per-type-pair values once it has calibrated them,
   and hands a copy to the bond storage (fix bbpd/bonds), which builds and
   caches with it without knowing the pair: a BondLaw is a value, it points
   into no table of the pair style.
------------------------------------------------------------------------- */

#ifndef BBPD_BOND_LAW_H
#define BBPD_BOND_LAW_H

#include "bbpd_bond_weighting.h"
#include "bbpd_kernel.h"

#include <cmath>
#include <vector>

namespace BBPD {

// grid spacing implied by an atom volume: vfrac / A (1D), sqrt(vfrac / h) (2D), cbrt(vfrac) (3D)
inline double grid_spacing_of(Model m, double geom, double vfrac)
{
  switch (family_dimension(m)) {
    case 1: return vfrac / geom;
    case 2: return std::sqrt(vfrac / geom);
    default: return std::cbrt(vfrac);
  }
}

// one value per type pair [itype][jtype], types 1..ntypes, held by value
class TypePairTable {
 public:
  TypePairTable() = default;
  // copies rows[1..ntypes][1..ntypes] (a LAMMPS per-type-pair array; row and column 0 unused)
  template <class T>
  TypePairTable(int ntypes, const T *const *rows) :
      stride(ntypes + 1), values(static_cast<size_t>(stride) * stride, 0.0)
  {
    for (int i = 1; i <= ntypes; i++)
      for (int j = 1; j <= ntypes; j++) values[i * stride + j] = static_cast<double>(rows[i][j]);
  }
  double operator()(int itype, int jtype) const { return values[itype * stride + jtype]; }
  bool empty() const { return values.empty(); }

 private:
  int stride = 0;
  std::vector<double> values;
};

struct BondLaw {
  KernelInfo kernel = kernel_info<ConstantKernel>();
  Model model = Model::Solid3D;
  double geom = 1.0;                 // cross-section A (1D), thickness h (2D), 1 in 3D
  double spacing = 0.0;              // grid spacing of the partial-volume correction (eq. 19)
  BondWeighting weighting;           // the family's: set by the pair style (bbpd_bond_weighting.h)
  // per type pair, as calibrated by the pair style: c0 (eq. 21; pmb: peri/pmb's c) and delta
  TypePairTable micromodulus, horizon;
  TypePairTable bondless;    // nonzero: the type pair forms no bonds (separate bodies)

  // reference distance below which a pair is in a family (pmb: up to and including delta)
  double family_cutoff(int itype, int jtype) const
  {
    const double delta = horizon(itype, jtype);
    return std::visit([&](const auto &w) { return w.cutoff(delta, spacing); }, weighting);
  }
  // is a pair at squared reference distance rsq in a family?
  bool bonded(int itype, int jtype, double rsq) const
  {
    if (!bondless.empty() && bondless(itype, jtype) != 0.0) return false;
    const double delta = horizon(itype, jtype);
    return std::visit([&](const auto &w) { return w.in_family(rsq, delta, spacing); }, weighting);
  }
  // the partner volume the bond counts (C_v V_j, eq. 19; whole volumes in peri/pmb's family)
  double partner_volume(int itype, int jtype, double xi0, double vj) const
  {
    const double delta = horizon(itype, jtype);
    return std::visit([&](const auto &w) { return w.partner_volume(xi0, delta, spacing, vj); },
                      weighting);
  }
  // what the bond storage keeps per bond: the force density per unit elongation
  // c(xi0) C_v V_j / xi0, or for LPS the weighted partner volume omega(xi0) V_j ramp
  double coefficient(int itype, int jtype, double xi0, double vj) const
  {
    const double c0 = micromodulus(itype, jtype), delta = horizon(itype, jtype);
    return std::visit(
        [&](const auto &w) { return w.coefficient(kernel, c0, xi0, delta, spacing, vj); }, weighting);
  }
  double spacing_of_volume(double vfrac) const { return grid_spacing_of(model, geom, vfrac); }
};

}    // namespace BBPD

#endif

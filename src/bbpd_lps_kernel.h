// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the constants of the kernel-weighted linear peridynamic solid of pair styles
   bbpd/lps/constant, bbpd/lps/triangular, bbpd/lps/gaussian (pair_bbpd_lps.h), with
   no LAMMPS dependency: the influence function (the kernel shape W of bbpd_kernel.h), the
   moduli K (kappa' in 2D) and G of the LPS force state from E and nu per model, the
   continuum weighted volume, and the critical stretch from G_c.

   The LPS in d dimensions (bbpd_lps.h; 3D: Silling et al., J. Elasticity 88 (2007) 151;
   2D: Le, Chan & Schwartz, Int. J. Numer. Meth. Engng 98 (2014) 547):
     theta = d / m sum omega xi e V,  W = K theta^2 / 2 + d (d + 2) G / (2 m) sum omega e_d^2 V.
   K is the bulk modulus of the model's strain energy W = K theta^2 / 2 + G eps_d : eps_d:
     3d             K = E / (3 (1 - 2 nu))
     plane strain   kappa' = lambda + G = E / (2 (1 + nu) (1 - 2 nu))
     plane stress   kappa' = lambda' + G = E / (2 (1 - nu)),  lambda' = E nu / (1 - nu^2)
   with G = E / (2 (1 + nu)) in all three.

   Critical stretch (the Silling-Askari construction, Comput. Struct. 83 (2005) 1526, with
   the LPS bond energy): G_c is the energy of all bond pairs crossing a unit area of a plane
   when every bond is at the stretch s0. The pair (i, j) holds in W_i V_i + W_j V_j the
   deviatoric energy 2 x d (d + 2) G / (2 m) omega (s0 xi)^2 V_i V_j; the dilatational term is
   left out (the common simplification: the two halves separate with theta of the order of s0
   only at the crack faces, and a bond's own share of theta is O(1 / family size)). With
   w(xi) = d (d + 2) G omega(xi) s0^2 xi^2 / m and the bonds of a direction at angle phi to the
   plane's normal crossing it xi cos(phi) times per unit area:
     3d   G_c = pi int_0^delta w xi^3 dxi,   m = 4 pi delta^5 M4
          -> G_c = (15 / 4) G s0^2 delta M5 / M4
     2d   G_c = 2 int_0^delta w xi^2 dxi,    m = 2 pi delta^4 M3 (per unit thickness)
          -> G_c = (8 / pi) G s0^2 delta M4 / M3
   M_n = int_0^1 W(r) r^n dr (bbpd_kernel.h). The thickness drops out in 2D: theta and the
   force state carry V / m, both proportional to it.
------------------------------------------------------------------------- */

#ifndef BBPD_LPS_KERNEL_H
#define BBPD_LPS_KERNEL_H

#include "bbpd_kernel.h"
#include "bbpd_lps.h"

#include <cmath>

namespace BBPD {
namespace LPS {

  // the admissible Poisson's ratios: positive-definite W needs K > 0 and G > 0, i.e.
  // -1 < nu < 1/2 in 3d and plane strain and -1 < nu < 1 in plane stress
  constexpr double NU_MIN = -1.0;
  inline double nu_max(Model m) { return m == Model::PlaneStress ? 1.0 : 0.5; }
  inline bool admissible_poisson_ratio(Model m, double nu) { return nu > NU_MIN && nu < nu_max(m); }

  // the dimension d of the LPS of a model (3d: 3, plane strain and plane stress: 2)
  inline double lps_dimension(Model m) { return family_dimension(m); }

  // the influence function of the kernel styles, omega(xi0) = W(xi0 / delta)
  inline double influence_function(const KernelInfo &k, double xi0, double delta)
  {
    return k.shape(xi0 / delta);
  }

  inline double shear_modulus(double E, double nu) { return E / (2.0 * (1.0 + nu)); }

  // K of the model's W = K theta^2 / 2 + G eps_d : eps_d (the header comment)
  inline double bulk_modulus(Model m, double E, double nu)
  {
    switch (m) {
      case Model::PlaneStrain: return E / (2.0 * (1.0 + nu) * (1.0 - 2.0 * nu));
      case Model::PlaneStress: return E / (2.0 * (1.0 - nu));
      default: return E / (3.0 * (1.0 - 2.0 * nu));
    }
  }

  inline Moduli moduli_of(Model m, double E, double nu)
  {
    return moduli(bulk_modulus(m, E, nu), shear_modulus(E, nu), lps_dimension(m));
  }

  // the weighted volume of an interior atom of the continuum, int_H omega xi^2 dV
  // (per unit thickness in 2D): 4 pi delta^5 M4 (3d), 2 pi delta^4 M3 (2d)
  inline double continuum_weighted_volume(const KernelInfo &k, Model m, double delta)
  {
    if (family_dimension(m) == 2) return 2.0 * PI * std::pow(delta, 4) * k.moment(3);
    return 4.0 * PI * std::pow(delta, 5) * k.moment(4);
  }

  // G_c / s0^2 of the header comment: (15/4) G delta M5 / M4 (3d), (8/pi) G delta M4 / M3 (2d)
  inline double fracture_energy_per_stretch2(const KernelInfo &k, Model m, double shear,
                                             double delta)
  {
    if (family_dimension(m) == 2) return 8.0 / PI * shear * delta * k.moment(4) / k.moment(3);
    return 15.0 / 4.0 * shear * delta * k.moment(5) / k.moment(4);
  }

  inline double critical_stretch_of(const KernelInfo &k, Model m, double shear, double Gc,
                                    double delta)
  {
    return std::sqrt(Gc / fracture_energy_per_stretch2(k, m, shear, delta));
  }

}    // namespace LPS
}    // namespace BBPD

#endif

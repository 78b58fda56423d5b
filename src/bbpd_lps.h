// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the linear peridynamic solid (LPS) of LAMMPS's pair style peri/lps
   (src/PERI/pair_peri_lps.cpp, pair_peri.cpp, fix_peri_neigh.cpp; Parks et al.,
   Comput. Phys. Commun. 179 (2008) 777; Silling et al., J. Elasticity 88 (2007)
   151), used by pair style bbpd/lps (pair_bbpd_lps.h). No LAMMPS header, so
   that the unit tests can use it on plain numbers.

   Per bond of reference length xi0 (|x0_j - x0_i|) with partner volume V_j and
   peri/pmb's volume ramp (bbpd_pmb_rules.h), the bond's weighted volume is
     w V = omega(xi0) V_j ramp(xi0),    omega(xi0) = 1 / xi0   (the influence function
   of peri/lps; the kernel styles bbpd/lps/KERNEL take the kernel shape, bbpd_lps_kernel.h);
   per atom, in d = 3 dimensions (d = 2: the 2D LPS of Le, Chan & Schwartz, Int. J. Numer.
   Meth. Engng 98 (2014) 547)
     m_i     = sum_j w V xi0^2                    (the weighted volume)
     theta_i = d / m_i sum_j w V xi0 e_ij          (the dilatation, e = |y| - xi0)
   and the scalar force state of the bond (force density along y_j - y_i, per |y|)
     t_ij = (d K - (d + 2) G) w V (theta_i / m_i + theta_j / m_j) xi0
          + d (d + 2) G w V (1 / m_i + 1 / m_j) e_ij,
   3K - 5G and 15G in 3D. The strain energy density of atom i is K theta_i^2 / 2 plus, per
   bond, d (d + 2) G / (2 m_i) w V (e_ij - theta_i xi0 / d)^2 (K: the 2D bulk modulus kappa'
   with d = 2).
------------------------------------------------------------------------- */

#ifndef BBPD_LPS_H
#define BBPD_LPS_H

#include "bbpd_pmb_rules.h"

#include <cmath>

namespace BBPD {
namespace LPS {

  // theta = DILATATION_FACTOR / m sum w V xi0 e: the 3 of the 3D dilatation (Silling et al.
  // 2007, eq. 94), as peri/lps
  constexpr double DILATATION_FACTOR = 3.0;
  // the deviatoric modulus of the force state, alpha = 15 G / m (Silling et al. 2007, eq. 95)
  constexpr double SHEAR_FACTOR = 15.0;
  // the dilatational coefficient 3K - 5G of the force state (ibid., 3K - alpha m / 3)
  constexpr double BULK_FACTOR = 3.0;
  constexpr double SHEAR_IN_BULK_FACTOR = 5.0;
  // peri/lps's short-range stiffness is that of peri/pmb (15 c V_j / delta) with c the PMB
  // micromodulus of the same bulk modulus, c = 18 K / (pi delta^4) (Silling & Askari 2005,
  // eq. 26)
  constexpr double PMB_MICROMODULUS_FACTOR = 18.0;
  constexpr double PI = 3.14159265358979323846;

  // the influence function omega(xi0) = 1 / |xi0| (peri/lps: 1 / NEAR_ZERO for a zero length)
  inline double influence(double xi0)
  {
    return std::fabs(xi0) < PMB::NEAR_ZERO ? 1.0 / PMB::NEAR_ZERO : 1.0 / xi0;
  }

  // the bond's weighted partner volume omega V_j ramp, what the bond storage keeps per bond,
  // for an influence function value omega = omega(xi0)
  inline double weighted_partner_volume_with(double omega, double xi0, double delta, double lc,
                                             double vj)
  {
    return omega * vj * PMB::volume_scale(xi0, delta, lc);
  }
  // the same with peri/lps's influence function 1 / |xi0|
  inline double weighted_partner_volume(double xi0, double delta, double lc, double vj)
  {
    return weighted_partner_volume_with(influence(xi0), xi0, delta, lc, vj);
  }

  // a bond's term of the weighted volume m_i (fix_peri_neigh: omega xi0^2 V_j ramp)
  inline double weighted_volume_term(double wv, double xi0) { return wv * (xi0 * xi0); }

  // a bond's term of the dilatation sum (pair_peri: omega xi0 e V_j ramp)
  inline double dilatation_term(double wv, double xi0, double e) { return wv * xi0 * e; }

  // theta_i from its sum of dilatation terms in d dimensions (the factor d of theta = d / m
  // sum: 3 in 3D, 2 in 2D, Le et al. 2014 eq. 10); an atom without weighted volume has none
  inline double dilatation(double sum, double m, double d = DILATATION_FACTOR)
  {
    return m != 0.0 ? (d / m) * sum : 0.0;
  }

  // the elongation of peri/lps: round-off elongations are zero
  inline double elongation(double r, double xi0)
  {
    const double e = r - xi0;
    return std::fabs(e) < PMB::NEAR_ZERO ? 0.0 : e;
  }

  // the moduli and the two coefficients of the force state they give, per type pair, in
  // d dimensions: the deviatoric modulus alpha m = d (d + 2) G makes the energy of a traceless
  // strain G eps:eps (the fourth moment of an isotropic family, m / (d (d + 2)) times the
  // symmetric identity), the dilatational one d K - alpha m / d (t = dW/de, Silling et al. 2007
  // eq. 95; Le et al. 2014 eq. 21 with d = 2)
  struct Moduli {
    double bulk, shear;
    double dilatational;    // 3K - 5G (2D: 2 kappa' - 4G)
    double deviatoric;      // 15 G (2D: 8 G)
    double dimension;       // d of the dilatation theta = d / m sum
  };
  inline Moduli moduli(double bulk, double shear, double d)
  {
    return {bulk, shear, d * bulk - (d + 2.0) * shear, d * (d + 2.0) * shear, d};
  }
  inline Moduli moduli(double bulk, double shear)
  {
    return {bulk, shear, BULK_FACTOR * bulk - SHEAR_IN_BULK_FACTOR * shear, SHEAR_FACTOR * shear,
            DILATATION_FACTOR};
  }

  // the dilatational coefficient d K of the force state split as the families with history
  // write it, t = d K w V (theta_i / m_i + theta_j / m_j) xi0 + d (d + 2) G w V (1 / m_i +
  // 1 / m_j) ed with ed = e - theta_i xi0 / d (3K and 15 G in 3D: peri/ves, peri/eps; the
  // -(d + 2) G of the dilatational coefficient above is carried by ed)
  inline double split_dilatational(const Moduli &m) { return m.dimension * m.bulk; }

  // the per-atom values a bond reads at each end: theta / m and 1 / m (0 without weighted volume)
  struct AtomState {
    double theta_over_m, inv_m;
  };
  inline AtomState atom_state(double theta, double m)
  {
    if (!(m > 0.0)) return {0.0, 0.0};
    return {theta / m, 1.0 / m};
  }

  /* the scalar force state t_ij of the bond (force density per unit current length along
     y_j - y_i: the bond pulls atom i by t / |y| (y_j - y_i)); zero unless both ends have a
     weighted volume (peri/lps) */
  inline double force_state(const Moduli &mod, double wv, double xi0, double e, const AtomState &a,
                            const AtomState &b)
  {
    if (!(a.inv_m > 0.0 && b.inv_m > 0.0)) return 0.0;
    return mod.dilatational * wv * (a.theta_over_m + b.theta_over_m) * xi0 +
        mod.deviatoric * wv * (a.inv_m + b.inv_m) * e;
  }

  // atom i's energy density of the dilatation, K theta^2 / 2
  inline double dilatation_energy(double bulk, double theta) { return 0.5 * bulk * (theta * theta); }

  // theta / d, the part of the dilatation in the extension of a bond per unit length
  inline double third(double theta, double d = DILATATION_FACTOR) { return theta / d; }

  // the deviatoric extension of a bond, e - theta_i xi0 / 3 (theta_third_i = third(theta_i))
  inline double deviatoric_extension(double e, double xi0, double theta_third_i)
  {
    return e - theta_third_i * xi0;
  }
  // atom i's energy density of the deviatoric extensions of its bonds, 15 G / (2 m_i) times the
  // sum of w V ed^2 over them (a row sums wV ed^2 and multiplies once)
  inline double deviatoric_energy_of(const Moduli &mod, double inv_m_i, double sum_wv_ed2)
  {
    return 0.5 * mod.deviatoric * inv_m_i * sum_wv_ed2;
  }
  // the same for one bond
  inline double deviatoric_energy(const Moduli &mod, double wv, double xi0, double e,
                                  double theta_third_i, double inv_m_i)
  {
    const double ed = deviatoric_extension(e, xi0, theta_third_i);
    return deviatoric_energy_of(mod, inv_m_i, wv * (ed * ed));
  }

  // the PMB micromodulus of the same bulk modulus, 18 K / (pi delta^4): peri/lps's short-range
  // stiffness is 15 times it (pair_peri_lps.cpp, kshort), and the stable time step estimate uses it
  inline double pmb_micromodulus(double bulk, double delta)
  {
    return (PMB_MICROMODULUS_FACTOR * bulk) / (PI * (delta * delta) * (delta * delta));
  }
  inline double short_range_stiffness(double bulk, double delta)
  {
    return (PMB::SHORT_RANGE_STIFFNESS_FACTOR * PMB_MICROMODULUS_FACTOR * bulk) /
        (PI * (delta * delta) * (delta * delta));
  }

}    // namespace LPS
}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_lps.h: the linear peridynamic solid of peri/lps on plain numbers: influence function,
   weighted volume, dilatation, force state and energy against the identities of the theory
   (Silling et al., J. Elasticity 88 (2007) 151) on a family of a cubic lattice. */

#include "bbpd_lps.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace LPS = BBPD::LPS;
namespace PMB = BBPD::PMB;

namespace {

constexpr double LC = 0.5e-3;
constexpr double DELTA = 1.5001e-3;    // the peri/lps example's horizon at lc = 0.5 mm
constexpr double VOLUME = LC * LC * LC;
constexpr double K = 14.9e9, G = 9.3e9;

struct Bond {
  double x, y, z, xi0, wv;
};

// the family of an atom of the example's lattice: every site with |xi| <= delta
std::vector<Bond> family()
{
  std::vector<Bond> bonds;
  for (int a = -3; a <= 3; a++)
    for (int b = -3; b <= 3; b++)
      for (int c = -3; c <= 3; c++) {
        const double x = a * LC, y = b * LC, z = c * LC;
        const double r = std::sqrt(x * x + y * y + z * z);
        if (r == 0.0 || !PMB::in_family(r * r, DELTA)) continue;
        bonds.push_back({x, y, z, r, LPS::weighted_partner_volume(r, DELTA, LC, VOLUME)});
      }
  return bonds;
}

double weighted_volume(const std::vector<Bond> &bonds)
{
  double m = 0.0;
  for (const auto &b : bonds) m += LPS::weighted_volume_term(b.wv, b.xi0);
  return m;
}

// the dilatation of the family deformed by y = F xi
double dilatation(const std::vector<Bond> &bonds, const double F[3][3], double m)
{
  double sum = 0.0;
  for (const auto &b : bonds) {
    const double y[3] = {F[0][0] * b.x + F[0][1] * b.y + F[0][2] * b.z,
                         F[1][0] * b.x + F[1][1] * b.y + F[1][2] * b.z,
                         F[2][0] * b.x + F[2][1] * b.y + F[2][2] * b.z};
    const double r = std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]);
    sum += LPS::dilatation_term(b.wv, b.xi0, LPS::elongation(r, b.xi0));
  }
  return LPS::dilatation(sum, m);
}

TEST(LPS, InfluenceIsOneOverLength)
{
  EXPECT_EQ(LPS::influence(2.0), 0.5);
  EXPECT_EQ(LPS::influence(LC), 1.0 / LC);
  EXPECT_EQ(LPS::influence(0.0), 1.0 / PMB::NEAR_ZERO);    // as peri/lps
}

TEST(LPS, WeightedPartnerVolumeCarriesTheRamp)
{
  EXPECT_DOUBLE_EQ(LPS::weighted_partner_volume(LC, DELTA, LC, VOLUME), VOLUME / LC);
  EXPECT_DOUBLE_EQ(LPS::weighted_partner_volume(DELTA, DELTA, LC, VOLUME), 0.5 * VOLUME / DELTA);
}

TEST(LPS, FamilyAndWeightedVolume)
{
  const auto bonds = family();
  EXPECT_EQ(bonds.size(), 122u);    // the family of peri/lps at delta = 3.0002 lc
  // m = sum omega xi0^2 V ramp = sum |xi| V ramp: positive, below the continuum's pi delta^4
  const double m = weighted_volume(bonds);
  double direct = 0.0;
  for (const auto &b : bonds) direct += b.xi0 * VOLUME * PMB::volume_scale(b.xi0, DELTA, LC);
  EXPECT_NEAR(m, direct, 1e-14 * direct);
  EXPECT_LT(m, LPS::PI * std::pow(DELTA, 4));
  EXPECT_GT(m, 0.85 * LPS::PI * std::pow(DELTA, 4));
}

TEST(LPS, UniformExpansionHasDilatationThreeTimesTheStretch)
{
  const auto bonds = family();
  const double m = weighted_volume(bonds);
  const double s = 1.0e-4;
  const double F[3][3] = {{1 + s, 0, 0}, {0, 1 + s, 0}, {0, 0, 1 + s}};
  // theta = 3 / m sum w V xi0 (s xi0) = 3 s for any family (to the rounding of the elongations,
  // |y| - xi0 = s xi0 with an error of an ulp of xi0: 1e-12 of s)
  EXPECT_NEAR(dilatation(bonds, F, m), 3.0 * s, 1e-9 * s);
  const double none[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  EXPECT_EQ(dilatation(bonds, none, m), 0.0);
}

TEST(LPS, SimpleShearHasNoDilatationToFirstOrder)
{
  const auto bonds = family();
  const double m = weighted_volume(bonds);
  const double g = 1.0e-6;
  const double F[3][3] = {{1, g, 0}, {0, 1, 0}, {0, 0, 1}};
  // the elongations are g^2 small on average: theta = O(g^2)
  EXPECT_LT(std::fabs(dilatation(bonds, F, m)), 10.0 * g * g);
}

TEST(LPS, ForceStateOfUniformExpansion)
{
  const auto bonds = family();
  const double m = weighted_volume(bonds);
  const double s = 1.0e-4, theta = 3.0 * s;
  const LPS::Moduli mod = LPS::moduli(K, G);
  const LPS::AtomState a = LPS::atom_state(theta, m);
  for (const auto &b : bonds) {
    // t = (3K - 5G) wV 2 theta / m xi0 + 15 G wV 2 / m s xi0 = 18 K s wV xi0 / m
    const double t = LPS::force_state(mod, b.wv, b.xi0, s * b.xi0, a, a);
    const double expected = 18.0 * K * s * b.wv * b.xi0 / m;
    EXPECT_NEAR(t, expected, 1e-13 * expected);
    // no deviatoric extension: the bond holds no deviatoric energy
    EXPECT_NEAR(LPS::deviatoric_energy(mod, b.wv, b.xi0, s * b.xi0, LPS::third(theta), a.inv_m), 0.0,
                1e-20 * K * s * s);
  }
  // the classical energy density of a uniform dilatation, K theta^2 / 2
  EXPECT_DOUBLE_EQ(LPS::dilatation_energy(K, theta), 0.5 * K * theta * theta);
}

TEST(LPS, NoForceWithoutWeightedVolume)
{
  const LPS::Moduli mod = LPS::moduli(K, G);
  const LPS::AtomState with = LPS::atom_state(1e-4, 1e-12), without = LPS::atom_state(0.0, 0.0);
  EXPECT_EQ(without.inv_m, 0.0);
  EXPECT_EQ(LPS::force_state(mod, 1.0, LC, 1e-7, with, without), 0.0);
  EXPECT_EQ(LPS::force_state(mod, 1.0, LC, 1e-7, without, with), 0.0);
  EXPECT_NE(LPS::force_state(mod, 1.0, LC, 1e-7, with, with), 0.0);
  EXPECT_EQ(LPS::dilatation(1.0, 0.0), 0.0);
}

TEST(LPS, RoundOffElongationsAreZero)
{
  EXPECT_EQ(LPS::elongation(LC + 1e-17, LC), 0.0);
  EXPECT_EQ(LPS::elongation(2 * LC, LC), LC);
}

TEST(LPS, ShortRangeStiffnessIsFifteenPMBMicromoduli)
{
  // peri/lps's kshort = 15 x 18 K / (pi delta^4); 18 K / (pi delta^4) is the PMB micromodulus
  // of bulk modulus K (the peri/pmb example's c = 1.6863e22 is that of the peri/lps example's K
  // to 3e-4)
  const double c = LPS::pmb_micromodulus(K, DELTA);
  EXPECT_NEAR(c, 18.0 * K / (M_PI * std::pow(DELTA, 4)), 1e-14 * c);
  EXPECT_NEAR(LPS::pmb_micromodulus(14.9e9, DELTA), 1.6863e22, 5e-4 * 1.6863e22);
  EXPECT_NEAR(LPS::short_range_stiffness(K, DELTA), 15.0 * c, 1e-14 * 15.0 * c);
}

}    // namespace

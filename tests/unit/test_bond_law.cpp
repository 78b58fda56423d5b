// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_bond_law.h: the family cutoff, the partner volume and the bond coefficient the bond
   storage caches, on plain per-type tables (no LAMMPS). */

#include "bbpd_bond_law.h"

#include <gtest/gtest.h>

namespace {

constexpr double DX = 1.0e-3;             // grid spacing
constexpr double DELTA = 3.015e-3;        // horizon, m = 3
constexpr double C0 = 2.0e20;             // micromodulus constant
constexpr double VJ = DX * DX * 1.0e-3;   // partner volume (plane, thickness 1 mm)

struct Tables {
  double c0[2][2] = {{0.0, 0.0}, {0.0, C0}};
  double delta[2][2] = {{0.0, 0.0}, {0.0, DELTA}};
  const double *c0_rows[2] = {c0[0], c0[1]};
  const double *delta_rows[2] = {delta[0], delta[1]};
};

BBPD::BondLaw gaussian_law(const Tables &t)
{
  BBPD::BondLaw law;
  law.kernel = BBPD::kernel_info<BBPD::GaussianKernel>();
  law.model = BBPD::Model::PlaneStrain;
  law.geom = 1.0e-3;
  law.spacing = DX;
  law.micromodulus = BBPD::TypePairTable(1, t.c0_rows);
  law.horizon = BBPD::TypePairTable(1, t.delta_rows);
  return law;
}

TEST(BondLaw, FamilyReachesHalfASpacingPastTheHorizon)
{
  Tables t;
  const BBPD::BondLaw law = gaussian_law(t);
  const double rc = DELTA + 0.5 * DX;
  EXPECT_EQ(law.family_cutoff(1, 1), rc);
  EXPECT_TRUE(law.bonded(1, 1, 0.999 * rc * rc));
  EXPECT_FALSE(law.bonded(1, 1, rc * rc));
}

TEST(BondLaw, CoefficientIsKernelTimesPartialVolumeOverLength)
{
  Tables t;
  const BBPD::BondLaw law = gaussian_law(t);
  for (const double xi : {DX, 2.0 * DX, DELTA - 0.2 * DX, DELTA + 0.3 * DX}) {
    const double cv = BBPD::partial_volume(xi, DELTA, DX);
    EXPECT_EQ(law.partner_volume(1, 1, xi, VJ), cv * VJ);
    EXPECT_EQ(law.coefficient(1, 1, xi, VJ),
              C0 * BBPD::GaussianKernel::shape(xi / DELTA) * (cv * VJ) / xi);
  }
  EXPECT_EQ(law.partner_volume(1, 1, DELTA + DX, VJ), 0.0);    // beyond the cell: no volume
}

TEST(BondLaw, PmbUsesWholeVolumesAndTheLatticeRamp)
{
  Tables t;
  BBPD::BondLaw law = gaussian_law(t);
  law.kernel = BBPD::kernel_info<BBPD::ConstantKernel>();
  law.weighting = BBPD::PmbWeighting{DX};
  EXPECT_EQ(law.family_cutoff(1, 1), DELTA);
  EXPECT_TRUE(law.bonded(1, 1, DELTA * DELTA));    // the horizon itself is in the family
  EXPECT_EQ(law.partner_volume(1, 1, DELTA, VJ), VJ);
  EXPECT_EQ(law.coefficient(1, 1, DELTA, VJ),
            C0 * VJ * BBPD::PMB::volume_scale(DELTA, DELTA, DX) / DELTA);
  EXPECT_EQ(law.coefficient(1, 1, DX, VJ), C0 * VJ / DX);    // far inside: no ramp
}

TEST(BondLaw, HoldsItsValuesNotThePairStylesTables)
{
  Tables t;
  const BBPD::BondLaw law = gaussian_law(t);
  const double before = law.coefficient(1, 1, DX, VJ);
  t.c0[1][1] = 2.0 * C0;    // the pair style recalibrates its table after handing the law
  t.delta[1][1] = 2.0 * DELTA;
  EXPECT_EQ(law.coefficient(1, 1, DX, VJ), before);
  EXPECT_EQ(law.family_cutoff(1, 1), DELTA + 0.5 * DX);
}

TEST(BondLaw, GridSpacingFromVolume)
{
  EXPECT_DOUBLE_EQ(BBPD::grid_spacing_of(BBPD::Model::Bar1D, 2.0, 6.0), 3.0);
  EXPECT_DOUBLE_EQ(BBPD::grid_spacing_of(BBPD::Model::PlaneStress, 1e-3, 1e-9), 1e-3);
  EXPECT_DOUBLE_EQ(BBPD::grid_spacing_of(BBPD::Model::Solid3D, 1.0, 8e-9), 2e-3);
}

}    // namespace

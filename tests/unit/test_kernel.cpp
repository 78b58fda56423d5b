// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_kernel.h against the paper as printed: Table 1 (c0 of three kernels in
   1D, plane stress and plane strain), eqs. 14-16 (s0 in 2D), eq. 19 (C_v) and
   eq. 25 (time step); 3D against Silling & Askari (2005). Kernel moments
   against quadrature. */

#include "bbpd_kernel.h"
#include "bbpd_quadrature.h"
#include "bbpd_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace BBPD;
using namespace BBPD::test::material;
using BBPD::test::rel_near;

namespace {

constexpr double TOL = 1.0e-12;

const double E4 = std::exp(4.0);
const double ERF2 = std::erf(2.0);
const double SQRT_PI = std::sqrt(PI);

const KernelInfo CONSTANT = kernel_info<ConstantKernel>();
const KernelInfo TRIANGULAR = kernel_info<TriangularKernel>();
const KernelInfo GAUSSIAN = kernel_info<GaussianKernel>();

double c0(const KernelInfo &k, Model m)
{
  return micromodulus(k, m, E, DELTA, m == Model::Bar1D ? A : H);
}

/* ---------------------------------------------------------------------- */
// Table 1, row by row

TEST(Table1, Constant)
{
  EXPECT_TRUE(rel_near(c0(CONSTANT, Model::Bar1D), 2 * E / (A * DELTA * DELTA), TOL));
  EXPECT_TRUE(rel_near(c0(CONSTANT, Model::PlaneStress), 9 * E / (PI * H * std::pow(DELTA, 3)), TOL));
  EXPECT_TRUE(
      rel_near(c0(CONSTANT, Model::PlaneStrain), 48 * E / (5 * PI * H * std::pow(DELTA, 3)), TOL));
}

TEST(Table1, Triangular)
{
  EXPECT_TRUE(rel_near(c0(TRIANGULAR, Model::Bar1D), 6 * E / (A * DELTA * DELTA), TOL));
  EXPECT_TRUE(
      rel_near(c0(TRIANGULAR, Model::PlaneStress), 36 * E / (PI * H * std::pow(DELTA, 3)), TOL));
  EXPECT_TRUE(rel_near(c0(TRIANGULAR, Model::PlaneStrain),
                       192 * E / (5 * PI * H * std::pow(DELTA, 3)), TOL));
}

TEST(Table1, Gaussian)
{
  EXPECT_TRUE(
      rel_near(c0(GAUSSIAN, Model::Bar1D), 8 * E4 * E / (A * DELTA * DELTA * (E4 - 1)), TOL));
  EXPECT_TRUE(rel_near(c0(GAUSSIAN, Model::PlaneStress),
                       96 * E4 * E / ((E4 * SQRT_PI * ERF2 - 4) * H * PI * std::pow(DELTA, 3)),
                       TOL));
  EXPECT_TRUE(rel_near(c0(GAUSSIAN, Model::PlaneStrain),
                       512 * E4 * E / (5 * (E4 * SQRT_PI * ERF2 - 4) * H * PI * std::pow(DELTA, 3)),
                       TOL));
}

// 3D is not in Table 1: Silling & Askari (2005) c = 18 K/(pi delta^4) with
// K = E/(3(1 - 2 nu)), nu = 1/4, and s0 = sqrt(5 G/(9 K delta)) (constant kernel)
TEST(Solid3D, ConstantKernelSillingAskari)
{
  const double K = E / (3.0 * (1.0 - 2.0 * 0.25));
  const double c = c0(CONSTANT, Model::Solid3D);
  EXPECT_TRUE(rel_near(c, 18 * K / (PI * std::pow(DELTA, 4)), TOL));
  EXPECT_TRUE(rel_near(critical_stretch(CONSTANT, Model::Solid3D, c, GC, DELTA),
                       std::sqrt(5 * GC / (9 * K * DELTA)), TOL));
}

/* ---------------------------------------------------------------------- */
// eqs. 14-16: plane stress as printed; 14 and 16 are written with c0 and h so
// they hold for plane strain too

TEST(CriticalStretch, Eq14Constant)
{
  for (Model m : {Model::PlaneStress, Model::PlaneStrain}) {
    const double c = c0(CONSTANT, m);
    EXPECT_TRUE(rel_near(critical_stretch(CONSTANT, m, c, GC, DELTA, H),
                         std::sqrt(4 * GC / (H * c * std::pow(DELTA, 4))), TOL));
  }
}

TEST(CriticalStretch, Eq15Triangular)
{
  const double c = c0(TRIANGULAR, Model::PlaneStress);
  EXPECT_TRUE(rel_near(critical_stretch(TRIANGULAR, Model::PlaneStress, c, GC, DELTA, H),
                       std::sqrt(5 * PI * GC / (9 * E * DELTA)), TOL));
}

TEST(CriticalStretch, Eq16Gaussian)
{
  for (Model m : {Model::PlaneStress, Model::PlaneStrain}) {
    const double c = c0(GAUSSIAN, m);
    EXPECT_TRUE(rel_near(critical_stretch(GAUSSIAN, m, c, GC, DELTA, H),
                         std::sqrt(32 * GC / (H * c * std::pow(DELTA, 4) * (1 - 5 / E4))), TOL));
  }
}

/* ---------------------------------------------------------------------- */
// kernels

TEST(Kernel, MomentsMatchQuadrature)
{
  const GaussLegendre gl(20);
  for (const auto &name : BBPD::test::kernel_names()) {
    const KernelInfo k = kernel_by_name(name);
    for (int n = 0; n <= 4; ++n) {
      const double q = gl.integrate([&](double r) { return k.shape(r) * std::pow(r, n); }, 0, 1, 4);
      EXPECT_TRUE(rel_near(k.moment(n), q, TOL)) << name << " M" << n;
    }
  }
}

TEST(Kernel, ShapesAsInTable1)
{
  EXPECT_DOUBLE_EQ(CONSTANT.shape(0.3), 1.0);
  EXPECT_DOUBLE_EQ(TRIANGULAR.shape(0.3), 0.7);
  EXPECT_DOUBLE_EQ(GAUSSIAN.shape(0.3), std::exp(-0.36));
  EXPECT_DOUBLE_EQ(GAUSSIAN.shape(1.0), 1.0 / E4);
}

TEST(Kernel, ByName)
{
  EXPECT_STREQ(kernel_by_name("gaussian").name, "gaussian");
  EXPECT_STREQ(kernel_by_name("triangular").name, "triangular");
  EXPECT_STREQ(kernel_by_name("constant").name, "constant");
  EXPECT_THROW(kernel_by_name("cubic"), std::invalid_argument);
}

/* ---------------------------------------------------------------------- */
// eq. 19

TEST(PartialVolume, Eq19)
{
  const double delta = 1.0, dx = 0.2;
  constexpr double EPS = 1.0e-14;    // 0.95 etc. are not exact in binary
  EXPECT_EQ(partial_volume(0.2, delta, dx), 1.0);
  EXPECT_EQ(partial_volume(0.875, delta, dx), 1.0);
  EXPECT_NEAR(partial_volume(0.95, delta, dx), 0.75, EPS);
  EXPECT_NEAR(partial_volume(1.0, delta, dx), 0.5, EPS);    // cell centred on the horizon
  EXPECT_NEAR(partial_volume(1.05, delta, dx), 0.25, EPS);
  EXPECT_NEAR(partial_volume(1.0999, delta, dx), 0.0005, EPS);
  EXPECT_EQ(partial_volume(1.125, delta, dx), 0.0);
  EXPECT_EQ(partial_volume(2.0, delta, dx), 0.0);
}

/* ---------------------------------------------------------------------- */
// eq. 25 as printed and Silling & Askari's factor 2

TEST(TimeStep, PaperAndSilling)
{
  EXPECT_DOUBLE_EQ(stable_timestep_paper(2.0, 8.0), 0.5);
  EXPECT_DOUBLE_EQ(stable_timestep_silling(2.0, 8.0), std::sqrt(0.5));
  EXPECT_DOUBLE_EQ(stable_timestep_silling(3.0, 5.0) / stable_timestep_paper(3.0, 5.0),
                   std::sqrt(2.0));
}

}    // namespace

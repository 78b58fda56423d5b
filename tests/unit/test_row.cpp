// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_row.h: the bond loop of one row on plain arrays (no LAMMPS). The portable loop gives
   the force of eq. 21 summed in fixed lanes, and the SIMD kernel of this build (AVX-512 or
   AVX2, if any) gives the same bits. */

#include "bbpd_row.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace {

using BBPD::LANES;
using BBPD::RowTally;

// atom 0 at the centre, NB partners around it, displaced a little from a reference grid
constexpr int NB = 37;

struct Row {
  std::vector<double> x;    // 3 per atom, atom 0 first
  std::vector<int> bj;
  std::vector<double> xi0, coef;
};

Row make_row(double strain)
{
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Row row;
  row.x = {0.1, -0.2, 0.05};
  for (int k = 0; k < NB; k++) {
    const double ref[3] = {1.0 + 0.1 * k, 0.5 * u(gen), 0.5 * u(gen)};
    const double len = std::sqrt(ref[0] * ref[0] + ref[1] * ref[1] + ref[2] * ref[2]);
    for (int m = 0; m < 3; m++) row.x.push_back(row.x[m] + ref[m] * (1.0 + strain) + 1e-3 * u(gen));
    row.bj.push_back(k + 1);
    row.xi0.push_back(len);
    row.coef.push_back(1.0 + 0.25 * u(gen));
  }
  return row;
}

template <int FRACTURE, int EV>
bool portable(const Row &row, double s0, double *f, RowTally *tally)
{
  double ax[LANES] = {0.0}, ay[LANES] = {0.0}, az[LANES] = {0.0};
  *tally = {};
  auto xi0_of = [&](int k) { return row.xi0[k]; };
  auto coef_of = [&](int k, double) { return row.coef[k]; };
  auto s0_of = [&](int) { return s0; };
  const bool broken = BBPD::row_force_portable<FRACTURE, EV>(
      row.x.data(), 0, row.bj.data(), NB, xi0_of, coef_of, s0_of, 0.0, ax, ay, az, tally);
  BBPD::lane_sum(ax, ay, az, f);
  return broken;
}

TEST(Row, PortableLoopIsEquation21)
{
  const Row row = make_row(0.01);
  double f[3];
  RowTally tally;
  EXPECT_FALSE((portable<1, 1>(row, 1.0, f, &tally)));
  double ref[3] = {0.0, 0.0, 0.0}, eng = 0.0;
  for (int k = 0; k < NB; k++) {
    double d[3];
    for (int m = 0; m < 3; m++) d[m] = row.x[3 * (k + 1) + m] - row.x[m];
    const double r = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double elong = r - row.xi0[k];
    for (int m = 0; m < 3; m++) ref[m] += row.coef[k] * elong * d[m] / r;
    eng += 0.25 * row.coef[k] * elong * elong;
  }
  for (int m = 0; m < 3; m++) EXPECT_NEAR(f[m], ref[m], 1e-12 * std::fabs(ref[m]) + 1e-15);
  EXPECT_NEAR(BBPD::lane_total(tally.eng), eng, 1e-12 * eng);
}

TEST(Row, PortableLoopFlagsAStretchedBond)
{
  const Row row = make_row(0.01);
  double f[3];
  RowTally tally;
  EXPECT_FALSE((portable<1, 0>(row, 0.5, f, &tally)));       // stretches are ~1 %
  EXPECT_TRUE((portable<1, 0>(row, 1.0e-4, f, &tally)));     // every bond past 1e-4
}

TEST(Row, SimdKernelGivesTheSameBits)
{
#ifndef BBPD_SIMD
  GTEST_SKIP() << "this build has no SIMD kernel (no AVX2 or AVX-512 target)";
#else
  for (const double strain : {0.002, -0.003}) {
    const Row row = make_row(strain);
    const BBPD::PerBondValues per_bond = {row.xi0.data(), row.coef.data()};
    // the same values through a class table (the kernels read LANES classes past the row end)
    BBPD::BondClassTable table;
    std::vector<BBPD::BondClass> cls(NB + LANES, 0);
    for (int k = 0; k < NB; k++) ASSERT_TRUE(table.add(row.xi0[k], row.coef[k], cls[k]));
    const BBPD::ClassValues by_class = {cls.data(), table.xi0.data(), table.coef.data()};
    double f[3], fs[3], fc[3], ax[LANES], ay[LANES], az[LANES];
    RowTally tally, tally_simd, tally_class;
    portable<0, 1>(row, 0.0, f, &tally);
    EXPECT_FALSE((row_force_simd<0, 1>(row.x.data(), 0, row.bj.data(), per_bond, NB, 0.0, 0.0,
                                       ax, ay, az, &tally_simd)));
    BBPD::lane_sum(ax, ay, az, fs);
    EXPECT_EQ(std::memcmp(f, fs, sizeof f), 0) << f[0] << " vs " << fs[0];
    EXPECT_EQ(std::memcmp(tally.eng, tally_simd.eng, sizeof tally.eng), 0);
    EXPECT_EQ(std::memcmp(tally.vir, tally_simd.vir, sizeof tally.vir), 0);
    EXPECT_FALSE((row_force_simd<0, 1>(row.x.data(), 0, row.bj.data(), by_class, NB, 0.0, 0.0,
                                       ax, ay, az, &tally_class)));
    BBPD::lane_sum(ax, ay, az, fc);
    EXPECT_EQ(std::memcmp(f, fc, sizeof f), 0) << f[0] << " vs " << fc[0];
    EXPECT_EQ(std::memcmp(tally.eng, tally_class.eng, sizeof tally.eng), 0);
    // breaking: the same verdict at a critical stretch between the smallest and largest stretch
    EXPECT_EQ((portable<1, 0>(row, 1e-3, f, &tally)),
              (row_force_simd<1, 0>(row.x.data(), 0, row.bj.data(), per_bond, NB, 1e-3, 0.0, ax,
                                    ay, az, &tally_simd)));
  }
#endif
}

}    // namespace

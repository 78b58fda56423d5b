// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_bond_model.h: a bond model is the one place that says what a bond does. Two toy
   models (toy_bond_models.h), each a struct of a few lines, go through the portable loop and this build's SIMD
   kernel (AVX-512 or AVX2) unchanged: a breaking rule that also breaks bonds in compression,
   and a bond twice as stiff. The loops need no edit, and the widths agree bit for bit. */

#include "bbpd_bond_model.h"
#include "bbpd_row.h"
#include "bbpd_test_row.h"
#include "toy_bond_models.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

namespace {

using BBPD::LANES;
using BBPD::RowTally;

using BBPDToy::DoubleStiffnessBond;
using BBPDToy::SymmetricStretchBond;

constexpr int NB = 29;    // partners of atom 0: 3 full groups of 8 and a tail

using BBPD::test::Row;

// atom 0 and NB partners, every bond at the given stretch to within 1e-4
Row make_row(double stretch)
{
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return BBPD::test::make_row(NB, {0.3, 0.1, -0.4}, [&](int k, const double *x0, double *ref, double *p) {
    ref[0] = u(gen);
    ref[1] = u(gen);
    ref[2] = 1.0 + 0.05 * k;
    const double scale = 1.0 + stretch + 1e-4 * u(gen);
    for (int m = 0; m < 3; m++) p[m] = x0[m] + ref[m] * scale;
    return 1.0 + 0.5 * u(gen);
  });
}

struct Result {
  bool broken;
  double f[3];
  RowTally tally;
};

template <class Model, int FRACTURE> Result portable(const Row &row, double s0)
{
  Result r;
  r.broken = BBPD::test::portable_row<Model, FRACTURE, 1>(row, s0, r.f, &r.tally);
  return r;
}

#ifdef BBPD_SIMD
template <class Model, int FRACTURE> Result simd(const Row &row, double s0)
{
  Result r;
  double ax[LANES], ay[LANES], az[LANES];
  const BBPD::PerBondValues per_bond = {row.xi0.data(), row.coef.data()};
  r.tally = {};
  r.broken = row_force_simd<FRACTURE, 1, Model>(row.x.data(), 0, row.bj.data(), per_bond, NB, s0,
                                                0.0, ax, ay, az, &r.tally);
  BBPD::lane_sum(ax, ay, az, r.f);
  return r;
}
#endif

bool same_bits(const Result &a, const Result &b)
{
  return std::memcmp(a.f, b.f, sizeof a.f) == 0 &&
      std::memcmp(a.tally.eng, b.tally.eng, sizeof a.tally.eng) == 0 &&
      std::memcmp(a.tally.vir, b.tally.vir, sizeof a.tally.vir) == 0;
}

TEST(BondModel, ToyBreakingRuleBreaksCompressedBondsTheDefaultKeeps)
{
  const Row squeezed = make_row(-0.02), pulled = make_row(0.02);
  const double s0 = 0.01;
  EXPECT_FALSE((portable<BBPD::CriticalStretchBond, 1>(squeezed, s0).broken));
  EXPECT_TRUE((portable<SymmetricStretchBond, 1>(squeezed, s0).broken));
  // in tension the two rules agree
  EXPECT_TRUE((portable<BBPD::CriticalStretchBond, 1>(pulled, s0).broken));
  EXPECT_TRUE((portable<SymmetricStretchBond, 1>(pulled, s0).broken));
  EXPECT_FALSE((portable<SymmetricStretchBond, 1>(make_row(0.005), s0).broken));
  EXPECT_FALSE((portable<SymmetricStretchBond, 1>(make_row(-0.005), s0).broken));
}

TEST(BondModel, ToyForceIsTwiceTheDefaultBitForBit)
{
  const Row row = make_row(0.003);
  const Result one = portable<BBPD::CriticalStretchBond, 0>(row, 0.0);
  const Result two = portable<DoubleStiffnessBond, 0>(row, 0.0);
  for (int m = 0; m < 3; m++) {
    EXPECT_NE(one.f[m], 0.0);
    EXPECT_EQ(two.f[m], 2.0 * one.f[m]);    // scaling by 2 is exact
  }
  // the energy share is the model's own, untouched by the toy
  EXPECT_EQ(std::memcmp(one.tally.eng, two.tally.eng, sizeof one.tally.eng), 0);
}

TEST(BondModel, EveryWidthGivesTheSameBitsForTheToys)
{
#ifndef BBPD_SIMD
  GTEST_SKIP() << "this build has no SIMD kernel (no AVX2 or AVX-512 target)";
#else
  for (const double stretch : {-0.02, -0.005, 0.003, 0.02}) {
    const Row row = make_row(stretch);
    EXPECT_TRUE(same_bits(portable<DoubleStiffnessBond, 0>(row, 0.0), simd<DoubleStiffnessBond, 0>(row, 0.0)));
    EXPECT_TRUE(same_bits(portable<SymmetricStretchBond, 0>(row, 0.0), simd<SymmetricStretchBond, 0>(row, 0.0)));
    for (const double s0 : {0.001, 0.01, 0.1}) {
      EXPECT_EQ((portable<SymmetricStretchBond, 1>(row, s0).broken), (simd<SymmetricStretchBond, 1>(row, s0).broken))
          << "stretch " << stretch << " s0 " << s0;
      EXPECT_EQ((portable<BBPD::CriticalStretchBond, 1>(row, s0).broken),
                (simd<BBPD::CriticalStretchBond, 1>(row, s0).broken));
    }
  }
  // the toy rule reaches the SIMD kernel: it breaks a squeezed row the default keeps
  EXPECT_TRUE((simd<SymmetricStretchBond, 1>(make_row(-0.02), 0.01).broken));
  EXPECT_FALSE((simd<BBPD::CriticalStretchBond, 1>(make_row(-0.02), 0.01).broken));
#endif
}

}    // namespace

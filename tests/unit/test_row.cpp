// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_row.h: the bond loop of one row on plain arrays (no LAMMPS). The portable loop gives
   the force of eq. 21 summed in fixed lanes, and the SIMD kernel of this build (AVX-512 or
   AVX2, if any) gives the same bits. */

#include "bbpd_row.h"
#include "bbpd_test_row.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace {

using BBPD::LANES;
using BBPD::RowTally;

// atom 0 at the centre, NB partners around it, displaced a little from a reference grid
constexpr int NB = 37;

using BBPD::test::Row;

Row make_row(double strain)
{
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return BBPD::test::make_row(NB, {0.1, -0.2, 0.05}, [&](int k, const double *x0, double *ref, double *p) {
    ref[0] = 1.0 + 0.1 * k;
    ref[1] = 0.5 * u(gen);
    ref[2] = 0.5 * u(gen);
    for (int m = 0; m < 3; m++) p[m] = x0[m] + ref[m] * (1.0 + strain) + 1e-3 * u(gen);
    return 1.0 + 0.25 * u(gen);
  });
}

template <int FRACTURE, int EV>
bool portable(const Row &row, double s0, double *f, RowTally *tally)
{
  return BBPD::test::portable_row<BBPD::CriticalStretchBond, FRACTURE, EV>(row, s0, f, tally);
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
    const BBPD::ClassValues by_class = {cls.data(), table.data()};
    double f[3], fs[3], fc[3], ax[LANES], ay[LANES], az[LANES];
    RowTally tally, tally_simd, tally_class;
    portable<0, 1>(row, 0.0, f, &tally);
    EXPECT_FALSE((row_force_simd<0, 1, BBPD::CriticalStretchBond>(row.x.data(), 0, row.bj.data(), per_bond, NB, 0.0, 0.0,
                                       ax, ay, az, &tally_simd)));
    BBPD::lane_sum(ax, ay, az, fs);
    EXPECT_EQ(std::memcmp(f, fs, sizeof f), 0) << f[0] << " vs " << fs[0];
    EXPECT_EQ(std::memcmp(tally.eng, tally_simd.eng, sizeof tally.eng), 0);
    EXPECT_EQ(std::memcmp(tally.vir, tally_simd.vir, sizeof tally.vir), 0);
    EXPECT_FALSE((row_force_simd<0, 1, BBPD::CriticalStretchBond>(row.x.data(), 0, row.bj.data(), by_class, NB, 0.0, 0.0,
                                       ax, ay, az, &tally_class)));
    BBPD::lane_sum(ax, ay, az, fc);
    EXPECT_EQ(std::memcmp(f, fc, sizeof f), 0) << f[0] << " vs " << fc[0];
    EXPECT_EQ(std::memcmp(tally.eng, tally_class.eng, sizeof tally.eng), 0);
    // breaking: the same verdict at a critical stretch between the smallest and largest stretch
    EXPECT_EQ((portable<1, 0>(row, 1e-3, f, &tally)),
              (row_force_simd<1, 0, BBPD::CriticalStretchBond>(row.x.data(), 0, row.bj.data(), per_bond, NB, 1e-3, 0.0, ax,
                                    ay, az, &tally_simd)));
  }
#endif
}

// the row of make_row with the centre atom moved to index CENTRE: partners before and after it
// in memory, named by indices or by offsets from CENTRE (bbpd_partner_index.h)
constexpr int CENTRE = 20;
struct MovedRow {
  std::vector<double> x;
  std::vector<int> bj;
  std::vector<BBPD::PartnerOffset> off;    // LANES entries of padding past the row end
};

MovedRow move_centre(const Row &row)
{
  MovedRow moved;
  moved.x.assign(row.x.size(), 0.0);
  const auto place = [&](int from, int to) {
    for (int m = 0; m < 3; m++) moved.x[3 * to + m] = row.x[3 * from + m];
  };
  place(0, CENTRE);
  for (int k = 0; k < NB; k++) {
    const int j = k < CENTRE ? k : k + 1;
    place(k + 1, j);
    moved.bj.push_back(j);
    moved.off.push_back(static_cast<BBPD::PartnerOffset>(j - CENTRE));
  }
  moved.off.resize(NB + LANES, 0);
  return moved;
}

TEST(Row, PartnerOffsetsGiveTheBitsOfIndices)
{
  EXPECT_TRUE(BBPD::fits_offset(40000, 40000 + 32767));
  EXPECT_FALSE(BBPD::fits_offset(40000, 40000 + 32768));
  EXPECT_TRUE(BBPD::fits_offset(40000, 40000 - 32768));
  EXPECT_FALSE(BBPD::fits_offset(40000, 40000 - 32769));
  const Row row = make_row(0.004);
  const MovedRow moved = move_centre(row);
  double f[3], fi[3], fo[3], ax[LANES], ay[LANES], az[LANES];
  RowTally tally, tally_i, tally_o;
  portable<1, 1>(row, 1.0, f, &tally);
  auto xi0_of = [&](int k) { return row.xi0[k]; };
  auto coef_of = [&](int k, double) { return row.coef[k]; };
  auto s0_of = [&](int) { return 1.0; };
  for (const bool offsets : {false, true}) {
    double a[3][LANES] = {};
    tally_o = {};
    EXPECT_FALSE(offsets
        ? (BBPD::row_force_portable<1, 1, BBPD::CriticalStretchBond>(moved.x.data(), CENTRE, moved.off.data(), NB, xi0_of,
                                          coef_of, s0_of, 0.0, a[0], a[1], a[2], &tally_o))
        : (BBPD::row_force_portable<1, 1, BBPD::CriticalStretchBond>(moved.x.data(), CENTRE, moved.bj.data(), NB, xi0_of,
                                          coef_of, s0_of, 0.0, a[0], a[1], a[2], &tally_o)));
    BBPD::lane_sum(a[0], a[1], a[2], fo);
    EXPECT_EQ(std::memcmp(f, fo, sizeof f), 0) << "portable, offsets " << offsets;
    EXPECT_EQ(std::memcmp(tally.eng, tally_o.eng, sizeof tally.eng), 0);
  }
#ifdef BBPD_SIMD
  const BBPD::PerBondValues per_bond = {row.xi0.data(), row.coef.data()};
  EXPECT_FALSE((row_force_simd<1, 1, BBPD::CriticalStretchBond>(moved.x.data(), CENTRE, moved.bj.data(), per_bond, NB, 1.0,
                                     0.0, ax, ay, az, &tally_i)));
  BBPD::lane_sum(ax, ay, az, fi);
  EXPECT_FALSE((row_force_simd<1, 1, BBPD::CriticalStretchBond>(moved.x.data(), CENTRE, moved.off.data(), per_bond, NB, 1.0,
                                     0.0, ax, ay, az, &tally_o)));
  BBPD::lane_sum(ax, ay, az, fo);
  EXPECT_EQ(std::memcmp(f, fi, sizeof f), 0);
  EXPECT_EQ(std::memcmp(f, fo, sizeof f), 0);
  EXPECT_EQ(std::memcmp(tally.vir, tally_o.vir, sizeof tally.vir), 0);
  // breaking: the same verdict from offsets as from indices
  EXPECT_EQ((row_force_simd<1, 0, BBPD::CriticalStretchBond>(moved.x.data(), CENTRE, moved.bj.data(), per_bond, NB, 1e-3,
                                  0.0, ax, ay, az, &tally_i)),
            (row_force_simd<1, 0, BBPD::CriticalStretchBond>(moved.x.data(), CENTRE, moved.off.data(), per_bond, NB, 1e-3,
                                  0.0, ax, ay, az, &tally_o)));
#endif
}

// compact storage caches coefficients by (reference length, partner volume, types): the distinct
// lengths of a family of 5 spacings (lattice offsets a, b, c; among them xi and 2 xi, which
// differ in the exponent only) all get their own slot, so a row never evicts its own entries
TEST(Row, CoefficientCacheSlotsSeparateTheLengthsOfAFamily)
{
  const double dx = 1e-3, volume = 1e-9;
  std::vector<double> lengths;    // 3D family (a = 0: the 2D one)
  for (int a = 0; a <= 5; a++)
    for (int b = a; b <= 5; b++)
      for (int c = b; c <= 5; c++) {
        const int q = a * a + b * b + c * c;
        if (q > 0 && q <= 25) lengths.push_back(std::sqrt(double(q)) * dx);
      }
  std::sort(lengths.begin(), lengths.end());
  lengths.erase(std::unique(lengths.begin(), lengths.end()), lengths.end());    // 3-4-5 and 0-0-5
  std::vector<std::uint64_t> slots;
  std::uint64_t vb;
  std::memcpy(&vb, &volume, sizeof vb);
  const std::uint64_t t = 1 * BBPD::CoefCache::TYPE_STRIDE + 1;
  for (const double len : lengths) {
    std::uint64_t xb;
    std::memcpy(&xb, &len, sizeof xb);
    slots.push_back(BBPD::CoefCache::slot(xb, vb, t));
  }
  std::sort(slots.begin(), slots.end());
  EXPECT_EQ(std::adjacent_find(slots.begin(), slots.end()), slots.end())
      << lengths.size() << " lengths share " << slots.size() << " slots";
}

}    // namespace

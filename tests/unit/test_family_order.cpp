// SPDX-License-Identifier: GPL-2.0-or-later
// The counting sort of a bond family by cell gives exactly std::sort's order: on a grid, on
// a jittered grid (entries that share a cell, out of order within it), with coincident
// partners (tag ties), and with cells too many or too few (the comparison sort's fallback).
#include "bbpd_family_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

using Entry = BBPD::FamilyEntry<int>;

static std::vector<Entry> grid_family(double h, int m, double jitter, std::mt19937 &rng)
{
  std::uniform_real_distribution<double> u(-jitter, jitter);
  std::vector<Entry> f;
  int tag = 1;
  for (int z = -m; z <= m; z++)
    for (int y = -m; y <= m; y++)
      for (int x = -m; x <= m; x++) {
        if (x * x + y * y + z * z > m * m || (x == 0 && y == 0 && z == 0)) continue;
        f.push_back({z * h + u(rng) * h, y * h + u(rng) * h, x * h + u(rng) * h, tag++});
      }
  std::shuffle(f.begin(), f.end(), rng);
  return f;
}

static bool same_order(const std::vector<Entry> &a, const std::vector<Entry> &b)
{
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); k++)
    if (a[k].tag != b[k].tag) return false;
  return true;
}

TEST(FamilyOrder, EqualsComparisonSortOnGridsAndJitteredGrids)
{
  std::mt19937 rng(7);
  BBPD::FamilyOrder<int> order;
  for (double jitter : {0.0, 0.3, 0.7, 2.0})
    for (double cell : {0.25e-3, 0.1e-3, 1e-3, 1.0, 1e-12}) {
      auto f = grid_family(0.25e-3, 4, jitter, rng);
      auto ref = f;
      std::sort(ref.begin(), ref.end());
      order.sort(f, cell);
      EXPECT_TRUE(same_order(f, ref)) << "jitter " << jitter << " cell " << cell;
    }
}

TEST(FamilyOrder, CoincidentPartnersInTagOrder)
{
  std::mt19937 rng(11);
  BBPD::FamilyOrder<int> order;
  auto f = grid_family(1.0, 3, 0.0, rng);
  const std::size_t n = f.size();
  for (std::size_t k = 0; k < n; k += 3) f.push_back({f[k].z, f[k].y, f[k].x, f[k].tag + 1000});
  std::shuffle(f.begin(), f.end(), rng);
  auto ref = f;
  std::sort(ref.begin(), ref.end());
  order.sort(f, 1.0);
  EXPECT_TRUE(same_order(f, ref));
}

// the insertion sort is what makes a jittered grid exact: without it, the cells alone misorder
TEST(FamilyOrder, CellsAloneWouldMisorderAJitteredGrid)
{
  std::mt19937 rng(3);
  auto f = grid_family(1.0, 4, 0.7, rng);
  auto ref = f;
  std::sort(ref.begin(), ref.end());
  auto cell = [](double v) { return std::floor(v + 0.5); };
  std::stable_sort(f.begin(), f.end(), [&](const Entry &a, const Entry &b) {
    if (cell(a.z) != cell(b.z)) return cell(a.z) < cell(b.z);
    if (cell(a.y) != cell(b.y)) return cell(a.y) < cell(b.y);
    return cell(a.x) < cell(b.x);
  });
  EXPECT_FALSE(same_order(f, ref));
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_bond_table.h: the table of distinct (reference length, coefficient) pairs that bonds
   point into by class. */

#include "bbpd_bond_table.h"

#include <gtest/gtest.h>

#include <cmath>

using BBPD::BondClass;
using BBPD::BondClassTable;

TEST(BondClassTable, EqualPairsShareAClass)
{
  BondClassTable t;
  BondClass a = 99, b = 99, c = 99;
  ASSERT_TRUE(t.add(1e-3, 2.5e17, a));
  ASSERT_TRUE(t.add(1.4142135623730951e-3, 2.5e17, b));
  ASSERT_TRUE(t.add(1e-3, 2.5e17, c));
  EXPECT_EQ(a, c);
  EXPECT_NE(a, b);
  EXPECT_EQ(t.size(), 2u);
  EXPECT_EQ(t.xi0(b), 1.4142135623730951e-3);
  EXPECT_EQ(t.coef(a), 2.5e17);
}

TEST(BondClassTable, PairsAreComparedByTheirBits)
{
  // one ulp apart in either member: distinct classes, each handed back exactly
  BondClassTable t;
  const double x = 1e-3, y = std::nextafter(x, 1.0);
  BondClass a = 0, b = 0, c = 0;
  ASSERT_TRUE(t.add(x, 1.0, a));
  ASSERT_TRUE(t.add(y, 1.0, b));
  ASSERT_TRUE(t.add(x, std::nextafter(1.0, 2.0), c));
  EXPECT_EQ(t.size(), 3u);
  EXPECT_EQ(t.xi0(b), y);
  EXPECT_EQ(t.coef(c), std::nextafter(1.0, 2.0));
  EXPECT_NE(a, b);
  EXPECT_NE(a, c);
}

TEST(BondClassTable, RefusesAPairBeyondTheLastClass)
{
  BondClassTable t;
  BondClass cls = 0;
  for (std::size_t k = 0; k < BondClassTable::MAX_CLASSES; k++)
    ASSERT_TRUE(t.add(1.0 + (double) k, 1.0, cls));
  EXPECT_EQ(cls, BondClassTable::MAX_CLASSES - 1);
  EXPECT_FALSE(t.add(-1.0, 1.0, cls));
  EXPECT_TRUE(t.add(1.0, 1.0, cls));    // known pairs still have their class
  EXPECT_EQ(cls, 0);
  t.clear();
  EXPECT_EQ(t.size(), 0u);
  EXPECT_TRUE(t.add(-1.0, 1.0, cls));
  EXPECT_EQ(cls, 0);
}

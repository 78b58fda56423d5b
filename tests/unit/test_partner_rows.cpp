// SPDX-License-Identifier: GPL-2.0-or-later
// The rows of bbpd_partner_rows.h (fix bbpd/bonds's partners, fix bbpd/history's history)
// against a plain vector of vectors driven through the same random LAMMPS callbacks: resize
// (a family built or an atom arriving), copy (a sort), move (migration) and clear (a new
// atom); every row keeps its values, however often the pool is compacted.
#include "bbpd_partner_rows.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

TEST(PartnerRows, FollowsTheCallbacksAsPlainRowsDo)
{
  constexpr int SLOTS = 64, STEPS = 20000, LONGEST = 40;
  std::mt19937 rng(12345);
  std::uniform_int_distribution<int> slot(0, SLOTS - 1), length(0, LONGEST), op(0, 3);
  BBPD::PartnerRows<double> rows;
  std::vector<std::vector<double>> plain(SLOTS);
  rows.grow(SLOTS);
  double next = 1.0;
  for (int step = 0; step < STEPS; step++) {
    const int i = slot(rng), j = slot(rng);
    switch (op(rng)) {
      case 0: {    // a new row of its own values
        const int n = length(rng);
        rows.clear(i);
        rows.resize(i, n);
        plain[i].assign(n, 0.0);
        for (int k = 0; k < n; k++) rows[i][k] = plain[i][k] = next++;
        break;
      }
      case 1:    // a sort's copy: the source stays
        rows.copy(i, j, rows.room(i));
        if (i != j) plain[j] = plain[i];
        break;
      case 2:    // migration: the source is emptied
        rows.move(i, j);
        if (i != j) {
          plain[j] = plain[i];
          plain[i].clear();
        }
        break;
      default:
        rows.clear(i);
        plain[i].clear();
    }
    // a copy into a row with more room keeps the room: the values held are the plain row's
    for (int s = 0; s < SLOTS; s++) {
      ASSERT_GE(rows.room(s), static_cast<int>(plain[s].size()));
      for (std::size_t k = 0; k < plain[s].size(); k++) ASSERT_EQ(rows[s][k], plain[s][k]);
    }
  }
}

TEST(PartnerRows, ARowWithRoomKeepsItsValues)
{
  BBPD::PartnerRows<int> rows;
  rows.grow(2);
  rows.resize(0, 4);
  for (int k = 0; k < 4; k++) rows[0][k] = k + 1;
  rows.resize(0, 3);    // room enough: untouched
  EXPECT_EQ(rows.room(0), 4);
  for (int k = 0; k < 4; k++) EXPECT_EQ(rows[0][k], k + 1);
  rows.clear(0);
  EXPECT_EQ(rows.room(0), 0);
  rows.resize(1, 2);    // a new row is zero
  EXPECT_EQ(rows[1][0], 0);
  EXPECT_EQ(rows[1][1], 0);
}

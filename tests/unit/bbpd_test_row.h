// SPDX-License-Identifier: GPL-2.0-or-later
/* The row the row-kernel unit tests share (test_row, test_bond_model): atom 0 and its partners
   on plain arrays, and the portable loop over it. */

#ifndef BBPD_TEST_ROW_H
#define BBPD_TEST_ROW_H

#include "bbpd_row.h"

#include <cmath>
#include <vector>

namespace BBPD::test {

struct Row {
  std::vector<double> x;    // 3 per atom, atom 0 first
  std::vector<int> bj;
  std::vector<double> xi0, coef;
  int size() const { return static_cast<int>(bj.size()); }
};

// atom 0 at x0 and n partners: place(k, x0, ref, p) gives partner k's reference bond vector ref
// and position p, and returns the bond's coefficient
template <class Place> Row make_row(int n, const double (&x0)[3], Place place)
{
  Row row;
  row.x.assign(x0, x0 + 3);
  for (int k = 0; k < n; k++) {
    double ref[3], p[3];
    const double coef = place(k, x0, ref, p);
    row.x.insert(row.x.end(), p, p + 3);
    row.bj.push_back(k + 1);
    row.xi0.push_back(std::sqrt(ref[0] * ref[0] + ref[1] * ref[1] + ref[2] * ref[2]));
    row.coef.push_back(coef);
  }
  return row;
}

// the portable loop of Model over the row: the force on atom 0 in f, the tally; true if a bond
// broke
template <class Model, int FRACTURE, int EV>
bool portable_row(const Row &row, double s0, double *f, RowTally *tally)
{
  double ax[LANES] = {0.0}, ay[LANES] = {0.0}, az[LANES] = {0.0};
  *tally = {};
  auto xi0_of = [&](int k) { return row.xi0[k]; };
  auto coef_of = [&](int k, double) { return row.coef[k]; };
  auto s0_of = [&](int) { return s0; };
  const bool broken = row_force_portable<FRACTURE, EV, Model>(
      row.x.data(), 0, row.bj.data(), row.size(), xi0_of, coef_of, s0_of, 0.0, ax, ay, az, tally);
  lane_sum(ax, ay, az, f);
  return broken;
}

}    // namespace BBPD::test

#endif

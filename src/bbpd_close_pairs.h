// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: candidate pairs of the short-range forces between atoms, with no LAMMPS
   dependency: the one search behind 'contact' and the short-range forces of
   pair style bbpd/pmb.

   The candidates of local atom i are the atoms j (local or ghost) within their pair's
   distance d(i, j) <= max_distance plus a skin, found by binning all positions once.
   While no atom has moved half the skin, every pair closer than its distance is a
   candidate, so the force loops test the candidates alone at every step and the search
   runs again only when an atom has moved that far (or the atoms changed indices). The
   candidates' order depends on the binning: the loops sum their forces in an order of
   their own (by tag or by offset), which depends on the pairs alone.

   Displacements count from the centre c of their bounding box: two atoms approach each other
   by at most |u_i - c| + |u_j - c|, so a body that moves as a whole, or half of it, searches
   again only when the atoms move apart from one another by the skin. An atom whose candidates
   were all beyond their distance by more than its own |u_i - c| plus the largest has none in
   range: the loops skip it without reading a candidate (may_be_close), so a body at rest or
   barely strained pays two passes over the displacements per step, not one over the pairs,
   also while a few atoms move fast (an indenter's, a crack's).
------------------------------------------------------------------------- */

#ifndef BBPD_CLOSE_PAIRS_H
#define BBPD_CLOSE_PAIRS_H

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace BBPD {

  // may_be_close's allowance for the round-off of the distances it compares (about 1e-16 of
  // the search's reach each): a pair is skipped only if it is farther by this share of the reach
  constexpr double CLOSE_PAIRS_ROUNDOFF = 1.0e-9;

class ClosePairs {
 public:
  // candidates of local atom i: pairs[first[i] .. first[i + 1]], each with its distance dist[]
  std::vector<int> first, pairs;
  std::vector<double> dist;

  // do the candidates still hold every pair in range? (the same atoms at the same nall
  // positions xx, 3 per atom, none of which has moved half the skin from the displacements'
  // centre since the search); keeps the largest such displacement for may_be_close
  bool current(const double *xx, int nlocal, int nall)
  {
    if (xhold.size() != 3 * (size_t) nall || first.size() != (size_t) nlocal + 1) return false;
    double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.0, 0.0, 0.0}, c[3];
    for (int i = 0; i < nall; i++)
      for (int m = 0; m < 3; m++) {
        const double u = xx[3 * i + m] - xhold[3 * i + m];
        lo[m] = i ? std::min(lo[m], u) : u;
        hi[m] = i ? std::max(hi[m], u) : u;
      }
    for (int m = 0; m < 3; m++) c[m] = 0.5 * (lo[m] + hi[m]);
    double largest = 0.0;
    for (int i = 0; i < nall; i++) {
      const double dx = xx[3 * i] - xhold[3 * i] - c[0], dy = xx[3 * i + 1] - xhold[3 * i + 1] - c[1],
                   dz = xx[3 * i + 2] - xhold[3 * i + 2] - c[2];
      const double dsq = dx * dx + dy * dy + dz * dz;
      // under half the skin, with room for round-off
      if (dsq > 0.2 * skin * skin) return false;
      largest = std::max(largest, dsq);
      if (i < nlocal) moved_sq[i] = dsq;    // sized by build() for these nlocal
    }
    moved = std::sqrt(largest);
    return true;
  }

  /* can a candidate of local atom i be closer than its distance now? (false: none can) Atom i
     moved by d_i from the centre and each candidate by at most the largest such displacement:
     none is within its distance while nearest[i] >= d_i + moved + roundoff, compared squared
     (no root per atom) */
  bool may_be_close(int i) const
  {
    const double room = nearest[i] - moved - roundoff;
    return !(room >= 0.0 && room * room >= moved_sq[i]);
  }

  /* search the candidates of local atoms 0..nlocal-1 among the nall atoms at xx: every j != i
     with |x_i - x_j| < distance(i, j) + skin, where distance(i, j) <= max_distance; false
     (and no candidates) if the positions are not finite */
  template <class Distance>
  bool build(const double *xx, int nlocal, int nall, double max_distance, double search_skin,
             Distance distance)
  {
    skin = search_skin;
    const double reach = max_distance + skin;
    xhold.assign(xx, xx + 3 * nall);
    first.assign(nlocal + 1, 0);
    pairs.clear();
    dist.clear();
    nearest.assign(nlocal, std::numeric_limits<double>::infinity());
    moved_sq.assign(nlocal, 0.0);
    moved = 0.0;
    roundoff = CLOSE_PAIRS_ROUNDOFF * reach;
    if (nall == 0) return true;

    // bins of at least the reach, coarser if the atoms are spread out (flying fragments)
    double lo[3], hi[3];
    for (int m = 0; m < 3; m++) lo[m] = hi[m] = xx[m];
    for (int i = 0; i < nall; i++)
      for (int m = 0; m < 3; m++) {
        lo[m] = std::min(lo[m], xx[3 * i + m]);
        hi[m] = std::max(hi[m], xx[3 * i + m]);
      }
    for (int m = 0; m < 3; m++)
      if (!std::isfinite(hi[m] - lo[m])) {
        xhold.clear();
        first.assign(nlocal + 1, 0);
        return false;
      }
    double b = reach;
    int nb[3];
    auto nbins = [&]() {
      for (int m = 0; m < 3; m++) nb[m] = static_cast<int>(std::min((hi[m] - lo[m]) / b, 1.0e6)) + 1;
      return (double) nb[0] * nb[1] * nb[2];
    };
    while (nbins() > 4.0 * nall + 64.0) b *= 1.5;
    auto cell = [&](int i, int m) {
      return std::min(nb[m] - 1, static_cast<int>((xx[3 * i + m] - lo[m]) / b));
    };
    std::vector<int> start((size_t) nb[0] * nb[1] * nb[2] + 1, 0), bin_of(nall), atoms(nall);
    for (int i = 0; i < nall; i++) {
      bin_of[i] = (cell(i, 0) * nb[1] + cell(i, 1)) * nb[2] + cell(i, 2);
      start[bin_of[i] + 1]++;
    }
    for (size_t c = 1; c < start.size(); c++) start[c] += start[c - 1];
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (int i = 0; i < nall; i++) atoms[fill[bin_of[i]]++] = i;
    // positions in bin order: the bins of a row of the search below are one contiguous run
    std::vector<double> xbin(3 * atoms.size());
    for (int a = 0; a < nall; a++)
      for (int m = 0; m < 3; m++) xbin[3 * a + m] = xx[3 * atoms[a] + m];

    for (int i = 0; i < nlocal; i++) {
      first[i] = (int) pairs.size();
      const int c[3] = {cell(i, 0), cell(i, 1), cell(i, 2)};
      const int zlo = std::max(c[2] - 1, 0), zhi = std::min(c[2] + 1, nb[2] - 1);
      for (int ax = std::max(c[0] - 1, 0); ax <= std::min(c[0] + 1, nb[0] - 1); ax++)
        for (int ay = std::max(c[1] - 1, 0); ay <= std::min(c[1] + 1, nb[1] - 1); ay++) {
          const int row = (ax * nb[1] + ay) * nb[2];
          for (int a = start[row + zlo]; a < start[row + zhi + 1]; a++) {
            const double dx = xx[3 * i] - xbin[3 * a], dy = xx[3 * i + 1] - xbin[3 * a + 1],
                         dz = xx[3 * i + 2] - xbin[3 * a + 2];
            const double rsq = dx * dx + dy * dy + dz * dz;
            if (rsq >= reach * reach) continue;
            const int j = atoms[a];
            if (j == i) continue;
            const double d = distance(i, j);
            const double r = std::sqrt(rsq);
            if (r >= d + skin) continue;
            pairs.push_back(j);
            dist.push_back(d);
            nearest[i] = std::min(nearest[i], r - d);
          }
        }
    }
    first[nlocal] = (int) pairs.size();
    return true;
  }

 private:
  std::vector<double> xhold;      // positions at the search
  std::vector<double> nearest;    // per local atom: the least r - d of its candidates at the search
  std::vector<double> moved_sq;   // per local atom: its squared displacement from the centre
  double skin = 0.0;
  double moved = 0.0;       // the largest displacement from the centre (current)
  double roundoff = 0.0;    // CLOSE_PAIRS_ROUNDOFF of the reach
};

}    // namespace BBPD

#endif

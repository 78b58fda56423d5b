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
   were all beyond their distance by more than its own |u_i - c| plus the largest |u_j - c| has
   none in range: the loops skip it without reading a candidate (may_be_close), so a body at
   rest or barely strained pays two passes over the displacements per step, not one over the
   pairs. While a few atoms move fast (an indenter's, a crack's), that bound skips hardly any
   atom, so a local one is tried: i's candidates lay in i's bin at the search or a bin next to it
   (the search looks nowhere else), so the box holding the displacements of the atoms of those
   27 bins (or of blocks of bins, when the bins outnumber the atoms) holds theirs, and the
   centre above may be that box's. On LAMMPS's cylinder (bbpd/lps) the one bound had 55 % of
   the atoms read their candidates at every step, 22 each, for 1 pair in range in 70; with the
   local one, 5 %. It is worked out only in a step that needs it: on LAMMPS's bpm/peri deck (a
   periodic block at rest, bbpd/pmb) doing it at every step cost 6 % of the step.
------------------------------------------------------------------------- */

#ifndef BBPD_CLOSE_PAIRS_H
#define BBPD_CLOSE_PAIRS_H

#include <algorithm>
#include <cmath>
#include <cstddef>
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
  // centre since the search); keeps what may_be_close reads
  bool current(const double *xx, int nlocal, int nall)
  {
    if (xhold.size() != 3 * (size_t) nall || first.size() != (size_t) nlocal + 1) return false;
    double c[3];
    displacement_centre(xx, nall, c);
    const double limit = 0.2 * skin * skin;    // under half the skin, with room for round-off
    const double *h = xhold.data();
    double largest = 0.0;
    for (int i = 0; i < nlocal; i++) {
      const double dsq = moved_from(xx, h, i, c);
      if (dsq > limit) return false;
      largest = std::max(largest, dsq);
      moved_sq[i] = dsq;    // sized by build() for these nlocal
    }
    // the ghosts: their largest only, in a loop without a branch
    double ghosts = 0.0;
    for (int i = nlocal; i < nall; i++) ghosts = std::max(ghosts, moved_from(xx, h, i, c));
    if (ghosts > limit) return false;
    moved = std::sqrt(std::max(largest, ghosts));
    now = xx;
    near_current = false;
    return true;
  }

  /* can a candidate of local atom i be closer than its distance now? (false: none can) Atom i
     moved by d_i from the centre and each candidate by at most the largest such displacement:
     none is within its distance while nearest[i] >= d_i + moved + roundoff, compared squared
     (no root per atom). Else the same with the centre and largest displacement of the atoms
     near i (near_bound), worked out at the first atom of a step that needs them. */
  bool may_be_close(int i)
  {
    const double room = nearest[i] - moved - roundoff;
    if (room >= 0.0 && room * room >= moved_sq[i]) return false;
    if (!near_current) near_bound();
    const double near_room = nearest[i] - near_radius[region_of[i]] - roundoff;
    return !(near_room >= 0.0 && near_room * near_room >= near_sq[i]);
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
    region_of.assign(nall, 0);
    nr[0] = nr[1] = nr[2] = 1;
    size_regions(1);
    near_sq.assign(nlocal, 0.0);
    moved = 0.0;
    near_current = true;    // nothing moved
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
    // regions of k^3 bins for may_be_close: no more than the atoms
    int k = 1;
    auto nregions = [&]() {
      for (int m = 0; m < 3; m++) nr[m] = (nb[m] + k - 1) / k;
      return (double) nr[0] * nr[1] * nr[2];
    };
    while (nregions() > nall + 1.0) k++;
    size_regions((size_t) nr[0] * nr[1] * nr[2]);
    for (int i = 0; i < nall; i++) {
      const int a = cell(i, 0), bb = cell(i, 1), cc = cell(i, 2);
      bin_of[i] = (a * nb[1] + bb) * nb[2] + cc;
      region_of[i] = (a / k * nr[1] + bb / k) * nr[2] + cc / k;
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
  // may_be_close's regions: blocks of k x k x k bins of the search (k = 1 unless there are
  // many more bins than atoms), nr[] along x, y, z: region (a, b, c) is (a nr[1] + b) nr[2] + c
  std::vector<int> region_of;    // per atom: its region at the search
  int nr[3] = {1, 1, 1};
  // per region, over the displacements of the atoms in it and in the regions next to it: their
  // box (lo and -hi per axis, 6 values, both kept by min), its centre (3) and half diagonal
  std::vector<double> near_box, near_centre, near_radius;
  double skin = 0.0;
  double roundoff = 0.0;    // CLOSE_PAIRS_ROUNDOFF of the reach

  const double *now = nullptr;    // the positions of the last current()
  bool near_current = true;        // near_* hold the bound at 'now'
  double moved = 0.0;              // the largest displacement from the centre (current)
  std::vector<double> near_sq;     // per local atom: its squared displacement from its region's centre

  // |u_i - c|^2, u_i atom i's displacement since the search
  static double moved_from(const double *xx, const double *hold, int i, const double *c)
  {
    const double dx = xx[3 * i] - hold[3 * i] - c[0], dy = xx[3 * i + 1] - hold[3 * i + 1] - c[1],
                 dz = xx[3 * i + 2] - hold[3 * i + 2] - c[2];
    return dx * dx + dy * dy + dz * dz;
  }
  /* the centre of the bounding box of the nall displacements since the search: 4 atoms (12
     values) at a time, value l of them component l % 3, so that the loop runs in vector lanes
     (a loop over the atoms with a branch for the first one ran scalar: 0.9 M instructions a step
     on LAMMPS's bpm/peri deck, 4 % of a bbpd/lps step) */
  void displacement_centre(const double *xx, int nall, double *c) const
  {
    constexpr int W = 12;
    const double inf = std::numeric_limits<double>::infinity();
    double lo[W], hi[W];
    for (int l = 0; l < W; l++) {
      lo[l] = inf;
      hi[l] = -inf;
    }
    const std::size_t n = 3 * (std::size_t) nall;
    const double *h = xhold.data();
    std::size_t x = 0;
    for (; x + W <= n; x += W)
      for (int l = 0; l < W; l++) {
        const double u = xx[x + l] - h[x + l];
        lo[l] = std::min(lo[l], u);
        hi[l] = std::max(hi[l], u);
      }
    for (int l = 0; x + l < n; l++) {    // the last atoms: l % 3 is still their component
      const double u = xx[x + l] - h[x + l];
      lo[l] = std::min(lo[l], u);
      hi[l] = std::max(hi[l], u);
    }
    for (int m = 0; m < 3; m++) {
      double a = lo[m], b = hi[m];
      for (int l = m + 3; l < W; l += 3) {
        a = std::min(a, lo[l]);
        b = std::max(b, hi[l]);
      }
      c[m] = nall > 0 ? 0.5 * (a + b) : 0.0;
    }
  }
  // the displacements near each atom at 'now': per region, the box holding those of the atoms
  // in it and in the regions next to it, its centre and half diagonal; per local atom, its
  // squared distance from its region's centre
  void near_bound()
  {
    const int nall = static_cast<int>(region_of.size()), nlocal = static_cast<int>(moved_sq.size());
    // each region's box (lo and -hi: both kept by min), gathered over runs of atoms in one
    // region (atoms come mostly in space order: no update waits for the last)
    std::fill(near_box.begin(), near_box.end(), std::numeric_limits<double>::infinity());
    double run[6];
    int run_region = -1;
    auto flush = [&]() {
      if (run_region < 0) return;
      double *box = &near_box[6 * (size_t) run_region];
      for (int v = 0; v < 6; v++) box[v] = std::min(box[v], run[v]);
    };
    for (int i = 0; i < nall; i++) {
      if (region_of[i] != run_region) {
        flush();
        run_region = region_of[i];
        for (double &v : run) v = std::numeric_limits<double>::infinity();
      }
      for (int m = 0; m < 3; m++) {
        const double u = now[3 * i + m] - xhold[3 * i + m];
        run[m] = std::min(run[m], u);
        run[3 + m] = std::min(run[3 + m], -u);
      }
    }
    flush();
    spread_to_neighbour_regions();
    for (std::size_t b = 0; b < near_radius.size(); b++) {
      const double *box = &near_box[6 * b];
      double dsq = 0.0;
      for (int m = 0; m < 3; m++) {
        near_centre[3 * b + m] = 0.5 * (box[m] - box[3 + m]);
        dsq += (-box[3 + m] - box[m]) * (-box[3 + m] - box[m]);
      }
      near_radius[b] = 0.5 * std::sqrt(dsq);
    }
    near_sq.resize(nlocal);
    for (int i = 0; i < nlocal; i++) {
      const double *cb = &near_centre[3 * (size_t) region_of[i]];
      double dsq = 0.0;
      for (int m = 0; m < 3; m++) {
        const double d = now[3 * i + m] - xhold[3 * i + m] - cb[m];
        dsq += d * d;
      }
      near_sq[i] = dsq;
    }
    near_current = true;
  }

  // n regions of no atom, none moved
  void size_regions(std::size_t n)
  {
    near_box.assign(6 * n, std::numeric_limits<double>::infinity());
    near_centre.assign(3 * n, 0.0);
    near_radius.assign(n, 0.0);
  }

  // each region's box: the smallest holding its own and its 26 neighbours', one axis at a time
  void spread_to_neighbour_regions()
  {
    const std::ptrdiff_t stride[3] = {(std::ptrdiff_t) nr[1] * nr[2], nr[2], 1};
    for (int m = 0; m < 3; m++) {
      if (nr[m] == 1) continue;
      spread.assign(near_box.begin(), near_box.end());
      const double *from = spread.data();
      double *to = near_box.data();
      std::size_t b = 0;
      int at[3];
      for (at[0] = 0; at[0] < nr[0]; at[0]++)
        for (at[1] = 0; at[1] < nr[1]; at[1]++)
          for (at[2] = 0; at[2] < nr[2]; at[2]++, b++) {
            const double *before = at[m] > 0 ? from + 6 * (b - stride[m]) : from + 6 * b;
            const double *after = at[m] + 1 < nr[m] ? from + 6 * (b + stride[m]) : from + 6 * b;
            for (int v = 0; v < 6; v++)
              to[6 * b + v] = std::min(std::min(before[v], from[6 * b + v]), after[v]);
          }
    }
  }
  std::vector<double> spread;    // spread_to_neighbour_regions' copy
};

}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the pieces of LAMMPS's peri/pmb rules that the styles on them
   (bbpd/pmb, bbpd/lps and its families, bbpd/lps/KERNEL) call: no 'contact'
   keyword, the lattice constant of the volume ramp and short-range distance,
   the short-range forces and the line of the setup report (bbpd_pmb_rules.h).
------------------------------------------------------------------------- */

#include "pair_bbpd.h"
#include "bbpd_compat.h"
#include "bbpd_pmb_rules.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "lattice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using namespace BBPD::PMB;

/* settings: peri/pmb's short-range forces act, 'contact' would add a second set */
void PairBBPD::forbid_contact() const
{
  if (contact)
    error->all(FLERR, "Pair style {} brings peri/{}'s short-range forces; drop "
               "'contact yes'", style, style.substr(5));
}

/* init_style: the lattice constant lc of the lattice command, as in peri/pmb */
double PairBBPD::peri_lattice_constant() const
{
  const Lattice *lat = domain->lattice;
  if (!lat || lat->style == Lattice::NONE)
    error->all(FLERR, "Pair style {} needs a lattice command before the run: "
               "peri/pmb's volume ramp and short-range distance use its lattice constant", style);
  if (lat->xlattice != lat->ylattice || lat->xlattice != lat->zlattice)
    error->all(FLERR, "Pair style {} needs a lattice with the same constant "
               "in x, y and z (as peri/{})", style, style.substr(5));
  const double lc = lat->xlattice;
  // the short-range partners are found among the local and ghost atoms (no neighbour list):
  // the ghosts cover every pair closer than the horizon
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && horizon[i][j] < SHORT_RANGE_LATTICE_FACTOR * lc)
        error->all(FLERR, "Pair style {}: horizon {} for types {} {} is "
                   "shorter than the short-range distance {} x lattice constant {}: use a horizon "
                   "of at least {}", style, horizon[i][j], i, j, SHORT_RANGE_LATTICE_FACTOR,
                   lc, SHORT_RANGE_LATTICE_FACTOR * lc);
  return lc;
}

std::string PairBBPD::peri_rules_report(double lc) const
{
  return fmt::format("  peri/pmb rules: families |xi| <= delta, volume ramp and short-range forces "
                     "below min({} |xi|, {} lc), lattice constant lc = {:.6g}\n",
                     SHORT_RANGE_BOND_FACTOR, SHORT_RANGE_LATTICE_FACTOR, lc);
}

/* the short-range stiffness of types i j per partner volume (peri/pmb: 15 c) */
double PairBBPD::short_range_stiffness(int itype, int jtype) const
{
  return SHORT_RANGE_STIFFNESS_FACTOR * micromodulus[itype][jtype];
}

/* ----------------------------------------------------------------------
   short-range forces between all atoms (bonded or not) closer than
   min(0.9 |xi|, 1.35 lc), stiffness 15 c V_j / delta. Each atom sums its own pairs
   in tag order, so the result does not depend on the decomposition.
------------------------------------------------------------------------- */

void PairBBPD::compute_short_range(double lc)
{
  double **x = atom->x, **f = atom->f;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const double *vfrac = atom->vfrac;
  const double rmax = SHORT_RANGE_LATTICE_FACTOR * lc;

  const double *xx = x[0];
  double **x0 = atom->x0;
  double horizon_min = std::numeric_limits<double>::infinity();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) horizon_min = std::min(horizon_min, horizon[i][j]);
  // candidate pairs must stay within the horizon, which the ghost atoms cover
  const double skin = std::min(SHORT_RANGE_CANDIDATE_SKIN * lc, horizon_min - rmax);
  const bool periodic = domain->xperiodic || domain->yperiodic || domain->zperiodic;
  // a pair's short-range distance, from its reference distance
  update_close_pairs(rmax, std::max(skin, 0.0), [&](int i, int j) {
    double d0[3] = {x0[i][0] - x0[j][0], x0[i][1] - x0[j][1], x0[i][2] - x0[j][2]};
    if (periodic) BBPDCompat::minimum_image(domain, d0);
    return short_range_distance(std::sqrt(d0[0] * d0[0] + d0[1] * d0[1] + d0[2] * d0[2]), lc);
  });
  const std::vector<int> &first = close_pairs.first, &pairs = close_pairs.pairs;
  const std::vector<double> &dist = close_pairs.dist;
  const int nlocal = atom->nlocal;

  std::vector<std::pair<tagint, int>> close;
  for (int i = 0; i < nlocal; i++) {
    if (!close_pairs.may_be_close(i)) continue;
    const double xi = xx[3 * i], yi = xx[3 * i + 1], zi = xx[3 * i + 2];
    close.clear();
    for (int m = first[i]; m < first[i + 1]; m++) {
      const int j = pairs[m];
      const double d = dist[m];
      const double dx = xi - xx[3 * j], dy = yi - xx[3 * j + 1], dz = zi - xx[3 * j + 2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      if (rsq >= d * d * (1.0 + 1.0e-12)) continue;    // the exact test follows
      if (std::sqrt(rsq) < d) close.emplace_back(tag[j], m);
    }
    // sum in tag order: the candidates' order depends on the domain decomposition
    std::sort(close.begin(), close.end());
    for (const auto &c : close) {
      const int j = pairs[c.second];
      const double dx = xi - xx[3 * j], dy = yi - xx[3 * j + 1], dz = zi - xx[3 * j + 2];
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
      const int itype = type[i], jtype = type[j];
      const double dr = r - dist[c.second];
      // written as in peri/pmb
      const double rk = (short_range_stiffness(itype, jtype) * vfrac[j]) * (dr / horizon[itype][jtype]);
      const double fpair = r > 0.0 ? -(rk / r) : 0.0;
      f[i][0] += dx * fpair;
      f[i][1] += dy * fpair;
      f[i][2] += dz * fpair;
      if (evflag) tally_short_range(i, 0.25 * rk * dr, fpair, dx, dy, dz);
    }
  }
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: pair style bbpd/pmb, the rules of LAMMPS's peri/pmb
   (pair_bbpd_pmb.h): its coefficients, lattice constant and short-range forces;
   the bonds are evaluated and broken by the Silling-Askari loop
   (pair_bbpd_alpha.cpp) in peri/pmb's order.
------------------------------------------------------------------------- */

#include "pair_bbpd_pmb.h"
#include "bbpd_compat.h"
#include "bbpd_pmb_rules.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "lattice.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using namespace BBPD::PMB;

/* ---------------------------------------------------------------------- */

// peri/pmb's rules: Silling-Askari breaking, its families and numbers, short-range forces
static constexpr PairBBPD::Rules PERI_PMB_RULES{true, true, true};

PairBBPDPMB::PairBBPDPMB(LAMMPS *lmp, const char *style_name) :
    PairBBPDAlpha(lmp, BBPD::kernel_info<BBPD::ConstantKernel>(), style_name, PERI_PMB_RULES),
    lattice_constant(0.0)
{
}

PairBBPDPMB::PairBBPDPMB(LAMMPS *lmp, BBPD::KernelInfo k, const char *style_name) :
    PairBBPDAlpha(lmp, k, style_name, PERI_PMB_RULES), lattice_constant(0.0)
{
}

/* pair_style bbpd/pmb MODEL [thickness h] [area A] [spacing dx] [dt/safety f] [bond/storage s]:
   the keywords of the kernel styles, without contact (peri/pmb's short-range forces act) */
void PairBBPDPMB::settings(int narg, char **arg)
{
  PairBBPD::settings(narg, arg);
  if (contact)
    error->all(FLERR, "Pair style {} brings peri/{}'s short-range forces; drop "
               "'contact yes'", style, style.substr(5));
}

/* the bond forces and breaking of one step in peri/pmb's order, then its short-range forces */
void PairBBPDPMB::eval_bonds()
{
  if (evflag) eval_silling_askari<1, BBPD::PeriPmbRule>();
  else eval_silling_askari<0, BBPD::PeriPmbRule>();
  compute_short_range();
}

std::string PairBBPDPMB::report_type_pair(int i, int j) const
{
  return fmt::format("  types {} {}: peri/pmb: c = {:.8g}  horizon = {:.6g}  s00 = {:.8g}  "
                     "alpha = {:.6g}\n", i, j, micromodulus[i][j], horizon[i][j],
                     critical_stretch[i][j], alpha[i][j]);
}

std::string PairBBPDPMB::report_rules() const
{
  return fmt::format("  peri/pmb rules: families |xi| <= delta, volume ramp and short-range forces "
                     "below min({} |xi|, {} lc), lattice constant lc = {:.6g}\n",
                     SHORT_RANGE_BOND_FACTOR, SHORT_RANGE_LATTICE_FACTOR, lattice_constant);
}

/* ----------------------------------------------------------------------
   pair_coeff I J c delta s00 alpha (peri/pmb's four numbers)
------------------------------------------------------------------------- */

void PairBBPDPMB::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  if (narg != 6)
    error->all(FLERR, "Pair coeff for bbpd/pmb: expected 'I J c delta s00 alpha' "
               "(the numbers of pair_coeff peri/pmb), got {} arguments", narg);
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double c = utils::numeric(FLERR, arg[2], false, lmp);
  const double delta = utils::numeric(FLERR, arg[3], false, lmp);
  const double s00 = utils::numeric(FLERR, arg[4], false, lmp);
  const double a = utils::numeric(FLERR, arg[5], false, lmp);
  if (!(c > 0.0)) error->all(FLERR, "Pair coeff for bbpd/pmb: c must be > 0");
  if (!(delta > 0.0)) error->all(FLERR, "Pair coeff for bbpd/pmb: delta must be > 0");
  if (!(s00 > 0.0)) error->all(FLERR, "Pair coeff for bbpd/pmb: s00 must be > 0");
  if (!(a >= 0.0) || !std::isfinite(a))
    error->all(FLERR, "Pair coeff for bbpd/pmb: alpha must be >= 0");

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      youngs[i][j] = 0.0;    // not used: c is given
      fracture_energy[i][j] = std::numeric_limits<double>::infinity();
      horizon[i][j] = delta;
      micromodulus[i][j] = c;
      critical_stretch[i][j] = s00;
      s0_user[i][j] = 1;
      alpha[i][j] = a;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* part of init_style: the Silling-Askari state (PairBBPDAlpha) and the lattice constant */
void PairBBPDPMB::init_rules()
{
  PairBBPDAlpha::init_rules();
  const Lattice *lat = domain->lattice;
  if (!lat || lat->style == Lattice::NONE)
    error->all(FLERR, "Pair style {} needs a lattice command before the run: "
               "peri/pmb's volume ramp and short-range distance use its lattice constant", style);
  if (lat->xlattice != lat->ylattice || lat->xlattice != lat->zlattice)
    error->all(FLERR, "Pair style {} needs a lattice with the same constant "
               "in x, y and z (as peri/{})", style, style.substr(5));
  lattice_constant = lat->xlattice;
  law.weighting = BBPD::PmbWeighting{lattice_constant};    // the families and volume ramp of the bond fix
  // the short-range partners are found among the local and ghost atoms (no neighbour list):
  // the ghosts cover every pair closer than the horizon
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && horizon[i][j] < SHORT_RANGE_LATTICE_FACTOR * lattice_constant)
        error->all(FLERR, "Pair style {}: horizon {} for types {} {} is "
                   "shorter than the short-range distance {} x lattice constant {}: use a horizon "
                   "of at least {}", style, horizon[i][j], i, j, SHORT_RANGE_LATTICE_FACTOR,
                   lattice_constant, SHORT_RANGE_LATTICE_FACTOR * lattice_constant);
}

/* ----------------------------------------------------------------------
   short-range forces between all atoms (bonded or not) closer than
   min(0.9 |xi|, 1.35 lc), stiffness 15 c V_j / delta. Each atom sums its own pairs
   in tag order, so the result does not depend on the decomposition.
------------------------------------------------------------------------- */

void PairBBPDPMB::compute_short_range()
{
  double **x = atom->x, **f = atom->f;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const double *vfrac = atom->vfrac;
  const double lc = lattice_constant;
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

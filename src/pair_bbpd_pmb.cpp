// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the rules of LAMMPS's peri/pmb in the bbpd pair styles.

   'pair_style bbpd/constant MODEL compat pmb' takes 'pair_coeff I J c delta s00 alpha'
   as peri/pmb does and follows its rules (bbpd_pmb_rules.h): families |xi| <= delta,
   the volume ramp within lc/2 of the horizon, short-range forces between all atoms
   closer than min(0.9 |xi|, 1.35 lc), and in each step: all intact bonds exert their
   force, then a bond breaks when its stretch exceeds s00 - alpha max(smin_i, smin_j),
   smin being the smallest stretch of each atom's bonds at the previous step.
   Without compat, 'alpha A' applies the same rule (compression only) to every kernel,
   with the usual bbpd order: a bond past its critical stretch exerts no force.
   smin lives in the per-atom s0 of atom_style peri, which LAMMPS already sends to
   ghost atoms every step and carries through migration and restart files; fix
   bbpd/alpha keeps what a second evaluation of the same step needs (fix_bbpd_alpha.h).
------------------------------------------------------------------------- */

#include "pair_bbpd.h"
#include "bbpd_compat.h"
#include "bbpd_pmb_rules.h"
#include "bbpd_pmb_row.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_bbpd_alpha.h"
#include "fix_bbpd_bonds.h"
#include "lattice.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using namespace BBPD::PMB;
using BBPD::LANES;
using BBPD::RowTally;
using BBPD::lane_sum;

// a bond's stretch seen through a periodic image and from the owners' positions differ by at
// most break_margin / xi0, plus the rounding of the division: twice that bounds both
static constexpr double STRETCH_MARGIN_FACTOR = 2.0;


/* ----------------------------------------------------------------------
   compat pmb: pair_coeff I J c delta s00 alpha (peri/pmb's four numbers)
------------------------------------------------------------------------- */

void PairBBPD::coeff_pmb(int narg, char **arg)
{
  if (narg != 6)
    error->all(FLERR, "Pair coeff for bbpd/constant compat pmb: expected 'I J c delta s00 alpha' "
               "(the numbers of pair_coeff peri/pmb), got {} arguments", narg);
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double c = utils::numeric(FLERR, arg[2], false, lmp);
  const double delta = utils::numeric(FLERR, arg[3], false, lmp);
  const double s00 = utils::numeric(FLERR, arg[4], false, lmp);
  const double a = utils::numeric(FLERR, arg[5], false, lmp);
  if (!(c > 0.0)) error->all(FLERR, "Pair coeff for bbpd/constant compat pmb: c must be > 0");
  if (!(delta > 0.0)) error->all(FLERR, "Pair coeff for bbpd/constant compat pmb: delta must be > 0");
  if (!(s00 > 0.0)) error->all(FLERR, "Pair coeff for bbpd/constant compat pmb: s00 must be > 0");
  if (!(a >= 0.0) || !std::isfinite(a))
    error->all(FLERR, "Pair coeff for bbpd/constant compat pmb: alpha must be >= 0");

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

/* part of init_style: the state fix and starting smin of the Silling-Askari rule, and the
   lattice constant of compat pmb */
void PairBBPD::init_pmb()
{
  alpha_any = compat_pmb;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && alpha[i][j] > 0.0) alpha_any = 1;
  if (alpha_any) {
    alpha_state = dynamic_cast<FixBBPDAlpha *>(modify->get_fix_by_id("BBPD_ALPHA"));
    if (!alpha_state)
      alpha_state = dynamic_cast<FixBBPDAlpha *>(modify->add_fix("BBPD_ALPHA all bbpd/alpha"));
    if (!alpha_state) error->all(FLERR, "Pair style bbpd: could not create its fix bbpd/alpha");
  }
  // before the families exist no atom has a bond: no smin yet (as peri/pmb)
  if (alpha_any && !bonds->families_built())
    for (int i = 0; i < atom->nlocal; i++) atom->s0[i] = NO_BOND_STRETCH;
  if (!compat_pmb) return;

  if (contact)
    error->all(FLERR, "Pair style bbpd/constant: compat pmb brings peri/pmb's short-range forces; "
               "drop 'contact yes'");
  const Lattice *lat = domain->lattice;
  if (!lat || lat->style == Lattice::NONE)
    error->all(FLERR, "Pair style bbpd/constant compat pmb needs a lattice command before the run: "
               "peri/pmb's volume ramp and short-range distance use its lattice constant");
  if (lat->xlattice != lat->ylattice || lat->xlattice != lat->zlattice)
    error->all(FLERR, "Pair style bbpd/constant compat pmb needs a lattice with the same constant "
               "in x, y and z (as peri/pmb)");
  lattice_constant = lat->xlattice;
  // the short-range partners are found among the local and ghost atoms (no neighbour list):
  // the ghosts cover every pair closer than the horizon
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && horizon[i][j] < SHORT_RANGE_LATTICE_FACTOR * lattice_constant)
        error->all(FLERR, "Pair style bbpd/constant compat pmb: horizon {} for types {} {} is "
                   "shorter than the short-range distance {} x lattice constant {}: use a horizon "
                   "of at least {}", horizon[i][j], i, j, SHORT_RANGE_LATTICE_FACTOR,
                   lattice_constant, SHORT_RANGE_LATTICE_FACTOR * lattice_constant);
}

/* ----------------------------------------------------------------------
   bond forces and breaking with the Silling-Askari critical stretch
------------------------------------------------------------------------- */

template <int EVFLAG> void PairBBPD::eval_alpha()
{
  const double *xx = atom->x[0];
  const int *type = atom->type;
  double *smin = atom->s0;    // smallest bond stretch at the previous step, ghosts included
  const int nlocal = atom->nlocal;
  if (nlocal > nmax_smin) {
    nmax_smin = atom->nmax;
    memory->destroy(smin_new);
    memory->create(smin_new, nmax_smin, "pair:smin_new");
  }
  const bool pmb = compat_pmb;
  const bool clamp = !pmb;
  // one s00 and alpha for every type pair: no per-bond lookups
  bool multi = false;
  const double s00_one = critical_stretch[1][1], alpha_one = alpha[1][1];
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++)
      if (critical_stretch[i][j] != s00_one || alpha[i][j] != alpha_one) multi = true;
  // a second evaluation of the last step (setup of a new run, read_restart): no breaking,
  // no new smallest stretches, and the bonds that broke then act again
  const bool replay = update->setupflag && update->ntimestep == alpha_state->last_step;
  double **fbroken = alpha_state->fbroken;
  // in a periodic box the two ends of a bond see each other through images that round
  // differently: a row with a bond within 'margin' (stretch) of breaking is decided again
  // from breaking_length(), which both ends compute alike. The margin bounds the stretch
  // difference of the two views (break_margin / shortest reference length), with a factor
  // for the rounding of the stretch itself.
  const bool canonical = bonds->raw_positions();
  const double margin = canonical && break_margin > 0.0
      ? STRETCH_MARGIN_FACTOR * break_margin / bonds->min_reference_length() : 0.0;
  double totals[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  int bad = -1;

#if defined(_OPENMP)
#pragma omp parallel num_threads(comm->nthreads) if (comm->nthreads > 1)
#endif
  {
    double acc[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    BBPD::CoefCache *cache = thread_coef_cache();
#if defined(_OPENMP)
#pragma omp for schedule(static, 512)
#endif
    for (int i = 0; i < nlocal; i++) {
      const int itype = type[i];
      const double *xi = atom->x[i];
      const double smin_i = smin[i];
      // stretch of bond k at current length r (peri/pmb zeroes round-off elongations)
      auto stretch_at = [&](int k, double r) {
        const double xi0 = bonds->xi0_of(i, k);
        double elong = BondModel::elongation(r, xi0);
        if (pmb && std::fabs(elong) < NEAR_ZERO) elong = 0.0;
        return BBPD::SillingAskariRule<false>::stretch(elong, xi0);
      };
      auto stretch_of = [&](int k) {
        const double *xj = atom->x[bonds->partner_of(i, k)];
        const double dx = xj[0] - xi[0], dy = xj[1] - xi[1], dz = xj[2] - xi[2];
        return stretch_at(k, std::sqrt(dx * dx + dy * dy + dz * dz));
      };
      // the stretch that decides breaking: the same at both ends of the bond
      auto breaking_stretch = [&](int k) {
        return canonical ? stretch_at(k, breaking_length(i, bonds->partner_of(i, k))) : stretch_of(k);
      };
      auto s0_of = [&](int k) {
        const int j = bonds->partner_of(i, k);
        if (!multi) return BBPD::PMB::critical_stretch(s00_one, alpha_one, smin_i, smin[j], clamp);
        return BBPD::PMB::critical_stretch(critical_stretch[itype][type[j]], alpha[itype][type[j]],
                                           smin_i, smin[j], clamp);
      };
      double fi[3];
      bool done = false;    // fi (and the tallies) summed by the fused kernel
      if (replay) {
        smin_new[i] = smin_i;
      } else {
        double snew = std::numeric_limits<double>::max();
        bool broken = false;
        const int n = bonds->nbond[i];
        if (!multi) {
          // the row in whatever layout the storage keeps it (FixBBPDBonds::visit_row)
          broken = bonds->visit_row(i, *cache, [&](const auto *bj, const auto &vals) {
#ifdef BBPD_SIMD
            // force and stretch in one pass
            double ax[LANES], ay[LANES], az[LANES];
            RowTally tally;
            const bool past = pmb
                ? row_force_stretch_simd<EVFLAG, true, false>(xx, i, bj, vals, n, smin, s00_one,
                                                              alpha_one, margin, &snew, ax, ay, az, &tally)
                : row_force_stretch_simd<EVFLAG, false, true>(xx, i, bj, vals, n, smin, s00_one,
                                                              alpha_one, margin, &snew, ax, ay, az, &tally);
            if (!past) {
              lane_sum(ax, ay, az, fi);
              if (EVFLAG) tally_lanes(i, tally, acc);
              done = true;
            }
            return past;
#else
            return pmb ? BBPD::row_stretch_portable<true, false>(xx, i, bj, vals, n, smin, s00_one,
                                                                 alpha_one, margin, &snew)
                       : BBPD::row_stretch_portable<false, true>(xx, i, bj, vals, n, smin, s00_one,
                                                                 alpha_one, margin, &snew);
#endif
          });
        } else {
          for (int k = bonds->bond_start[i]; k < bonds->bond_start[i] + n; k++) {
            const double s = stretch_of(k);
            snew = std::min(snew, s);
            broken |= BBPD::SillingAskariRule<false>::past_critical(s, s0_of(k), margin);
          }
        }
        smin_new[i] = n > 0 ? snew : NO_BOND_STRETCH;
        double fb[3] = {0.0, 0.0, 0.0};
        if (broken)
          bonds->remove_bonds_if(i, [&](int k) {
            if (!BBPD::SillingAskariRule<false>::past_critical(breaking_stretch(k), s0_of(k), 0.0))
              return false;
            // peri/pmb applies the force of a bond in the step it breaks; bbpd drops it at once
            if (pmb) broken_bond_force<EVFLAG>(i, k, fb, acc);
            return true;
          });
        if (pmb)
          for (int m = 0; m < 3; m++) fbroken[i][m] = fb[m];
      }
      if (!done) row_force<EVFLAG, 0, 0>(i, fi, nullptr, acc, cache);
      if (pmb)
        for (int m = 0; m < 3; m++) fi[m] += fbroken[i][m];
      add_row_force(i, fi, bad);
    }
    if (EVFLAG) add_thread_totals(totals, acc);
  }
  finish_eval(bad, EVFLAG, totals);
  // the new smin takes effect at the next step, once sent to the ghosts
  for (int i = 0; i < nlocal; i++) smin[i] = smin_new[i];
  alpha_state->last_step = update->ntimestep;
}

/* add the force density of bond k of atom i (about to break) to fb, in the order the
   bonds break; tally its energy and virial as row_force does */
template <int EVFLAG> void PairBBPD::broken_bond_force(int i, int k, double *fb, double *acc)
{
  const double *xx = atom->x[0];
  const int j = bonds->partner_of(i, k);
  const double dx = xx[3 * j] - xx[3 * i], dy = xx[3 * j + 1] - xx[3 * i + 1],
               dz = xx[3 * j + 2] - xx[3 * i + 2];
  const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
  const double xi0 = bonds->xi0_of(i, k);
  const double coef = bonds->coef_of(i, k, xi0);
  const double elong = BondModel::elongation(r, xi0);
  const double fbond = BondModel::force_per_length(coef, elong, r);
  fb[0] += fbond * dx;
  fb[1] += fbond * dy;
  fb[2] += fbond * dz;
  if (EVFLAG) {
    const double eng = BondModel::energy_share(coef, elong);
    const double vir[6] = {-BondModel::virial_share(fbond, dx, dx), -BondModel::virial_share(fbond, dy, dy),
                           -BondModel::virial_share(fbond, dz, dz), -BondModel::virial_share(fbond, dx, dy),
                           -BondModel::virial_share(fbond, dx, dz), -BondModel::virial_share(fbond, dy, dz)};
    acc[0] += eng;
    if (eflag_atom) eatom[i] += eng;
    for (int m = 0; m < 6; m++) {
      acc[1 + m] += vir[m];
      if (vflag_atom) vatom[i][m] += vir[m];
    }
  }
}

template void PairBBPD::eval_alpha<0>();
template void PairBBPD::eval_alpha<1>();

/* ----------------------------------------------------------------------
   compat pmb: short-range forces between all atoms (bonded or not) closer than
   min(0.9 |xi|, 1.35 lc), stiffness 15 c V_j / delta. Each atom sums its own pairs
   in tag order, so the result does not depend on the decomposition.
------------------------------------------------------------------------- */

void PairBBPD::compute_short_range()
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
      const double rk = (SHORT_RANGE_STIFFNESS_FACTOR * micromodulus[itype][jtype] * vfrac[j]) *
          (dr / horizon[itype][jtype]);
      const double fpair = r > 0.0 ? -(rk / r) : 0.0;
      f[i][0] += dx * fpair;
      f[i][1] += dy * fpair;
      f[i][2] += dz * fpair;
      if (evflag) {
        const double e = 0.25 * rk * dr;    // half of the pair's energy: the other end adds the rest
        if (eflag_global) eng_vdwl += e;
        if (eflag_atom) eatom[i] += e;
        const double v[6] = {0.5 * fpair * dx * dx, 0.5 * fpair * dy * dy, 0.5 * fpair * dz * dz,
                             0.5 * fpair * dx * dy, 0.5 * fpair * dx * dz, 0.5 * fpair * dy * dz};
        for (int m = 0; m < 6; m++) {
          if (vflag_global) virial[m] += v[m];
          if (vflag_atom) vatom[i][m] += v[m];
        }
      }
    }
  }
}

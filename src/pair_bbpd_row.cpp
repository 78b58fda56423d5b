// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the bond loop of one row of the bbpd/* pair styles, shared by
   the plain loop (pair_bbpd.cpp) and the Silling-Askari loop
   (pair_bbpd_pmb.cpp): dispatch to the SIMD or portable kernel of
   bbpd_row.h over the rows of fix bbpd/bonds, the energy and virial tallies,
   adding a row's force, the breaking test both ends of a bond agree on, and the
   diagnosis of a non-finite force.
------------------------------------------------------------------------- */

#include "pair_bbpd.h"
#include "bbpd_compat.h"
#include "bbpd_row.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "fix_bbpd_bonds.h"
#include "update.h"

#include <cmath>

using namespace LAMMPS_NS;
using BBPD::LANES;
using BBPD::RowTally;
using BBPD::lane_sum;
using BBPD::lane_total;

/* explain a non-finite force on atom i and stop */
void PairBBPD::nonfinite_error(int i)
{
  const double *xx = atom->x[0];
  const tagint *tag = atom->tag;
  const std::string cause = fmt::format(
      "timestep {:.6g} vs stable bound {:.6g}: reduce the timestep, or check the input for "
      "atoms placed on top of each other", update->dt, dt_bound);
  for (int m = 0; m < 3; m++)
    if (!std::isfinite(xx[3 * i + m]))
      error->one(FLERR, "Atom {} has a non-finite position at step {} (the run became unstable; {})",
                 tag[i], update->ntimestep, cause);
  for (int k = bonds->bond_start[i]; k < bonds->bond_start[i] + bonds->nbond[i]; k++) {
    const int j = bonds->partner_of(i, k);
    const double dx = xx[3 * j] - xx[3 * i], dy = xx[3 * j + 1] - xx[3 * i + 1],
                 dz = xx[3 * j + 2] - xx[3 * i + 2];
    const double rsq = dx * dx + dy * dy + dz * dz;
    if (!std::isfinite(rsq))
      error->one(FLERR, "Bond partner {} of atom {} has a non-finite position at step {} (the run "
                 "became unstable; {})", tag[j], tag[i], update->ntimestep, cause);
    if (rsq == 0.0)
      error->one(FLERR, "Atoms {} and {} coincide at step {}: a bond of zero length has no "
                 "direction ({})", tag[i], tag[j], update->ntimestep, cause);
  }
  error->one(FLERR, "Non-finite force on atom {} at step {} ({})", tag[i], update->ntimestep, cause);
}

/* Force density on atom i from its intact bonds (eq. 21). The sum runs in
   LANES fixed partial sums (bond k goes to lane k % LANES) combined in a fixed
   order, in the SIMD (AVX-512, AVX2) and portable paths alike: the result depends
   only on the row, never on the domain decomposition or on whether energy is
   tallied. With FRACTURE it returns true, and tallies nothing, if a bond of the
   row is past its critical stretch. */
template <int EVFLAG, int FRACTURE, int MULTI>
bool PairBBPD::row_force(int i, double *fi, const double *s0row, double *acc,
                         BBPD::CoefCache *cache)
{
  const int beg = bonds->bond_start[i];
  // partners as offsets from i or as indices (bbpd_partner_index.h): the same atoms
  return bonds->bdelta
      ? row_force<EVFLAG, FRACTURE, MULTI>(i, bonds->bdelta + beg, fi, s0row, acc, cache)
      : row_force<EVFLAG, FRACTURE, MULTI>(i, bonds->bj + beg, fi, s0row, acc, cache);
}

/* compact storage: a cache per thread of the coefficients (bbpd_row.h), taken once per thread
   and force evaluation (a thread-local variable of a plugin costs a call at every access) */
BBPD::CoefCache *PairBBPD::thread_coef_cache()
{
  static thread_local BBPD::CoefCache cache;
  return &cache;
}

template <int EVFLAG, int FRACTURE, int MULTI, class Idx>
bool PairBBPD::row_force(int i, const Idx *bj, double *fi, const double *s0row, double *acc,
                         BBPD::CoefCache *cache_ptr)
{
  const double *xx = atom->x[0];
  const int beg = bonds->bond_start[i], n = bonds->nbond[i];
  // reference lengths and coefficients: by class (the default), per bond (a rank with too many
  // distinct pairs for the class table), or recomputed (bond/storage compact)
  const BBPD::ClassValues by_class = {bonds->bclass ? bonds->bclass + beg : nullptr,
                                      bonds->classes.xi0.data(), bonds->classes.coef.data()};
  const BBPD::PerBondValues per_bond = {bonds->bxi0 ? bonds->bxi0 + beg : nullptr,
                                        bonds->bcoef ? bonds->bcoef + beg : nullptr};
  const bool classed = by_class.cls != nullptr;
  const bool compact = !classed && per_bond.xi0 == nullptr;
  double ax[LANES] = {0.0}, ay[LANES] = {0.0}, az[LANES] = {0.0};
  // compact: the thread's cache of the coefficients, computed from the bond law
  BBPD::CoefCache &cache = *cache_ptr;
  const int *type = atom->type;
  auto coef_fn = [this, type, i](int jtype, double xi0, double vj) {
    return law.coefficient(type[i], jtype, xi0, vj);
  };
  if (compact) cache.start(memo_epoch);
  const int t_uniform = bonds->uniform_type * BBPD::CoefCache::TYPE_STRIDE + bonds->uniform_type;
  const bool uniform = compact && bonds->uniform_type > 0 &&
      cache.holds_only(bonds->uniform_vfrac, t_uniform);
  const BBPD::RecomputedValues<decltype(coef_fn)> recomputed = {
      atom->x0 ? atom->x0[0] : nullptr, i, atom->vfrac, type, &cache, coef_fn,
      bonds->uniform_type, bonds->uniform_vfrac};

#ifdef BBPD_SIMD
  if (!MULTI && !compact) {
    RowTally tally;
    const bool broken = classed
        ? row_force_simd<FRACTURE, EVFLAG, BondModel>(xx, i, bj, by_class, n, s0_single,
                                                      break_margin, ax, ay, az, &tally)
        : row_force_simd<FRACTURE, EVFLAG, BondModel>(xx, i, bj, per_bond, n, s0_single,
                                                      break_margin, ax, ay, az, &tally);
    if (broken) return true;
    lane_sum(ax, ay, az, fi);
    if (EVFLAG) tally_lanes(i, tally, acc);
    return false;
  }
#endif
#ifdef BBPD_SIMD
  if (!MULTI && compact) {
    RowTally tally;
    const BBPD::RecomputedValues<decltype(coef_fn), true> recomputed_uniform = {
        recomputed.x0, i, atom->vfrac, type, &cache, coef_fn, bonds->uniform_type,
        bonds->uniform_vfrac};
    const bool broken = uniform
        ? row_force_simd<FRACTURE, EVFLAG, BondModel>(xx, i, bj, recomputed_uniform, n, s0_single,
                                                      break_margin, ax, ay, az, &tally)
        : row_force_simd<FRACTURE, EVFLAG, BondModel>(xx, i, bj, recomputed, n, s0_single,
                                                      break_margin, ax, ay, az, &tally);
    if (broken) return true;
    lane_sum(ax, ay, az, fi);
    if (EVFLAG) tally_lanes(i, tally, acc);
    return false;
  }
#endif

  RowTally lanes = {};    // energy and virial in the same lanes as the SIMD kernels
  auto xi0_of = [&](int k) {
    return classed ? by_class.xi0_of(k)
        : compact  ? recomputed.xi0_of(BBPD::partner_index(bj, i, k))
                   : per_bond.xi0_of(k);
  };
  auto coef_of = [&](int k, double xi0) {
    return classed ? by_class.coef_of(k)
        : compact  ? recomputed.coef_of(BBPD::partner_index(bj, i, k))
                   : per_bond.coef_of(k);
  };
  auto s0_of = [&](int j) { return MULTI ? s0row[type[j]] : s0_single; };
  const bool broken = BBPD::row_force_portable<FRACTURE, EVFLAG, BondModel>(
      xx, i, bj, n, xi0_of, coef_of, s0_of, break_margin, ax, ay, az, &lanes);

  if (broken) return true;
  lane_sum(ax, ay, az, fi);
  if (EVFLAG) tally_lanes(i, lanes, acc);
  return false;
}

/* energy and virial of the row of atom i: per atom where LAMMPS asked for them, and the
   global totals into acc (energy, then the six virial components) */
void PairBBPD::tally_lanes(int i, const RowTally &lanes, double *acc)
{
  const double eng = lane_total(lanes.eng);
  double vir[6];
  for (int c = 0; c < 6; c++) vir[c] = lane_total(lanes.vir[c]);
  acc[0] += eng;
  if (eflag_atom) eatom[i] += eng;
  for (int m = 0; m < 6; m++) {
    acc[1 + m] += vir[m];
    if (vflag_atom) vatom[i][m] += vir[m];
  }
}

/* a row's force into f; the lowest atom with a non-finite force is kept for finish_eval()
   (three compares per atom turn the first NaN/inf into an ERROR that names its cause) */
void PairBBPD::add_row_force(int i, const double *fi, int &bad)
{
  if (!std::isfinite(fi[0]) || !std::isfinite(fi[1]) || !std::isfinite(fi[2])) {
#if defined(_OPENMP)
#pragma omp critical(bbpd_nonfinite)
#endif
    if (bad < 0 || i < bad) bad = i;
  }
  double *fi_atom = atom->f[i];
  fi_atom[0] += fi[0];
  fi_atom[1] += fi[1];
  fi_atom[2] += fi[2];
}

/* a thread's energy and virial sums (acc) into the loop's totals, one thread at a time */
void PairBBPD::add_thread_totals(double *totals, const double *acc)
{
#if defined(_OPENMP)
#pragma omp critical(bbpd_totals)
#endif
  for (int m = 0; m < 7; m++) totals[m] += acc[m];
}

/* after the loop over rows: the ERROR of a non-finite force, then the global tallies */
void PairBBPD::finish_eval(int bad, bool evflag_on, const double *totals)
{
  if (bad >= 0) nonfinite_error(bad);
  if (evflag_on) {
    if (eflag_global) eng_vdwl += totals[0];
    if (vflag_global)
      for (int m = 0; m < 6; m++) virial[m] += totals[1 + m];
  }
}

/* is bond i-j past its critical stretch? Decided from breaking_length(), the same at both ends */
bool PairBBPD::past_critical(int i, int j, double xi0, double s0) const
{
  return BondModel::past_critical(BondModel::elongation(breaking_length(i, j), xi0), xi0, s0, 0.0);
}

/* the current length of bond i-j from which breaking is decided: in a periodic box from the
   minimum-image difference of the owners' unshifted positions, identical at both ends (the
   ghost image x +- L rounds differently at the two ends, and one end could break a bond the
   other keeps) */
double PairBBPD::breaking_length(int i, int j) const
{
  const double *xi = atom->x[i];
  const double *xj = bonds->raw_positions() ? bonds->raw_x(j) : atom->x[j];
  double d[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
  if (bonds->raw_positions()) BBPDCompat::minimum_image(domain, d);
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

// the plain loop (eval) and the Silling-Askari loop (eval_alpha) sum rows with these
template bool PairBBPD::row_force<0, 0, 0>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<1, 0, 0>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<0, 1, 0>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<1, 1, 0>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<0, 0, 1>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<1, 0, 1>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<0, 1, 1>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<1, 1, 1>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);

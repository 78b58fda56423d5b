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

/* compact storage: a cache per thread of the coefficients (bbpd_bond_values.h), taken once per
   thread and force evaluation (a thread-local variable of a plugin costs a call at every access) */
BBPD::CoefCache *PairBBPD::thread_coef_cache()
{
  static thread_local BBPD::CoefCache cache;
  return &cache;
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
  const double *xx = atom->x[0];
  const int *type = atom->type;
  const int n = bonds->nbond[i];
  double ax[LANES] = {0.0}, ay[LANES] = {0.0}, az[LANES] = {0.0};
  RowTally lanes;    // energy and virial in the same lanes in every kernel (filled with EVFLAG)
  // the row in whatever layout the storage keeps it (FixBBPDBonds::visit_row)
  const bool broken = bonds->visit_row(i, *cache, [&](const auto *bj, const auto &vals) {
#ifdef BBPD_SIMD
    if (!MULTI)
      return row_force_simd<FRACTURE, EVFLAG, BondModel>(xx, i, bj, vals, n, s0_single,
                                                         break_margin, ax, ay, az, &lanes);
#endif
    auto xi0_of = [&](int k) { return vals.xi0_at(k, BBPD::partner_index(bj, i, k)); };
    auto coef_of = [&](int k, double) { return vals.coef_at(k, BBPD::partner_index(bj, i, k)); };
    auto s0_of = [&](int j) { return MULTI ? s0row[type[j]] : s0_single; };
    if (EVFLAG) lanes = {};    // the portable loop adds to the lanes, the SIMD kernels store them
    return BBPD::row_force_portable<FRACTURE, EVFLAG, BondModel>(
        xx, i, bj, n, xi0_of, coef_of, s0_of, break_margin, ax, ay, az, &lanes);
  });
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

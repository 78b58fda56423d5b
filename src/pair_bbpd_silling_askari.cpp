// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the loop over the rows of fix bbpd/bonds that breaks bonds with
   the Silling-Askari critical stretch (bbpd_silling_askari.h), a helper of
   PairBBPD that bbpd/KERNEL/alpha (pair_bbpd_alpha.h) and bbpd/pmb
   (pair_bbpd_pmb.h) call with their state (pair_bbpd_silling_askari_state.h)
   and their breaking rule.
------------------------------------------------------------------------- */

#include "pair_bbpd.h"
#include "bbpd_pmb_rules.h"
#include "bbpd_silling_askari.h"
#include "bbpd_stretch_row.h"
#include "pair_bbpd_rows.h"
#include "pair_bbpd_silling_askari_state.h"

#include "atom.h"
#include "fix_bbpd_alpha.h"
#include "fix_bbpd_bonds.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <limits>

using namespace LAMMPS_NS;
using namespace BBPD::PMB;
using BBPD::LANES;
using BBPD::RowTally;
using BBPD::lane_sum;

// a bond's stretch seen through a periodic image and from the owners' positions differ by at
// most break_margin / xi0, plus the rounding of the division: twice that bounds both
static constexpr double STRETCH_MARGIN_FACTOR = 2.0;

/* ----------------------------------------------------------------------
   bond forces and breaking with a Silling-Askari critical stretch: how a stretch is read, the
   critical stretch and what a breaking bond does in its step come from Rule
   (bbpd_plugin_model.h lists the rules)
------------------------------------------------------------------------- */

template <int EVFLAG, class Rule> void PairBBPD::eval_silling_askari(SillingAskariState &state)
{
  const BBPD::SillingAskariCoefficients sa =
      BBPD::SillingAskariCoefficients::of(critical_stretch, alpha, atom->ntypes);
  // a second evaluation of the last step (setup of a new run, read_restart): no breaking,
  // no new smallest stretches, and the bonds that broke then act again
  const bool replay = state.begin_step(memory, atom, update);
  // in a periodic box the two ends of a bond see each other through images that round
  // differently: a row with a bond within 'margin' (stretch) of breaking is decided again
  // from breaking_length(), which both ends compute alike. The margin bounds the stretch
  // difference of the two views (break_margin / shortest reference length), with a factor
  // for the rounding of the stretch itself.
  const bool canonical = bonds->raw_positions();
  const double margin = stretch_margin();
  // the largest smallest stretch of the atoms a row can reach, ghosts included: the SIMD rows
  // test each bond only when their largest stretch reaches the floor it gives
  // (critical_stretch_floor)
  const double smin_cap = replay || sa.multi ? std::numeric_limits<double>::max()
                                             : BBPD::largest_of(atom->s0, atom->nlocal + atom->nghost);
  // the row of atom i: its critical stretches from the smallest stretches of the last step;
  // snew, its smallest stretch now; fb, the forces of the bonds it breaks in this step
  struct Row {
    PairBBPD &p;
    SillingAskariState &state;
    int i;
    double *acc;
    BBPD::CoefCache *cache;
    bool replay, canonical;
    BBPD::SillingAskariCoefficients sa;
    double margin, smin_cap;
    double fb[3];
    bool sum_and_check(double *fi)
    {
      if (replay) {
        state.smin_new[i] = p.atom->s0[i];
        p.row_force<EVFLAG, 0, 0>(i, fi, nullptr, acc, cache);
        return false;
      }
      double snew = std::numeric_limits<double>::max();
      bool broken = false, summed = false;
      const int n = p.bonds->nbond[i];
      const double *xx = p.atom->x[0], *smin = p.atom->s0;
      if (!sa.multi) {
        // the row in whatever layout the storage keeps it (FixBBPDBonds::visit_row)
        broken = p.bonds->visit_row(i, *cache, [&](const auto *bj, const auto &vals) {
          auto portable = [&] {
            return BBPD::row_stretch_portable<BondModel, Rule>(xx, i, bj, vals, n, smin, sa.s00_one,
                                                               sa.alpha_one, margin, &snew);
          };
          // force and stretch in one pass
          return BBPD::on_path(p.simd_path, [&](auto path) {
            double ax[LANES], ay[LANES], az[LANES];
            RowTally tally;
            const double s0_floor =
                BBPD::critical_stretch_floor<Rule>(sa.s00_one, sa.alpha_one, smin[i], smin_cap);
            const bool past = decltype(path)::template row_force_stretch<EVFLAG, BondModel, Rule>(
                xx, i, bj, vals, n, smin, sa.s00_one, sa.alpha_one, margin, s0_floor, &snew, ax, ay,
                az, &tally);
            if (!past) {
              lane_sum(ax, ay, az, fi);
              if (EVFLAG) p.tally_lanes(i, tally, acc, BBPD::tallies_virial(EVFLAG));
              summed = true;
            }
            return past;
          }, portable);
        });
      } else {
        for (int k = p.bonds->bond_start[i]; k < p.bonds->bond_start[i] + n; k++) {
          const double s = stretch_of(k);
          snew = std::min(snew, s);
          broken |= Rule::past_critical(s, s0_of(k), margin);
        }
      }
      state.smin_new[i] = n > 0 ? snew : NO_BOND_STRETCH;
      if (!broken && !summed) p.row_force<EVFLAG, 0, 0>(i, fi, nullptr, acc, cache);
      return broken;
    }
    bool breaks(int k)
    {
      if (!Rule::past_critical(breaking_stretch(k), s0_of(k), 0.0)) return false;
      // a rule may apply the force of a bond in the step it breaks (its energy then is what it
      // carries away), or drop it at once, at its critical stretch
      if (Rule::FORCE_IN_BREAKING_STEP)
        p.bonds->ebroken[i] += p.broken_bond_force<EVFLAG>(i, k, fb, acc, state) * p.atom->vfrac[i];
      else
        p.book_broken_bond(i, k, s0_of(k));
      return true;
    }
    void sum(double *fi) { p.row_force<EVFLAG, 0, 0>(i, fi, nullptr, acc, cache); }
    void finish(double *fi)
    {
      if (!Rule::FORCE_IN_BREAKING_STEP) return;
      double *fbroken = state.fix->fbroken[i];
      if (!replay)
        for (int m = 0; m < 3; m++) fbroken[m] = fb[m];
      for (int m = 0; m < 3; m++) fi[m] += fbroken[m];
    }
    // stretch of bond k at current length r, as the rule reads it
    double stretch_at(int k, double r) const
    {
      const double xi0 = p.bonds->xi0_of(i, k);
      return Rule::stretch(Rule::settled_elongation(BondModel::elongation(r, xi0)), xi0);
    }
    double stretch_of(int k) const
    {
      const double *xi = p.atom->x[i], *xj = p.atom->x[p.bonds->partner_of(i, k)];
      const double dx = xj[0] - xi[0], dy = xj[1] - xi[1], dz = xj[2] - xi[2];
      return stretch_at(k, std::sqrt(dx * dx + dy * dy + dz * dz));
    }
    // the stretch that decides breaking: the same at both ends of the bond
    double breaking_stretch(int k) const
    {
      return canonical ? stretch_at(k, p.breaking_length(i, p.bonds->partner_of(i, k))) : stretch_of(k);
    }
    double s0_of(int k) const
    {
      const int j = p.bonds->partner_of(i, k);
      const double *smin = p.atom->s0;
      return sa.critical_stretch<Rule>(p.atom->type, i, j, smin[i], smin[j]);
    }
  };
  eval_rows<EVFLAG>([&](int i, double *acc, BBPD::CoefCache *cache) BBPD_ROW_BODY {
    return Row{*this, state, i, acc, cache, replay, canonical, sa, margin, smin_cap,
               {0.0, 0.0, 0.0}};
  });
  add_replayed_virial(replay, EVFLAG, state);
  state.end_step(atom, update);
}

double PairBBPD::stretch_margin() const
{
  return bonds->raw_positions() && break_margin > 0.0
      ? STRETCH_MARGIN_FACTOR * break_margin / bonds->min_reference_length() : 0.0;
}

/* add the force density of bond k of atom i (about to break) to fb, in the order the
   bonds break; tally its energy and virial as row_force does; returns the row's share of its
   energy density */
template <int EVFLAG>
double PairBBPD::broken_bond_force(int i, int k, double *fb, double *acc, SillingAskariState &state)
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
  const double eng = BondModel::energy_share(coef, elong);
  if (EVFLAG) {
    acc[0] += eng;
    if (eflag_atom) eatom[i] += eng;
  }
  double vir[6];
  bond_end_virial(fbond, dx, dy, dz, vir);
  state.book_broken_virial(vir);
  if (BBPD::tallies_virial(EVFLAG)) {
    for (int m = 0; m < 6; m++) {
      acc[1 + m] += vir[m];
      if (vflag_atom) vatom[i][m] += vir[m];
    }
  }
  return eng;
}

void PairBBPD::add_replayed_virial(bool replay, int ev, const SillingAskariState &state)
{
  if (replay && BBPD::tallies_virial(ev) && vflag_global) state.add_broken_virial(virial, update);
}

#define BBPD_EVAL_SILLING_ASKARI(EVFLAG, RULE) \
  template void PairBBPD::eval_silling_askari<EVFLAG, RULE>(SillingAskariState &);
BBPD_FOR_STRETCH_RULES(BBPD_EVAL_SILLING_ASKARI, 0)
BBPD_FOR_STRETCH_RULES(BBPD_EVAL_SILLING_ASKARI, 1)
BBPD_FOR_STRETCH_RULES(BBPD_EVAL_SILLING_ASKARI, 2)
#undef BBPD_EVAL_SILLING_ASKARI

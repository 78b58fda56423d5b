// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the Silling-Askari critical stretch in the bbpd pair styles
   (pair_bbpd_alpha.h): the loop over the rows of fix bbpd/bonds that breaks
   bonds with it, for bbpd/KERNEL/alpha and for bbpd/pmb.
------------------------------------------------------------------------- */

#include "pair_bbpd_alpha.h"
#include "bbpd_pmb_rules.h"
#include "bbpd_silling_askari.h"
#include "bbpd_stretch_row.h"
#include "pair_bbpd_rows.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_bbpd_alpha.h"
#include "fix_bbpd_bonds.h"
#include "memory.h"
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
static constexpr const char *ALPHA_FIX_ID = "BBPD_ALPHA";

/* ---------------------------------------------------------------------- */

PairBBPDAlpha::PairBBPDAlpha(LAMMPS *lmp, BBPD::KernelInfo k, const char *style_name, Rules r) :
    PairBBPD(lmp, k, style_name ? style_name : (std::string("bbpd/") + k.name + "/alpha").c_str(), r),
    nmax_smin(0), smin_new(nullptr), alpha_state(nullptr)
{
}

PairBBPDAlpha::~PairBBPDAlpha()
{
  if (copymode) return;
  memory->destroy(smin_new);
  release_fix(alpha_state, ALPHA_FIX_ID);
}

/* part of init_style: the state fix and the starting smin */
void PairBBPDAlpha::init_rules()
{
  alpha_state = static_cast<FixBBPDAlpha *>(own_fix(ALPHA_FIX_ID, "bbpd/alpha"));
  // before the families exist no atom has a bond: no smin yet (as peri/pmb)
  if (!bonds->families_built())
    for (int i = 0; i < atom->nlocal; i++) atom->s0[i] = NO_BOND_STRETCH;
  if (rules.pmb_rules || comm->me != 0) return;
  bool any = false;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && alpha[i][j] > 0.0) any = true;
  if (!any)
    error->warning(FLERR, "Pair style {}: alpha is 0 for every type pair, which turns the "
                   "Silling-Askari rule off: pair style bbpd/{} breaks bonds alike, faster",
                   style, kernel.name);
}

std::string PairBBPDAlpha::report_rules() const
{
  return "  Silling-Askari critical stretch: s0 - alpha min(0, smallest stretch of the atom)\n";
}

/* the bond forces and breaking of one step, in the bbpd order */
void PairBBPDAlpha::eval_bonds()
{
  // only compression lowers s0: a body in pure tension keeps the calibrated s00
  if (evflag) eval_silling_askari<1, BBPD::SillingAskariRule<true>>();
  else eval_silling_askari<0, BBPD::SillingAskariRule<true>>();
}

/* ----------------------------------------------------------------------
   bond forces and breaking with a Silling-Askari critical stretch: how a stretch is read, the
   critical stretch and what a breaking bond does in its step come from Rule
   (bbpd_plugin_model.h lists the rules)
------------------------------------------------------------------------- */

template <int EVFLAG, class Rule> void PairBBPDAlpha::eval_silling_askari()
{
  const int nlocal = atom->nlocal;
  if (nlocal > nmax_smin) {
    nmax_smin = atom->nmax;
    memory->destroy(smin_new);
    memory->create(smin_new, nmax_smin, "pair:smin_new");
  }
  const BBPD::SillingAskariCoefficients sa =
      BBPD::SillingAskariCoefficients::of(critical_stretch, alpha, atom->ntypes);
  // a second evaluation of the last step (setup of a new run, read_restart): no breaking,
  // no new smallest stretches, and the bonds that broke then act again
  const bool replay = update->setupflag && update->ntimestep == alpha_state->last_step;
  // in a periodic box the two ends of a bond see each other through images that round
  // differently: a row with a bond within 'margin' (stretch) of breaking is decided again
  // from breaking_length(), which both ends compute alike. The margin bounds the stretch
  // difference of the two views (break_margin / shortest reference length), with a factor
  // for the rounding of the stretch itself.
  const bool canonical = bonds->raw_positions();
  const double margin = canonical && break_margin > 0.0
      ? STRETCH_MARGIN_FACTOR * break_margin / bonds->min_reference_length() : 0.0;
  // the row of atom i: its critical stretches from the smallest stretches of the last step;
  // snew, its smallest stretch now; fb, the forces of the bonds it breaks in this step
  struct Row {
    PairBBPDAlpha &p;
    int i;
    double *acc;
    BBPD::CoefCache *cache;
    bool replay, canonical;
    BBPD::SillingAskariCoefficients sa;
    double margin;
    double fb[3];
    bool sum_and_check(double *fi)
    {
      if (replay) {
        p.smin_new[i] = p.atom->s0[i];
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
            const bool past = decltype(path)::template row_force_stretch<EVFLAG, BondModel, Rule>(
                xx, i, bj, vals, n, smin, sa.s00_one, sa.alpha_one, margin, &snew, ax, ay, az, &tally);
            if (!past) {
              lane_sum(ax, ay, az, fi);
              if (EVFLAG) p.tally_lanes(i, tally, acc);
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
      p.smin_new[i] = n > 0 ? snew : NO_BOND_STRETCH;
      if (!broken && !summed) p.row_force<EVFLAG, 0, 0>(i, fi, nullptr, acc, cache);
      return broken;
    }
    bool breaks(int k)
    {
      if (!Rule::past_critical(breaking_stretch(k), s0_of(k), 0.0)) return false;
      // a rule may apply the force of a bond in the step it breaks (its energy then is what it
      // carries away), or drop it at once, at its critical stretch
      if (Rule::FORCE_IN_BREAKING_STEP)
        p.bonds->ebroken[i] += p.broken_bond_force<EVFLAG>(i, k, fb, acc) * p.atom->vfrac[i];
      else
        p.book_broken_bond(i, k, s0_of(k));
      return true;
    }
    void sum(double *fi) { p.row_force<EVFLAG, 0, 0>(i, fi, nullptr, acc, cache); }
    void finish(double *fi)
    {
      if (!Rule::FORCE_IN_BREAKING_STEP) return;
      double *fbroken = p.alpha_state->fbroken[i];
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
    return Row{*this, i, acc, cache, replay, canonical, sa, margin,
               {0.0, 0.0, 0.0}};
  });
  // the new smin takes effect at the next step, once sent to the ghosts
  double *smin = atom->s0;    // smallest bond stretch at the previous step, ghosts included
  for (int i = 0; i < nlocal; i++) smin[i] = smin_new[i];
  alpha_state->last_step = update->ntimestep;
}

/* add the force density of bond k of atom i (about to break) to fb, in the order the
   bonds break; tally its energy and virial as row_force does; returns the row's share of its
   energy density */
template <int EVFLAG> double PairBBPDAlpha::broken_bond_force(int i, int k, double *fb, double *acc)
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
  return eng;
}

#define BBPD_EVAL_SILLING_ASKARI(EVFLAG, RULE) \
  template void PairBBPDAlpha::eval_silling_askari<EVFLAG, RULE>();
BBPD_FOR_STRETCH_RULES(BBPD_EVAL_SILLING_ASKARI, 0)
BBPD_FOR_STRETCH_RULES(BBPD_EVAL_SILLING_ASKARI, 1)
#undef BBPD_EVAL_SILLING_ASKARI

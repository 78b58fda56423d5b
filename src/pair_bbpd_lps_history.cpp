// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the bond loop of pair styles bbpd/ves and bbpd/eps (pair_bbpd_lps.h), the
   LPS state with a family F whose deviatoric part has a history (bbpd_ves.h, bbpd_eps.h):
   the dilatations, breaking, tallies and short-range forces are those of bbpd/lps
   (pair_bbpd_lps.cpp, pair_bbpd_lps_row.h); the row hands the family to the history rows in
   lanes of bbpd_lps_history_lanes.h (on the pair style's path) and keeps the history in fix bbpd/history (fix_bbpd_history.h).

   The history of a step is advanced once, by its first evaluation, as peri/ves and peri/eps
   do at every evaluation; a second evaluation of the same step (the setup of a new run,
   read_restart) repeats that step's forces from what the history kept (VES: the back
   extension it reached; EPS: the plastic extension it started from and the norm of the
   trial state), so that a run split in two, or restarted, continues in the same bits.
------------------------------------------------------------------------- */

#include "pair_bbpd_lps_row.h"

#include "bbpd_lps_history_lanes.h"

#include "bbpd_eps.h"
#include "bbpd_lps_history_row.h"
#include "bbpd_ves.h"

#include "error.h"
#include "fix_bbpd_history.h"
#include "memory.h"
#include "update.h"

#include <limits>
#include <type_traits>

using namespace LAMMPS_NS;
namespace LPS = BBPD::LPS;

/* the family's coefficients for the row of local atom i (peri/ves and peri/eps take atom i's
   type); the deviatoric modulus d (d + 2) G of its model (15 G in 3D) */
BBPD::VES::Family PairBBPDLPS::ves_of_type(int t) const
{
  return {BBPD::VES::coeffs(moduli_of_type(t).deviatoric, relax_share[t][t], relax_time[t][t],
                            update->dt)};
}

// from ves_types, which eval_history fills once per step (an exp per type, not per row)
template <> BBPD::VES::Family PairBBPDLPS::family_of<BBPD::VES::Family>(int i) const
{
  return ves_types[atom->type[i]];
}

template <> BBPD::EPS::Family PairBBPDLPS::family_of<BBPD::EPS::Family>(int i) const
{
  const int t = atom->type[i];
  return {{moduli_of_type(t).deviatoric,
           BBPD::EPS::pointwise_yield_value(yield_stress[t][t], horizon[t][t]),
           lps_state->weighted_volume[i]}};
}

/* the force pass of a step's first evaluation of row i (VES: the force pass that rolls the
   history; EPS: its norm and force pass in one), with the breaking test never reached, on the
   pair style's path: the auto path's timing. hist: the row's own scratch history, which the
   pass reads and writes as a step does its real one. */
double PairBBPDLPS::history_row_probe(int i, const LPS::AtomState *states, BBPD::CoefCache *cache,
                                      double *hist)
{
  const int n = bonds->nbond[i];
  const int t = atom->type[i];
  const LPS::Moduli mod = moduli_of_type(t);
  LPS::HistoryCoefficients c{{mod.dilatational, mod.deviatoric, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0},
                             0.0};
  c.s0_floor = std::numeric_limits<double>::infinity();    // no bond is tested for breaking
  const double *xx = atom->x[0];
  const int *slot = probe_slot.data();
  LPS::ForceLanes lanes;
  double snew, norm;
  auto no_s0 = [](int) { return std::numeric_limits<double>::infinity(); };
  bonds->visit_row(i, *cache, [&](const auto *bj, const auto &vals) {
    if (family == Family::VES) {
      using F = BBPD::VES::Family;
      static_assert(F::BOND_HISTORY == PROBE_BOND_HISTORY, "the probe's scratch history's width");
      const F fam = ves_of_type(t);
      return BBPD::on_path(simd_path, [&](auto path) {
        return decltype(path)::template lps_history_force<F, 0, 1, 1>(
            xx, i, bj, vals, n, states, fam, F::Plan{}, c, slot, hist, nullptr, &snew, lanes);
      }, [&] {
        return LPS::history_force_portable<F, 0, 1, 1>(xx, i, bj, vals, n, states, fam, F::Plan{},
                                                       c, slot, hist, no_s0, &snew, lanes);
      });
    }
    using F = BBPD::EPS::Family;
    static_assert(F::BOND_HISTORY == PROBE_BOND_HISTORY, "the probe's scratch history's width");
    const F fam{{mod.deviatoric, 1.0, 1.0}};
    return BBPD::on_path(simd_path, [&](auto path) {
      return decltype(path)::template lps_history_norm_force<F, 0>(
          xx, i, bj, vals, n, states, fam, c, slot, hist, nullptr, &snew, lanes, &norm);
    }, [&] {
      return LPS::history_norm_force_portable<F, 0>(xx, i, bj, vals, n, states, fam, c, slot, hist,
                                                    no_s0, &snew, lanes, &norm);
    });
  });
  return lanes.fx[0];
}

// the family's history per atom and per bond end, in doubles
std::array<int, 2> PairBBPDLPS::history_widths() const
{
  using VES = BBPD::VES::Family;
  using EPS = BBPD::EPS::Family;
  if (family == Family::VES) return {VES::ATOM_HISTORY, VES::BOND_HISTORY};
  return {EPS::ATOM_HISTORY, EPS::BOND_HISTORY};
}

/* every local atom's history row as long as its family (rows come with atoms that migrate or
   are read from a restart file; a new family's rows start at zero) */
void PairBBPDLPS::fit_history()
{
  history->fit(bonds->npartner, bonds->maxpartner);
}

double PairBBPDLPS::plastic_multiplier(int i) const
{
  if (family != Family::EPS || !history || history->length(i) <= BBPD::EPS::Family::LAMBDA) return 0.0;
  return history->row(i)[BBPD::EPS::Family::LAMBDA];
}

// the intact bonds of local atom i in its partner slots 0 .. nbond[i] - 1 (it lost no partner)
bool PairBBPDLPS::row_dense(int i) const
{
  const int n = bonds->nbond[i];
  for (int m = 0; m < n; m++)
    if (bonds->partner[i][m] <= 0) return false;
  return true;
}

/* the slots of the intact bonds of local atom i (bbpd_bond_slots.h): none of its own while it
   lost no partner, else the slots of its partners with a positive tag, in order; the number
   found */
int PairBBPDLPS::find_row_slots(int i)
{
  const int n = bonds->nbond[i];
  if (bond_slots.dense(i) && row_dense(i)) return n;
  return intact_slots(i, bond_slots.own(i, n));
}

// the partner slots of the intact bonds of local atom i, in order, into s; how many
int PairBBPDLPS::intact_slots(int i, int *s) const
{
  const int n = bonds->nbond[i];
  int found = 0;
  for (int m = 0; m < bonds->npartner[i] && found < n; m++)
    if (bonds->partner[i][m] > 0) s[found++] = m;
  return found;
}

// the ints bond_slots will hold for the local atoms (the setup report comes before the first step)
double PairBBPDLPS::slot_bytes_when_found() const
{
  double ints = atom->nlocal + bonds->maxpartner;    // where each row's slots start; 0, 1, 2, ...
  for (int i = 0; i < atom->nlocal; i++)
    if (!row_dense(i)) ints += bonds->nbond[i];
  return ints * sizeof(int);
}

/* bond_slots.of(i)[k]: the slot in partner[i] (and in the history) of the k-th intact bond of
   local atom i, the k-th partner with a positive tag */
void PairBBPDLPS::find_bond_slots()
{
  const int nlocal = atom->nlocal;
  // the slots change only when the cache is rebuilt or bonds break (a row that breaks bonds
  // shifts its slots itself, in its step, and the next step finds them all again)
  if (bonds->cache_generation() == slot_generation && bonds->row_removals() == slot_removals &&
      nlocal == slot_nlocal)
    return;
  slot_generation = bonds->cache_generation();
  slot_removals = bonds->row_removals();
  slot_nlocal = nlocal;
  bond_slots.reset(nlocal, bonds->maxpartner);
  for (int i = 0; i < nlocal; i++) {
    const int found = find_row_slots(i);
    if (found != bonds->nbond[i])
      error->one(FLERR,
                 "Pair style {}: atom {} has {} intact bonds but {} bond partners: "
                 "the history of its bonds is lost (please report this)",
                 style, atom->tag[i], bonds->nbond[i], found);
  }
}

/* the row of local atom i for a family F with history: the force state of
   bbpd_lps_history_lanes.h, the breaking, tallies and finish of the LPS row (Row) */
template <int EVFLAG, class F> struct PairBBPDLPS::HistoryRow : PairBBPDLPS::Row<EVFLAG> {
  using Base = PairBBPDLPS::Row<EVFLAG>;
  using Base::acc;
  using Base::cache;
  using Base::fb;
  using Base::i;
  using Base::mod;
  using Base::nlost;
  using Base::p;
  using Base::replay;
  using Base::si;
  using Base::smin_i;
  using Base::snew;
  using Base::tally;
  using Base::theta_third_i;

  F fam;
  typename F::Plan plan;
  double *atom_hist;    // the atom's history, then its bonds' (by slot)
  double *hist;
  const int *slot;    // bond_slots.of(i)
  std::vector<int> new_slots;    // the row's slots after this step's breaking, until it owns them

  HistoryRow(PairBBPDLPS &pair, int atom_i, double *acc_, BBPD::CoefCache *cache_, bool replay_,
             bool canonical_, const BBPD::SillingAskariCoefficients &rule, double margin_) :
      Base(pair, atom_i, acc_, cache_, replay_, canonical_, rule, margin_),
      fam(pair.family_of<F>(atom_i)), plan{}, atom_hist(pair.history->row(atom_i)),
      hist(atom_hist + F::ATOM_HISTORY), slot(pair.bond_slots.of(atom_i))
  {
  }

  LPS::HistoryCoefficients coefficients() const
  {
    return {{mod.dilatational, mod.deviatoric, si.theta_over_m, si.inv_m, theta_third_i,
             this->sa.s00_one, this->sa.alpha_one, smin_i, this->margin, this->s0_floor},
            LPS::split_dilatational(mod)};
  }
  // the row's force lanes into f and its tallies: atom i's deviatoric energy (half of it, as
  // peri/ves and peri/eps) and half the virial
  void take_lanes(const LPS::ForceLanes &lanes, double *f)
  {
    BBPD::lane_sum(lanes.fx, lanes.fy, lanes.fz, f);
    if (EVFLAG) {
      tally[0] = p.deviatoric_share *
          LPS::deviatoric_energy_of(mod, si.inv_m, BBPD::lane_total(lanes.tally.eng));
      for (int v = 0; v < 6; v++)
        tally[1 + v] = -BondModel::virial_share(1.0, BBPD::lane_total(lanes.tally.vir[v]), 1.0);
    }
  }

  /* the first evaluation of a step of a family with a norm (EPS): the norm (which rolls the
     history), the plan it gives, and the row's force with the breaking check; one pass over the
     row for an elastic row (history_norm_force of bbpd_lps_history_lanes.h), the force pass again
     for a plastic one. The norm is kept for a second evaluation of the step. */
  bool norm_and_sum(double *f)
  {
    const double *xx = p.atom->x[0];
    const int n = p.bonds->nbond[i];
    const LPS::HistoryCoefficients c = coefficients();
    constexpr int EV = EVFLAG != 0;
    LPS::ForceLanes lanes;
    double sum = 0.0;
    const bool past = p.bonds->visit_row(i, *cache, [&](const auto *bj, const auto &vals) {
      auto portable = [&] {
        return LPS::history_norm_force_portable<F, EV>(xx, i, bj, vals, n, p.atom_states, fam, c, slot,
                                                       hist, [&](int j) { return this->s0_with(j); },
                                                       &snew, lanes, &sum);
      };
      if (this->sa.multi) return portable();
      return BBPD::on_path(p.simd_path, [&](auto path) {
        return decltype(path)::template lps_history_norm_force<F, EV>(
            xx, i, bj, vals, n, p.atom_states, fam, c, slot, hist, p.atom->s0, &snew, lanes, &sum);
      }, portable);
    });
    const double norm = std::sqrt(sum);
    atom_hist[F::NORM] = norm;
    plan = fam.plan(norm);
    if (!plan.plastic) {
      take_lanes(lanes, f);
      return past;
    }
    atom_hist[F::LAMBDA] += plan.delta_lambda;
    return row_sum<true, true>(f);
  }

  // the row's force into f and its tallies (bbpd_lps_history_lanes.h, on the pair style's path;
  // per type pair s00 and alpha: the portable loop); with CHECK its smallest stretch and whether
  // a bond is past, or within margin of, its critical stretch (decided canonically by breaks);
  // COMMIT: the first evaluation of a step, which advances the bonds' history
  template <bool CHECK, bool COMMIT> bool row_sum(double *f)
  {
    const double *xx = p.atom->x[0];
    const int n = p.bonds->nbond[i];
    const LPS::HistoryCoefficients c = coefficients();
    constexpr int EV = EVFLAG != 0, CH = CHECK, CO = COMMIT;
    LPS::ForceLanes lanes;
    const bool past = p.bonds->visit_row(i, *cache, [&](const auto *bj, const auto &vals) {
      auto portable = [&] {
        return LPS::history_force_portable<F, EV, CH, CO>(
            xx, i, bj, vals, n, p.atom_states, fam, plan, c, slot, hist,
            [&](int j) { return this->s0_with(j); }, &snew, lanes);
      };
      if (this->sa.multi) return portable();
      return BBPD::on_path(p.simd_path, [&](auto path) {
        return decltype(path)::template lps_history_force<F, EV, CH, CO>(
            xx, i, bj, vals, n, p.atom_states, fam, plan, c, slot, hist, p.atom->s0, &snew, lanes);
      }, portable);
    });
    take_lanes(lanes, f);
    return past;
  }
  bool sum_and_check(double *fi)
  {
    if (replay) {    // the plan of the step's first evaluation (EPS: from the norm it kept)
      if constexpr (F::NEEDS_NORM) plan = fam.plan(atom_hist[F::NORM]);
      p.silling_askari.smin_new[i] = smin_i;
      row_sum<false, false>(fi);
      return false;
    }
    const bool had_bonds = p.bonds->nbond[i] > 0;
    bool broken;
    if constexpr (F::NEEDS_NORM)
      broken = norm_and_sum(fi);
    else
      broken = row_sum<true, true>(fi);
    p.silling_askari.smin_new[i] = had_bonds ? snew : BBPD::PMB::NO_BOND_STRETCH;
    return broken;
  }
  // as Row::breaks, with the family's force state of the bond (its history as this step left it)
  bool breaks(int k)
  {
    const double *xx = p.atom->x[0];
    const int j = p.bonds->partner_of(i, k);
    const double xi0 = p.bonds->xi0_of(i, k);
    const double dx = xx[3 * j] - xx[3 * i], dy = xx[3 * j + 1] - xx[3 * i + 1],
                 dz = xx[3 * j + 2] - xx[3 * i + 2];
    const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double e = LPS::elongation(r, xi0);
    if (!LPSStretchRule::past_critical(this->breaking_stretch(j, e, xi0), this->s0_with(j), 0.0))
      return false;
    // the bond's slot: k counts the bonds kept so far in this row
    const int kr = k - p.bonds->bond_start[i];
    const int m = slot[kr + nlost];
    constexpr int B = F::BOND_HISTORY;
    double energy;
    const double t = LPS::history_force_state<F, false>(
        LPS::split_dilatational(mod), fam, plan, p.bonds->coef_of(i, k, xi0), xi0, e, theta_third_i, si,
        p.atom_states[j], BBPD::history_value<B>(hist, m, 0), BBPD::history_value<B>(hist, m, 1),
        energy);
    const double fpl = r > 0.0 ? t / r : 0.0;
    fb[0] += fpl * dx;
    fb[1] += fpl * dy;
    fb[2] += fpl * dz;
    const double eng = p.deviatoric_share * LPS::deviatoric_energy_of(mod, si.inv_m, energy);
    // the energy the bond held at atom i goes with it (term 3 of compute bbpd/energy)
    p.bonds->ebroken[i] += eng * p.atom->vfrac[i];
    double vir[6];
    p.bond_end_virial(fpl, dx, dy, dz, vir);
    p.silling_askari.book_broken_virial(vir);
    if (EVFLAG) {
      acc[0] += eng;
      if (p.eflag_atom) p.eatom[i] += eng;
      for (int c = 0; c < 6; c++) {
        acc[1 + c] += vir[c];
        if (p.vflag_atom) p.vatom[i][c] += vir[c];
      }
    }
    nlost++;
    return true;
  }
  // the row has shifted: the history is this step's already
  void sum(double *fi)
  {
    slot_shift();
    row_sum<false, false>(fi);
  }
  /* the slots of the bonds left, in row order (the broken ones are gone from the row): where
     the row keeps its own, else (it lost its first partners now) here, and it gets its own
     after the rows (rows run in threads; owning them may move the others') */
  void slot_shift()
  {
    if (!p.bond_slots.dense(i)) {
      p.find_row_slots(i);
      slot = p.bond_slots.of(i);
      return;
    }
    if (p.row_dense(i)) return;    // the bonds it lost were its last
    new_slots.resize(p.bonds->nbond[i]);
    p.intact_slots(i, new_slots.data());
    slot = new_slots.data();
    const std::lock_guard<std::mutex> lock(p.rows_to_own_mutex);
    p.rows_to_own.push_back(i);
  }
};

template <int EVFLAG, class F> void PairBBPDLPS::eval_history()
{
  // rows change with the atoms at the local indices (migration, sorting), which refresh the
  // bond cache
  if (bonds->cache_generation() != history_generation) {
    fit_history();
    history_generation = bonds->cache_generation();
  }
  const bool replay = begin_state();
  find_bond_slots();
  if constexpr (std::is_same_v<F, BBPD::VES::Family>) {
    ves_types.resize(atom->ntypes + 1);
    for (int t = 1; t <= atom->ntypes; t++) ves_types[t] = ves_of_type(t);
  }
  const bool canonical = bonds->raw_positions();
  const BBPD::SillingAskariCoefficients rule = breaking_rule();
  const double margin = stretch_margin();
  eval_rows<EVFLAG>([&](int i, double *acc, BBPD::CoefCache *cache) BBPD_ROW_BODY {
    return HistoryRow<EVFLAG, F>(*this, i, acc, cache, replay, canonical, rule, margin);
  });
  add_replayed_virial(replay, EVFLAG, silling_askari);
  for (const int i : rows_to_own) find_row_slots(i);
  rows_to_own.clear();
  // every row that broke bonds in this step has shifted its slots (HistoryRow::sum): the slots
  // are current until bonds go another way (on LAMMPS's cylinder example, finding them all again
  // each step was 12 % of a VES run)
  slot_removals = bonds->row_removals();
  end_state();
}

template void PairBBPDLPS::eval_history<0, BBPD::VES::Family>();
template void PairBBPDLPS::eval_history<1, BBPD::VES::Family>();
template void PairBBPDLPS::eval_history<0, BBPD::EPS::Family>();
template void PairBBPDLPS::eval_history<1, BBPD::EPS::Family>();

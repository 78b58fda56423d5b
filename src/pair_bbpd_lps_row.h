// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the row of an atom in the bond loop of pair style bbpd/lps
   (PairBBPDLPS::Row: its LPS force state, peri/lps's Silling-Askari breaking and its tallies),
   shared by pair_bbpd_lps.cpp and the rows of the families with history
   (pair_bbpd_lps_history.cpp), which take its breaking and tallies.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_LPS_ROW_H
#define LMP_PAIR_BBPD_LPS_ROW_H

#include "pair_bbpd_lps.h"
#include "pair_bbpd_rows.h"

#include "bbpd_lps_lanes.h"
#include "bbpd_row_paths.h"

#include "atom.h"
#include "fix_bbpd_alpha.h"
#include "fix_bbpd_bonds.h"
#include "fix_bbpd_lps.h"

#include <cmath>
#include <limits>

namespace LAMMPS_NS {

using LPSStretchRule = BBPD::SillingAskariRule<false>;    // peri/lps: smin not clamped

/* the force density of the bond of local atom i to j (reference length xi0, weighted partner
   volume wv) added to f, and with EVFLAG its energy density and virial (as peri/lps tallies
   them: half the deviatoric energy of the bond at each end) into acc[0] and acc[1..6] */
template <int EVFLAG>
void PairBBPDLPS::add_bond_force(int i, int j, double xi0, double wv, double *f, double *acc)
{
  const double *xx = atom->x[0];
  const double dx = xx[3 * j] - xx[3 * i], dy = xx[3 * j + 1] - xx[3 * i + 1],
               dz = xx[3 * j + 2] - xx[3 * i + 2];
  const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
  const double e = BBPD::LPS::elongation(r, xi0);
  const int itype = atom->type[i];
  const BBPD::LPS::Moduli mod = moduli_of_type(itype);    // atom i's type
  const double t = BBPD::LPS::force_state(mod, wv, xi0, e, atom_states[i], atom_states[j]);
  const double fpl = r > 0.0 ? t / r : 0.0;
  f[0] += fpl * dx;
  f[1] += fpl * dy;
  f[2] += fpl * dz;
  if (EVFLAG) {
    const double eng = deviatoric_share *
        BBPD::LPS::deviatoric_energy(mod, wv, xi0, e, BBPD::LPS::third(lps_state->dilatation[i], dimension), atom_states[i].inv_m);
    double vir[6];
    bond_end_virial(fpl, dx, dy, dz, vir);
    acc[0] += eng;
    for (int m = 0; m < 6; m++) acc[1 + m] += vir[m];
  }
}

/* the row of local atom i in the bond loop of eval_lps: the LPS force state of its bonds
   (theta and m of both ends), with peri/lps's Silling-Askari breaking (a bond acts in the step
   it breaks) and its tallies */
template <int EVFLAG> struct PairBBPDLPS::Row {
  PairBBPDLPS &p;
  int i;
  double *acc;
  BBPD::CoefCache *cache;
  bool replay, canonical;    // as in eval_lps
  BBPD::SillingAskariCoefficients sa;
  double margin;    // periodic box: a stretch this close to s0 is decided canonically (breaks)
  BBPD::LPS::Moduli mod;                  // i's type
  BBPD::LPS::AtomState si;
  double theta_i, theta_third_i, smin_i;
  double s0_floor;        // no bond of the row breaks below it (RowCoefficients)
  double tally[7];        // the row's energy and virial
  double fb[3];           // the forces of the bonds it breaks
  int nlost;              // how many bonds it breaks
  double snew;            // its smallest stretch now (summed with CHECK)

  Row(PairBBPDLPS &pair, int atom_i, double *acc_, BBPD::CoefCache *cache_, bool replay_,
      bool canonical_, const BBPD::SillingAskariCoefficients &sa_, double margin_) :
      p(pair), i(atom_i), acc(acc_), cache(cache_), replay(replay_), canonical(canonical_),
      sa(sa_), margin(margin_), mod(p.moduli_of_type(p.atom->type[i])),
      si(p.atom_states[i]), theta_i(p.lps_state->dilatation[i]),
      theta_third_i(BBPD::LPS::third(theta_i, p.dimension)), smin_i(p.atom->s0[i]),
      s0_floor(BBPD::LPS::critical_stretch_floor(sa.s00_one, sa.alpha_one, smin_i, p.smin_cap)),
      fb{0.0, 0.0, 0.0}, nlost(0), snew(std::numeric_limits<double>::max())
  {
  }
  double s0_with(int j) const
  {
    return sa.critical_stretch<LPSStretchRule>(p.atom->type, i, j, smin_i, p.atom->s0[j]);
  }
  // the stretch that decides breaking of the bond to j at elongation e: in a periodic box the
  // one both ends compute alike
  double breaking_stretch(int j, double e, double xi0) const
  {
    return canonical ? LPSStretchRule::stretch(BBPD::LPS::elongation(p.breaking_length(i, j), xi0), xi0)
                     : LPSStretchRule::stretch(e, xi0);
  }
  // the row's force into f and its tallies into tally (bbpd_lps_lanes.h, on the pair style's
  // path; per type pair s00 and alpha: the portable loop); with CHECK also its smallest stretch
  // (snew) and whether a bond is past, or within margin of, its critical stretch
  template <bool CHECK> bool row_sum(double *f)
  {
    const double *xx = p.atom->x[0];
    const BBPD::LPS::RowCoefficients c{mod.dilatational, mod.deviatoric, si.theta_over_m, si.inv_m,
                                       theta_third_i, sa.s00_one, sa.alpha_one, smin_i, margin,
                                       s0_floor};
    const int n = p.bonds->nbond[i];
    BBPD::LPS::ForceLanes lanes;
    const bool past = p.bonds->visit_row(i, *cache, [&](const auto *bj, const auto &vals) {
      auto portable = [&] {
        return BBPD::LPS::force_row_portable<EVFLAG, CHECK>(
            xx, i, bj, vals, n, p.atom_states, c, [&](int j) { return s0_with(j); }, &snew, lanes);
      };
      if (sa.multi) return portable();
      return BBPD::on_path(p.simd_path, [&](auto path) {
        return decltype(path)::template lps_force<EVFLAG, CHECK>(xx, i, bj, vals, n, p.atom_states,
                                                                 c, p.atom->s0, &snew, lanes);
      }, portable);
    });
    BBPD::lane_sum(lanes.fx, lanes.fy, lanes.fz, f);
    // atom i's deviatoric energy (bbpd/lps: half of it, as peri/lps) and half the virial
    if (EVFLAG)
      tally[0] = p.deviatoric_share *
          BBPD::LPS::deviatoric_energy_of(mod, si.inv_m, BBPD::lane_total(lanes.tally.eng));
    if (BBPD::tallies_virial(EVFLAG)) {
      for (int v = 0; v < 6; v++)
        tally[1 + v] = -BondModel::virial_share(1.0, BBPD::lane_total(lanes.tally.vir[v]), 1.0);
    }
    return past;
  }
  bool sum_and_check(double *fi)
  {
    if (replay) {
      p.silling_askari.smin_new[i] = smin_i;
      row_sum<false>(fi);
      return false;
    }
    const bool had_bonds = p.bonds->nbond[i] > 0;
    const bool broken = row_sum<true>(fi);
    p.silling_askari.smin_new[i] = had_bonds ? snew : BBPD::PMB::NO_BOND_STRETCH;
    return broken;
  }
  // a bond past its critical stretch breaks, adding its force (fbroken, applied again by a
  // second evaluation of this step) and taking its energy with it
  bool breaks(int k)
  {
    const double *xx = p.atom->x[0];
    const int j = p.bonds->partner_of(i, k);
    const double xi0 = p.bonds->xi0_of(i, k);
    const double dx = xx[3 * j] - xx[3 * i], dy = xx[3 * j + 1] - xx[3 * i + 1],
                 dz = xx[3 * j + 2] - xx[3 * i + 2];
    const double e = BBPD::LPS::elongation(std::sqrt(dx * dx + dy * dy + dz * dz), xi0);
    if (!LPSStretchRule::past_critical(breaking_stretch(j, e, xi0), s0_with(j), 0.0)) return false;
    double bond_tally[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    p.add_bond_force<1>(i, j, xi0, p.bonds->coef_of(i, k, xi0), fb, bond_tally);
    p.silling_askari.book_broken_virial(bond_tally + 1);
    // the energy the bond held at atom i goes with it (term 3 of compute bbpd/energy)
    p.bonds->ebroken[i] += bond_tally[0] * p.atom->vfrac[i];
    if (EVFLAG) {
      acc[0] += bond_tally[0];
      if (p.eflag_atom) p.eatom[i] += bond_tally[0];
    }
    if (BBPD::tallies_virial(EVFLAG)) {
      for (int c = 1; c < 7; c++) acc[c] += bond_tally[c];
      for (int c = 0; c < 6 && p.vflag_atom; c++) p.vatom[i][c] += bond_tally[1 + c];
    }
    nlost++;
    return true;
  }
  void sum(double *fi) { row_sum<false>(fi); }    // the row has shifted
  void finish(double *fi)
  {
    double *fbroken = p.silling_askari.fix->fbroken[i];
    if (!replay) {
      for (int c = 0; c < 3; c++) fbroken[c] = fb[c];
      p.lps_state->lost[i] = nlost;
    }
    for (int c = 0; c < 3; c++) fi[c] += fbroken[c];
    if (EVFLAG) {
      tally[0] += BBPD::LPS::dilatation_energy(mod.bulk, theta_i);
      acc[0] += tally[0];
      if (p.eflag_atom) p.eatom[i] += tally[0];
      for (int c = 0; c < 6 && BBPD::tallies_virial(EVFLAG); c++) {
        acc[1 + c] += tally[1 + c];
        if (p.vflag_atom) p.vatom[i][c] += tally[1 + c];
      }
    }
  }
};

}    // namespace LAMMPS_NS

#endif

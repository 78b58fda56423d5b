// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: pair style bbpd/lps, the linear peridynamic solid of LAMMPS's peri/lps
   (pair_bbpd_lps.h): its coefficients, the dilatation pass and its ghost exchange, the
   bond loop of the LPS force state with the Silling-Askari breaking of peri/lps, and
   peri/lps's short-range forces (pair_bbpd_pmb.cpp).
------------------------------------------------------------------------- */

#include "pair_bbpd_lps.h"
#include "pair_bbpd_rows.h"

#include "bbpd_lps_kernel.h"
#include "bbpd_lps_row.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_bbpd_alpha.h"
#include "fix_bbpd_bonds.h"
#include "fix_bbpd_lps.h"
#include "memory.h"
#include "update.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

using namespace LAMMPS_NS;
namespace LPS = BBPD::LPS;
using StretchRule = BBPD::SillingAskariRule<false>;    // peri/lps: smin not clamped

static constexpr const char *LPS_FIX_ID = "BBPD_LPS";
// peri/lps tallies half of atom i's deviatoric energy density at i (its ev_tally(i, i, ...,
// 0.5 * evdwl)): bbpd/lps does the same, to give its energies; the kernel styles tally all of it
static constexpr double PERI_LPS_DEVIATORIC_SHARE = 0.5;
// forward communication: theta / m and 1 / m of every ghost atom
static constexpr int LPS_FORWARD_VALUES = 2;

/* ---------------------------------------------------------------------- */

PairBBPDLPS::PairBBPDLPS(LAMMPS *lmp) :
    PairBBPDLPS(lmp, BBPD::kernel_info<BBPD::ConstantKernel>(), "bbpd/lps")
{
}

PairBBPDLPS::PairBBPDLPS(LAMMPS *lmp, BBPD::KernelInfo k, const char *style_name) :
    PairBBPDPMB(lmp, k, style_name), bulk(nullptr), shear(nullptr),
    dimension(LPS::DILATATION_FACTOR), deviatoric_share(PERI_LPS_DEVIATORIC_SHARE), lps_state(nullptr), nmax_lps(0), atom_states(nullptr),
    nmax_length(0), bond_length(nullptr)
{
  comm_forward = LPS_FORWARD_VALUES;
}

PairBBPDLPS::~PairBBPDLPS()
{
  if (copymode) return;
  memory->destroy(bulk);
  memory->destroy(shear);
  memory->sfree(atom_states);
  memory->destroy(bond_length);
  release_fix(lps_state, LPS_FIX_ID);
}

void PairBBPDLPS::allocate_moduli()
{
  if (bulk) return;
  const int n = atom->ntypes + 1;
  memory->create(bulk, n, n, "pair:bulk");
  memory->create(shear, n, n, "pair:shear");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) bulk[i][j] = shear[i][j] = 0.0;
}

/* pair_style bbpd/lps 3d [keywords of bbpd/pmb]: peri/lps is the 3D solid */
void PairBBPDLPS::settings(int narg, char **arg)
{
  const int imodel = (narg > 0 && strcmp(arg[0], "model") == 0) ? 1 : 0;
  if (imodel < narg && strcmp(arg[imodel], "3d") != 0)
    error->all(FLERR, "Pair style bbpd/lps: model '{}' is not available: peri/lps is the 3D "
               "linear peridynamic solid, write 'pair_style bbpd/lps 3d'", arg[imodel]);
  PairBBPDPMB::settings(narg, arg);
}

/* ----------------------------------------------------------------------
   pair_coeff I J K G delta s00 alpha (peri/lps's five numbers)
------------------------------------------------------------------------- */

void PairBBPDLPS::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  allocate_moduli();
  if (narg != 7)
    error->all(FLERR, "Pair coeff for bbpd/lps: expected 'I J K G delta s00 alpha' (bulk and "
               "shear modulus, horizon, critical stretch, Silling-Askari alpha: the numbers of "
               "pair_coeff peri/lps), got {} arguments", narg);
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double K = utils::numeric(FLERR, arg[2], false, lmp);
  const double G = utils::numeric(FLERR, arg[3], false, lmp);
  const double delta = utils::numeric(FLERR, arg[4], false, lmp);
  const double s00 = utils::numeric(FLERR, arg[5], false, lmp);
  const double a = utils::numeric(FLERR, arg[6], false, lmp);
  if (!(K > 0.0)) error->all(FLERR, "Pair coeff for bbpd/lps: the bulk modulus K must be > 0");
  if (!(G > 0.0)) error->all(FLERR, "Pair coeff for bbpd/lps: the shear modulus G must be > 0");
  if (!(delta > 0.0)) error->all(FLERR, "Pair coeff for bbpd/lps: the horizon delta must be > 0");
  if (!(s00 > 0.0)) error->all(FLERR, "Pair coeff for bbpd/lps: s00 must be > 0");
  if (!(a >= 0.0) || !std::isfinite(a))
    error->all(FLERR, "Pair coeff for bbpd/lps: alpha must be >= 0");

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      youngs[i][j] = 0.0;    // not used: K and G are given
      fracture_energy[i][j] = std::numeric_limits<double>::infinity();
      horizon[i][j] = delta;
      // the PMB micromodulus of the same K: short-range forces and the stable time step
      micromodulus[i][j] = LPS::pmb_micromodulus(K, delta);
      critical_stretch[i][j] = s00;
      s0_user[i][j] = 1;
      alpha[i][j] = a;
      bulk[i][j] = bulk[j][i] = K;
      shear[i][j] = shear[j][i] = G;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* the coefficients of bbpd/pmb, then K and G */
void PairBBPDLPS::write_restart(FILE *fp)
{
  PairBBPD::write_restart(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j]) {
        fwrite(&bulk[i][j], sizeof(double), 1, fp);
        fwrite(&shear[i][j], sizeof(double), 1, fp);
      }
}

void PairBBPDLPS::read_restart(FILE *fp)
{
  PairBBPD::read_restart(fp);
  allocate_moduli();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (!setflag[i][j]) continue;
      double v[2] = {0.0, 0.0};
      if (comm->me == 0) utils::sfread(FLERR, v, sizeof(double), 2, fp, nullptr, error);
      MPI_Bcast(v, 2, MPI_DOUBLE, 0, world);
      bulk[i][j] = bulk[j][i] = v[0];
      shear[i][j] = shear[j][i] = v[1];
    }
}

/* part of init_style: peri/pmb's rules (lattice constant, Silling-Askari state), the LPS
   coefficient of the bond storage, and the LPS state */
void PairBBPDLPS::init_rules()
{
  PairBBPDPMB::init_rules();
  law.weighting = BBPD::LpsWeighting{{lattice_constant}};    // omega V_j ramp in the bond storage
  dimension = LPS::lps_dimension(model);    // 3 for bbpd/lps (model 3d)
  lps_state = static_cast<FixBBPDLPS *>(own_fix(LPS_FIX_ID, "bbpd/lps"));
}

double PairBBPDLPS::short_range_stiffness(int itype, int jtype) const
{
  // peri/lps takes the bulk modulus of atom i's type and the horizon of the pair
  return LPS::short_range_stiffness(bulk[itype][itype], horizon[itype][jtype]);
}

/* the stable time step estimate: the bond as a PMB bond of the same bulk modulus */
double PairBBPDLPS::bond_stiffness(int i, int k) const
{
  const int j = bonds->partner_of(i, k);
  return micromodulus[atom->type[i]][atom->type[j]] * bonds->coef_of(i, k, bonds->xi0_of(i, k));
}

std::string PairBBPDLPS::report_type_pair(int i, int j) const
{
  return fmt::format("  types {} {}: peri/lps: K = {:.8g}  G = {:.8g}  horizon = {:.6g}  "
                     "s00 = {:.8g}  alpha = {:.6g}\n", i, j, bulk[i][j], shear[i][j],
                     horizon[i][j], critical_stretch[i][j], alpha[i][j]);
}

std::string PairBBPDLPS::report_rules() const
{
  return PairBBPDPMB::report_rules() +
      "  peri/lps state: influence function 1/|xi|, weighted volume m fixed at the first "
      "evaluation, dilatation theta every step (sent to the ghost atoms); stable time step "
      "estimated as for a PMB bond of the same bulk modulus, c = 18 K / (pi delta^4)\n";
}

int PairBBPDLPS::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  int m = 0;
  for (int k = 0; k < n; k++) {
    buf[m++] = atom_states[list[k]].theta_over_m;
    buf[m++] = atom_states[list[k]].inv_m;
  }
  return m;
}

void PairBBPDLPS::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++) {
    atom_states[i].theta_over_m = buf[m++];
    atom_states[i].inv_m = buf[m++];
  }
}

/* extract: "theta" (the dilatation of every local atom, as peri/lps), and those of bbpd/pmb */
void *PairBBPDLPS::extract(const char *name, int &dim)
{
  if (strcmp(name, "theta") == 0) {
    dim = 1;
    return lps_state ? (void *) lps_state->dilatation : nullptr;
  }
  return PairBBPDPMB::extract(name, dim);
}

double PairBBPDLPS::memory_usage()
{
  const int n = atom->ntypes + 1;
  return PairBBPDPMB::memory_usage() + 2.0 * n * n * sizeof(double) +
      (double) LPS_FORWARD_VALUES * nmax_lps * sizeof(double) + (double) nmax_length * sizeof(double);
}

/* ----------------------------------------------------------------------
   the step: dilatations, bonds, short-range forces
------------------------------------------------------------------------- */

void PairBBPDLPS::eval_bonds()
{
  if (evflag) eval_lps<1>();
  else eval_lps<0>();
  compute_short_range();
}

/* m_i over the bonds each local atom has now (fix_peri_neigh sums wvolume as it builds the
   families; here after fix bbpd/notch has cut its bonds, so that a notch counts as a surface) */
void PairBBPDLPS::sum_weighted_volumes()
{
  double *m = lps_state->weighted_volume;
  for (int i = 0; i < atom->nlocal; i++) {
    double sum = 0.0;
    for (int k = bonds->bond_start[i]; k < bonds->bond_start[i] + bonds->nbond[i]; k++) {
      const double xi0 = bonds->xi0_of(i, k);
      sum += LPS::weighted_volume_term(bonds->coef_of(i, k, xi0), xi0);
    }
    m[i] = sum;
  }
}

/* theta_i over the intact bonds of local atom i, in row order; the bonds' current lengths into
   r (the force loop reads them there) */
double PairBBPDLPS::dilatation_of(int i, double *r)
{
  const double *xx = atom->x[0];
  const int n = bonds->nbond[i];
  const double sum = bonds->visit_row(i, *thread_coef_cache(), [&](const auto *bj, const auto &vals) {
    const double xi = xx[3 * i], yi = xx[3 * i + 1], zi = xx[3 * i + 2];
    double s = 0.0;
    for (int k = 0; k < n; k++) {
      const int j = BBPD::partner_index(bj, i, k);
      const double dx = xx[3 * j] - xi, dy = xx[3 * j + 1] - yi, dz = xx[3 * j + 2] - zi;
      r[k] = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double xi0 = vals.xi0_at(k, j);
      s += LPS::dilatation_term(vals.coef_at(k, j), xi0, LPS::elongation(r[k], xi0));
    }
    return s;
  });
  return LPS::dilatation(sum, lps_state->weighted_volume[i], dimension);
}

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
  const double e = LPS::elongation(r, xi0);
  const int itype = atom->type[i];
  const LPS::Moduli mod = moduli_of_type(itype);    // atom i's type
  const double t = LPS::force_state(mod, wv, xi0, e, atom_states[i], atom_states[j]);
  const double fpl = r > 0.0 ? t / r : 0.0;
  f[0] += fpl * dx;
  f[1] += fpl * dy;
  f[2] += fpl * dz;
  if (EVFLAG) {
    const double eng = deviatoric_share *
        LPS::deviatoric_energy(mod, wv, xi0, e, LPS::third(lps_state->dilatation[i], dimension), atom_states[i].inv_m);
    const double vir[6] = {-BondModel::virial_share(fpl, dx, dx), -BondModel::virial_share(fpl, dy, dy),
                           -BondModel::virial_share(fpl, dz, dz), -BondModel::virial_share(fpl, dx, dy),
                           -BondModel::virial_share(fpl, dx, dz), -BondModel::virial_share(fpl, dy, dz)};
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
  bool replay, canonical, multi;    // as in eval_lps
  double s00_one, alpha_one;
  LPS::Moduli mod;                  // i's type
  LPS::AtomState si;
  double theta_i, theta_third_i, smin_i;
  const double *r_row;    // the bond lengths of the dilatation pass (the row as it was then)
  double tally[7];        // the row's energy and virial
  double fb[3];           // the forces of the bonds it breaks
  int nlost;              // how many bonds it breaks
  double snew;            // its smallest stretch now (summed with CHECK)

  Row(PairBBPDLPS &pair, int atom_i, double *acc_, BBPD::CoefCache *cache_, bool replay_,
      bool canonical_, bool multi_, double s00, double alpha) :
      p(pair), i(atom_i), acc(acc_), cache(cache_), replay(replay_), canonical(canonical_),
      multi(multi_), s00_one(s00), alpha_one(alpha), mod(p.moduli_of_type(p.atom->type[i])),
      si(p.atom_states[i]), theta_i(p.lps_state->dilatation[i]),
      theta_third_i(LPS::third(theta_i, p.dimension)), smin_i(p.atom->s0[i]),
      r_row(p.bond_length + p.bonds->bond_start[i]), fb{0.0, 0.0, 0.0}, nlost(0),
      snew(std::numeric_limits<double>::max())
  {
  }
  double s0_with(int j) const
  {
    const double *smin = p.atom->s0;
    if (!multi) return StretchRule::critical_stretch(s00_one, alpha_one, smin_i, smin[j]);
    const int itype = p.atom->type[i], jtype = p.atom->type[j];
    return StretchRule::critical_stretch(p.critical_stretch[itype][jtype], p.alpha[itype][jtype],
                                         smin_i, smin[j]);
  }
  // the stretch that decides breaking of the bond to j at elongation e: in a periodic box the
  // one both ends compute alike
  double breaking_stretch(int j, double e, double xi0) const
  {
    return canonical ? StretchRule::stretch(LPS::elongation(p.breaking_length(i, j), xi0), xi0)
                     : StretchRule::stretch(e, xi0);
  }
  // the row's force into f and its tallies into tally (bbpd_lps_row.h); with CHECK also its
  // smallest stretch (snew) and whether a bond is past its critical stretch; with CACHED the
  // bond lengths of the dilatation pass
  template <bool CHECK, bool CACHED> bool row_sum(double *f)
  {
    const double *xx = p.atom->x[0];
    auto check = [&](int j, double e, double xi0) BBPD_ROW_BODY {
      const double s = breaking_stretch(j, e, xi0);
      snew = std::min(snew, s);
      return StretchRule::past_critical(s, s0_with(j), 0.0);
    };
    LPS::RowSums sums;
    const bool past = p.bonds->visit_row(i, *cache, [&](const auto *bj, const auto &vals) {
      return LPS::row_sums<EVFLAG != 0, CHECK, CACHED>(xx, i, bj, vals, p.bonds->nbond[i], r_row,
                                                      p.atom_states, mod, theta_third_i, check,
                                                      sums);
    });
    for (int c = 0; c < 3; c++) f[c] = sums.f[c];
    // atom i's deviatoric energy (bbpd/lps: half of it, as peri/lps) and half the virial
    tally[0] = p.deviatoric_share * LPS::deviatoric_energy_of(mod, si.inv_m, sums.wv_ed2);
    for (int c = 0; c < 6; c++) tally[1 + c] = -BondModel::virial_share(1.0, sums.fdd[c], 1.0);
    return past;
  }
  bool sum_and_check(double *fi)
  {
    if (replay) {
      p.smin_new[i] = smin_i;
      row_sum<false, true>(fi);
      return false;
    }
    const bool had_bonds = p.bonds->nbond[i] > 0;
    const bool broken = row_sum<true, true>(fi);
    p.smin_new[i] = had_bonds ? snew : BBPD::PMB::NO_BOND_STRETCH;
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
    const double e = LPS::elongation(std::sqrt(dx * dx + dy * dy + dz * dz), xi0);
    if (!StretchRule::past_critical(breaking_stretch(j, e, xi0), s0_with(j), 0.0)) return false;
    double bond_tally[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    p.add_bond_force<1>(i, j, xi0, p.bonds->coef_of(i, k, xi0), fb, bond_tally);
    // the energy the bond held at atom i goes with it (term 3 of compute bbpd/energy)
    p.bonds->ebroken[i] += bond_tally[0] * p.atom->vfrac[i];
    if (EVFLAG) {
      for (int c = 0; c < 7; c++) acc[c] += bond_tally[c];
      if (p.eflag_atom) p.eatom[i] += bond_tally[0];
      for (int c = 0; c < 6 && p.vflag_atom; c++) p.vatom[i][c] += bond_tally[1 + c];
    }
    nlost++;
    return true;
  }
  void sum(double *fi) { row_sum<false, false>(fi); }    // the row has shifted
  void finish(double *fi)
  {
    double *fbroken = p.alpha_state->fbroken[i];
    if (!replay) {
      for (int c = 0; c < 3; c++) fbroken[c] = fb[c];
      p.lps_state->lost[i] = nlost;
    }
    for (int c = 0; c < 3; c++) fi[c] += fbroken[c];
    if (EVFLAG) {
      tally[0] += LPS::dilatation_energy(mod.bulk, theta_i);
      acc[0] += tally[0];
      if (p.eflag_atom) p.eatom[i] += tally[0];
      for (int c = 0; c < 6; c++) {
        acc[1 + c] += tally[1 + c];
        if (p.vflag_atom) p.vatom[i][c] += tally[1 + c];
      }
    }
  }
};

template <int EVFLAG> void PairBBPDLPS::eval_lps()
{
  const int nlocal = atom->nlocal;
  if (atom->nmax > nmax_lps) {
    nmax_lps = atom->nmax;
    memory->sfree(atom_states);
    atom_states = static_cast<LPS::AtomState *>(
        memory->smalloc(sizeof(LPS::AtomState) * nmax_lps, "pair:atom_states"));
  }
  const int nends = nlocal > 0 ? bonds->bond_start[nlocal - 1] + bonds->nbond[nlocal - 1] : 0;
  if (nends > nmax_length) {
    nmax_length = nends + nends / 8;    // headroom: migration changes the count a little
    memory->destroy(bond_length);
    memory->create(bond_length, nmax_length, "pair:bond_length");
  }
  if (nlocal > nmax_smin) {
    nmax_smin = atom->nmax;
    memory->destroy(smin_new);
    memory->create(smin_new, nmax_smin, "pair:smin_new");
  }
  // a second evaluation of the last step (setup of a new run, read_restart): no breaking, no
  // new smallest stretches, the bonds that broke then act again, and an atom that lost bonds
  // keeps the dilatation they counted in
  const bool replay = update->setupflag && update->ntimestep == alpha_state->last_step;
  if (!lps_state->ready) {
    sum_weighted_volumes();
    lps_state->ready = 1;
  }
  const double *m = lps_state->weighted_volume;
  double *theta = lps_state->dilatation, *lost = lps_state->lost;

  // 1. the dilatations, over the bonds intact at the start of the step, then to the ghosts
#if defined(_OPENMP)
#pragma omp parallel for num_threads(comm->nthreads) if (comm->nthreads > 1) schedule(static, 512)
#endif
  for (int i = 0; i < nlocal; i++) {
    const double th = dilatation_of(i, bond_length + bonds->bond_start[i]);
    if (!(replay && lost[i] > 0.0)) theta[i] = th;
    atom_states[i] = LPS::atom_state(theta[i], m[i]);
  }
  comm->forward_comm(this);

  // 2. the bonds: forces, and breaking (peri/lps: a bond acts in the step it breaks)
  const bool canonical = bonds->raw_positions();    // periodic: both ends decide alike
  // one s00 and alpha for every type pair: no per-bond lookups
  bool multi = false;
  const double s00_one = critical_stretch[1][1], alpha_one = alpha[1][1];
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = 1; j <= atom->ntypes; j++)
      if (critical_stretch[i][j] != s00_one || alpha[i][j] != alpha_one) multi = true;
  eval_rows<EVFLAG>([&](int i, double *acc, BBPD::CoefCache *cache) BBPD_ROW_BODY {
    return Row<EVFLAG>(*this, i, acc, cache, replay, canonical, multi, s00_one, alpha_one);
  });
  // the new smin takes effect at the next step, once sent to the ghosts
  double *smin = atom->s0;    // smallest bond stretch at the previous step, ghosts included
  for (int i = 0; i < nlocal; i++) smin[i] = smin_new[i];
  alpha_state->last_step = update->ntimestep;
}

template void PairBBPDLPS::eval_lps<0>();
template void PairBBPDLPS::eval_lps<1>();

/* ---------------------------------------------------------------------- */

double PairBBPDLPS::youngs_modulus(int itype) const
{
  const double K = bulk[itype][itype], G = shear[itype][itype];
  return 9.0 * K * G / (3.0 * K + G);
}

double PairBBPDLPS::poisson_ratio(int itype) const
{
  const double K = bulk[itype][itype], G = shear[itype][itype];
  return (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
}

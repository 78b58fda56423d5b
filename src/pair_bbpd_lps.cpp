// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: pair style bbpd/lps, the linear peridynamic solid of LAMMPS's peri/lps
   (pair_bbpd_lps.h): its coefficients, the dilatation pass and its ghost exchange, the
   bond loop of the LPS force state with the Silling-Askari breaking of peri/lps, and
   peri/lps's short-range forces (pair_bbpd_pmb.cpp). The kernel styles bbpd/lps/KERNEL are
   this class with Coefficients::KERNEL: their coefficients are in pair_bbpd_lps_kernel.cpp.
------------------------------------------------------------------------- */

#include "pair_bbpd_lps.h"
#include "pair_bbpd_lps_row.h"
#include "pair_bbpd_rows.h"

#include "bbpd_eps.h"
#include "bbpd_history_blocks.h"
#include "bbpd_lps_kernel.h"
#include "bbpd_ves.h"
#include "bbpd_lps_lanes.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_bbpd_alpha.h"
#include "fix_bbpd_bonds.h"
#include "fix_bbpd_history.h"
#include "fix_bbpd_lps.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

using namespace LAMMPS_NS;
namespace LPS = BBPD::LPS;

static constexpr const char *LPS_FIX_ID = "BBPD_LPS";
static constexpr const char *HISTORY_FIX_ID = "BBPD_HISTORY";
// peri/lps tallies half of atom i's deviatoric energy density at i (its ev_tally(i, i, ...,
// 0.5 * evdwl)): bbpd/lps does the same, to give its energies
static constexpr double PERI_LPS_DEVIATORIC_SHARE = 0.5;
// the kernel styles: atom i tallies its whole strain energy density W_i, so that pe/atom is
// the energy density of the LPS
static constexpr double WHOLE_DEVIATORIC_ENERGY = 1.0;
// forward communication: theta / m and 1 / m of every ghost atom
static constexpr int LPS_FORWARD_VALUES = 2;
// pair_coeff I J K G delta s00 alpha: the arguments before a family's own
static constexpr int PERI_COEFFS = 7;

/* ---------------------------------------------------------------------- */

// the style name and the peri/* style of a family
static const char *style_of(PairBBPDLPS::Family f)
{
  return f == PairBBPDLPS::Family::VES ? "bbpd/ves"
      : f == PairBBPDLPS::Family::EPS  ? "bbpd/eps"
                                       : "bbpd/lps";
}
static const char *peri_style_of(PairBBPDLPS::Family f)
{
  return f == PairBBPDLPS::Family::VES ? "peri/ves"
      : f == PairBBPDLPS::Family::EPS  ? "peri/eps"
                                       : "peri/lps";
}

PairBBPDLPS::PairBBPDLPS(LAMMPS *lmp, Family f) :
    PairBBPDLPS(lmp, f, Coefficients::PERI, BBPD::kernel_info<BBPD::ConstantKernel>(), style_of(f))
{
}

PairBBPDLPS::PairBBPDLPS(LAMMPS *lmp, BBPD::KernelInfo k, Family f) :
    PairBBPDLPS(lmp, f, Coefficients::KERNEL, k, std::string(style_of(f)) + "/" + k.name)
{
}

PairBBPDLPS::PairBBPDLPS(LAMMPS *lmp, Family f, Coefficients c, BBPD::KernelInfo k,
                         const std::string &style_name) :
    PairBBPD(lmp, k, style_name.c_str(), Rules{true, true, true, f != Family::LPS}), lattice_constant(0.0), bulk(nullptr), shear(nullptr),
    dimension(LPS::DILATATION_FACTOR),
    deviatoric_share(c == Coefficients::KERNEL ? WHOLE_DEVIATORIC_ENERGY : PERI_LPS_DEVIATORIC_SHARE),
    lps_state(nullptr), nmax_lps(0), atom_states(nullptr),
    family(f), coefficients(c), relax_share(nullptr),
    relax_time(nullptr), yield_stress(nullptr), history(nullptr)
{
  comm_forward = LPS_FORWARD_VALUES;
}

PairBBPDLPS::~PairBBPDLPS()
{
  if (copymode) return;
  memory->destroy(bulk);
  memory->destroy(shear);
  memory->sfree(atom_states);
  memory->destroy(relax_share);
  memory->destroy(relax_time);
  memory->destroy(yield_stress);
  release_fix(lps_state, LPS_FIX_ID);
  release_fix(history, HISTORY_FIX_ID);
  silling_askari.destroy(memory);
  release_fix(silling_askari.fix, SillingAskariState::FIX_ID);
}

void PairBBPDLPS::allocate_moduli()
{
  if (bulk) return;
  const int n = atom->ntypes + 1;
  memory->create(bulk, n, n, "pair:bulk");
  memory->create(shear, n, n, "pair:shear");
  memory->create(relax_share, n, n, "pair:relax_share");
  memory->create(relax_time, n, n, "pair:relax_time");
  memory->create(yield_stress, n, n, "pair:yield_stress");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++)
      bulk[i][j] = shear[i][j] = relax_share[i][j] = relax_time[i][j] = yield_stress[i][j] = 0.0;
}

/* pair_style bbpd/lps 3d [keywords of bbpd/pmb]: peri/lps is the 3D solid */
void PairBBPDLPS::settings(int narg, char **arg)
{
  if (coefficients == Coefficients::KERNEL) return kernel_settings(narg, arg);
  const int imodel = (narg > 0 && strcmp(arg[0], "model") == 0) ? 1 : 0;
  if (imodel < narg && strcmp(arg[imodel], "3d") != 0)
    error->all(FLERR, "Pair style {}: model '{}' is not available: {} is the 3D "
               "linear peridynamic solid, write 'pair_style {} 3d'", style_of(family), arg[imodel],
               peri_style_of(family), style_of(family));
  PairBBPD::settings(narg, arg);
  forbid_contact();
}

/* ----------------------------------------------------------------------
   pair_coeff I J K G delta s00 alpha (peri/lps's five numbers), then lambda tau (peri/ves)
   or the yield stress (peri/eps)
------------------------------------------------------------------------- */

int PairBBPDLPS::family_args() const
{
  return family == Family::VES ? 2 : family == Family::EPS ? 1 : 0;
}

const char *PairBBPDLPS::family_coeffs() const
{
  if (family == Family::VES)
    return "'I J K G delta s00 alpha lambda tau' (bulk and shear modulus, horizon, critical "
           "stretch, Silling-Askari alpha, relaxing share of G, relaxation time: the numbers of "
           "pair_coeff peri/ves)";
  if (family == Family::EPS)
    return "'I J K G delta s00 alpha Y' (bulk and shear modulus, horizon, critical stretch, "
           "Silling-Askari alpha, yield stress: the numbers of pair_coeff peri/eps)";
  return "'I J K G delta s00 alpha' (bulk and "
         "shear modulus, horizon, critical stretch, Silling-Askari alpha: the numbers of "
         "pair_coeff peri/lps)";
}

/* the family's own numbers (own[0] on: after alpha, or after delta for the kernel styles) */
void PairBBPDLPS::check_family_coeffs(char **own)
{
  if (family == Family::VES) {
    const double lambda = utils::numeric(FLERR, own[0], false, lmp);
    const double tau = utils::numeric(FLERR, own[1], false, lmp);
    if (!(lambda >= 0.0 && lambda <= 1.0))
      error->all(FLERR, "Pair coeff for {}: lambda (the relaxing share of the shear "
                 "modulus) must be in [0, 1], got {}", style, lambda);
    if (!(tau > 0.0) || !std::isfinite(tau))
      error->all(FLERR, "Pair coeff for {}: the relaxation time tau must be > 0 and "
                 "finite, got {}", style, tau);
  } else if (family == Family::EPS) {
    const double y = utils::numeric(FLERR, own[0], false, lmp);
    if (!(y > 0.0) || !std::isfinite(y))
      error->all(FLERR, "Pair coeff for {}: the yield stress must be > 0 and finite, "
                 "got {}", style, y);
  }
}

void PairBBPDLPS::set_family_coeffs(int i, int j, char **own)
{
  if (family == Family::VES) {
    relax_share[i][j] = relax_share[j][i] = utils::numeric(FLERR, own[0], false, lmp);
    relax_time[i][j] = relax_time[j][i] = utils::numeric(FLERR, own[1], false, lmp);
  } else if (family == Family::EPS) {
    yield_stress[i][j] = yield_stress[j][i] = utils::numeric(FLERR, own[0], false, lmp);
  }
}

/* the family's numbers in the report's type pair line */
std::string PairBBPDLPS::family_report(int i, int j) const
{
  return family == Family::VES
      ? fmt::format("  lambda = {:.6g}  tau = {:.6g}", relax_share[i][j], relax_time[i][j])
      : family == Family::EPS ? fmt::format("  yield stress = {:.8g}", yield_stress[i][j]) : "";
}

void PairBBPDLPS::coeff(int narg, char **arg)
{
  if (coefficients == Coefficients::KERNEL) return kernel_coeff(narg, arg);
  if (!allocated) allocate();
  allocate_moduli();
  if (narg != PERI_COEFFS + family_args())
    error->all(FLERR, "Pair coeff for {}: expected {}, got {} arguments", style_of(family),
               family_coeffs(), narg);
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double K = utils::numeric(FLERR, arg[2], false, lmp);
  const double G = utils::numeric(FLERR, arg[3], false, lmp);
  const double delta = utils::numeric(FLERR, arg[4], false, lmp);
  const double s00 = utils::numeric(FLERR, arg[5], false, lmp);
  const double a = utils::numeric(FLERR, arg[6], false, lmp);
  if (!(K > 0.0)) error->all(FLERR, "Pair coeff for {}: the bulk modulus K must be > 0", style_of(family));
  if (!(G > 0.0)) error->all(FLERR, "Pair coeff for {}: the shear modulus G must be > 0", style_of(family));
  if (!(delta > 0.0)) error->all(FLERR, "Pair coeff for {}: the horizon delta must be > 0", style_of(family));
  if (!(s00 > 0.0)) error->all(FLERR, "Pair coeff for {}: s00 must be > 0", style_of(family));
  if (!(a >= 0.0) || !std::isfinite(a))
    error->all(FLERR, "Pair coeff for {}: alpha must be >= 0", style_of(family));
  check_family_coeffs(arg + PERI_COEFFS);

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
      set_family_coeffs(i, j, arg + PERI_COEFFS);
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
        if (family == Family::VES) {
          fwrite(&relax_share[i][j], sizeof(double), 1, fp);
          fwrite(&relax_time[i][j], sizeof(double), 1, fp);
        } else if (family == Family::EPS) {
          fwrite(&yield_stress[i][j], sizeof(double), 1, fp);
        }
      }
}

void PairBBPDLPS::read_restart(FILE *fp)
{
  PairBBPD::read_restart(fp);
  allocate_moduli();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (!setflag[i][j]) continue;
      const int nv = 2 + family_args();
      double v[4] = {0.0, 0.0, 0.0, 0.0};
      if (comm->me == 0) utils::sfread(FLERR, v, sizeof(double), nv, fp, nullptr, error);
      MPI_Bcast(v, nv, MPI_DOUBLE, 0, world);
      bulk[i][j] = bulk[j][i] = v[0];
      shear[i][j] = shear[j][i] = v[1];
      if (family == Family::VES) {
        relax_share[i][j] = relax_share[j][i] = v[2];
        relax_time[i][j] = relax_time[j][i] = v[3];
      } else if (family == Family::EPS) {
        yield_stress[i][j] = yield_stress[j][i] = v[2];
      }
    }
}

/* part of init_style: peri/pmb's rules (lattice constant, Silling-Askari state), the LPS
   coefficient of the bond storage, and the LPS state */
void PairBBPDLPS::init_rules()
{
  silling_askari.attach(
      static_cast<FixBBPDAlpha *>(own_fix(SillingAskariState::FIX_ID, "bbpd/alpha")), atom,
      bonds->families_built());
  lattice_constant = peri_lattice_constant();
  // omega V_j ramp in the bond storage; the kernel styles: omega = W(|xi| / delta)
  if (coefficients == Coefficients::KERNEL)
    law.weighting = BBPD::LpsKernelWeighting{{lattice_constant}};
  else
    law.weighting = BBPD::LpsWeighting{{lattice_constant}};
  dimension = LPS::lps_dimension(model);    // 3 for bbpd/lps (model 3d)
  lps_state = static_cast<FixBBPDLPS *>(own_fix(LPS_FIX_ID, "bbpd/lps"));
  if (family == Family::LPS) return;
  check_history_solver();
  const auto w = history_widths();
  history = static_cast<FixBBPDHistory *>(
      own_fix(HISTORY_FIX_ID, "bbpd/history", fmt::format("{} {}", w[0], w[1])));
  if (history->atom_width() != w[0] || history->bond_width() != w[1])
    error->all(FLERR, "Pair style {}: fix {} holds {} doubles of history per atom and {} per bond "
               "end, this model needs {} and {}: unfix it or use the model it was made for",
               style, HISTORY_FIX_ID, history->atom_width(), history->bond_width(), w[0], w[1]);
  // the rows' size for the atoms that migrate before the first step (rows read from a restart
  // file are as long as they were written)
  if (bonds->families_built()) fit_history();
}

/* The viscous and plastic states advance once per time step (peri/ves, peri/eps). A minimizer's
   iterations and fix bbpd/relax's fictitious steps are no time steps: they would advance the
   history along a path that is not the body's, so both are refused rather than run. */
void PairBBPDLPS::check_history_solver() const
{
  const char *state = family == Family::VES ? "viscous" : "plastic";
  if (update->whichflag == BBPD::BondHold::MINIMIZE)
    error->all(FLERR, "pair_style {} cannot be used with minimize: its {} state advances once per "
               "time step and a minimizer's iterations are not time steps; load the body with "
               "'run' instead", style, state);
  if (!modify->get_fix_by_style("^bbpd/relax$").empty())
    error->all(FLERR, "pair_style {} cannot be used with fix bbpd/relax: its {} state advances once "
               "per time step and the relaxation's fictitious steps are not time steps; load the "
               "body with 'run' and fix nve instead", style, state);
}

double PairBBPDLPS::short_range_stiffness(int itype, int jtype) const
{
  // peri/lps takes the bulk modulus of atom i's type and the horizon of the pair
  return LPS::short_range_stiffness(bulk[itype][itype], horizon[itype][jtype]);
}

/* the stable time step estimate: the bond as a PMB bond of the same bulk modulus */
double PairBBPDLPS::bond_stiffness(int i, int k) const
{
  if (coefficients == Coefficients::KERNEL) return kernel_bond_stiffness(i, k);
  const int j = bonds->partner_of(i, k);
  return micromodulus[atom->type[i]][atom->type[j]] * bonds->coef_of(i, k, bonds->xi0_of(i, k));
}

std::string PairBBPDLPS::report_type_pair(int i, int j) const
{
  if (coefficients == Coefficients::KERNEL) return kernel_report_type_pair(i, j);
  return fmt::format("  types {} {}: {}: K = {:.8g}  G = {:.8g}  horizon = {:.6g}  "
                     "s00 = {:.8g}  alpha = {:.6g}{}\n", i, j, peri_style_of(family), bulk[i][j],
                     shear[i][j], horizon[i][j], critical_stretch[i][j], alpha[i][j],
                     family_report(i, j));
}

std::string PairBBPDLPS::report_rules() const
{
  if (coefficients == Coefficients::KERNEL) return kernel_report_rules();
  return peri_rules_report(lattice_constant) +
      fmt::format("  {} state: influence function 1/|xi|, weighted volume m fixed at the first "
                  "evaluation, dilatation theta every step (sent to the ghost atoms); stable time "
                  "step estimated as for a PMB bond of the same bulk modulus, c = 18 K / (pi "
                  "delta^4)\n", peri_style_of(family)) + history_report();
}

/* the report's line on the family's history (none for the LPS) */
std::string PairBBPDLPS::history_report() const
{
  const std::string name = coefficients == Coefficients::KERNEL ? style : peri_style_of(family);
  if (family == Family::VES)
    return fmt::format("  {} history: per bond end the deviatoric extension and back extension "
                       "of the last step (relaxation over the time step, exp(-dt/tau))\n",
                       name);
  if (family == Family::EPS)
    return fmt::format("  {} history: per bond end the plastic deviatoric extension, per atom "
                       "lambda; plastic steps return the deviatoric state to the yield "
                       "surface\n", name);
  return "";
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
  return PairBBPD::extract(name, dim);
}

double PairBBPDLPS::memory_usage()
{
  const int n = atom->ntypes + 1;
  return PairBBPD::memory_usage() + 2.0 * n * n * sizeof(double) +
      (double) LPS_FORWARD_VALUES * nmax_lps * sizeof(double) + bond_slots.bytes();
}

/* the per-atom state of the LPS (weighted volumes, dilatations) and of the families' history
   (per atom and per bond end, and the bond ends' slots), held by fixes this style owns; the
   history as the first step sizes it (the setup report comes before) */
double PairBBPDLPS::state_memory()
{
  double bytes = lps_state ? lps_state->memory_usage() : 0.0;
  if (history && bonds) {
    bytes += (bonds->families_built() ? history->bytes_when_fit(bonds->npartner)
                                      : history->memory_usage()) +
        slot_bytes_when_found() - bond_slots.bytes();
  }
  return bytes;
}

/* ----------------------------------------------------------------------
   the step: dilatations, bonds, short-range forces
------------------------------------------------------------------------- */

void PairBBPDLPS::eval_bonds()
{
  if (family == Family::VES) {
    if (evflag) eval_history<1, BBPD::VES::Family>();
    else eval_history<0, BBPD::VES::Family>();
  } else if (family == Family::EPS) {
    if (evflag) eval_history<1, BBPD::EPS::Family>();
    else eval_history<0, BBPD::EPS::Family>();
  } else {
    with_row_tally([&](auto ev) { eval_lps<decltype(ev)::value>(); });
  }
  compute_short_range(lattice_constant);
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

/* theta_i over the intact bonds of local atom i (bbpd_lps_lanes.h, on the pair style's path) */
double PairBBPDLPS::dilatation_of(int i)
{
  const double *xx = atom->x[0];
  const int n = bonds->nbond[i];
  const double sum = bonds->visit_row(i, *thread_coef_cache(), [&](const auto *bj, const auto &vals) {
    return BBPD::on_path(simd_path, [&](auto path) {
      return decltype(path)::lps_dilatation(xx, i, bj, vals, n);
    }, [&] { return LPS::dilatation_sum_portable(xx, i, bj, vals, n); });
  });
  return LPS::dilatation(sum, lps_state->weighted_volume[i], dimension);
}

/* seconds for the two passes of rows first..last-1 on path p (results discarded): the auto
   path's timing. The states are not there yet at the first setup: the force pass reads stand-in
   states of the same layout (no dilatation, unit 1 / m), which cost what the real ones do. The
   passes run as a step runs them, the dilatation of every row and then the forces, and a
   family's force pass rolls a scratch history row of each row: timed with both passes of a row
   at once (its partners still in L1) and one small history for every row, the AVX-512 path of
   the state-based rows took 0.83-1.13 of the AVX2 path's time on the bpm/peri deck (AMD EPYC
   Zen 4, 9 setups) and was chosen in 2 of them, while its whole step was slower
   (doc/performance.md); timed as the step runs, 1.03-1.14 in 18 setups. */
double PairBBPDLPS::time_path(BBPD::SimdPath p, int first, int last)
{
  const BBPD::SimdPath kept = simd_path;
  simd_path = p;
  const std::vector<LPS::AtomState> states(atom->nlocal + atom->nghost, LPS::AtomState{0.0, 1.0});
  const LPS::Moduli mod = moduli_of_type(1);
  const LPS::RowCoefficients c{mod.dilatational, mod.deviatoric, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const double *xx = atom->x[0];
  BBPD::CoefCache *cache = thread_coef_cache();
  double sum = 0.0;
  // the families' rows each read and write a history row of their own, as in a step
  size_t hist_len = 0;
  int widest = 0;
  for (int i = first; i < last && family != Family::LPS; i++) {
    hist_len += BBPD::history_length(PROBE_BOND_HISTORY, bonds->nbond[i]);
    widest = std::max(widest, bonds->nbond[i]);
  }
  probe_history.assign(hist_len, 0.0);
  probe_slot.resize(widest);
  for (int k = 0; k < widest; k++) probe_slot[k] = k;
  double *hist = probe_history.data();
  const auto t0 = std::chrono::steady_clock::now();
  // the two passes one after the other over the rows, as a step makes them
  for (int i = first; i < last; i++) sum += dilatation_of(i);
  for (int i = first; i < last; i++) {
    if (family != Family::LPS) {    // the family's own force rows (their history gathers)
      sum += history_row_probe(i, states.data(), cache, hist);
      hist += BBPD::history_length(PROBE_BOND_HISTORY, bonds->nbond[i]);
      continue;
    }
    const int n = bonds->nbond[i];
    BBPD::LPS::ForceLanes lanes;
    double snew;
    bonds->visit_row(i, *cache, [&](const auto *bj, const auto &vals) {
      return BBPD::on_path(simd_path, [&](auto path) {
        return decltype(path)::template lps_force<0, 0>(xx, i, bj, vals, n, states.data(), c,
                                                        nullptr, &snew, lanes);
      }, [&] {
        return LPS::force_row_portable<0, 0>(xx, i, bj, vals, n, states.data(), c,
                                             [](int) { return 0.0; }, &snew, lanes);
      });
    });
    sum += lanes.fx[0];
  }
  const auto t1 = std::chrono::steady_clock::now();
  simd_path = kept;
  timing_sink = sum;    // kept, so that no loop is optimised away
  std::vector<double>().swap(probe_history);
  return std::chrono::duration<double>(t1 - t0).count();
}

/* the state of a step before its bonds: per-atom arrays grown, the weighted volumes at the
   first evaluation, the dilatations of the local atoms and their exchange with the ghosts.
   Returns whether this is a second evaluation of the last step (setup of a new run,
   read_restart): then no breaking, no new smallest stretches, the bonds that broke then act
   again, and an atom that lost bonds keeps the dilatation they counted in */
bool PairBBPDLPS::begin_state()
{
  const int nlocal = atom->nlocal;
  if (atom->nmax > nmax_lps) {
    nmax_lps = atom->nmax;
    memory->sfree(atom_states);
    atom_states = static_cast<LPS::AtomState *>(
        memory->smalloc(sizeof(LPS::AtomState) * nmax_lps, "pair:atom_states"));
  }
  const bool replay = silling_askari.begin_step(memory, atom, update);
  if (!lps_state->ready) {
    sum_weighted_volumes();
    lps_state->ready = 1;
  }
  const double *m = lps_state->weighted_volume;
  double *theta = lps_state->dilatation, *lost = lps_state->lost;

  // the dilatations, over the bonds intact at the start of the step, then to the ghosts
#if defined(_OPENMP)
#pragma omp parallel for num_threads(comm->nthreads) if (comm->nthreads > 1) schedule(static, 512)
#endif
  for (int i = 0; i < nlocal; i++) {
    const double th = dilatation_of(i);
    if (!(replay && lost[i] > 0.0)) theta[i] = th;
    atom_states[i] = LPS::atom_state(theta[i], m[i]);
  }
  comm->forward_comm(this);
  // the largest smallest stretch of the atoms a row can reach, ghosts included (the rows'
  // critical stretch floors)
  smin_cap = BBPD::largest_of(atom->s0, atom->nlocal + atom->nghost);
  return replay;
}

/* peri/lps's s00 and alpha per type pair */
BBPD::SillingAskariCoefficients PairBBPDLPS::breaking_rule() const
{
  return BBPD::SillingAskariCoefficients::of(critical_stretch, alpha, atom->ntypes);
}

/* the new smin takes effect at the next step, once sent to the ghosts */
void PairBBPDLPS::end_state()
{
  silling_askari.end_step(atom, update);
}

template <int EVFLAG> void PairBBPDLPS::eval_lps()
{
  // 1. the dilatations
  const bool replay = begin_state();
  // 2. the bonds: forces, and breaking (peri/lps: a bond acts in the step it breaks)
  const bool canonical = bonds->raw_positions();    // periodic: both ends decide alike
  const BBPD::SillingAskariCoefficients rule = breaking_rule();
  const double margin = stretch_margin();
  eval_rows<EVFLAG>([&](int i, double *acc, BBPD::CoefCache *cache) BBPD_ROW_BODY {
    return Row<EVFLAG>(*this, i, acc, cache, replay, canonical, rule, margin);
  });
  add_replayed_virial(replay, EVFLAG, silling_askari);
  end_state();
}

template void PairBBPDLPS::eval_lps<0>();
template void PairBBPDLPS::eval_lps<1>();
template void PairBBPDLPS::eval_lps<2>();

/* ---------------------------------------------------------------------- */

double PairBBPDLPS::youngs_modulus(int itype) const
{
  if (coefficients == Coefficients::KERNEL) return youngs[itype][itype];
  const double K = bulk[itype][itype], G = shear[itype][itype];
  return 9.0 * K * G / (3.0 * K + G);
}

double PairBBPDLPS::poisson_ratio(int itype) const
{
  if (coefficients == Coefficients::KERNEL)
    return youngs[itype][itype] / (2.0 * shear[itype][itype]) - 1.0;    // G = E / (2 (1 + nu))
  const double K = bulk[itype][itype], G = shear[itype][itype];
  return (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
}

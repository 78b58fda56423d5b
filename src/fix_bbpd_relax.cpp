// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: fix bbpd/relax, adaptive dynamic relaxation with breaking
   between converged states (see fix_bbpd_relax.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_relax.h"
#include "bbpd_exact_sum.h"
#include "fix_bbpd_bonds.h"
#include "pair_bbpd.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "output.h"
#include "platform.h"
#include "timer.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// c dt must stay below 2, or (2 - c dt) would reverse the velocity: the adaptive damping is
// capped just below (a Rayleigh quotient above (2/dt)^2 means the body is stiffer than lambda
// accounts for, which the Gershgorin bound excludes up to round-off)
static constexpr double MAX_DAMPING_DT = 1.9;
static constexpr int NSUMS = 3;    // exact sums of one reduction

namespace {

/* lambda_i >= dt^2/4 sum_j |K_ij| (Kilic & Madenci 2010, eq. 19: Gershgorin's bound on the
   highest frequency of the stiffness K, so that the central difference is stable). A bond of
   stiffness k along the unit vector n adds k n n^T to the diagonal block of each end and -k n n^T
   to the off-diagonal one; the row of component x sums 2 k |n_x| (|n_x| + |n_y| + |n_z|), at most
   2 k (1 + sqrt(d)) / 2 in d dimensions (the largest eigenvalue of the symmetric part of e_x 1^T).
   So lambda_i = dt^2 (1 + sqrt(d)) / 4 sum_k k_ik. */
double density_factor(int dimension)
{
  return 0.25 * (1.0 + std::sqrt((double) dimension));
}

/* the ranks' exact partial sums, added as integers: the same bits on any rank count */
void global_sums(BBPD::ExactSum *sums, double *values, MPI_Comm world)
{
  static_assert(sizeof(long long) == sizeof(int64_t), "limbs are sent as MPI_LONG_LONG");
  constexpr int N = BBPD::ExactSum::NLIMBS;
  long long local[NSUMS * N], all[NSUMS * N];
  for (int t = 0; t < NSUMS; t++) {
    sums[t].normalize();
    for (int k = 0; k < N; k++) local[t * N + k] = sums[t].limbs()[k];
  }
  MPI_Allreduce(local, all, NSUMS * N, MPI_LONG_LONG, MPI_SUM, world);
  for (int t = 0; t < NSUMS; t++) {
    for (int k = 0; k < N; k++) sums[t].limbs()[k] = all[t * N + k];
    values[t] = sums[t].value();
  }
}

}    // namespace

FixBBPDRelax::FixBBPDRelax(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), tol(0.0), state(nullptr), pair(nullptr), bonds(nullptr), phase(DONE),
    reference(0.0), residual(0.0), broken_ends(0), load_step(0), iterations(0), nbroken(0),
    relaxations(0), wall_start(0.0), halted(false), converged(false)
{
  if (narg != 5 || strcmp(arg[3], "tol") != 0)
    error->all(FLERR, "Illegal fix bbpd/relax command: expected 'fix ID group bbpd/relax tol TOL'");
  tol = utils::numeric(FLERR, arg[4], false, lmp);
  if (!(tol > 0.0) || !std::isfinite(tol))
    error->all(FLERR, "Fix bbpd/relax: tol must be > 0 (the residual force that ends a "
               "relaxation, relative to the residual at the start of the load step), got {}", arg[4]);
  if (!atom->rmass_flag || !atom->vfrac_flag || !atom->peri_flag)
    error->all(FLERR, "Fix bbpd/relax needs atom_style peri (density, volume and reference "
               "positions x0)");
  time_integrate = 1;
  vector_flag = 1;
  size_vector = 7;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  maxexchange = NSTATE;
  FixBBPDRelax::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
}

FixBBPDRelax::~FixBBPDRelax()
{
  if (force && force->pair) hold_bonds(false);
  atom->delete_callback(id, Atom::GROW);
  memory->destroy(state);
}

int FixBBPDRelax::setmask()
{
  return INITIAL_INTEGRATE | END_OF_STEP;
}

/* the pair style's bonds held (while iterating) or free to break */
void FixBBPDRelax::hold_bonds(bool on)
{
  auto p = dynamic_cast<PairBBPD *>(force->pair_match("^bbpd/", 0));
  if (p) p->hold.by_fix = on;
}

void FixBBPDRelax::init()
{
  pair = dynamic_cast<PairBBPD *>(force->pair_match("^bbpd/", 0));
  bonds = dynamic_cast<FixBBPDBonds *>(modify->get_fix_by_id("BBPD_BONDS"));
  if (!pair || !bonds) error->all(FLERR, "Fix bbpd/relax requires a bbpd/* pair style");
  if (!utils::strmatch(update->integrate_style, "^verlet"))
    error->all(FLERR, "Fix bbpd/relax runs with run_style verlet only (run_style is {})",
               update->integrate_style);
  // from the setup's force evaluation on: a run's first state is not an equilibrium
  hold_bonds(true);
}

/* a run is a load step: it starts at rest, with a relaxation */
void FixBBPDRelax::setup(int)
{
  const int *mask = atom->mask;
  int bad = 0, anybad = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && !(atom->rmass[i] > 0.0)) bad = 1;
  MPI_Allreduce(&bad, &anybad, 1, MPI_INT, MPI_MAX, world);
  if (anybad)
    error->all(FLERR, "Fix bbpd/relax: atoms of group {} have density <= 0: set it with 'set "
               "... density' (the relaxation does not use it, the pair style and the energy "
               "account do)", group->names[igroup]);
  double **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit) v[i][0] = v[i][1] = v[i][2] = 0.0;
  // 'run 0' (e.g. the one that makes the bonds) evaluates forces only: no load step
  if (update->nsteps == 0) {
    phase = DONE;
    return;
  }
  phase = START;
  load_step++;
  iterations = nbroken = 0;
  relaxations = 0;
  residual = 0.0;
  converged = halted = false;
  wall_start = platform::walltime();
}

/* at the start of a relaxation: the fictitious densities from the bonds now, and the residual
   that tol is relative to (the reference) */
void FixBBPDRelax::start_relaxation()
{
  const int *mask = atom->mask;
  const double scale = density_factor(domain->dimension) * update->dt * update->dt;
  int bonded = 0, anybonded = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    double sum = 0.0;
    if (mask[i] & groupbit)
      for (int k = bonds->bond_start[i]; k < bonds->bond_start[i] + bonds->nbond[i]; k++)
        sum += pair->bond_stiffness(i, k);
    // an atom with no bonds (or none with stiffness) is not moved: it has no equilibrium
    state[i][LAMBDA] = sum > 0.0 ? scale * sum : 0.0;
    if (sum > 0.0) bonded = 1;
  }
  MPI_Allreduce(&bonded, &anybonded, 1, MPI_INT, MPI_MAX, world);
  if (!anybonded)
    error->all(FLERR, "Fix bbpd/relax: no atom of group {} has a bond with stiffness: the "
               "group must hold bonded atoms (bonds are made at the first run; check the "
               "group, the horizon and 'pair_coeff ... bonds')", group->names[igroup]);
  residual = residual_now();
  // the load increment's out-of-balance force; a load step that starts in equilibrium keeps
  // the last one, and so do the relaxations after bonds broke (the residual they start from
  // is that of the broken bonds, which can be below what round-off lets a relaxation reach)
  if (relaxations == 0 && residual > 0.0) reference = residual;
  if (reference == 0.0) reference = residual;
  relaxations++;
}

/* the residual: the norm of the forces (force density times volume) on the atoms that move */
double FixBBPDRelax::residual_now()
{
  const int *mask = atom->mask;
  double **f = atom->f;
  const int dim = domain->dimension;
  BBPD::ExactSum sums[NSUMS];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || state[i][LAMBDA] == 0.0) continue;
    for (int d = 0; d < dim; d++) {
      const double fd = f[i][d] * atom->vfrac[i];
      if (!std::isfinite(fd))
        error->one(FLERR, "Fix bbpd/relax: non-finite force on atom {} at step {}",
                   atom->tag[i], update->ntimestep);
      sums[0].add(fd * fd);
    }
  }
  double values[NSUMS];
  global_sums(sums, values, world);
  return std::sqrt(values[0]);
}

/* c = 2 sqrt(u^T K u / u^T u) with the local diagonal stiffness K of the last step,
   K_ii = -(a_i(n) - a_i(n-1)) / (dt v_i(n-1/2)), a = f / lambda (Kilic & Madenci 2010,
   eqs. 20-21); u is the displacement from the reference positions x0 */
double FixBBPDRelax::damping()
{
  const int *mask = atom->mask;
  double **x = atom->x, **v = atom->v, **f = atom->f, **x0 = atom->x0;
  const imageint *image = atom->image;
  const int dim = domain->dimension;
  const double dt = update->dt;
  BBPD::ExactSum sums[NSUMS];
  for (int i = 0; i < atom->nlocal; i++) {
    const double lambda = state[i][LAMBDA];
    if (!(mask[i] & groupbit) || lambda == 0.0) continue;
    double xu[3];
    domain->unmap(x[i], image[i], xu);
    for (int d = 0; d < dim; d++) {
      const double u = xu[d] - x0[i][d];
      sums[1].add(u * u);
      if (v[i][d] == 0.0) continue;
      const double k = -(f[i][d] / lambda - state[i][APREV + d]) / (dt * v[i][d]);
      sums[0].add(u * u * k);
    }
  }
  double values[NSUMS];
  global_sums(sums, values, world);
  if (!(values[0] > 0.0) || !(values[1] > 0.0)) return 0.0;
  return std::fmin(2.0 * std::sqrt(values[0] / values[1]), MAX_DAMPING_DT / dt);
}

/* one iteration: the damped central-difference step from the forces of the last one; at rest
   while bonds may break */
void FixBBPDRelax::initial_integrate(int)
{
  if (phase != START && phase != ITERATE) return;
  const bool first = phase == START;
  if (first) start_relaxation();
  const double dt = update->dt;
  const double c = first ? 0.0 : damping();
  const int *mask = atom->mask;
  double **x = atom->x, **v = atom->v, **f = atom->f;
  const int dim = domain->dimension;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double *s = state[i];
    if (s[LAMBDA] == 0.0) {
      v[i][0] = v[i][1] = v[i][2] = 0.0;
      continue;
    }
    for (int d = 0; d < dim; d++) {
      const double a = f[i][d] / s[LAMBDA];
      v[i][d] = first ? 0.5 * dt * a : ((2.0 - c * dt) * v[i][d] + 2.0 * dt * a) / (2.0 + c * dt);
      x[i][d] += dt * v[i][d];
      s[APREV + d] = a;
    }
  }
  phase = ITERATE;
}

/* after the forces of the step: converged? did bonds break? */
void FixBBPDRelax::end_of_step()
{
  if (phase == ITERATE) {
    iterations++;
    residual = residual_now();
    if (residual > tol * reference) return;
    // an equilibrium: the next force evaluation, at rest, lets the bonds past breaking break
    phase = BREAK;
    broken_ends = bonds->count_broken();
    double **v = atom->v;
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->mask[i] & groupbit) v[i][0] = v[i][1] = v[i][2] = 0.0;
    hold_bonds(false);
  } else if (phase == BREAK) {
    hold_bonds(true);
    const bigint now = (bonds->count_broken() - broken_ends) / 2;
    nbroken += now;
    residual = residual_now();
    if (now > 0) {
      phase = START;    // the same load, fewer bonds: relax again
    } else {
      // one more evaluation at rest, as the last step of the run, with thermo output and
      // every compute's energy (as a minimize ends): the load step's state, current for
      // thermo keywords and variables after the run
      phase = FINAL;
      const bigint next = update->ntimestep + 1;
      output->next_thermo = next;
      output->next = MIN(output->next, next);
      modify->addstep_compute_all(next);
    }
  } else if (phase == FINAL) {
    finish_load_step(true);
    timer->force_timeout();    // end the run, as fix halt does
    halted = true;
  }
}

void FixBBPDRelax::finish_load_step(bool done)
{
  phase = DONE;
  converged = done;
  const double wall = platform::walltime() - wall_start;
  const std::string mesg = fmt::format(
      "bbpd/relax: load step {} {} at step {}: {} iterations, {} relaxations, {} bonds broken, "
      "residual {:.6g} ({:.3g} of the reference, tol {:.3g}), {:.3g} s\n", load_step,
      done ? "converged" : "NOT converged", update->ntimestep, iterations, relaxations, nbroken,
      residual, reference > 0.0 ? residual / reference : 0.0, tol, wall);
  if (comm->me == 0) utils::logmesg(lmp, mesg);
  if (!done && comm->me == 0)
    error->warning(FLERR, "Fix bbpd/relax: load step {} did not converge in {} iterations: "
                   "run more steps", load_step, iterations);
}

void FixBBPDRelax::post_run()
{
  if (phase != DONE) finish_load_step(false);
  if (halted) timer->reset_timeout();
  halted = false;
  hold_bonds(false);
}

/* [1] load step [2] iterations [3] relaxations [4] bonds broken [5] residual [6] residual
   relative to the reference [7] 1 if the load step converged */
double FixBBPDRelax::compute_vector(int n)
{
  switch (n) {
    case 0: return (double) load_step;
    case 1: return (double) iterations;
    case 2: return (double) relaxations;
    case 3: return (double) nbroken;
    case 4: return residual;
    case 5: return reference > 0.0 ? residual / reference : 0.0;
    default: return converged ? 1.0 : 0.0;
  }
}

void FixBBPDRelax::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  const double list[2] = {(double) load_step, reference};
  const int size = sizeof(list);
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list, sizeof(double), 2, fp);
}

void FixBBPDRelax::restart(char *buf)
{
  const double *list = reinterpret_cast<double *>(buf);
  load_step = (bigint) list[0];
  reference = list[1];
}

double FixBBPDRelax::memory_usage()
{
  return (double) atom->nmax * NSTATE * sizeof(double);
}

void FixBBPDRelax::grow_arrays(int nmax)
{
  memory->grow(state, nmax, NSTATE, "bbpd/relax:state");
}

void FixBBPDRelax::copy_arrays(int i, int j, int)
{
  memcpy(state[j], state[i], NSTATE * sizeof(double));
}

int FixBBPDRelax::pack_exchange(int i, double *buf)
{
  for (int m = 0; m < NSTATE; m++) buf[m] = state[i][m];
  return NSTATE;
}

int FixBBPDRelax::unpack_exchange(int nlocal, double *buf)
{
  for (int m = 0; m < NSTATE; m++) state[nlocal][m] = buf[m];
  return NSTATE;
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the setup report of the bbpd pair styles (pair_bbpd.h): per type pair and
   global, with the bonds, their storage and the stable time step
------------------------------------------------------------------------- */

#include "pair_bbpd.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_bbpd_bonds.h"
#include "memory.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

using namespace LAMMPS_NS;

static constexpr double MBYTES = 1024.0 * 1024.0;    // as LAMMPS counts its "Mbytes"

/* ----------------------------------------------------------------------
   setup report, per type pair and global: armed by setup(), printed by the setup's force
   evaluation (after fix bbpd/notch has cut its bonds)
------------------------------------------------------------------------- */

/* armed at every setup; printed by the setup's force evaluation, after fix bbpd/notch has cut
   its bonds in setup_pre_force, so that the bounds and counts include the notches */
void PairBBPD::setup()
{
  report_due = 1;
}

void PairBBPD::report()
{
  const FixBBPDBonds *fb = bonds;
  // stable time step from the actual bonds: sum_j C_v V_j c/xi = sum of coef (eq. 26)
  // with contact on, one contact's stiffness is added (crack faces pressed together)
  double dtmin = std::numeric_limits<double>::infinity();
  int limp = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    double sum = 0.0;
    for (int k = fb->bond_start[i]; k < fb->bond_start[i] + fb->nbond[i]; k++)
      sum += bond_stiffness(i, k);
    if (fb->nbond[i] > 0 && sum <= 0.0) limp = 1;
    const int it = atom->type[i];
    if (short_range_forces())
      sum += CONTACT_STIFFNESS_FACTOR * micromodulus[it][it] * atom->vfrac[i] / horizon[it][it];
    if (sum > 0.0) dtmin = MIN(dtmin, BBPD::stable_timestep_paper(atom->rmass[i], sum));
  }
  int anylimp = 0;
  MPI_Allreduce(&limp, &anylimp, 1, MPI_INT, MPI_MAX, world);
  if (anylimp)
    error->all(FLERR, "Pair {}: atoms have bonds but no stiffness (the kernel vanishes at "
               "every partner, e.g. triangular with delta = spacing): increase the horizon",
               style);
  MPI_Allreduce(&dtmin, &dt_bound_paper, 1, MPI_DOUBLE, MPI_MIN, world);
  dt_bound = dt_bound_paper * std::sqrt(2.0);
  // compute pair sums pvector over the ranks: only rank 0 contributes
  pvector[0] = comm->me == 0 ? dt_bound : 0.0;
  pvector[1] = comm->me == 0 ? dt_bound_paper : 0.0;
  send_run_limits();

  int nmin = INT_MAX, nmax = 0;
  bigint nsum = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    nmin = MIN(nmin, fb->npartner[i]);
    nmax = MAX(nmax, fb->npartner[i]);
    nsum += fb->npartner[i];
  }
  int gmin, gmax;
  bigint gsum;
  MPI_Allreduce(&nmin, &gmin, 1, MPI_INT, MPI_MIN, world);
  MPI_Allreduce(&nmax, &gmax, 1, MPI_INT, MPI_MAX, world);
  MPI_Allreduce(&nsum, &gsum, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  const bigint nbroken = fb->count_broken();
  // distinct (reference length, coefficient) pairs the bonds point into, largest over the ranks
  int nclass = fb->bclass ? (int) fb->classes.size() : 0, gclass = 0;
  MPI_Allreduce(&nclass, &gclass, 1, MPI_INT, MPI_MAX, world);
  // ranks choose partner offsets or indices on their own: the largest storage over the ranks
  double bytes = fb->bytes_per_bond(), gbytes = 0.0;
  MPI_Allreduce(&bytes, &gbytes, 1, MPI_DOUBLE, MPI_MAX, world);
  // what the bonds fix, the pair style and the fixes of its state hold (their memory_usage, part
  // of LAMMPS's "Per MPI rank memory" line): the size of a big run per atom and per bond
  const double mine = bonds->memory_usage() + memory_usage() + state_memory();
  double mem_sum = 0.0, mem_max = 0.0;
  MPI_Allreduce(&mine, &mem_sum, 1, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&mine, &mem_max, 1, MPI_DOUBLE, MPI_MAX, world);

  if (comm->me == 0) {
    std::string mesg = fmt::format("BBPD pair style {} model {}{}:\n", style,
                                   BBPD::model_name(model),
                                   model == BBPD::Model::Solid3D ? ""
                                       : fmt::format(" ({} {})", model == BBPD::Model::Bar1D ? "area" : "thickness", geom));
    for (int i = 1; i <= atom->ntypes; i++)
      for (int j = i; j <= atom->ntypes; j++) mesg += report_type_pair(i, j);
    mesg += report_rules();
    mesg += fmt::format("  grid spacing for the volume correction = {:.6g}{}\n", spacing,
                        spacing_user ? " (given)" : " (from atom volumes)");
    mesg += fmt::format("  bonds per atom: min {} mean {:.6g} max {}; total bonds {} ({} broken)\n",
                        gmin, atom->natoms ? (double) gsum / atom->natoms : 0.0, gmax, gsum / 2,
                        nbroken / 2);
    mesg += fmt::format("  fracture: {}\n", fracture_any ? "on" : "off (elastic, no bond-failure checks)");
    mesg += contact ? fmt::format("  contact: on, distance {:.6g}\n", contact_factor * spacing)
                    : std::string("  contact: off (no neighbour list)\n");
    mesg += fmt::format("  bond loop: {} path ({})\n", BBPD::path_name(simd_path), simd_reason);
    mesg += fmt::format("  bond storage: {:.1f} bytes per bond ({:.1f} per bond end){}\n",
                        gbytes, 0.5 * gbytes,
                        gclass ? fmt::format("; table of {} distinct (reference length, "
                                             "coefficient) pairs", gclass) : std::string());
    mesg += fmt::format("  memory of the bonds and the pair style: {:.6g} Mbytes on the largest "
                        "rank, {:.6g} in all: {:.1f} bytes per atom, {:.1f} per bond\n",
                        mem_max / MBYTES, mem_sum / MBYTES,
                        atom->natoms ? mem_sum / atom->natoms : 0.0,
                        gsum ? mem_sum / (0.5 * gsum) : 0.0);
    mesg += fmt::format("  stable timestep: eq. 25 {:.6g}, velocity-Verlet limit {:.6g}; "
                        "timestep = {:.6g} ({:.3g} of the limit)\n",
                        dt_bound_paper, dt_bound, update->dt, update->dt / dt_bound);
    utils::logmesg(lmp, mesg);
  }
  if (update->dt > dt_safety * dt_bound && comm->me == 0)
    error->warning(FLERR, "Pair {}: timestep {:.6g} exceeds {} x the stable bound {:.6g}; "
                   "the run may blow up: reduce the timestep", style, update->dt, dt_safety,
                   dt_bound);
}

/* bond k of atom i in the stable time step: its coefficient (force density per elongation) */
double PairBBPD::bond_stiffness(int i, int k) const
{
  return bonds->coef_of(i, k, bonds->xi0_of(i, k));
}

/* the report's line for types i j */
std::string PairBBPD::report_type_pair(int i, int j) const
{
  if (bondless[i][j])
    return fmt::format("  types {} {}: no bonds (separate bodies); contact stiffness from "
                       "E = {:.6g}  horizon = {:.6g}  micromodulus c0 = {:.8g}{}\n", i, j,
                       youngs[i][j], horizon[i][j], micromodulus[i][j],
                       contact ? "" : " (contact is off: the bodies pass through each other)");
  return fmt::format("  types {} {}: E = {:.6g}  Gc = {:.6g}  horizon = {:.6g}  "
                     "micromodulus c0 = {:.8g}  critical_stretch s0 = {:.8g}{}\n",
                     i, j, youngs[i][j], fracture_energy[i][j], horizon[i][j],
                     micromodulus[i][j], critical_stretch[i][j],
                     s0_user[i][j] ? " (given)" : "");
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: compute bbpd/energy (see header)
------------------------------------------------------------------------- */

#include "compute_bbpd_energy.h"

#include "bbpd_exact_sum.h"
#include "fix_bbpd_bonds.h"
#include "fix_bbpd_work.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "pair.h"
#include "update.h"

#include <cstdint>

using namespace LAMMPS_NS;

ComputeBBPDEnergy::ComputeBBPDEnergy(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), work(nullptr), bonds(nullptr)
{
  if (narg != 3) error->all(FLERR, "Illegal compute bbpd/energy command: it takes no arguments");
  if (!atom->rmass_flag || !atom->vfrac_flag)
    error->all(FLERR, "Compute bbpd/energy needs atom_style peri (per-atom density and volume)");
  vector_flag = 1;
  size_vector = NTERMS + 1;
  extvector = 1;
  peatomflag = 1;    // LAMMPS tallies the pair style's per-atom energy on the steps it is invoked
  timeflag = 1;
  vector = new double[size_vector];
  // the work of term 4 is summed over every step, whether the compute is invoked or not
  work_id = std::string("BBPD_WORK_") + id;
  work = dynamic_cast<FixBBPDWork *>(
      modify->add_fix(fmt::format("{} {} bbpd/work", work_id, group->names[igroup])));
}

ComputeBBPDEnergy::~ComputeBBPDEnergy()
{
  if (modify->nfix && modify->get_fix_by_id(work_id)) modify->delete_fix(work_id);
  delete[] vector;
}

void ComputeBBPDEnergy::init()
{
  bonds = dynamic_cast<FixBBPDBonds *>(modify->get_fix_by_id("BBPD_BONDS"));
  if (!bonds || !force->pair_match("^bbpd/", 0))
    error->all(FLERR, "Compute bbpd/energy requires a bbpd/* pair style (it reads the pair "
               "style's energy and its broken bonds)");
  work = dynamic_cast<FixBBPDWork *>(modify->get_fix_by_id(work_id));
  if (!work) error->all(FLERR, "Compute bbpd/energy {}: its fix {} was deleted", id, work_id);
}

void ComputeBBPDEnergy::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (update->eflag_atom != invoked_vector)
    error->all(FLERR, "Compute bbpd/energy {}: the pair style's energy was not tallied at step "
               "{}; use the compute only on steps on which thermo output or a fix invokes it",
               id, update->ntimestep);
  const double *eatom = force->pair->eatom;
  const double *vfrac = atom->vfrac, *rmass = atom->rmass;
  double **v = atom->v;
  const int *mask = atom->mask;
  BBPD::ExactSum sums[NTERMS];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    // the pair style tallies every atom's energy on its own row: local atoms hold all of it
    sums[0].add(eatom[i] * vfrac[i]);
    sums[1].add(0.5 * rmass[i] * (v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]) * vfrac[i]);
    sums[2].add(bonds->ebroken[i]);
    sums[3].add(work->work(i));
  }
  // the ranks' exact partial sums, added as integers: the same bits on any rank count
  // (long long: an MPI type that LAMMPS's serial MPI stubs have too)
  static_assert(sizeof(long long) == sizeof(int64_t), "limbs are sent as MPI_LONG_LONG");
  constexpr int N = BBPD::ExactSum::NLIMBS;
  long long local[NTERMS * N], all[NTERMS * N];
  for (int t = 0; t < NTERMS; t++) {
    sums[t].normalize();
    for (int k = 0; k < N; k++) local[t * N + k] = sums[t].limbs()[k];
  }
  MPI_Allreduce(local, all, NTERMS * N, MPI_LONG_LONG, MPI_SUM, world);
  BBPD::ExactSum total;
  for (int t = 0; t < NTERMS; t++) {
    for (int k = 0; k < N; k++) sums[t].limbs()[k] = all[t * N + k];
    vector[t] = sums[t].value();
    // term 5 from the exact terms: no rounding of the four doubles in between
    if (t == NTERMS - 1) sums[t].negate();
    total.combine(sums[t]);
  }
  vector[NTERMS] = total.value();
}

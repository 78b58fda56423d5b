// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the per-step state of the Silling-Askari critical stretch
   (pair_bbpd_silling_askari_state.h)
------------------------------------------------------------------------- */

#include "pair_bbpd_silling_askari_state.h"
#include "bbpd_pmb_rules.h"

#include "atom.h"
#include "fix_bbpd_alpha.h"
#include "memory.h"
#include "update.h"

using namespace LAMMPS_NS;

void SillingAskariState::attach(FixBBPDAlpha *f, Atom *atom, bool families_built)
{
  fix = f;
  if (!families_built)
    for (int i = 0; i < atom->nlocal; i++) atom->s0[i] = BBPD::PMB::NO_BOND_STRETCH;
}

bool SillingAskariState::begin_step(Memory *memory, Atom *atom, Update *update)
{
  if (atom->nlocal > nmax) {
    nmax = atom->nmax;
    memory->destroy(smin_new);
    memory->create(smin_new, nmax, "pair:smin_new");
  }
  const bool replay = update->setupflag && update->ntimestep == fix->last_step;
  if (!replay) {
    for (double &v : broken_virial) v = 0.0;
    broken_virial_step = update->ntimestep;
  }
  return replay;
}

void SillingAskariState::book_broken_virial(const double *vir)
{
#if defined(_OPENMP)
#pragma omp critical(bbpd_broken_virial)
#endif
  for (int m = 0; m < 6; m++) broken_virial[m] += vir[m];
}

void SillingAskariState::add_broken_virial(double *virial, Update *update) const
{
  if (broken_virial_step != update->ntimestep) return;
  for (int m = 0; m < 6; m++) virial[m] += broken_virial[m];
}

void SillingAskariState::end_step(Atom *atom, Update *update)
{
  double *smin = atom->s0;    // smallest bond stretch at the previous step, ghosts included
  for (int i = 0; i < atom->nlocal; i++) smin[i] = smin_new[i];
  fix->last_step = update->ntimestep;
}

void SillingAskariState::destroy(Memory *memory)
{
  memory->destroy(smin_new);
  nmax = 0;
}

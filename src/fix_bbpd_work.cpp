// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the work done by everything but the pair style (see fix_bbpd_work.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_work.h"

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "update.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

FixBBPDWork::FixBBPDWork(LAMMPS *lmp, int narg, char **arg) :
    FixBBPDAtomState(lmp, narg, arg, "compute bbpd/energy", NSTATE, 1)
{
  if (!atom->rmass_flag || !atom->vfrac_flag)
    error->all(FLERR, "Compute bbpd/energy needs atom_style peri (per-atom density and volume)");
  // atoms created later start with no work done on them (create_attribute), from where they are
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

int FixBBPDWork::setmask()
{
  return POST_INTEGRATE | PRE_REVERSE | END_OF_STEP;
}

void FixBBPDWork::init()
{
  if (!utils::strmatch(update->integrate_style, "^verlet"))
    error->all(FLERR, "Compute bbpd/energy tracks the work of external loads with run_style "
               "verlet only (run_style is {})", update->integrate_style);
}

double FixBBPDWork::kinetic(int i) const
{
  const double *v = atom->v[i];
  return 0.5 * atom->rmass[i] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) * atom->vfrac[i];
}

void FixBBPDWork::start_steps()
{
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    state[i][KE] = kinetic(i);
    for (int m = 0; m < 3; m++) {
      state[i][DX + m] = 0.0;
      state[i][XOLD + m] = atom->x[i][m];
    }
  }
}

/* the pair force at the run's first evaluation; KE and positions once every fix has set up */
void FixBBPDWork::setup_pre_reverse(int, int)
{
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit)
      for (int m = 0; m < 3; m++) state[i][FP + m] = atom->f[i][m];
}

void FixBBPDWork::setup(int)
{
  start_steps();
}

/* the step's displacement, before LAMMPS maps atoms back into a periodic box */
void FixBBPDWork::post_integrate()
{
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    if (mask[i] & groupbit)
      for (int m = 0; m < 3; m++) state[i][DX + m] = atom->x[i][m] - state[i][XOLD + m];
}

/* the pair force at the new positions: the work of the pair force over the step */
void FixBBPDWork::pre_reverse(int, int)
{
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double *s = state[i];
    const double *f = atom->f[i];
    double wpair = 0.0;
    for (int m = 0; m < 3; m++) {
      wpair += 0.5 * (s[FP + m] + f[m]) * s[DX + m];
      s[FP + m] = f[m];
    }
    s[W] -= wpair * atom->vfrac[i];
  }
}

/* the kinetic energy once every fix has integrated the step */
void FixBBPDWork::end_of_step()
{
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    double *s = state[i];
    const double ke = kinetic(i);
    s[W] += ke - s[KE];
    s[KE] = ke;
    for (int m = 0; m < 3; m++) s[XOLD + m] = atom->x[i][m];
  }
}

void FixBBPDWork::set_arrays(int i)
{
  for (int m = 0; m < NSTATE; m++) state[i][m] = 0.0;
  if (atom->x && i < atom->nmax)
    for (int m = 0; m < 3; m++) state[i][XOLD + m] = atom->x[i][m];
}


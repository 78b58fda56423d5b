// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: state of the Silling-Askari bond loop (see fix_bbpd_alpha.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_alpha.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"

using namespace LAMMPS_NS;

FixBBPDAlpha::FixBBPDAlpha(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), last_step(-1), fbroken(nullptr)
{
  if (narg != 3) error->all(FLERR, "Fix bbpd/alpha takes no arguments (it is created by the pair style)");
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  FixBBPDAlpha::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixBBPDAlpha::~FixBBPDAlpha()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(fbroken);
}

double FixBBPDAlpha::memory_usage()
{
  return 3.0 * atom->nmax * sizeof(double);
}

void FixBBPDAlpha::grow_arrays(int nmax)
{
  memory->grow(fbroken, nmax, 3, "bbpd/alpha:fbroken");
}

void FixBBPDAlpha::copy_arrays(int i, int j, int)
{
  for (int m = 0; m < 3; m++) fbroken[j][m] = fbroken[i][m];
}

void FixBBPDAlpha::set_arrays(int i)
{
  fbroken[i][0] = fbroken[i][1] = fbroken[i][2] = 0.0;
}

int FixBBPDAlpha::pack_exchange(int i, double *buf)
{
  for (int m = 0; m < 3; m++) buf[m] = fbroken[i][m];
  return 3;
}

int FixBBPDAlpha::unpack_exchange(int nlocal, double *buf)
{
  for (int m = 0; m < 3; m++) fbroken[nlocal][m] = buf[m];
  return 3;
}

void FixBBPDAlpha::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    double step = (double) last_step;
    int size = sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(&step, sizeof(double), 1, fp);
  }
}

void FixBBPDAlpha::restart(char *buf)
{
  last_step = (bigint) ((double *) buf)[0];
}

int FixBBPDAlpha::pack_restart(int i, double *buf)
{
  buf[0] = 4;
  for (int m = 0; m < 3; m++) buf[1 + m] = fbroken[i][m];
  return 4;
}

void FixBBPDAlpha::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int k = 0; k < 3; k++) fbroken[nlocal][k] = extra[nlocal][m++];
}

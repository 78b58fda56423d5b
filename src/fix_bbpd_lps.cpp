// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the per-atom state of pair style bbpd/lps (see fix_bbpd_lps.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_lps.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "memory.h"

using namespace LAMMPS_NS;

FixBBPDLPS::FixBBPDLPS(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), ready(0), weighted_volume(nullptr), dilatation(nullptr), lost(nullptr)
{
  if (narg != 3) error->all(FLERR, "Fix bbpd/lps takes no arguments (it is created by the pair style)");
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  FixBBPDLPS::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixBBPDLPS::~FixBBPDLPS()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(weighted_volume);
  memory->destroy(dilatation);
  memory->destroy(lost);
}

double FixBBPDLPS::memory_usage()
{
  return (double) VALUES * atom->nmax * sizeof(double);
}

void FixBBPDLPS::grow_arrays(int nmax)
{
  memory->grow(weighted_volume, nmax, "bbpd/lps:weighted_volume");
  memory->grow(dilatation, nmax, "bbpd/lps:dilatation");
  memory->grow(lost, nmax, "bbpd/lps:lost");
}

void FixBBPDLPS::copy_arrays(int i, int j, int)
{
  weighted_volume[j] = weighted_volume[i];
  dilatation[j] = dilatation[i];
  lost[j] = lost[i];
}

void FixBBPDLPS::set_arrays(int i)
{
  weighted_volume[i] = dilatation[i] = lost[i] = 0.0;
}

int FixBBPDLPS::pack_exchange(int i, double *buf)
{
  buf[0] = weighted_volume[i];
  buf[1] = dilatation[i];
  buf[2] = lost[i];
  return VALUES;
}

int FixBBPDLPS::unpack_exchange(int nlocal, double *buf)
{
  weighted_volume[nlocal] = buf[0];
  dilatation[nlocal] = buf[1];
  lost[nlocal] = buf[2];
  return VALUES;
}

void FixBBPDLPS::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    double flag = ready;
    int size = sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(&flag, sizeof(double), 1, fp);
  }
}

void FixBBPDLPS::restart(char *buf)
{
  ready = static_cast<int>(((double *) buf)[0]);
}

int FixBBPDLPS::pack_restart(int i, double *buf)
{
  buf[0] = 1 + VALUES;
  buf[1] = weighted_volume[i];
  buf[2] = dilatation[i];
  buf[3] = lost[i];
  return 1 + VALUES;
}

void FixBBPDLPS::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  weighted_volume[nlocal] = extra[nlocal][m++];
  dilatation[nlocal] = extra[nlocal][m++];
  lost[nlocal] = extra[nlocal][m++];
}

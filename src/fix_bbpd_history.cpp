// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the history of bbpd/ves and bbpd/eps (see fix_bbpd_history.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_history.h"

#include "atom.h"
#include "error.h"
#include "memory.h"

#include <algorithm>

using namespace LAMMPS_NS;

FixBBPDHistory::FixBBPDHistory(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), width(1), values(nullptr), nmax_values(0)
{
  if (narg != 3)
    error->all(FLERR, "Fix bbpd/history takes no arguments (it is created by the pair style)");
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange_dynamic = 1;
  maxexchange = width;
  FixBBPDHistory::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) set_arrays(i);
}

FixBBPDHistory::~FixBBPDHistory()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(values);
}

double FixBBPDHistory::memory_usage()
{
  return (double) width * nmax_values * sizeof(double);
}

void FixBBPDHistory::grow_arrays(int nmax)
{
  memory->grow(values, nmax, width, "bbpd/history:values");
  nmax_values = nmax;
}

void FixBBPDHistory::set_width(int w)
{
  if (w == width) return;
  double **wider = nullptr;
  memory->create(wider, nmax_values, w, "bbpd/history:values");
  const int keep = std::min(w, width);
  for (int i = 0; i < nmax_values; i++)
    for (int c = 0; c < w; c++) wider[i][c] = c < keep ? values[i][c] : 0.0;
  memory->destroy(values);
  values = wider;
  width = w;
  maxexchange = width;
}

void FixBBPDHistory::copy_arrays(int i, int j, int)
{
  for (int c = 0; c < width; c++) values[j][c] = values[i][c];
}

void FixBBPDHistory::set_arrays(int i)
{
  for (int c = 0; c < width; c++) values[i][c] = 0.0;
}

int FixBBPDHistory::pack_exchange(int i, double *buf)
{
  for (int c = 0; c < width; c++) buf[c] = values[i][c];
  return width;
}

int FixBBPDHistory::unpack_exchange(int nlocal, double *buf)
{
  for (int c = 0; c < width; c++) values[nlocal][c] = buf[c];
  return width;
}

int FixBBPDHistory::pack_restart(int i, double *buf)
{
  buf[0] = 1 + width;
  for (int c = 0; c < width; c++) buf[1 + c] = values[i][c];
  return 1 + width;
}

void FixBBPDHistory::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  set_width(static_cast<int>(extra[nlocal][m]) - 1);    // the width the file was written with
  m++;
  for (int c = 0; c < width; c++) values[nlocal][c] = extra[nlocal][m++];
}

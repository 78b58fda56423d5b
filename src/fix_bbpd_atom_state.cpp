// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the per-atom state of the internal fixes (see fix_bbpd_atom_state.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_atom_state.h"

#include "atom.h"
#include "error.h"
#include "memory.h"

#include <algorithm>

using namespace LAMMPS_NS;

FixBBPDAtomState::FixBBPDAtomState(LAMMPS *lmp, int narg, char **arg, const char *created_by,
                                   int width_, int saved_, Layout layout_) :
    Fix(lmp, narg, arg),
    width(width_), values(nullptr), columns(nullptr), layout(layout_), saved(saved_),
    nmax_values(0)
{
  if (narg != 3)
    error->all(FLERR, "Fix {} takes no arguments (it is created by {})", style, created_by);
  if (layout == Layout::COLUMNS) {
    columns = new double *[width];
    for (int c = 0; c < width; c++) columns[c] = nullptr;
  }
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange = width;
  FixBBPDAtomState::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) FixBBPDAtomState::set_arrays(i);
}

FixBBPDAtomState::~FixBBPDAtomState()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(values);
  if (columns)
    for (int c = 0; c < width; c++) memory->destroy(columns[c]);
  delete[] columns;
}

double FixBBPDAtomState::memory_usage()
{
  return (double) width * nmax_values * sizeof(double);
}

void FixBBPDAtomState::grow_arrays(int nmax)
{
  if (layout == Layout::ROWS)
    memory->grow(values, nmax, width, "bbpd:atom_state");
  else
    for (int c = 0; c < width; c++) memory->grow(columns[c], nmax, "bbpd:atom_state");
  nmax_values = nmax;
}

void FixBBPDAtomState::set_width(int w)
{
  if (w == width) return;
  if (layout == Layout::COLUMNS)
    error->one(FLERR, "Fix {} keeps {} values per atom, not {} (a restart file of another "
               "version?)", style, width, w);
  double **wider = nullptr;
  memory->create(wider, nmax_values, w, "bbpd:atom_state");
  const int keep = std::min(w, width);
  for (int i = 0; i < nmax_values; i++)
    for (int c = 0; c < w; c++) wider[i][c] = c < keep ? values[i][c] : 0.0;
  memory->destroy(values);
  values = wider;
  width = w;
  maxexchange = width;
}

void FixBBPDAtomState::copy_arrays(int i, int j, int)
{
  for (int c = 0; c < width; c++) value(j, c) = value(i, c);
}

void FixBBPDAtomState::set_arrays(int i)
{
  for (int c = 0; c < width; c++) value(i, c) = 0.0;
}

int FixBBPDAtomState::pack_exchange(int i, double *buf)
{
  for (int c = 0; c < width; c++) buf[c] = value(i, c);
  return width;
}

int FixBBPDAtomState::unpack_exchange(int nlocal, double *buf)
{
  for (int c = 0; c < width; c++) value(nlocal, c) = buf[c];
  return width;
}

int FixBBPDAtomState::pack_restart(int i, double *buf)
{
  const int n = saved_width();
  buf[0] = 1 + n;
  for (int c = 0; c < n; c++) buf[1 + c] = value(i, c);
  return 1 + n;
}

void FixBBPDAtomState::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const int n = static_cast<int>(extra[nlocal][m]) - 1;    // the columns the file holds
  if (saved == ALL) set_width(n);                          // as wide as it was written
  set_arrays(nlocal);
  m++;
  for (int c = 0; c < n && c < width; c++) value(nlocal, c) = extra[nlocal][m++];
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the history of bbpd/ves and bbpd/eps (see fix_bbpd_history.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_history.h"

#include "bbpd_history_blocks.h"

#include "atom.h"
#include "error.h"

#include <algorithm>
#include <vector>

using namespace LAMMPS_NS;

FixBBPDHistory::FixBBPDHistory(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), atom_values(0), bond_values(0), max_length(0)
{
  if (narg != 5)
    error->all(FLERR, "Fix {} takes the doubles of history per atom and per bond end (it is "
               "created by the pair style)", style);
  atom_values = utils::inumeric(FLERR, arg[3], false, lmp);
  bond_values = utils::inumeric(FLERR, arg[4], false, lmp);
  if (atom_values < 0 || bond_values < 1)
    error->all(FLERR, "Fix {}: {} doubles per atom and {} per bond end: need >= 0 and >= 1",
               style, atom_values, bond_values);
  restart_peratom = 1;
  create_attribute = 1;
  maxexchange = 1;
  maxexchange_dynamic = 1;    // rows grow when the families are built
  FixBBPDHistory::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
}

FixBBPDHistory::~FixBBPDHistory()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
}

double FixBBPDHistory::memory_usage()
{
  return rows.bytes();
}

void FixBBPDHistory::grow_arrays(int nmax)
{
  rows.grow(nmax);
}

void FixBBPDHistory::copy_arrays(int i, int j, int delflag)
{
  // a deleted source (migration) hands its row over; a sort reads the source again
  if (delflag) rows.move(i, j);
  else rows.copy(i, j, rows.room(i));
}

void FixBBPDHistory::set_arrays(int i)
{
  rows.clear(i);
}

// the row i at least n long, its values kept
void FixBBPDHistory::resize_keep(int i, int n)
{
  const int held = rows.room(i);
  if (n <= held) return;
  const std::vector<double> kept(rows[i], rows[i] + held);
  rows.resize(i, n);
  std::copy(kept.begin(), kept.end(), rows[i]);
  std::fill(rows[i] + held, rows[i] + n, 0.0);
}

// the doubles of a row of nslots slots (whole blocks)
int FixBBPDHistory::row_length(int nslots) const
{
  return atom_values + BBPD::history_length(bond_values, nslots);
}

void FixBBPDHistory::fit(const int *npartner, int maxpartner)
{
  allow_length(row_length(maxpartner));
  for (int i = 0; i < atom->nlocal; i++) resize_keep(i, row_length(npartner[i]));
}

// rows of n values may be sent: the exchange buffer holds them with their count
void FixBBPDHistory::allow_length(int n)
{
  max_length = std::max(max_length, n);
  maxexchange = 1 + max_length;
}

// row i becomes the n values at src (an atom that arrives or is read back)
void FixBBPDHistory::take_row(int i, int n, const double *src)
{
  allow_length(n);
  rows.clear(i);
  rows.resize(i, n);
  std::copy_n(src, n, rows[i]);
}

double FixBBPDHistory::bytes_when_fit(const int *npartner) const
{
  double bytes = rows.bytes();
  for (int i = 0; i < atom->nlocal; i++)
    bytes += std::max(0, row_length(npartner[i]) - rows.room(i)) * sizeof(double);
  return bytes;
}

int FixBBPDHistory::pack_exchange(int i, double *buf)
{
  const int n = rows.room(i);
  buf[0] = n;
  std::copy_n(rows[i], n, buf + 1);
  return 1 + n;
}

int FixBBPDHistory::unpack_exchange(int nlocal, double *buf)
{
  const int n = static_cast<int>(buf[0]);
  take_row(nlocal, n, buf + 1);
  return 1 + n;
}

// the slots of a row of n doubles (a row of blocks holds whole blocks, a file's row whole slots)
static int slots_of(int n, int atom_values, int bond_values)
{
  return std::max(0, n - atom_values) / bond_values;
}

// a restart file holds a slot's values side by side (the layout before the blocks)
int FixBBPDHistory::pack_restart(int i, double *buf)
{
  const int n = rows.room(i);
  buf[0] = 1 + n;
  if (n > 0) {
    const int nslots = slots_of(n, atom_values, bond_values);
    std::copy_n(rows[i], atom_values, buf + 1);
    BBPD::history_to_pairs(bond_values, nslots, rows[i] + atom_values, buf + 1 + atom_values);
  }
  return 1 + n;
}

void FixBBPDHistory::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const int n = static_cast<int>(extra[nlocal][m]) - 1;    // the values the file holds
  const double *file = &extra[nlocal][m + 1];
  if (n == 0) {
    take_row(nlocal, 0, file);
    return;
  }
  if (n < atom_values || (n - atom_values) % bond_values != 0)
    error->one(FLERR, "Fix {}: atom {} has {} values of history in the restart file, not {} per "
               "atom and {} per bond end: the file was written by another model (pair style)",
               style, atom->tag[nlocal], n, atom_values, bond_values);
  const int nslots = slots_of(n, atom_values, bond_values);
  std::vector<double> row(row_length(nslots));
  std::copy_n(file, atom_values, row.begin());
  BBPD::history_from_pairs(bond_values, nslots, file + atom_values, row.data() + atom_values);
  take_row(nlocal, (int) row.size(), row.data());
}

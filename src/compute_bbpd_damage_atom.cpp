// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: compute bbpd/damage/atom (see header)
------------------------------------------------------------------------- */

#include "compute_bbpd_damage_atom.h"

#include "atom.h"
#include "error.h"
#include "fix_bbpd_bonds.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputeBBPDDamageAtom::ComputeBBPDDamageAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), damage(nullptr), bonds(nullptr)
{
  if (narg != 3) error->all(FLERR, "Illegal compute bbpd/damage/atom command: it takes no arguments");
  peratom_flag = 1;
  size_peratom_cols = 0;
}

ComputeBBPDDamageAtom::~ComputeBBPDDamageAtom()
{
  memory->destroy(damage);
}

void ComputeBBPDDamageAtom::init()
{
  bonds = dynamic_cast<FixBBPDBonds *>(modify->get_fix_by_id("BBPD_BONDS"));
  if (!bonds || !force->pair_match("^bbpd/", 0)) error->all(FLERR, "Compute bbpd/damage/atom requires a bbpd/* pair style");
}

void ComputeBBPDDamageAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(damage);
    nmax = atom->nmax;
    memory->create(damage, nmax, "bbpd/damage/atom:damage");
    vector_atom = damage;
  }
  const int *mask = atom->mask;
  // the fix keeps the intact volume per atom: no pass over the bonds here
  for (int i = 0; i < atom->nlocal; i++) damage[i] = (mask[i] & groupbit) ? bonds->damage(i) : 0.0;
}

double ComputeBBPDDamageAtom::memory_usage()
{
  return (double) nmax * sizeof(double);
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: compute bbpd/plasticity/atom (see header)
------------------------------------------------------------------------- */

#include "compute_bbpd_plasticity_atom.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "pair_bbpd_lps.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputeBBPDPlasticityAtom::ComputeBBPDPlasticityAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), values(nullptr)
{
  if (narg != 3)
    error->all(FLERR, "Illegal compute bbpd/plasticity/atom command: it takes no arguments");
  peratom_flag = 1;
  size_peratom_cols = 0;
}

ComputeBBPDPlasticityAtom::~ComputeBBPDPlasticityAtom()
{
  memory->destroy(values);
}

static PairBBPDLPS *eps_pair(LAMMPS *lmp)
{
  return dynamic_cast<PairBBPDLPS *>(lmp->force->pair_match("bbpd/eps", 1));
}

void ComputeBBPDPlasticityAtom::init()
{
  if (!eps_pair(lmp))
    error->all(FLERR,
               "Compute bbpd/plasticity/atom requires pair style bbpd/eps (the only "
               "bbpd style with plasticity)");
}

void ComputeBBPDPlasticityAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(values);
    nmax = atom->nmax;
    memory->create(values, nmax, "bbpd/plasticity/atom:values");
    vector_atom = values;
  }
  const PairBBPDLPS *pair = eps_pair(lmp);
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++)
    values[i] = (mask[i] & groupbit) ? pair->plastic_multiplier(i) : 0.0;
}

double ComputeBBPDPlasticityAtom::memory_usage()
{
  return (double) nmax * sizeof(double);
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: compute bbpd/dilatation/atom (see header)
------------------------------------------------------------------------- */

#include "compute_bbpd_dilatation_atom.h"

#include "atom.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "pair.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputeBBPDDilatationAtom::ComputeBBPDDilatationAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), nmax(0), values(nullptr)
{
  if (narg != 3)
    error->all(FLERR, "Illegal compute bbpd/dilatation/atom command: it takes no arguments");
  peratom_flag = 1;
  size_peratom_cols = 0;
}

ComputeBBPDDilatationAtom::~ComputeBBPDDilatationAtom()
{
  memory->destroy(values);
}

// the pair style's dilatations (its extract("theta"), as peri/lps, peri/ves and peri/eps)
static double *dilatations(LAMMPS *lmp)
{
  int dim = 0;
  Pair *pair = lmp->force->pair_match("^bbpd/", 0);
  double *theta = pair ? static_cast<double *>(pair->extract("theta", dim)) : nullptr;
  return theta && dim == 1 ? theta : nullptr;
}

void ComputeBBPDDilatationAtom::init()
{
  if (!dilatations(lmp))
    error->all(FLERR,
               "Compute bbpd/dilatation/atom requires a state-based bbpd pair style "
               "(bbpd/lps, bbpd/lps/KERNEL, bbpd/ves or bbpd/eps): the bond-based styles have "
               "no dilatation");
}

void ComputeBBPDDilatationAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (atom->nmax > nmax) {
    memory->destroy(values);
    nmax = atom->nmax;
    memory->create(values, nmax, "bbpd/dilatation/atom:values");
    vector_atom = values;
  }
  const double *theta = dilatations(lmp);
  const int *mask = atom->mask;
  for (int i = 0; i < atom->nlocal; i++) values[i] = (mask[i] & groupbit) ? theta[i] : 0.0;
}

double ComputeBBPDDilatationAtom::memory_usage()
{
  return (double) nmax * sizeof(double);
}

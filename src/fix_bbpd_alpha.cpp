// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: state of the Silling-Askari bond loop (see fix_bbpd_alpha.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_alpha.h"

#include "comm.h"

using namespace LAMMPS_NS;

// the force density of the bonds that broke: three values per atom
static constexpr int FBROKEN_VALUES = 3;

FixBBPDAlpha::FixBBPDAlpha(LAMMPS *lmp, int narg, char **arg) :
    FixBBPDAtomState(lmp, narg, arg, "the pair style", FBROKEN_VALUES), last_step(-1)
{
  restart_global = 1;
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

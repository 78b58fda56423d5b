// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the per-atom state of pair style bbpd/lps (see fix_bbpd_lps.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_lps.h"

#include "comm.h"

using namespace LAMMPS_NS;

FixBBPDLPS::FixBBPDLPS(LAMMPS *lmp, int narg, char **arg) :
    FixBBPDAtomState(lmp, narg, arg, "the pair style", VALUES, ALL, Layout::COLUMNS), ready(0)
{
  restart_global = 1;
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

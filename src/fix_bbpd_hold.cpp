// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the log of the bonds a minimize holds (see fix_bbpd_hold.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_hold.h"
#include "pair_bbpd.h"

#include "comm.h"
#include "error.h"
#include "force.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

FixBBPDHold::FixBBPDHold(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg)
{
  if (narg != 3)
    error->all(FLERR, "Fix bbpd/hold takes no arguments (it is created by the pair style)");
}

int FixBBPDHold::setmask()
{
  return 0;    // min_setup and post_run are called for every fix
}

PairBBPD *FixBBPDHold::fracturing_pair()
{
  auto pair = dynamic_cast<PairBBPD *>(force->pair_match("^bbpd/", 0));
  return pair && pair->fracture_any ? pair : nullptr;
}

bigint FixBBPDHold::held_bonds()
{
  PairBBPD *pair = fracturing_pair();
  bigint ends = pair ? pair->hold.held_ends : 0, all = 0;
  MPI_Allreduce(&ends, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return all / 2;    // both ends of a bond decide alike (PairBBPD::breaking_length)
}

void FixBBPDHold::min_setup(int)
{
  if (fracturing_pair() && comm->me == 0)
    utils::logmesg(lmp, "bbpd: minimize holds bonds: no bond breaks in a minimizer's trial "
                   "states; use fix bbpd/relax to break bonds between converged states\n");
}

/* at the end of a minimize: the bonds past breaking in the minimized state, which it held */
void FixBBPDHold::post_run()
{
  if (update->whichflag != BBPD::BondHold::MINIMIZE || !fracturing_pair()) return;
  const bigint n = held_bonds();
  if (n > 0) {
    if (comm->me == 0)
      error->warning(FLERR, "bbpd: minimize held {} bonds past breaking in the minimized state "
                     "(they did not break): the state is not admissible with fracture; use fix "
                     "bbpd/relax to break bonds between converged states", n);
  } else if (comm->me == 0) {
    utils::logmesg(lmp, "bbpd: minimize held 0 bonds past breaking in the minimized state\n");
  }
}

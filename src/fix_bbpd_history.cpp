// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the history of bbpd/ves and bbpd/eps (see fix_bbpd_history.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_history.h"

using namespace LAMMPS_NS;

// one value per atom until the pair style knows the families' size
static constexpr int INITIAL_WIDTH = 1;

FixBBPDHistory::FixBBPDHistory(LAMMPS *lmp, int narg, char **arg) :
    FixBBPDAtomState(lmp, narg, arg, "the pair style", INITIAL_WIDTH)
{
  maxexchange_dynamic = 1;    // the width grows when the families are built
}

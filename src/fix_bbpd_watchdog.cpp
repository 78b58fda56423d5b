// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the run-explosion watchdog (see fix_bbpd_watchdog.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_watchdog.h"
#include "fix_bbpd_bonds.h"

#include "atom.h"
#include "error.h"
#include "modify.h"
#include "update.h"

#include <cmath>
#include <string>

using namespace LAMMPS_NS;
using namespace FixConst;

// an atom cloud this many times larger than the body at bond creation means the run has blown
// up; stop before LAMMPS bins the exploded box (which can take all the memory)
static constexpr double MAX_EXTENT_GROWTH = 1000.0;
// nor can an atom that moves this many grid spacings in one step be part of a valid run (a stable
// step moves atoms a small fraction of a spacing: dt < spacing / wave speed, and v << wave speed)
static constexpr double MAX_STEP_SPACINGS = 10.0;

FixBBPDWatchdog::FixBBPDWatchdog(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), bonds(nullptr)
{
  if (narg != 3)
    error->all(FLERR, "Fix bbpd/watchdog takes no arguments (it is created by the pair style)");
}

int FixBBPDWatchdog::setmask()
{
  return PRE_EXCHANGE;
}

void FixBBPDWatchdog::init()
{
  bonds = dynamic_cast<FixBBPDBonds *>(modify->get_fix_by_id("BBPD_BONDS"));
  if (!bonds) error->all(FLERR, "Fix bbpd/watchdog requires a bbpd pair style");
}

/* before atoms migrate (once per reneighboring): catch an exploding run */
void FixBBPDWatchdog::pre_exchange()
{
  if (!bonds->families_built()) return;
  // no atom may cross a horizon in one step, and the bonded body may not spread out
  double vmax = 0.0, gvmax = 0.0;
  double **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++)
    vmax = MAX(vmax, v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
  MPI_Allreduce(&vmax, &gvmax, 1, MPI_DOUBLE, MPI_MAX, world);
  const double e = bonds->bonded_extent();
  const double extent0 = bonds->initial_extent();
  const double step = std::sqrt(gvmax) * update->dt;
  const double spacing = limits.grid_spacing;
  const bool too_fast = !(step <= spacing * MAX_STEP_SPACINGS);
  if (!too_fast && (extent0 <= 0.0 || e <= MAX_EXTENT_GROWTH * extent0)) return;
  const double bound = limits.stable_timestep;
  const std::string what = fmt::format(
      "BBPD: the run is unstable at step {} (an atom moves {:.3g} grid spacings per step, the "
      "bonded body spans {:.3g} x its size)", update->ntimestep, step / spacing,
      extent0 > 0.0 ? e / extent0 : 0.0);
  if (!(update->dt <= limits.timestep_safety * bound))
    error->all(FLERR, "{}: the timestep {:.6g} ({:.3g} of the stable bound {:.6g} printed at "
               "setup) must stay below that bound", what, update->dt, update->dt / bound, bound);
  // below the stable bound the timestep is not the cause: atoms were set moving faster than
  // the material can carry (a stable run moves atoms a small fraction of a spacing per step),
  // e.g. an impact velocity far above the wave speed
  error->all(FLERR, "{}: atoms move at up to {:.3g} (velocity units), far faster than a signal "
             "crosses the grid (about {:.3g}: grid spacing / stable timestep), while the "
             "timestep {:.6g} is only {:.3g} of the stable bound. Reduce the imposed velocities "
             "(velocity, fix move, boundary conditions) or use a stiffer material, so that atoms "
             "move well below one grid spacing per step", what, std::sqrt(gvmax),
             spacing / bound, update->dt, update->dt / bound);
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the arguments of the crack computes (see header)
------------------------------------------------------------------------- */

#include "compute_bbpd_crack_args.h"

#include "error.h"
#include "input.h"
#include "pair_bbpd.h"
#include "variable.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

CrackComputeArgs::CrackComputeArgs(LAMMPS *lmp, const char *style_name, int narg, char **arg) :
    Pointers(lmp), style(style_name), dir{1.0, 0.0}, youngs(UNSET), poisson(UNSET),
    plane(PLANE_UNSET), tip_value{0.0, 0.0}, tip_ivar{-1, -1}
{
  if (narg < 6 || strcmp(arg[3], "tip") != 0)
    error->all(FLERR, "Illegal compute {} command: expected 'compute ID group {} tip X Y "
               "[keyword value ...]'", style, style);
  for (int m = 0; m < 2; m++) {
    if (utils::strmatch(arg[4 + m], "^v_")) tip_var[m] = arg[4 + m] + 2;
    else tip_value[m] = utils::numeric(FLERR, arg[4 + m], false, lmp);
  }
}

double CrackComputeArgs::positive(int narg, char **arg, int iarg) const
{
  if (iarg + 1 >= narg) error->all(FLERR, "Compute {}: keyword {} needs a value", style, arg[iarg]);
  const double v = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
  if (v <= 0.0) error->all(FLERR, "Compute {}: {} must be > 0, got {}", style, arg[iarg], v);
  return v;
}

bool CrackComputeArgs::parse(int narg, char **arg, int &iarg, std::initializer_list<Positive> own)
{
  const std::string key = arg[iarg];
  for (const Positive &p : own)
    if (key == p.key) {
      *p.value = positive(narg, arg, iarg);
      iarg += 2;
      return true;
    }
  if (key == "E") {
    youngs = positive(narg, arg, iarg);
    iarg += 2;
  } else if (key == "nu") {
    if (iarg + 1 >= narg) error->all(FLERR, "Compute {}: keyword nu needs a value", style);
    poisson = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    if (poisson <= -1.0 || poisson >= 0.5)
      error->all(FLERR, "Compute {}: nu must lie in (-1, 0.5), got {}", style, poisson);
    iarg += 2;
  } else if (key == "plane") {
    if (iarg + 1 >= narg)
      error->all(FLERR, "Compute {}: keyword plane needs stress or strain", style);
    if (strcmp(arg[iarg + 1], "stress") == 0) plane = PLANE_STRESS;
    else if (strcmp(arg[iarg + 1], "strain") == 0) plane = PLANE_STRAIN;
    else
      error->all(FLERR, "Compute {}: plane must be stress or strain, got {}", style,
                 arg[iarg + 1]);
    iarg += 2;
  } else if (key == "direction") {
    if (iarg + 2 >= narg) error->all(FLERR, "Compute {}: direction needs DX DY", style);
    const double dx = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    const double dy = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
    const double len = std::sqrt(dx * dx + dy * dy);
    if (len == 0.0)
      error->all(FLERR, "Compute {}: direction {} {} has zero length", style, dx, dy);
    dir[0] = dx / len;
    dir[1] = dy / len;
    iarg += 3;
  } else {
    return false;
  }
  return true;
}

void CrackComputeArgs::init_tip()
{
  for (int m = 0; m < 2; m++) {
    tip_ivar[m] = -1;
    if (tip_var[m].empty()) continue;
    tip_ivar[m] = input->variable->find(tip_var[m].c_str());
    if (tip_ivar[m] < 0)
      error->all(FLERR, "Compute {}: tip variable {} does not exist", style, tip_var[m]);
    if (!input->variable->equalstyle(tip_ivar[m]))
      error->all(FLERR, "Compute {}: tip variable {} is not equal-style", style, tip_var[m]);
  }
}

void CrackComputeArgs::current_tip(double *tip) const
{
  for (int m = 0; m < 2; m++)
    tip[m] = tip_ivar[m] >= 0 ? input->variable->compute_equal(tip_ivar[m]) : tip_value[m];
}

BBPD::JIntegral::Elastic CrackComputeArgs::elastic(PairBBPD *pair, int itype) const
{
  BBPD::JIntegral::Elastic e{youngs, poisson, plane == PLANE_STRESS};
  if (e.E == UNSET) e.E = pair->youngs_modulus(itype);
  if (e.nu == UNSET) e.nu = pair->poisson_ratio(itype);
  if (plane == PLANE_UNSET) e.plane_stress = pair->model == BBPD::Model::PlaneStress;
  return e;
}

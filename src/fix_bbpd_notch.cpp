// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: fix bbpd/notch (see fix_bbpd_notch.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_notch.h"

#include "bbpd_compat.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_bbpd_bonds.h"
#include "force.h"
#include "group.h"
#include "modify.h"
#include "pair.h"

#include <cmath>
#include <cstring>
#include <limits>

using namespace LAMMPS_NS;
using namespace FixConst;

// a bond through a notch's end point counts as cut: without this tolerance round-off decides,
// and mirror-image notches would cut different bonds (relative to the notch's edge lengths)
static constexpr double NOTCH_END_TOLERANCE = 1.0e-12;

FixBBPDNotch::FixBBPDNotch(LAMMPS *lmp, int narg, char **arg) : Fix(lmp, narg, arg), bonds(nullptr)
{
  const int dim = domain->dimension;
  if (narg < 4) utils::missing_cmd_args(FLERR, "fix bbpd/notch", error);
  int iarg = 3;
  while (iarg < narg) {
    Cut c = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    if (strcmp(arg[iarg], "segment") == 0) {
      if (dim != 2)
        error->all(FLERR, "Fix bbpd/notch: 'segment' is for dimension 2; in 3D use 'rectangle "
                   "cx cy cz ax ay az bx by bz'");
      if (iarg + 5 > narg) error->all(FLERR, "Fix bbpd/notch: segment needs 4 numbers: x1 y1 x2 y2");
      double v[4];
      for (int m = 0; m < 4; m++) v[m] = utils::numeric(FLERR, arg[iarg + 1 + m], false, lmp);
      c.p[0] = v[0];
      c.p[1] = v[1];
      c.a[0] = v[2] - v[0];
      c.a[1] = v[3] - v[1];
      if (c.a[0] == 0.0 && c.a[1] == 0.0)
        error->all(FLERR, "Fix bbpd/notch: segment {} {} {} {} has zero length", v[0], v[1], v[2], v[3]);
      iarg += 5;
    } else if (strcmp(arg[iarg], "rectangle") == 0) {
      if (dim != 3)
        error->all(FLERR, "Fix bbpd/notch: 'rectangle' is for dimension 3; in 2D use 'segment x1 y1 x2 y2'");
      if (iarg + 10 > narg)
        error->all(FLERR, "Fix bbpd/notch: rectangle needs 9 numbers: corner cx cy cz, edge ax ay az, edge bx by bz");
      double v[9];
      for (int m = 0; m < 9; m++) v[m] = utils::numeric(FLERR, arg[iarg + 1 + m], false, lmp);
      for (int m = 0; m < 3; m++) {
        c.p[m] = v[m];
        c.a[m] = v[3 + m];
        c.b[m] = v[6 + m];
      }
      const double n[3] = {c.a[1] * c.b[2] - c.a[2] * c.b[1], c.a[2] * c.b[0] - c.a[0] * c.b[2],
                           c.a[0] * c.b[1] - c.a[1] * c.b[0]};
      if (n[0] == 0.0 && n[1] == 0.0 && n[2] == 0.0)
        error->all(FLERR, "Fix bbpd/notch: rectangle edges are parallel or zero: it has no area");
      iarg += 10;
    } else if (strcmp(arg[iarg], "groups") == 0) {
      if (iarg + 3 > narg)
        error->all(FLERR, "Fix bbpd/notch: groups needs two group IDs: groups G1 G2");
      for (int m = 1; m <= 2; m++)
        if (group->find(arg[iarg + m]) < 0)
          error->all(FLERR, "Fix bbpd/notch: no group named {} (define it with the group command "
                     "before this fix)", arg[iarg + m]);
      group_names.emplace_back(arg[iarg + 1], arg[iarg + 2]);
      iarg += 3;
      continue;
    } else {
      error->all(FLERR, "Unknown fix bbpd/notch keyword: {} (expected {} or groups)", arg[iarg],
                 dim == 2 ? "segment" : "rectangle");
    }
    cuts.push_back(c);
  }
}

/* PRE_FORCE only for its setup hook: pre_force() itself does nothing */
int FixBBPDNotch::setmask()
{
  return PRE_FORCE | MIN_PRE_FORCE;
}

void FixBBPDNotch::init()
{
  if (!atom->peri_flag) error->all(FLERR, "Fix bbpd/notch requires atom_style peri");
  if (!force->pair_match("^bbpd/", 0))
    error->all(FLERR, "Fix bbpd/notch requires a bbpd/* pair style (it cuts their bonds)");
  // the pair style has created its bond fix in its init_style(), which runs before this
  auto fixes = modify->get_fix_by_style("^bbpd/bonds$");
  bonds = fixes.empty() ? nullptr : dynamic_cast<FixBBPDBonds *>(fixes.front());
  if (!bonds) error->all(FLERR, "Fix bbpd/notch found no bond families of a bbpd/* pair style");
  group_bits.clear();
  for (const auto &g : group_names) {
    int bit[2];
    const std::string *name[2] = {&g.first, &g.second};
    for (int m = 0; m < 2; m++) {
      const int igroup = group->find(*name[m]);
      if (igroup < 0)
        error->all(FLERR, "Fix bbpd/notch: group {} no longer exists (define it again before "
                   "the run)", *name[m]);
      // an empty group cuts nothing: almost always a region or a type that missed the atoms
      if (group->count(igroup) == 0)
        error->all(FLERR, "Fix bbpd/notch: group {} has no atoms, so 'groups {} {}' would cut "
                   "nothing (check the group's region or types)", *name[m], g.first, g.second);
      bit[m] = group->bitmask[igroup];
    }
    group_bits.emplace_back(bit[0], bit[1]);
  }
}

/* does the bond xa-xb cross the notch? points on the notch plane count as its positive side */
/* a normal of the notch's line (2D) or plane (3D) */
static void notch_normal(const FixBBPDNotch::Cut &c, int dim, double *n)
{
  if (dim == 2) {
    n[0] = -c.a[1];
    n[1] = c.a[0];
    n[2] = 0.0;
  } else {
    n[0] = c.a[1] * c.b[2] - c.a[2] * c.b[1];
    n[1] = c.a[2] * c.b[0] - c.a[0] * c.b[2];
    n[2] = c.a[0] * c.b[1] - c.a[1] * c.b[0];
  }
}

/* distance of x from the notch's line or plane (0 for a degenerate notch) */
double FixBBPDNotch::plane_distance(const Cut &c, const double *x, int dim)
{
  double n[3], nn = 0.0, s = 0.0;
  notch_normal(c, dim, n);
  for (int m = 0; m < dim; m++) {
    nn += n[m] * n[m];
    s += n[m] * (x[m] - c.p[m]);
  }
  return nn > 0.0 ? std::fabs(s) / std::sqrt(nn) : 0.0;
}

bool FixBBPDNotch::crosses(const Cut &c, const double *xa, const double *xb, int dim)
{
  double n[3];
  notch_normal(c, dim, n);
  double sa = 0.0, sb = 0.0;
  for (int m = 0; m < dim; m++) {
    sa += n[m] * (xa[m] - c.p[m]);
    sb += n[m] * (xb[m] - c.p[m]);
  }
  if ((sa >= 0.0) == (sb >= 0.0)) return false;
  const double u = sa / (sa - sb);
  double d[3] = {0.0, 0.0, 0.0};
  for (int m = 0; m < dim; m++) d[m] = xa[m] + u * (xb[m] - xa[m]) - c.p[m];
  // coordinates of the crossing point in the notch's own frame
  double aa = 0.0, ab = 0.0, bb = 0.0, ad = 0.0, bd = 0.0;
  for (int m = 0; m < dim; m++) {
    aa += c.a[m] * c.a[m];
    ab += c.a[m] * c.b[m];
    bb += c.b[m] * c.b[m];
    ad += c.a[m] * d[m];
    bd += c.b[m] * d[m];
  }
  if (dim == 2) {
    const double t = ad / aa;
    return t >= -NOTCH_END_TOLERANCE && t <= 1.0 + NOTCH_END_TOLERANCE;
  }
  const double det = aa * bb - ab * ab;
  const double t = (ad * bb - bd * ab) / det;
  const double w = (bd * aa - ad * ab) / det;
  return t >= -NOTCH_END_TOLERANCE && t <= 1.0 + NOTCH_END_TOLERANCE &&
      w >= -NOTCH_END_TOLERANCE && w <= 1.0 + NOTCH_END_TOLERANCE;
}

/* break every intact bond crossing a notch; idempotent, so it is safe on every run setup */
void FixBBPDNotch::setup_pre_force(int)
{
  if (!bonds->families_built()) return;
  double **x0 = atom->x0;
  int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const int dim = domain->dimension;
  const bool periodic = domain->xperiodic || domain->yperiodic || domain->zperiodic;
  bigint n = 0;
  // Both ends of a bond must agree: test it from its lower-tag end, and under periodic
  // boundaries test both unwrapped copies (the notch may sit beside either end).
  auto bond_cut = [&](int i, int j) {
    const int lo = tag[i] < tag[j] ? i : j, hi = lo == i ? j : i;
    double d[3] = {x0[hi][0] - x0[lo][0], x0[hi][1] - x0[lo][1], x0[hi][2] - x0[lo][2]};
    if (periodic) BBPDCompat::minimum_image(domain, d);
    const double a[3] = {x0[lo][0] + d[0], x0[lo][1] + d[1], x0[lo][2] + d[2]};
    const double b[3] = {x0[hi][0] - d[0], x0[hi][1] - d[1], x0[hi][2] - d[2]};
    for (const auto &c : cuts) {
      if (crosses(c, x0[lo], a, dim)) return true;
      if (periodic && crosses(c, b, x0[hi], dim)) return true;
    }
    // symmetric in i and j, and a ghost's mask is its owner's: both ends agree
    for (const auto &g : group_bits)
      if (((mask[i] & g.first) && (mask[j] & g.second)) ||
          ((mask[i] & g.second) && (mask[j] & g.first)))
        return true;
    return false;
  };
  // a bond that crosses a notch has both ends within its length of the notch's plane: rows
  // farther from every plane than the longest bond keep their bonds unread (not under periodic
  // boundaries, where an end may be an image, nor with group notches)
  const double reach = force->pair ? force->pair->cutforce : std::numeric_limits<double>::infinity();
  auto near_a_cut = [&](int i) {
    if (periodic || !group_bits.empty()) return true;
    for (const auto &c : cuts)
      if (plane_distance(c, x0[i], dim) <= reach) return true;
    return false;
  };
  for (int i = 0; i < atom->nlocal; i++)
    if (near_a_cut(i)) n += bonds->remove_bonds_if(i, [&](int k) {
      const int j = bonds->partner_of(i, k);
      return ((mask[i] & groupbit) || (mask[j] & groupbit)) && bond_cut(i, j);
    });
  bigint all = 0;
  MPI_Allreduce(&n, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  const size_t nnotch = cuts.size() + group_bits.size();
  if (comm->me == 0 && all > 0)
    utils::logmesg(lmp, "  fix {} bbpd/notch: {} bonds cut by {} notch{}\n", id, all / 2,
                   nnotch, nnotch > 1 ? "es" : "");
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: compute bbpd/dsif (see header and doc/compute_bbpd_dsif.rst)
------------------------------------------------------------------------- */

#include "compute_bbpd_dsif.h"

#include "atom.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "pair_bbpd.h"
#include "update.h"

#include <cmath>
#include <limits>

using namespace LAMMPS_NS;

namespace {
constexpr double UNSET = CrackComputeArgs::UNSET;
// defaults in units of the grid spacing: the paper's B and D (Fig. 7) and the
// face rows of a notch that runs between two rows of atoms
constexpr double R1_DEFAULT = 1.0, R2_DEFAULT = 2.0, OFFSET_DEFAULT = 0.5, TOLERANCE_DEFAULT = 0.5;
// nodes closer to a face point than the nearest one by less than this fraction
// of the tolerance are ties, resolved by the smaller atom ID (decomposition independent)
constexpr double TIE_FRACTION = 1.0e-9;
const char *const POINT_NAME[4] = {"upper-face r1", "lower-face r1", "upper-face r2",
                                   "lower-face r2"};
}    // namespace

/* ---------------------------------------------------------------------- */

ComputeBBPDDsif::ComputeBBPDDsif(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), kvec{0.0, 0.0}, args(lmp, "bbpd/dsif", narg, arg),
    r_user{UNSET, UNSET}, offset_user(UNSET), tolerance_user(UNSET), pair(nullptr),
    tags{0, 0, 0, 0}, cached_tip{0.0, 0.0}, cached(0)
{
  for (int iarg = 6; iarg < narg;)
    if (!args.parse(narg, arg, iarg,
                    {{"r1", &r_user[0]}, {"r2", &r_user[1]}, {"offset", &offset_user},
                     {"tolerance", &tolerance_user}}))
      error->all(FLERR, "Compute bbpd/dsif: unknown keyword '{}' (expected r1, r2, direction, "
                 "offset, E, nu, plane or tolerance)", arg[iarg]);
  if (r_user[0] > 0.0 && r_user[1] > 0.0 && r_user[1] <= r_user[0])
    error->all(FLERR, "Compute bbpd/dsif: need r2 > r1, got r1 = {} r2 = {}", r_user[0], r_user[1]);

  vector_flag = 1;
  size_vector = 2;
  extvector = 0;
  vector = kvec;
}

/* ---------------------------------------------------------------------- */

void ComputeBBPDDsif::init()
{
  if (domain->dimension != 2)
    error->all(FLERR, "Compute bbpd/dsif works in 2D only (dimension 2, crack faces in the x-y plane)");
  if (!atom->peri_flag || !atom->x0)
    error->all(FLERR, "Compute bbpd/dsif requires atom_style peri (reference positions x0)");
  if (atom->map_style == Atom::MAP_NONE)
    error->all(FLERR, "Compute bbpd/dsif requires an atom map, see atom_modify");

  pair = dynamic_cast<PairBBPD *>(force->pair_match("^bbpd/", 0));
  const bool need_spacing = r_user[0] < 0.0 || r_user[1] < 0.0 || offset_user < 0.0 ||
      tolerance_user < 0.0;
  if (!pair && (need_spacing || !args.elastic_given()))
    error->all(FLERR, "Compute bbpd/dsif without a bbpd/* pair style needs r1, r2, offset, "
               "tolerance, E, nu and plane");
  if (pair && (pair->model == BBPD::Model::Bar1D || pair->model == BBPD::Model::Solid3D) &&
      args.plane == CrackComputeArgs::PLANE_UNSET)
    error->all(FLERR, "Compute bbpd/dsif: pair model {} is not plane/stress or plane/strain: "
               "give 'plane stress' or 'plane strain'", BBPD::model_name(pair->model));
  const double r1 = r_user[0] > 0.0 ? r_user[0] : R1_DEFAULT * grid_spacing();
  const double r2 = r_user[1] > 0.0 ? r_user[1] : R2_DEFAULT * grid_spacing();
  if (r2 <= r1) error->all(FLERR, "Compute bbpd/dsif: need r2 > r1, got r1 = {} r2 = {}", r1, r2);

  args.init_tip();
  cached = 0;    // atoms may have been added or the group changed since the last run
}

double ComputeBBPDDsif::grid_spacing() const
{
  return pair ? pair->spacing : 0.0;
}

/* upper (left of the direction) and lower face points at r1 and r2 behind the tip */
void ComputeBBPDDsif::face_points(const double *tip, double pts[NPOINT][2]) const
{
  const double dx = grid_spacing();
  const double r[2] = {r_user[0] > 0.0 ? r_user[0] : R1_DEFAULT * dx,
                       r_user[1] > 0.0 ? r_user[1] : R2_DEFAULT * dx};
  const double h = offset_user > 0.0 ? offset_user : OFFSET_DEFAULT * dx;
  const double *dir = args.dir;    // ahead of the tip
  const double n[2] = {-dir[1], dir[0]};
  for (int k = 0; k < 2; k++)
    for (int side = 0; side < 2; side++) {
      const double s = side == 0 ? h : -h;
      pts[2 * k + side][0] = tip[0] - r[k] * dir[0] + s * n[0];
      pts[2 * k + side][1] = tip[1] - r[k] * dir[1] + s * n[1];
    }
}

/* nearest node of the group to each face point, on the right side of the crack line */
void ComputeBBPDDsif::find_face_nodes(const double *tip)
{
  double pts[NPOINT][2];
  face_points(tip, pts);
  const double *dir = args.dir;    // ahead of the tip
  const double n[2] = {-dir[1], dir[0]};
  const double big = std::numeric_limits<double>::max();
  double **x0 = atom->x0;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;

  double dloc[NPOINT], dmin[NPOINT];
  for (int p = 0; p < NPOINT; p++) dloc[p] = big;
  auto on_side = [&](int i, int p) {
    const double side = (x0[i][0] - tip[0]) * n[0] + (x0[i][1] - tip[1]) * n[1];
    return (p % 2 == 0) ? side > 0.0 : side < 0.0;
  };
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int p = 0; p < NPOINT; p++) {
      if (!on_side(i, p)) continue;
      dloc[p] = MIN(dloc[p], std::hypot(x0[i][0] - pts[p][0], x0[i][1] - pts[p][1]));
    }
  }
  MPI_Allreduce(dloc, dmin, NPOINT, MPI_DOUBLE, MPI_MIN, world);

  const double tol = tolerance_user > 0.0 ? tolerance_user : TOLERANCE_DEFAULT * grid_spacing();
  for (int p = 0; p < NPOINT; p++)
    if (dmin[p] > tol)
      error->all(FLERR, "Compute bbpd/dsif {}: no atom of group {} within tolerance {} of the {} "
                 "face point ({}, {}) for the tip at ({}, {}); put the tip on a node column "
                 "(see the doc page) or change r1/r2, offset or tolerance",
                 id, group->names[igroup], tol, POINT_NAME[p], pts[p][0], pts[p][1], tip[0], tip[1]);

  tagint tloc[NPOINT];
  for (int p = 0; p < NPOINT; p++) tloc[p] = MAXTAGINT;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int p = 0; p < NPOINT; p++) {
      if (!on_side(i, p)) continue;
      const double d = std::hypot(x0[i][0] - pts[p][0], x0[i][1] - pts[p][1]);
      if (d <= dmin[p] + TIE_FRACTION * tol) tloc[p] = MIN(tloc[p], tag[i]);
    }
  }
  MPI_Allreduce(tloc, tags, NPOINT, MPI_LMP_TAGINT, MPI_MIN, world);
  if (tags[0] == tags[2] || tags[1] == tags[3])
    error->all(FLERR, "Compute bbpd/dsif {}: the same atom is nearest to the r1 and r2 face "
               "points; r2 - r1 must exceed the grid spacing", id);
  cached_tip[0] = tip[0];
  cached_tip[1] = tip[1];
  cached = 1;
}

/* ---------------------------------------------------------------------- */

double ComputeBBPDDsif::extrapolate(double jump1, double jump2, double r1, double r2, double mu,
                                    double kappa)
{
  // K = 2 mu sqrt(2 pi)/(kappa + 1) (u(r1) r2/sqrt(r1) - u(r2) r1/sqrt(r2))/(r2 - r1), u = jump/2
  constexpr double FACE_JUMP = 2.0;
  return 2.0 * mu * std::sqrt(2.0 * BBPD::PI) / (kappa + 1.0) *
      (jump1 * r2 / std::sqrt(r1) - jump2 * r1 / std::sqrt(r2)) / (r2 - r1) / FACE_JUMP;
}

void ComputeBBPDDsif::compute_vector()
{
  invoked_vector = update->ntimestep;
  double tip[2];
  args.current_tip(tip);
  if (!cached || tip[0] != cached_tip[0] || tip[1] != cached_tip[1]) find_face_nodes(tip);

  // per face node: displacement (2), reference position (2), type, owner count
  constexpr int NV = 6;
  double loc[NPOINT * NV] = {0.0}, all[NPOINT * NV];
  double **x = atom->x, **x0 = atom->x0;
  for (int p = 0; p < NPOINT; p++) {
    const int i = atom->map(tags[p]);
    if (i < 0 || i >= atom->nlocal) continue;
    double d[2] = {x[i][0] - x0[i][0], x[i][1] - x0[i][1]};
    // displacement, not position: undo a periodic wrap of x relative to x0
    const double prd[2] = {domain->xprd, domain->yprd};
    const int periodic[2] = {domain->xperiodic, domain->yperiodic};
    for (int m = 0; m < 2; m++)
      if (periodic[m] && std::fabs(d[m]) > 0.5 * prd[m]) d[m] -= prd[m] * std::round(d[m] / prd[m]);
    double *v = loc + NV * p;
    v[0] = d[0];
    v[1] = d[1];
    v[2] = x0[i][0];
    v[3] = x0[i][1];
    v[4] = atom->type[i];
    v[5] = 1.0;
  }
  MPI_Allreduce(loc, all, NPOINT * NV, MPI_DOUBLE, MPI_SUM, world);
  for (int p = 0; p < NPOINT; p++)
    if (all[NV * p + 5] != 1.0)
      error->all(FLERR, "Compute bbpd/dsif {}: the {} face atom (ID {}) is lost", id,
                 POINT_NAME[p], tags[p]);

  const double *dir = args.dir;    // ahead of the tip
  const double n[2] = {-dir[1], dir[0]};
  double r[2], opening[2], sliding[2];
  for (int k = 0; k < 2; k++) {
    const double *up = all + NV * (2 * k), *lo = all + NV * (2 * k + 1);
    // actual distance behind the tip: mean of the two face nodes
    r[k] = -(0.5 * (up[2] + lo[2]) - tip[0]) * dir[0] - (0.5 * (up[3] + lo[3]) - tip[1]) * dir[1];
    const double du[2] = {up[0] - lo[0], up[1] - lo[1]};
    opening[k] = du[0] * n[0] + du[1] * n[1];
    sliding[k] = du[0] * dir[0] + du[1] * dir[1];
  }
  if (r[0] <= 0.0 || r[1] <= r[0])
    error->all(FLERR, "Compute bbpd/dsif {}: face nodes at r = {} and {} behind the tip; need "
               "0 < r1 < r2", id, r[0], r[1]);

  // elastic constants at node B (upper face, r1)
  const BBPD::JIntegral::Elastic e = args.elastic(pair, static_cast<int>(all[4]));
  const double mu = e.mu(), kappa = e.kappa();    // eq. 40

  kvec[0] = extrapolate(opening[0], opening[1], r[0], r[1], mu, kappa);
  kvec[1] = extrapolate(sliding[0], sliding[1], r[0], r[1], mu, kappa);
}

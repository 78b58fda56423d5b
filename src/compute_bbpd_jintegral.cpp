// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: compute bbpd/jintegral (see header and doc/compute_bbpd_jintegral.rst)
------------------------------------------------------------------------- */

#include "compute_bbpd_jintegral.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "pair_bbpd.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace LAMMPS_NS;
namespace JI = BBPD::JIntegral;

namespace {
constexpr double UNSET = CrackComputeArgs::UNSET;
// defaults: the annulus in units of the horizon (outside the nonlocal zone at the tip, as
// FE practice keeps q,j out of the process zone), the gradient stencil in grid spacings
// (the nearest and next-nearest neighbours, with a margin against round-off)
constexpr double RIN_DEFAULT = 2.0, ROUT_DEFAULT = 5.0, GRADIENT_DEFAULT = 2.01;
constexpr int MAX_BINS = 512;    // bins per side for the stencil search (bounds its memory)
constexpr int NPACK = 6;     // gathered per atom at cache time: tag, x0 (2), area, rho, type
constexpr int NFIELD = 7;    // gathered per atom and call: u (2), v (2), a (2), owner count
}    // namespace

/* ---------------------------------------------------------------------- */

ComputeBBPDJIntegral::ComputeBBPDJIntegral(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), jvec{0.0, 0.0, 0.0}, args(lmp, "bbpd/jintegral", narg, arg),
    rin_user(UNSET), rout_user(UNSET), grad_user(UNSET), thickness_user(UNSET), pair(nullptr),
    rin(0.0), rout(0.0), rgrad(0.0), thickness(0.0), cached(0), cached_tip{0.0, 0.0},
    aux_elastic{0.0, 0.0, 0.0}, itype_tip(1)
{
  for (int iarg = 6; iarg < narg;)
    if (!args.parse(narg, arg, iarg,
                    {{"rin", &rin_user}, {"rout", &rout_user}, {"gradient", &grad_user},
                     {"thickness", &thickness_user}}))
      error->all(FLERR, "Compute bbpd/jintegral: unknown keyword '{}' (expected rin, rout, "
                 "gradient, direction, E, nu, plane or thickness)", arg[iarg]);
  if (rin_user > 0.0 && rout_user > 0.0 && rout_user <= rin_user)
    error->all(FLERR, "Compute bbpd/jintegral: need rout > rin, got rin = {} rout = {}; "
               "increase rout or decrease rin", rin_user, rout_user);

  vector_flag = 1;
  size_vector = 3;
  extvector = 0;
  vector = jvec;
}

/* ---------------------------------------------------------------------- */

void ComputeBBPDJIntegral::init()
{
  pair = dynamic_cast<PairBBPD *>(force->pair_match("^bbpd/", 0));
  if (pair && (pair->model == BBPD::Model::Bar1D || pair->model == BBPD::Model::Solid3D))
    error->all(FLERR, "Compute bbpd/jintegral works with the 2D models only: pair model is {}; "
               "use pair_style bbpd/* plane/stress or plane/strain with dimension 2",
               BBPD::model_name(pair->model));
  if (domain->dimension != 2)
    error->all(FLERR, "Compute bbpd/jintegral works in 2D only (dimension 2, crack in the x-y "
               "plane)");
  if (!atom->peri_flag || !atom->x0 || !atom->rmass || !atom->vfrac)
    error->all(FLERR, "Compute bbpd/jintegral requires atom_style peri (x0, density, volume)");
  if (atom->map_style == Atom::MAP_NONE)
    error->all(FLERR, "Compute bbpd/jintegral requires an atom map, see atom_modify");
  if (!pair && (!args.elastic_given() || thickness_user < 0.0 || rin_user < 0.0 ||
                rout_user < 0.0 || grad_user < 0.0))
    error->all(FLERR, "Compute bbpd/jintegral without a bbpd/* pair style needs rin, rout, "
               "gradient, E, nu, plane and thickness");

  double delta = 0.0;
  if (pair) {
    int dim = 0;
    auto horizon = static_cast<double **>(pair->extract("horizon", dim));
    for (int t = 1; t <= atom->ntypes; t++) delta = std::max(delta, horizon[t][t]);
  }
  rin = rin_user > 0.0 ? rin_user : RIN_DEFAULT * delta;
  rout = rout_user > 0.0 ? rout_user : ROUT_DEFAULT * delta;
  rgrad = grad_user > 0.0 ? grad_user : GRADIENT_DEFAULT * pair->spacing;
  thickness = thickness_user > 0.0 ? thickness_user : pair->geom;
  if (rout <= rin)
    error->all(FLERR, "Compute bbpd/jintegral: need rout > rin, got rin = {} rout = {}; "
               "increase rout or decrease rin", rin, rout);

  args.init_tip();
  cached = 0;    // atoms may have been added or the group changed since the last run
}

/* ----------------------------------------------------------------------
   gather the atoms within rout + rgrad of the tip (reference positions) to
   every rank in the order of their reference positions and build each
   point's gradient stencil
------------------------------------------------------------------------- */

void ComputeBBPDJIntegral::build_cache(const double *tip)
{
  double **x0 = atom->x0;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double reach = rout + rgrad;

  // the body's extent (group atoms, reference positions) for the checks below
  double lo[2] = {1.0e300, 1.0e300}, hi[2] = {-1.0e300, -1.0e300};
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    for (int m = 0; m < 2; m++) {
      lo[m] = std::min(lo[m], x0[i][m]);
      hi[m] = std::max(hi[m], x0[i][m]);
    }
    const double d[2] = {x0[i][0] - tip[0], x0[i][1] - tip[1]};
    if (d[0] * d[0] + d[1] * d[1] > reach * reach) continue;
    mine.insert(mine.end(), {static_cast<double>(atom->tag[i]), x0[i][0], x0[i][1],
                             atom->vfrac[i] / thickness, atom->rmass[i],
                             static_cast<double>(atom->type[i])});
  }
  double glo[2], ghi[2];
  MPI_Allreduce(lo, glo, 2, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(hi, ghi, 2, MPI_DOUBLE, MPI_MAX, world);
  // atoms are cell centres: the body reaches half a grid spacing beyond them
  const double margin = pair ? 0.5 * pair->spacing : 0.0;
  for (int m = 0; m < 2; m++) {
    glo[m] -= margin;
    ghi[m] += margin;
  }
  if (tip[0] < glo[0] || tip[0] > ghi[0] || tip[1] < glo[1] || tip[1] > ghi[1])
    error->all(FLERR, "Compute bbpd/jintegral {}: the tip ({}, {}) lies outside the body of "
               "group {} ([{}, {}] x [{}, {}]); put the tip inside the plate", id, tip[0],
               tip[1], group->names[igroup], glo[0], ghi[0], glo[1], ghi[1]);
  const double room = std::min({tip[0] - glo[0], ghi[0] - tip[0], tip[1] - glo[1],
                                ghi[1] - tip[1]});
  if (rout > room)
    error->all(FLERR, "Compute bbpd/jintegral {}: the disc rout = {} around the tip ({}, {}) "
               "reaches outside the body ([{}, {}] x [{}, {}]); choose rout <= {} (and rin < rout)",
               id, rout, tip[0], tip[1], glo[0], ghi[0], glo[1], ghi[1], room);

  // gather in rank order, then sort: the same list on every rank
  int nmine = static_cast<int>(mine.size());    // not const: the serial MPI stubs take void *
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs, 0);
  MPI_Allgather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  std::partial_sum(counts.begin(), counts.end() - 1, displs.begin() + 1);
  const int ntotal = displs.back() + counts.back();
  std::vector<double> all(ntotal);
  MPI_Allgatherv(mine.data(), nmine, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, world);
  const int n = ntotal / NPACK;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  // order by reference position (then ID): atom IDs depend on how many ranks created the atoms
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    const double *pa = &all[NPACK * a], *pb = &all[NPACK * b];
    if (pa[2] != pb[2]) return pa[2] < pb[2];
    if (pa[1] != pb[1]) return pa[1] < pb[1];
    return pa[0] < pb[0];
  });

  const double *dir = args.dir;    // ahead of the tip
  const double n2[2] = {-dir[1], dir[0]};
  tags.assign(n, 0);
  xloc.assign(2 * n, 0.0);
  area.assign(n, 0.0);
  rho.assign(n, 0.0);
  double rmin = 1.0e300;
  itype_tip = 1;
  for (int k = 0; k < n; k++) {
    const double *p = all.data() + NPACK * order[k];
    tags[k] = static_cast<tagint>(p[0]);
    const double d[2] = {p[1] - tip[0], p[2] - tip[1]};
    xloc[2 * k] = d[0] * dir[0] + d[1] * dir[1];
    xloc[2 * k + 1] = d[0] * n2[0] + d[1] * n2[1];
    area[k] = p[3];
    rho[k] = p[4];
    const double r = std::hypot(d[0], d[1]);
    if (r < rmin) {
      rmin = r;
      itype_tip = static_cast<int>(p[5]);
    }
  }

  // stencils by binning the gathered atoms with cells of side >= rgrad
  double blo[2] = {1.0e300, 1.0e300};
  for (int k = 0; k < n; k++)
    for (int m = 0; m < 2; m++) blo[m] = std::min(blo[m], xloc[2 * k + m]);
  const double side = std::max(rgrad, 2.0 * reach / MAX_BINS);
  const int nb = static_cast<int>(std::ceil(2.0 * reach / side)) + 2;
  auto cell = [&](int k, int m) {
    return std::min(nb - 1, static_cast<int>((xloc[2 * k + m] - blo[m]) / side));
  };
  std::vector<int> head(nb * nb, -1), next(n, -1);
  for (int k = n - 1; k >= 0; k--) {    // lists in the sorted order
    const int c = cell(k, 0) * nb + cell(k, 1);
    next[k] = head[c];
    head[c] = k;
  }
  points.clear();
  nbr_start.assign(1, 0);
  nbr.clear();
  kinv.clear();
  int unresolved = 0;
  for (int k = 0; k < n; k++) {
    const double *pk = &xloc[2 * k];
    if (pk[0] * pk[0] + pk[1] * pk[1] > rout * rout) continue;
    JI::Moment mom;
    const size_t start = nbr.size();
    const int cx = cell(k, 0), cy = cell(k, 1);
    for (int ix = std::max(0, cx - 1); ix <= std::min(nb - 1, cx + 1); ix++)
      for (int iy = std::max(0, cy - 1); iy <= std::min(nb - 1, cy + 1); iy++)
        for (int j = head[ix * nb + iy]; j >= 0; j = next[j]) {
          if (j == k) continue;
          const double *pj = &xloc[2 * j];
          const double xi[2] = {pj[0] - pk[0], pj[1] - pk[1]};
          if (xi[0] * xi[0] + xi[1] * xi[1] > rgrad * rgrad) continue;
          if (JI::crosses_crack(pk, pj)) continue;
          mom.add(xi, area[j]);
          nbr.push_back(j);
        }
    double ki[3];
    if (!mom.inverse(ki)) {
      nbr.resize(start);
      unresolved++;
      continue;
    }
    points.push_back(k);
    nbr_start.push_back(static_cast<int>(nbr.size()));
    kinv.insert(kinv.end(), ki, ki + 3);
  }
  if (points.empty() && unresolved)
    error->all(FLERR, "Compute bbpd/jintegral {}: none of the {} atoms of the disc has enough "
               "neighbours within gradient = {} for a gradient; increase gradient (at least "
               "the grid spacing)", id, unresolved, rgrad);
  if (unresolved && comm->me == 0)
    error->warning(FLERR, "Compute bbpd/jintegral {}: {} atoms of the disc have too few "
                   "neighbours within gradient = {} for a gradient and are left out; increase "
                   "gradient", id, unresolved, rgrad);
  if (points.empty())
    error->all(FLERR, "Compute bbpd/jintegral {}: no atom of group {} in the disc rout = {} "
               "around the tip ({}, {}); check the tip and rout", id, group->names[igroup],
               rout, tip[0], tip[1]);

  fields.assign(NFIELD * n, 0.0);
  aux.clear();    // made by compute_vector() with the elastic constants
  cached_tip[0] = tip[0];
  cached_tip[1] = tip[1];
  cached = 1;
}

/* ---------------------------------------------------------------------- */

void ComputeBBPDJIntegral::compute_vector()
{
  invoked_vector = update->ntimestep;
  double tip[2];
  args.current_tip(tip);
  if (!cached || tip[0] != cached_tip[0] || tip[1] != cached_tip[1]) build_cache(tip);

  // displacement, velocity, acceleration of the cached atoms, in crack-tip coordinates;
  // each atom has one owner, so the sum over ranks is exact
  const int n = static_cast<int>(tags.size());
  std::fill(fields.begin(), fields.end(), 0.0);
  double **x = atom->x, **x0 = atom->x0, **v = atom->v, **f = atom->f;
  const double *rmass = atom->rmass;
  const double *dir = args.dir;    // ahead of the tip
  const double n2[2] = {-dir[1], dir[0]};
  const double prd[2] = {domain->xprd, domain->yprd};
  const int periodic[2] = {domain->xperiodic, domain->yperiodic};
  auto rotate = [&](const double *w, double *out) {
    out[0] = w[0] * dir[0] + w[1] * dir[1];
    out[1] = w[0] * n2[0] + w[1] * n2[1];
  };
  for (int k = 0; k < n; k++) {
    const int i = atom->map(tags[k]);
    if (i < 0 || i >= atom->nlocal) continue;
    double d[2] = {x[i][0] - x0[i][0], x[i][1] - x0[i][1]};
    // displacement, not position: undo a periodic wrap of x relative to x0
    for (int m = 0; m < 2; m++)
      if (periodic[m] && std::fabs(d[m]) > 0.5 * prd[m]) d[m] -= prd[m] * std::round(d[m] / prd[m]);
    const double acc[2] = {f[i][0] / rmass[i], f[i][1] / rmass[i]};
    double *out = &fields[NFIELD * k];
    rotate(d, out);
    rotate(v[i], out + 2);
    rotate(acc, out + 4);
    out[6] = 1.0;
  }
  MPI_Allreduce(MPI_IN_PLACE, fields.data(), NFIELD * n, MPI_DOUBLE, MPI_SUM, world);
  for (int k = 0; k < n; k++)
    if (fields[NFIELD * k + 6] != 1.0)
      error->all(FLERR, "Compute bbpd/jintegral {}: atom ID {} of the disc is lost", id, tags[k]);

  const JI::Elastic el = args.elastic(pair, itype_tip);
  const int npoint = static_cast<int>(points.size());
  if (aux.empty() || aux_elastic[0] != el.E || aux_elastic[1] != el.nu ||
      aux_elastic[2] != el.plane_stress) {
    aux.resize(npoint);
    for (int p = 0; p < npoint; p++)
      JI::aux_fields(&xloc[2 * points[p]], el, rin, rout, aux[p]);
    aux_elastic[0] = el.E;
    aux_elastic[1] = el.nu;
    aux_elastic[2] = el.plane_stress;
  }

  double sum[3] = {0.0, 0.0, 0.0};
  for (int p = 0; p < npoint; p++) {
    const int k = points[p];
    const double *fk = &fields[NFIELD * k];
    double bu[2][2] = {{0.0, 0.0}, {0.0, 0.0}}, bv[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
    for (int s = nbr_start[p]; s < nbr_start[p + 1]; s++) {
      const int j = nbr[s];
      const double *fj = &fields[NFIELD * j];
      const double xi[2] = {xloc[2 * j] - xloc[2 * k], xloc[2 * j + 1] - xloc[2 * k + 1]};
      for (int c = 0; c < 2; c++)
        for (int m = 0; m < 2; m++) {
          bu[c][m] += area[j] * (fj[c] - fk[c]) * xi[m];
          bv[c][m] += area[j] * (fj[2 + c] - fk[2 + c]) * xi[m];
        }
    }
    JI::Point pt{};
    pt.x[0] = xloc[2 * k];
    pt.x[1] = xloc[2 * k + 1];
    JI::apply_inverse(bu, &kinv[3 * p], pt.gu);
    JI::apply_inverse(bv, &kinv[3 * p], pt.gv);
    for (int m = 0; m < 2; m++) {
      pt.v[m] = fk[2 + m];
      pt.a[m] = fk[4 + m];
    }
    pt.rho = rho[k];
    pt.area = area[k];
    double out[3];
    JI::integrand(pt, el, aux[p], out);
    for (int c = 0; c < 3; c++) sum[c] += out[c];
  }
  jvec[0] = sum[0];
  jvec[1] = JI::k_from_interaction(sum[1], el);
  jvec[2] = JI::k_from_interaction(sum[2], el);
}

double ComputeBBPDJIntegral::memory_usage()
{
  return sizeof(double) * (xloc.size() + area.size() + rho.size() + kinv.size() + fields.size()) +
      sizeof(JI::Aux) * aux.size() +
      sizeof(tagint) * tags.size() + sizeof(int) * (points.size() + nbr_start.size() + nbr.size());
}

/* ----------------------------------------------------------------------
   BBPD plugin: bond families (see fix_bbpd_bonds.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_bonds.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_bbpd_notch.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair_bbpd.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

FixBBPDBonds::FixBBPDBonds(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), maxpartner(1), npartner(nullptr), partner(nullptr), vinit(nullptr),
    jlocal(nullptr), xi0(nullptr), coef(nullptr), rbreak2(nullptr), cvv(nullptr), first(1),
    nmax_cache(0), list(nullptr), pair(nullptr)
{
  if (narg != 3) error->all(FLERR, "Fix bbpd/bonds takes no arguments (it is created by the pair style)");
  restart_global = 1;
  restart_peratom = 1;
  stores_ids = 1;

  FixBBPDBonds::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) {
    npartner[i] = 0;
    vinit[i] = 0.0;
  }
}

FixBBPDBonds::~FixBBPDBonds()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(npartner);
  memory->destroy(partner);
  memory->destroy(vinit);
  memory->destroy(jlocal);
  memory->destroy(xi0);
  memory->destroy(coef);
  memory->destroy(rbreak2);
  memory->destroy(cvv);
}

int FixBBPDBonds::setmask()
{
  return POST_NEIGHBOR | MIN_POST_NEIGHBOR;
}

void FixBBPDBonds::init()
{
  pair = dynamic_cast<PairBBPD *>(force->pair_match("^bbpd/", 0));
  if (!pair) error->all(FLERR, "Fix bbpd/bonds requires a bbpd/* pair style");
  // the occasional full list is only needed to build the families once
  if (first) neighbor->add_request(this, NeighConst::REQ_FULL | NeighConst::REQ_OCCASIONAL);
}

void FixBBPDBonds::init_list(int, NeighList *ptr)
{
  list = ptr;
}

/* families are built at the first setup (from the reference positions of that
   moment), then only the local-index cache is refreshed */
void FixBBPDBonds::setup_post_neighbor()
{
  if (first) build_families();
  refresh_cache();
  apply_notches();
  pair->report(this);
}

void FixBBPDBonds::post_neighbor()
{
  refresh_cache();
}

/* ---------------------------------------------------------------------- */

void FixBBPDBonds::build_families()
{
  neighbor->build_one(list);
  double **x = atom->x;
  tagint *tag = atom->tag;
  int *type = atom->type;
  const int nlocal = atom->nlocal;

  auto in_family = [&](int i, int j) {
    const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], dz = x[j][2] - x[i][2];
    const double rc = pair->family_cutoff(type[i], type[j]);
    return dx * dx + dy * dy + dz * dz < rc * rc;
  };

  int mymax = 0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    int n = 0;
    for (int jj = 0; jj < list->numneigh[i]; jj++)
      if (in_family(i, list->firstneigh[i][jj] & NEIGHMASK)) n++;
    mymax = MAX(mymax, n);
  }
  MPI_Allreduce(&mymax, &maxpartner, 1, MPI_INT, MPI_MAX, world);
  maxpartner = MAX(maxpartner, 1);
  memory->destroy(partner);
  partner = nullptr;
  grow_arrays(atom->nmax);
  nmax_cache = 0;    // the cache's row length changed

  for (int i = 0; i < nlocal; i++) npartner[i] = 0;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = list->firstneigh[i][jj] & NEIGHMASK;
      if (in_family(i, j)) partner[i][npartner[i]++] = tag[j];
    }
    // tag order fixes the summation order on every rank count
    std::sort(partner[i], partner[i] + npartner[i]);
    if (std::adjacent_find(partner[i], partner[i] + npartner[i]) != partner[i] + npartner[i])
      error->one(FLERR, "Atom {} bonds twice to the same partner: the periodic box is smaller "
                 "than two horizons", tag[i]);
  }
  first = 0;
  refresh_cache();
  for (int i = 0; i < nlocal; i++) {
    vinit[i] = 0.0;
    for (int k = 0; k < npartner[i]; k++) vinit[i] += cvv[i][k];
  }
}

void FixBBPDBonds::grow_cache()
{
  nmax_cache = atom->nmax;
  memory->destroy(jlocal);
  memory->destroy(xi0);
  memory->destroy(coef);
  memory->destroy(rbreak2);
  memory->destroy(cvv);
  memory->create(jlocal, nmax_cache, maxpartner, "bbpd/bonds:jlocal");
  memory->create(xi0, nmax_cache, maxpartner, "bbpd/bonds:xi0");
  memory->create(coef, nmax_cache, maxpartner, "bbpd/bonds:coef");
  memory->create(rbreak2, nmax_cache, maxpartner, "bbpd/bonds:rbreak2");
  memory->create(cvv, nmax_cache, maxpartner, "bbpd/bonds:cvv");
}

/* local indices and bond coefficients after every reneighboring */
void FixBBPDBonds::refresh_cache()
{
  if (first) return;
  if (nmax_cache < atom->nmax) grow_cache();
  double **x0 = atom->x0;
  double **x = atom->x;
  double *vfrac = atom->vfrac;
  int *type = atom->type;
  tagint *tag = atom->tag;
  const bool periodic = domain->xperiodic || domain->yperiodic || domain->zperiodic;

  for (int i = 0; i < atom->nlocal; i++) {
    for (int k = 0; k < npartner[i]; k++) {
      const tagint t = partner[i][k];
      if (t <= 0) {
        jlocal[i][k] = -1;
        xi0[i][k] = coef[i][k] = cvv[i][k] = 0.0;
        rbreak2[i][k] = 0.0;
        continue;
      }
      int j = atom->map(t);
      if (j < 0)
        error->one(FLERR, "Bond partner {} of atom {} is neither a local nor a ghost atom: "
                   "increase the ghost cutoff with 'comm_modify cutoff' (at least horizon + "
                   "maximum bond elongation)", t, tag[i]);
      if (periodic) j = domain->closest_image(x[i], j);
      double d[3] = {x0[j][0] - x0[i][0], x0[j][1] - x0[i][1], x0[j][2] - x0[i][2]};
      if (periodic) domain->minimum_image(FLERR, d);
      const double xi = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (xi <= 0.0)
        error->one(FLERR, "Atoms {} and {} share a reference position: bonds need distinct atoms",
                   tag[i], t);
      jlocal[i][k] = j;
      xi0[i][k] = xi;
      pair->bond_params(type[i], type[j], xi, vfrac[j], coef[i][k], rbreak2[i][k], cvv[i][k]);
    }
  }
}

void FixBBPDBonds::apply_notches()
{
  for (auto *fix : modify->get_fix_by_style("^bbpd/notch"))
    dynamic_cast<FixBBPDNotch *>(fix)->cut_bonds(this);
}

bigint FixBBPDBonds::count_broken() const
{
  bigint n = 0, all = 0;
  for (int i = 0; i < atom->nlocal; i++)
    for (int k = 0; k < npartner[i]; k++)
      if (partner[i][k] <= 0) n++;
  MPI_Allreduce(&n, &all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return all;
}

/* ---------------------------------------------------------------------- */

double FixBBPDBonds::memory_usage()
{
  const double nmax = atom->nmax;
  double bytes = nmax * (sizeof(int) + sizeof(double));
  bytes += nmax * maxpartner * sizeof(tagint);
  bytes += (double) nmax_cache * maxpartner * (sizeof(int) + 4.0 * sizeof(double));
  return bytes;
}

void FixBBPDBonds::grow_arrays(int nmax)
{
  memory->grow(npartner, nmax, "bbpd/bonds:npartner");
  memory->grow(partner, nmax, maxpartner, "bbpd/bonds:partner");
  memory->grow(vinit, nmax, "bbpd/bonds:vinit");
}

void FixBBPDBonds::copy_arrays(int i, int j, int)
{
  npartner[j] = npartner[i];
  for (int k = 0; k < npartner[j]; k++) partner[j][k] = partner[i][k];
  vinit[j] = vinit[i];
}

int FixBBPDBonds::pack_exchange(int i, double *buf)
{
  int m = 0;
  buf[m++] = npartner[i];
  for (int k = 0; k < npartner[i]; k++) buf[m++] = ubuf(partner[i][k]).d;
  buf[m++] = vinit[i];
  return m;
}

int FixBBPDBonds::unpack_exchange(int nlocal, double *buf)
{
  int m = 0;
  npartner[nlocal] = static_cast<int>(buf[m++]);
  for (int k = 0; k < npartner[nlocal]; k++) partner[nlocal][k] = (tagint) ubuf(buf[m++]).i;
  vinit[nlocal] = buf[m++];
  return m;
}

void FixBBPDBonds::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    double list[2] = {(double) first, (double) maxpartner};
    int size = 2 * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), 2, fp);
  }
}

void FixBBPDBonds::restart(char *buf)
{
  auto *list = (double *) buf;
  first = static_cast<int>(list[0]);
  maxpartner = static_cast<int>(list[1]);
  nmax_cache = 0;
  memory->destroy(partner);
  partner = nullptr;
  grow_arrays(atom->nmax);
}

int FixBBPDBonds::pack_restart(int i, double *buf)
{
  int m = 0;
  buf[m++] = npartner[i] + 3;
  buf[m++] = npartner[i];
  for (int k = 0; k < npartner[i]; k++) buf[m++] = ubuf(partner[i][k]).d;
  buf[m++] = vinit[i];
  return m;
}

void FixBBPDBonds::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  npartner[nlocal] = static_cast<int>(extra[nlocal][m++]);
  for (int k = 0; k < npartner[nlocal]; k++) partner[nlocal][k] = (tagint) ubuf(extra[nlocal][m++]).i;
  vinit[nlocal] = extra[nlocal][m++];
}

int FixBBPDBonds::size_restart(int i)
{
  return npartner[i] + 3;
}

int FixBBPDBonds::maxsize_restart()
{
  return maxpartner + 3;
}

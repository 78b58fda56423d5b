/* ----------------------------------------------------------------------
   BBPD plugin: bond families (see fix_bbpd_bonds.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_bonds.h"
#include "bbpd_compat.h"

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
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// an atom cloud this many times larger than the body at bond creation means the run has blown
// up; stop before LAMMPS bins the exploded box (which can take all the memory)
static constexpr double MAX_EXTENT_GROWTH = 1000.0;
// nor can an atom that moves this many grid spacings in one step be part of a valid run (a stable
// step moves atoms a small fraction of a spacing: dt < spacing / wave speed, and v << wave speed)
static constexpr double MAX_STEP_SPACINGS = 10.0;

FixBBPDBonds::FixBBPDBonds(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), maxpartner(1), npartner(nullptr), partner(nullptr), vinit(nullptr),
    bond_start(nullptr), nbond(nullptr), bj(nullptr), bxi0(nullptr), bcoef(nullptr),
    vintact(nullptr), first(1),
    nlocal_cache(0), nbond_cache(0), list(nullptr), pair(nullptr), extent0(0.0)
{
  if (narg != 3) error->all(FLERR, "Fix bbpd/bonds takes no arguments (it is created by the pair style)");
  restart_global = 1;
  restart_peratom = 1;
  stores_ids = 1;
  create_attribute = 1;    // atoms created later start with no bonds

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
  memory->destroy(bond_start);
  memory->destroy(nbond);
  memory->destroy(bj);
  memory->destroy(bxi0);
  memory->destroy(bcoef);
  memory->destroy(vintact);
}

int FixBBPDBonds::setmask()
{
  return POST_NEIGHBOR | MIN_POST_NEIGHBOR | PRE_EXCHANGE;
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

/* largest extent of the atoms that still have bonds (free fragments may fly away) */
double FixBBPDBonds::local_extent()
{
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300}, glo[3], ghi[3];
  double **x = atom->x;
  for (int i = 0; i < atom->nlocal; i++)
    for (int m = 0; m < 3; m++) {
      if (!first && nbond && nbond[i] == 0) continue;
      lo[m] = MIN(lo[m], x[i][m]);
      hi[m] = MAX(hi[m], x[i][m]);
    }
  MPI_Allreduce(lo, glo, 3, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(hi, ghi, 3, MPI_DOUBLE, MPI_MAX, world);
  double e = 0.0;
  for (int m = 0; m < domain->dimension; m++) e = MAX(e, ghi[m] - glo[m]);
  return MAX(e, 0.0);
}

/* before atoms migrate (once per reneighboring): catch an exploding run */
void FixBBPDBonds::pre_exchange()
{
  if (first) return;
  // no atom may cross a horizon in one step, and the bonded body may not spread out
  double vmax = 0.0, gvmax = 0.0;
  double **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++)
    vmax = MAX(vmax, v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
  MPI_Allreduce(&vmax, &gvmax, 1, MPI_DOUBLE, MPI_MAX, world);
  const double e = local_extent();
  const double step = std::sqrt(gvmax) * update->dt;
  if (!(step <= pair->spacing * MAX_STEP_SPACINGS) || (extent0 > 0.0 && !(e <= MAX_EXTENT_GROWTH * extent0)))
    error->all(FLERR, "BBPD: the run is unstable at step {} (an atom moves {:.3g} grid spacings "
               "per step, the bonded body spans {:.3g} x its size): the timestep {:.6g} must "
               "stay below the stable bound printed at setup", update->ntimestep,
               step / pair->spacing, extent0 > 0.0 ? e / extent0 : 0.0, update->dt);
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
    return pair->in_family(type[i], type[j], dx * dx + dy * dy + dz * dz);
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
  extent0 = local_extent();
  refresh_cache();
  for (int i = 0; i < nlocal; i++) vinit[i] = vintact[i];
}

/* local indices and bond coefficients after every reneighboring */
void FixBBPDBonds::refresh_cache()
{
  if (first) return;
  const int nlocal = atom->nlocal;
  if (nlocal_cache < nlocal + 1) {
    nlocal_cache = atom->nmax + 1;
    memory->destroy(bond_start);
    memory->destroy(nbond);
    memory->destroy(vintact);
    memory->create(bond_start, nlocal_cache, "bbpd/bonds:bond_start");
    memory->create(nbond, nlocal_cache, "bbpd/bonds:nbond");
    memory->create(vintact, nlocal_cache, "bbpd/bonds:vintact");
  }
  int n = 0;
  for (int i = 0; i < nlocal; i++) {
    bond_start[i] = n;
    for (int k = 0; k < npartner[i]; k++) n += partner[i][k] > 0;
  }
  bond_start[nlocal] = n;
  const bool compact = pair->compact_storage;
  if (nbond_cache < n || compact != (bxi0 == nullptr)) {
    nbond_cache = n + n / 8;    // headroom: migration changes the count a little
    memory->destroy(bj);
    memory->destroy(bxi0);
    memory->destroy(bcoef);
    bxi0 = bcoef = nullptr;
    memory->create(bj, nbond_cache, "bbpd/bonds:bj");
    if (!compact) {
      memory->create(bxi0, nbond_cache, "bbpd/bonds:bxi0");
      memory->create(bcoef, nbond_cache, "bbpd/bonds:bcoef");
    }
  }

  double **x0 = atom->x0;
  double **x = atom->x;
  double *vfrac = atom->vfrac;
  int *type = atom->type;
  tagint *tag = atom->tag;
  const bool periodic = domain->xperiodic || domain->yperiodic || domain->zperiodic;

  for (int i = 0; i < nlocal; i++) {
    int m = bond_start[i];
    for (int k = 0; k < npartner[i]; k++) {
      const tagint t = partner[i][k];
      if (t <= 0) continue;
      int j = atom->map(t);
      if (j < 0)
        error->one(FLERR, "Bond partner {} of atom {} is neither a local nor a ghost atom at "
                   "step {}: either the run is unstable (timestep {:.6g}, stable bound {:.6g}) "
                   "or an intact bond stretched beyond the ghost cutoff: then increase it with "
                   "'comm_modify cutoff' (at least horizon + maximum bond elongation)", t, tag[i],
                   update->ntimestep, update->dt, *pair->extract_bound());
      if (periodic) j = domain->closest_image(x[i], j);
      double d[3] = {x0[j][0] - x0[i][0], x0[j][1] - x0[i][1], x0[j][2] - x0[i][2]};
      if (periodic) BBPDCompat::minimum_image(domain, d);
      const double xi = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (xi <= 0.0)
        error->one(FLERR, "Atoms {} and {} share a reference position: bonds need distinct atoms",
                   tag[i], t);
      bj[m] = j;
      if (!compact) {
        bxi0[m] = xi;
        bcoef[m] = pair->bond_coef(type[i], type[j], xi, vfrac[j]);
      }
      m++;
    }
    nbond[i] = m - bond_start[i];
    vintact[i] = intact_volume(i);
  }
}

/* sum of C_v V_j over the intact bonds of atom i, in tag order */
double FixBBPDBonds::intact_volume(int i) const
{
  double v = 0.0;
  for (int k = bond_start[i]; k < bond_start[i] + nbond[i]; k++)
    v += pair->bond_volume(atom->type[i], atom->type[bj[k]], xi0_of(i, k), atom->vfrac[bj[k]]);
  return v;
}

/* break bond k of local atom i: flag its partner tag, then close the gap in the row */
void FixBBPDBonds::remove_bond(int i, int k)
{
  const tagint t = atom->tag[bj[k]];
  tagint *p = partner[i];
  // partners are sorted by tag and a broken one keeps its tag's magnitude
  int lo = 0, hi = npartner[i] - 1;
  while (lo <= hi) {
    const int mid = (lo + hi) / 2;
    const tagint v = p[mid] < 0 ? -p[mid] : p[mid];
    if (v == t) {
      p[mid] = -t;
      break;
    }
    if (v < t) lo = mid + 1;
    else hi = mid - 1;
  }
  const int last = bond_start[i] + nbond[i] - 1;
  for (int m = k; m < last; m++) bj[m] = bj[m + 1];
  if (bxi0)
    for (int m = k; m < last; m++) {
      bxi0[m] = bxi0[m + 1];
      bcoef[m] = bcoef[m + 1];
    }
  nbond[i]--;
  // summed again rather than decremented: the same bits as after the next reneighboring
  vintact[i] = intact_volume(i);
}

/* the same operations as refresh_cache(), so compact storage gives the same bits */
double FixBBPDBonds::xi0_of(int i, int k) const
{
  if (bxi0) return bxi0[k];
  double **x0 = atom->x0;
  const int j = bj[k];
  double d[3] = {x0[j][0] - x0[i][0], x0[j][1] - x0[i][1], x0[j][2] - x0[i][2]};
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

double FixBBPDBonds::coef_of(int i, int k, double xi0) const
{
  if (bcoef) return bcoef[k];
  const int j = bj[k];
  return pair->bond_coef(atom->type[i], atom->type[j], xi0, atom->vfrac[j]);
}

double FixBBPDBonds::bytes_per_bond() const
{
  // per bond end: partner tag (persistent) + bj [+ bxi0 + bcoef] (cache); two ends per bond
  const double cached = pair->compact_storage ? 0.0 : 2.0 * sizeof(double);
  return 2.0 * (sizeof(tagint) + sizeof(int) + cached);
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
  bytes += nlocal_cache * (2.0 * sizeof(int) + sizeof(double));
  bytes += (double) nbond_cache * (sizeof(int) + (bxi0 ? 2.0 * sizeof(double) : 0.0));
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

void FixBBPDBonds::set_arrays(int i)
{
  npartner[i] = 0;
  vinit[i] = 0.0;
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

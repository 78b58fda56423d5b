// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: bond families (see fix_bbpd_bonds.h)
------------------------------------------------------------------------- */

#include "fix_bbpd_bonds.h"
#include "bbpd_compat.h"
#include "bbpd_family_order.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "memory.h"
#include "my_page.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "pair.h"
#include "math_const.h"
#include "update.h"

#include <algorithm>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
// the offset x_j - x_i of atoms i and j in a flat array of positions (LAMMPS allocates its
// per-atom vectors contiguous: a component is one load away, not a row pointer and then it);
// the families, the bond cache and xi0_of take the reference offsets here, with the same bits
inline void offset_of(const double *xf, int i, int j, double *d)
{
  for (int m = 0; m < 3; m++) d[m] = xf[3 * j + m] - xf[3 * i + m];
}
}    // namespace

using MathConst::MY_PI;

// LAMMPS's default page size is 100 x its default 'neigh_modify one' (neighbor.cpp); the family
// build asks for at least this ratio when it raises 'one' (LAMMPS requires page >= 10 x one)
static constexpr int PAGE_PER_ONE = 10;
// the bond cache is allocated 1/64 larger than the rank's bonds: atoms that migrate in at a
// reneighboring rarely bring more, and the headroom costs 0.2 bytes per bond (16 bytes per bond)
static constexpr int CACHE_HEADROOM = 64;

FixBBPDBonds::FixBBPDBonds(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), maxpartner(1), npartner(nullptr), vinit(nullptr),
    ebroken(nullptr),
    bond_start(nullptr), nbond(nullptr), bdelta(nullptr), jstart(nullptr), bj(nullptr), bclass(nullptr),
    bxi0(nullptr),
    bcoef(nullptr),
    vintact(nullptr), uniform_type(0), uniform_vfrac(0.0), first(1),
    nlocal_cache(0), nbond_cache(0), list(nullptr), have_rules(false),
    extent0(0.0), need_raw(0), nmax_raw(0), xraw(nullptr), generation(0), xi0_min(0.0),
    nbj_cache(0), nindex_ends(0)
{
  if (narg != 3) error->all(FLERR, "Fix bbpd/bonds takes no arguments (it is created by the pair style)");
  restart_global = 1;
  restart_peratom = 1;
  stores_ids = 1;
  create_attribute = 1;    // atoms created later start with no bonds
  // a migrating atom carries all its partner tags: LAMMPS must size its exchange buffer for them
  maxexchange_dynamic = 1;
  set_maxexchange();

  FixBBPDBonds::grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) {
    npartner[i] = 0;
    vinit[i] = 0.0;
    ebroken[i] = 0.0;
  }
}

FixBBPDBonds::~FixBBPDBonds()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(npartner);
  memory->destroy(vinit);
  memory->destroy(ebroken);
  memory->destroy(bond_start);
  memory->destroy(nbond);
  memory->destroy(bdelta);
  memory->destroy(jstart);
  memory->destroy(bj);
  memory->destroy(bclass);
  memory->destroy(bxi0);
  memory->destroy(bcoef);
  memory->destroy(vintact);
  memory->destroy(xraw);
}

int FixBBPDBonds::setmask()
{
  return POST_NEIGHBOR | MIN_POST_NEIGHBOR | PRE_FORCE | MIN_PRE_FORCE;
}

void FixBBPDBonds::init()
{
  if (!have_rules) error->all(FLERR, "Fix bbpd/bonds requires a bbpd/* pair style");
  // the occasional half list (newton off: a pair of a local and a ghost atom at its local atom)
  // is only needed to build the families once
  if (first) {
    neighbor->add_request(this, NeighConst::REQ_NEWTON_OFF | NeighConst::REQ_OCCASIONAL);
    size_family_neighbor_list();
  }
  choose_sort_bins();
  // in a periodic box the two ends of a bond see different images of each other (x + L rounds
  // differently from x - L): both decide breaking from their owners' unshifted positions
  // (a 2D body has no image in z)
  const bool periodic = domain->xperiodic || domain->yperiodic ||
      (domain->zperiodic && domain->dimension == 3);
  need_raw = periodic && limits.breaks_bonds;
  comm_forward = need_raw ? 3 : 0;
}

/* The family build lists every atom within the family cutoff + skin. An atom's cell of volume
   at least dmin^d (d the family dimension, dmin the smallest grid spacing implied by the atom
   volumes) lies within half a cell diagonal of the atom, so at most
   ball_d(R + sqrt(d) dmin / 2) / dmin^d atoms are within R of it. Raise LAMMPS's per-atom
   neighbor limit (neigh_modify one, and page) to that bound when it is larger. */
void FixBBPDBonds::size_family_neighbor_list()
{
  double vmin = 1e300, gvmin = 1e300;
  for (int i = 0; i < atom->nlocal; i++)
    if (atom->vfrac[i] > 0.0) vmin = MIN(vmin, atom->vfrac[i]);
  MPI_Allreduce(&vmin, &gvmin, 1, MPI_DOUBLE, MPI_MIN, world);
  if (gvmin >= 1e300) return;
  const int d = BBPD::family_dimension(law.model);
  const double dmin = law.spacing_of_volume(gvmin);
  const double r = (force->pair->cutforce + neighbor->skin) / dmin + 0.5 * std::sqrt((double) d);
  const double ball = d == 1 ? 2.0 * r : d == 2 ? MY_PI * r * r : 4.0 / 3.0 * MY_PI * r * r * r;
  if (!(ball < (double) MAXSMALLINT / PAGE_PER_ONE))
    error->all(FLERR, "BBPD: bond families of up to {:.3g} partners per atom cannot be listed: "
               "reduce the horizon (delta/spacing)", ball);
  const int need = static_cast<int>(std::ceil(ball));
  if (need <= neighbor->oneatom) return;
  neighbor->oneatom = need;
  neighbor->pgsize = MAX(neighbor->pgsize, PAGE_PER_ONE * need);
  if (comm->me == 0)
    utils::logmesg(lmp, "BBPD: bond families need up to {} neighbors per atom: set "
                   "'neigh_modify one {} page {}'\n", need, neighbor->oneatom, neighbor->pgsize);
}

/* In 3D LAMMPS sorts atoms by bins of half the neighbor cutoff, z slowest: in a body thicker
   than two bins the partners above and below an atom lie a whole layer of bins away in memory,
   beyond a 2-byte offset (bbpd_partner_index.h), and the rows take indices (4 bytes per bond end
   instead of 2). Bins as wide as the family cutoff keep every partner within the neighboring
   bins, and a plate up to two cutoffs thick in one layer of bins. Only when the input has not
   chosen a bin size ('atom_modify sort'); the bins order memory, never what is computed. */
void FixBBPDBonds::choose_sort_bins()
{
  if (domain->dimension != 3 || atom->sortfreq <= 0 || !force->pair) return;
  if (atom->userbinsize > 0.0 && atom->userbinsize != sort_binsize) return;    // the input's
  if (atom->userbinsize == force->pair->cutforce) return;
  sort_binsize = atom->userbinsize = force->pair->cutforce;
  if (comm->me == 0)
    utils::logmesg(lmp, "BBPD: atoms sorted in bins of the family cutoff {:.6g}, so that bond "
                   "partners stay near in memory (set 'atom_modify sort' to choose)\n",
                   sort_binsize);
}

/* ghosts get their owners' unshifted positions before every force evaluation */
void FixBBPDBonds::setup_pre_force(int vflag)
{
  pre_force(vflag);
}

void FixBBPDBonds::pre_force(int)
{
  if (!need_raw) return;
  // on one rank every ghost's owner is local, and the atom map finds it (owned atoms before
  // ghosts): raw_x reads it when a row asks, with no copy of every ghost each step (the
  // forward_comm below cost about 2 % of a bbpd/pmb step on LAMMPS's bpm/peri deck)
  owners_local = comm->nprocs == 1 && atom->map_style != Atom::MAP_NONE;
  if (owners_local) return;
  if (atom->nmax > nmax_raw) {
    nmax_raw = atom->nmax;
    memory->destroy(xraw);
    memory->create(xraw, nmax_raw, 3, "bbpd/bonds:xraw");
  }
  comm->forward_comm(this);
}

const double *FixBBPDBonds::raw_x(int j) const
{
  if (j < atom->nlocal) return atom->x[j];
  return owners_local ? atom->x[atom->map(atom->tag[j])] : xraw[j];
}

int FixBBPDBonds::pack_forward_comm(int n, int *list, double *buf, int, int *)
{
  // no periodic shift: the receiver wants the owner's coordinates
  double **x = atom->x;
  int m = 0;
  for (int k = 0; k < n; k++) {
    const int j = list[k];
    const double *src = j < atom->nlocal ? x[j] : xraw[j];
    buf[m++] = src[0];
    buf[m++] = src[1];
    buf[m++] = src[2];
  }
  return m;
}

void FixBBPDBonds::unpack_forward_comm(int n, int first_atom, double *buf)
{
  int m = 0;
  for (int i = first_atom; i < first_atom + n; i++) {
    xraw[i][0] = buf[m++];
    xraw[i][1] = buf[m++];
    xraw[i][2] = buf[m++];
  }
}

void FixBBPDBonds::init_list(int, NeighList *ptr)
{
  list = ptr;
}

/* families are built at the first setup (from the reference positions of that
   moment), then only the local-index cache is refreshed. Notches are cut by fix
   bbpd/notch and the setup report is printed by the pair style, from their own hooks. */
void FixBBPDBonds::setup_post_neighbor()
{
  // (a family build ends with a fresh cache)
  if (first) build_families();
  else refresh_cache();
}

void FixBBPDBonds::post_neighbor()
{
  if (same_atoms_at_same_indices()) return;
  refresh_cache();
}

/* A reneighboring that neither migrated, sorted nor re-imaged an atom leaves the same atom
   at every local and ghost index: then every cached partner index, and every value derived
   from the atoms' fixed reference data, is still exact. Only in a box without periodic
   dimensions: there a ghost with the same tag could be another image of its owner. */
bool FixBBPDBonds::same_atoms_at_same_indices()
{
  if (domain->xperiodic || domain->yperiodic || domain->zperiodic) return false;
  const int nall = atom->nlocal + atom->nghost;
  const tagint *tag = atom->tag;
  return tags_cached.size() == (size_t) nall &&
      std::equal(tags_cached.begin(), tags_cached.end(), tag);
}

/* largest extent of the atoms that still have bonds (free fragments may fly away); of all atoms
   before the families exist */
double FixBBPDBonds::bonded_extent()
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

/* ---------------------------------------------------------------------- */

void FixBBPDBonds::build_families()
{
  neighbor->build_one(list);
  double **x = atom->x;
  double **x0 = atom->x0;
  tagint *tag = atom->tag;
  int *type = atom->type;
  const int nlocal = atom->nlocal;

  const double *xf = nlocal ? x[0] : nullptr, *x0f = nlocal ? x0[0] : nullptr;
  auto in_family = [&](int i, int j) {
    double d[3];
    offset_of(xf, i, j, d);
    return law.bonded(type[i], type[j], d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  };

  // the list is half (each pair of local atoms once, a local-ghost pair at its local atom): a
  // listed pair joins the family of each local end
  // counted first, so that every row is allocated once at its length; the count marks each
  // listed pair that is bonded (a bit per pair), so that the fill reads no position again
  std::vector<std::uint64_t> bonded;
  grow_arrays(atom->nmax);
  for (int i = 0; i < nlocal; i++) npartner[i] = 0;
  {
    std::size_t e = 0;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      bonded.resize((e + list->numneigh[i]) / 64 + 1, 0);
      for (int jj = 0; jj < list->numneigh[i]; jj++, e++) {
        const int j = list->firstneigh[i][jj] & NEIGHMASK;
        if (!in_family(i, j)) continue;
        bonded[e / 64] |= std::uint64_t(1) << (e % 64);
        npartner[i]++;
        if (j < nlocal) npartner[j]++;
      }
    }
  }
  auto for_each_pair = [&](auto &&add) {
    std::size_t e = 0;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      for (int jj = 0; jj < list->numneigh[i]; jj++, e++) {
        if (!(bonded[e / 64] >> (e % 64) & 1)) continue;
        const int j = list->firstneigh[i][jj] & NEIGHMASK;
        add(i, j);
        if (j < nlocal) add(j, i);
      }
    }
  };
  int mymax = 0;
  std::size_t total = 0;
  for (int i = 0; i < nlocal; i++) {
    partner.clear(i);
    total += npartner[i];
  }
  partner.reserve_more(total);
  for (int i = 0; i < nlocal; i++) {
    partner.resize(i, npartner[i]);
    mymax = MAX(mymax, npartner[i]);
    npartner[i] = 0;
  }
  // local or ghost indices until the families are sorted below, then tags
  for_each_pair([&](int i, int j) { partner[i][npartner[i]++] = j; });
  std::vector<std::uint64_t>().swap(bonded);
  MPI_Allreduce(&mymax, &maxpartner, 1, MPI_INT, MPI_MAX, world);
  maxpartner = MAX(maxpartner, 1);
  set_maxexchange();
  // the rows hold the families: the list's pages go back before the sort below and the cache
  release_family_list();
#if defined(__GLIBC__)
  // the pages are small blocks inside the heap, which glibc keeps resident once freed: hand the
  // free memory back, so that the resident set peaks at the tags and the cache alone
  malloc_trim(0);
#endif

  // partners in the order of their reference offset (z, then y, then x, compared exactly; ties:
  // tag order, only for partners that share a reference position): the summation order then
  // depends on the geometry alone, not on how atoms are numbered (create_atoms numbers them
  // rank by rank) or listed. x varies fastest, as in LAMMPS's spatial sort of the atoms in
  // memory. A partner's offset is the minimum image in a periodic box, the same for any of
  // its images.
  {
    const bool periodic = domain->xperiodic || domain->yperiodic || domain->zperiodic;
    std::vector<BBPD::FamilyEntry<tagint>> family;
    BBPD::FamilyOrder<tagint> order;
    std::vector<tagint> tags;
    for (int i = 0; i < nlocal; i++) {
      // entries written in place: an entry built aside and copied in was read back whole from
      // its scalar stores (a stalled store forwarding per partner, 19 % of this function)
      family.resize(npartner[i]);
      for (int k = 0; k < npartner[i]; k++) {
        const int j = partner[i][k];
        double d[3];
        offset_of(x0f, i, j, d);
        if (periodic) BBPDCompat::minimum_image(domain, d);
        BBPD::FamilyEntry<tagint> &e = family[k];
        e.z = d[2];
        e.y = d[1];
        e.x = d[0];
        e.tag = tag[j];
      }
      order.sort(family, law.spacing);
      for (int k = 0; k < npartner[i]; k++) partner[i][k] = family[k].tag;
      // two images of one atom in a family (only a periodic box has images)
      if (!periodic) continue;
      tags.assign(partner[i], partner[i] + npartner[i]);
      std::sort(tags.begin(), tags.end());
      if (std::adjacent_find(tags.begin(), tags.end()) != tags.end())
        error->one(FLERR, "Atom {} bonds twice to the same partner: the periodic box is smaller "
                   "than two horizons", tag[i]);
    }
  }
  first = 0;
  extent0 = bonded_extent();
  refresh_cache();
  for (int i = 0; i < nlocal; i++) vinit[i] = vintact[i];
}

/* The families are in the partner tags now: the list's pages go back before the families are
   sorted and the bond cache is allocated, so that the two never take memory at the same time (4
   bytes per listed pair; the list is half, and with LAMMPS's skin holds about 0.7-0.9 pairs
   per bond). MyPage::init frees every page but a first one, of each of the list's page sets
   (one per thread); a later build_one() refills the list. */
void FixBBPDBonds::release_family_list()
{
  // only pages of the list's own: a copy of another list (with 'contact yes' the pair's list
  // may be the parent) points at the parent's pages, and a list derived from this one would
  // still read them
  if (list->copy || list->listcopy || !list->ipage) return;
  for (int m = 0; m < neighbor->nlist; m++) {
    const NeighList *other = neighbor->lists[m];
    if (other != list && (other->listcopy == list || other->listskip == list || other->listfull == list))
      return;
  }
  list->inum = list->gnum = 0;    // firstneigh pointed into the pages
  for (int t = 0; t < comm->nthreads; t++) list->ipage[t].init(neighbor->oneatom, neighbor->pgsize);
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
    memory->destroy(jstart);
    memory->create(bond_start, nlocal_cache, "bbpd/bonds:bond_start");
    memory->create(nbond, nlocal_cache, "bbpd/bonds:nbond");
    memory->create(jstart, nlocal_cache, "bbpd/bonds:jstart");
    memory->create(vintact, nlocal_cache, "bbpd/bonds:vintact");
  }
  // bond ends of this rank, counted in a bigint: the cache indexes them with int
  bigint nbig = 0;
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < npartner[i]; k++) nbig += partner[i][k] > 0;
  if (nbig > MAXSMALLINT)
    error->one(FLERR, "BBPD: rank {} holds {} bond ends, more than the {} one rank can index: "
               "run on more MPI ranks (at least {} x as many)", comm->me, nbig, MAXSMALLINT,
               nbig / MAXSMALLINT + 1);
  int n = 0;
  for (int i = 0; i < nlocal; i++) {
    bond_start[i] = n;
    for (int k = 0; k < npartner[i]; k++) n += partner[i][k] > 0;
  }
  bond_start[nlocal] = n;
  generation++;
  tags_cached.assign(atom->tag, atom->tag + nlocal + atom->nghost);
  const bool compact = !policy.caches_geometry();
  if (nbond_cache < n) {
    // headroom: migration changes the count a little (a rebuild reallocates past it)
    nbond_cache = static_cast<int>(MIN((bigint) n + n / CACHE_HEADROOM, (bigint) MAXSMALLINT));
    free_partners();
    free_bond_values();
  }
  // offsets; a row with a partner out of reach of an offset keeps indices (in bj, from
  // jstart[i]), decided again at every refresh (as is a rank of indices alone)
  if (!bdelta) {
    free_partners();
    memory->create(bdelta, nbond_cache + LANES_PAD, "bbpd/bonds:bdelta");
    for (int m = nbond_cache; m < nbond_cache + LANES_PAD; m++) bdelta[m] = 0;
  }
  if (compact) free_bond_values();
  else if (!bclass && !bxi0) {
    // the SIMD kernels read the classes of a row in whole vectors: LANES more, never used
    memory->create(bclass, nbond_cache + LANES_PAD, "bbpd/bonds:bclass");
    for (int m = nbond_cache; m < nbond_cache + LANES_PAD; m++) bclass[m] = 0;
  }
  classes.clear();

  double **x = atom->x;
  const double *x0f = nlocal ? atom->x0[0] : nullptr;
  double *vfrac = atom->vfrac;
  int *type = atom->type;
  tagint *tag = atom->tag;
  const bool periodic = domain->xperiodic || domain->yperiodic || domain->zperiodic;
  xi0_min = std::numeric_limits<double>::infinity();

  uniform_type = 0;
  const int nall = atom->nlocal + atom->nghost;
  if (compact && nall > 0) {
    uniform_type = type[0];
    uniform_vfrac = vfrac[0];
    for (int j = 1; j < nall && uniform_type; j++)
      if (type[j] != uniform_type || std::memcmp(&vfrac[j], &uniform_vfrac, sizeof(double)) != 0)
        uniform_type = 0;
  }

  int nbj = 0;    // entries of bj taken by index rows
  std::vector<int> row;
  // on a grid most rows repeat the row before bond for bond: a bond of the same length to a
  // partner of the same type and volume from an atom of the same type has the same coefficient
  // and class (compared by their bits), found without the bond law or the class table's hash
  struct Seen {
    double xi, vj, coef, volume;
    int jtype, cls;
  };
  std::vector<Seen> prev, cur;
  int prev_itype = -1;
  auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; };
  for (int i = 0; i < nlocal; i++) {
    int m = bond_start[i];
    cur.clear();
    double volume = 0.0;    // intact_volume(i), summed as it does (fast storage)
    bool fits = bdelta != nullptr;
    row.clear();
    for (int k = 0; k < npartner[i]; k++) {
      const tagint t = partner[i][k];
      if (t <= 0) continue;
      int j = atom->map(t);
      if (j < 0)
        error->one(FLERR, "Bond partner {} of atom {} is neither a local nor a ghost atom at "
                   "step {}: either the run is unstable (timestep {:.6g}, stable bound {:.6g}) "
                   "or an intact bond stretched beyond the ghost cutoff: then increase it with "
                   "'comm_modify cutoff' (at least horizon + maximum bond elongation)", t, tag[i],
                   update->ntimestep, update->dt, limits.stable_timestep);
      if (periodic) j = domain->closest_image(x[i], j);
      double d[3];
      offset_of(x0f, i, j, d);
      if (periodic) BBPDCompat::minimum_image(domain, d);
      const double xi = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (xi <= 0.0)
        error->one(FLERR, "Atoms {} and {} share a reference position: bonds need distinct atoms",
                   tag[i], t);
      fits = fits && BBPD::fits_offset(i, j);
      row.push_back(j);
      xi0_min = std::min(xi0_min, xi);
      if (!compact) {
        const std::size_t kk = cur.size();
        if (type[i] == prev_itype && kk < prev.size() && same(prev[kk].xi, xi) &&
            prev[kk].jtype == type[j] && same(prev[kk].vj, vfrac[j])) {
          cur.push_back(prev[kk]);
          if (bclass) bclass[m] = static_cast<BBPD::BondClass>(prev[kk].cls);
          else store_bond_values(m, xi, prev[kk].coef);
        } else {
          const double coef = law.coefficient(type[i], type[j], xi, vfrac[j]);
          store_bond_values(m, xi, coef);
          cur.push_back({xi, vfrac[j], coef, law.partner_volume(type[i], type[j], xi, vfrac[j]),
                         type[j], bclass ? (int) bclass[m] : -1});
        }
        volume += cur.back().volume;
      }
      m++;
    }
    prev.swap(cur);
    prev_itype = type[i];
    const int beg = bond_start[i];
    nbond[i] = m - beg;
    jstart[i] = -1;
    if (!bdelta) {
      std::copy(row.begin(), row.end(), bj + beg);
    } else if (fits) {
      for (int k = 0; k < nbond[i]; k++) bdelta[beg + k] = static_cast<BBPD::PartnerOffset>(row[k] - i);
    } else {
      reserve_indices(nbj + nbond[i]);
      jstart[i] = nbj;
      std::copy(row.begin(), row.end(), bj + nbj);
      nbj += nbond[i];
    }
    vintact[i] = compact ? intact_volume(i) : volume;
  }
  nindex_ends = bdelta ? nbj : n;
  // an end of an index row costs 6 bytes beside offsets (its unused offset too), 4 in a rank of
  // index rows alone: past half of the ends the rank keeps indices alone (offsets are tried
  // again at the next rebuild)
  if (bdelta && 2 * (bigint) nbj > n) all_indices();
}

/* every row of the rank as indices, indexed like bclass: no offsets, no jstart */
void FixBBPDBonds::all_indices()
{
  const int nlocal = atom->nlocal;
  std::vector<int> full(bond_start[nlocal]);
  for (int i = 0; i < nlocal; i++)
    for (int k = bond_start[i]; k < bond_start[i] + nbond[i]; k++) full[k] = partner_of(i, k);
  free_partners();
  reserve_indices(nbond_cache);
  std::copy(full.begin(), full.end(), bj);
  nindex_ends = bond_start[nlocal];
}

void FixBBPDBonds::free_partners()
{
  memory->destroy(bdelta);
  memory->destroy(bj);
  bdelta = nullptr;
  bj = nullptr;
  nbj_cache = 0;
}

/* bj holds at least n entries (and a SIMD vector's more, which a row end may read); the entries
   kept keep their values. Index rows beside offsets grow it by half again at a time. */
void FixBBPDBonds::reserve_indices(int n)
{
  if (n + LANES_PAD <= nbj_cache) return;
  const bigint want = bdelta ? MAX((bigint) n, (bigint) nbj_cache + nbj_cache / 2) : (bigint) n;
  nbj_cache = static_cast<int>(MIN(want + LANES_PAD, (bigint) MAXSMALLINT));
  memory->grow(bj, nbj_cache, "bbpd/bonds:bj");
}

void FixBBPDBonds::free_bond_values()
{
  memory->destroy(bclass);
  memory->destroy(bxi0);
  memory->destroy(bcoef);
  bclass = nullptr;
  bxi0 = bcoef = nullptr;
}

/* reference length and coefficient of cache entry m: its class, or per bond once the table
   is full (the entries before m then move from the table to per-bond storage) */
void FixBBPDBonds::store_bond_values(int m, double xi, double coef)
{
  if (bclass) {
    if (classes.add(xi, coef, bclass[m])) return;
    memory->create(bxi0, nbond_cache, "bbpd/bonds:bxi0");
    memory->create(bcoef, nbond_cache, "bbpd/bonds:bcoef");
    for (int e = 0; e < m; e++) {
      bxi0[e] = classes.xi0(bclass[e]);
      bcoef[e] = classes.coef(bclass[e]);
    }
    memory->destroy(bclass);
    bclass = nullptr;
    classes.clear();
  }
  bxi0[m] = xi;
  bcoef[m] = coef;
}

/* sum of C_v V_j over the intact bonds of atom i, in row order */
double FixBBPDBonds::intact_volume(int i) const
{
  double v = 0.0;
  for (int k = bond_start[i]; k < bond_start[i] + nbond[i]; k++)
  {
    const int j = partner_of(i, k);
    v += law.partner_volume(atom->type[i], atom->type[j], xi0_of(i, k), atom->vfrac[j]);
  }
  return v;
}

/* a new generation of the compact coefficients, distinct across every bond fix of the process:
   a thread's cache (bbpd_bond_values.h) may have served another pair style */
unsigned FixBBPDBonds::next_coef_epoch()
{
  static std::atomic<unsigned> epochs{0};
  return ++epochs;
}

/* break bond k of local atom i: flag its partner tag, then close the gap in the row (vintact is
   summed again by remove_bonds_if, once per row) */
void FixBBPDBonds::remove_bond(int i, int k)
{
  const tagint t = atom->tag[partner_of(i, k)];
  tagint *p = partner[i];
  // partners are in reference-offset order; bonds break rarely, so a scan is enough
  for (int m = 0; m < npartner[i]; m++)
    if (p[m] == t) {
      p[m] = -t;
      break;
    }
  const int last = bond_start[i] + nbond[i] - 1;
  if (index_row(i)) {
    // the same shift in the row's own entries of bj
    const int shift = bdelta ? jstart[i] - bond_start[i] : 0;
    for (int m = k; m < last; m++) bj[m + shift] = bj[m + shift + 1];
  } else {
    for (int m = k; m < last; m++) bdelta[m] = bdelta[m + 1];
  }
  if (bclass)
    for (int m = k; m < last; m++) bclass[m] = bclass[m + 1];
  if (bxi0)
    for (int m = k; m < last; m++) {
      bxi0[m] = bxi0[m + 1];
      bcoef[m] = bcoef[m + 1];
    }
  nbond[i]--;
}

/* the same operations as refresh_cache(), so compact storage gives the same bits */
double FixBBPDBonds::xi0_of(int i, int k) const
{
  if (bclass) return classes.xi0(bclass[k]);
  if (bxi0) return bxi0[k];
  double d[3];
  offset_of(atom->x0[0], i, partner_of(i, k), d);
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

double FixBBPDBonds::coef_of(int i, int k, double xi0) const
{
  if (bclass) return classes.coef(bclass[k]);
  if (bcoef) return bcoef[k];
  const int j = partner_of(i, k);
  return law.coefficient(atom->type[i], atom->type[j], xi0, atom->vfrac[j]);
}

double FixBBPDBonds::bytes_per_bond() const
{
  // per bond end: partner tag (persistent) + bdelta | bj [+ bclass | bxi0 + bcoef] (cache); two
  // ends per bond (the class table itself is a few kB per rank, not counted)
  const double cached = bclass ? sizeof(BBPD::BondClass) : bxi0 ? 2.0 * sizeof(double) : 0.0;
  // offsets where the rows have them, and 4 bytes more for each end of an index row
  const bigint ends = bond_start ? (bigint) bond_start[atom->nlocal] : 0;
  const double index = bdelta ? sizeof(BBPD::PartnerOffset) + (ends ? sizeof(int) * (double) nindex_ends / ends : 0.0)
                              : sizeof(int);
  return 2.0 * (sizeof(tagint) + index + cached);
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
  double bytes = nmax * (sizeof(int) + 2.0 * sizeof(double));    // npartner, vinit, ebroken
  bytes += partner.bytes();
  bytes += nlocal_cache * (2.0 * sizeof(int) + sizeof(double));
  bytes += (double) nbond_cache * (bxi0 ? 2.0 * sizeof(double) : 0.0);
  if (bdelta) bytes += (nbond_cache + LANES_PAD) * sizeof(BBPD::PartnerOffset);
  bytes += (double) nbj_cache * sizeof(int) + nlocal_cache * sizeof(int);    // bj, jstart
  if (bclass)
    bytes += (nbond_cache + LANES_PAD) * sizeof(BBPD::BondClass) +
        2.0 * sizeof(double) * classes.size();
  bytes += 3.0 * nmax_raw * sizeof(double);
  return bytes;
}

void FixBBPDBonds::grow_arrays(int nmax)
{
  memory->grow(npartner, nmax, "bbpd/bonds:npartner");
  partner.grow(nmax);
  memory->grow(vinit, nmax, "bbpd/bonds:vinit");
  memory->grow(ebroken, nmax, "bbpd/bonds:ebroken");
}

void FixBBPDBonds::copy_arrays(int i, int j, int delflag)
{
  npartner[j] = npartner[i];
  // a deleted source (migration) hands its row over; a sort reads the source again
  if (delflag) partner.move(i, j);
  else partner.copy(i, j, npartner[i]);
  vinit[j] = vinit[i];
  ebroken[j] = ebroken[i];
}

void FixBBPDBonds::set_arrays(int i)
{
  npartner[i] = 0;
  partner.clear(i);
  vinit[i] = 0.0;
  ebroken[i] = 0.0;
}

int FixBBPDBonds::pack_exchange(int i, double *buf)
{
  int m = 0;
  buf[m++] = npartner[i];
  for (int k = 0; k < npartner[i]; k++) buf[m++] = ubuf(partner[i][k]).d;
  buf[m++] = vinit[i];
  buf[m++] = ebroken[i];
  return m;
}

int FixBBPDBonds::unpack_exchange(int nlocal, double *buf)
{
  int m = 0;
  npartner[nlocal] = static_cast<int>(buf[m++]);
  partner.resize(nlocal, npartner[nlocal]);
  for (int k = 0; k < npartner[nlocal]; k++) partner[nlocal][k] = (tagint) ubuf(buf[m++]).i;
  vinit[nlocal] = buf[m++];
  ebroken[nlocal] = buf[m++];
  return m;
}

// global restart data: {first + RESTART_WITH_EXTENT, maxpartner, extent0}; files written before
// extent0 was stored hold {first, maxpartner} with first 0 or 1
static constexpr int RESTART_WITH_EXTENT = 2;

void FixBBPDBonds::write_restart(FILE *fp)
{
  if (comm->me == 0) {
    double list[3] = {(double) (first + RESTART_WITH_EXTENT), (double) maxpartner, extent0};
    int size = 3 * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), 3, fp);
  }
}

void FixBBPDBonds::restart(char *buf)
{
  auto *list = (double *) buf;
  first = static_cast<int>(list[0]);
  maxpartner = static_cast<int>(list[1]);
  if (first >= RESTART_WITH_EXTENT) {
    first -= RESTART_WITH_EXTENT;
    extent0 = list[2];
  }
  set_maxexchange();
  grow_arrays(atom->nmax);
}

// per atom: {size, npartner, partners..., vinit, ebroken}; files written before ebroken was
// stored end at vinit (their size is npartner + 3)
static constexpr int RESTART_VALUES_OLD = 3, RESTART_VALUES = 4;

int FixBBPDBonds::pack_restart(int i, double *buf)
{
  int m = 0;
  buf[m++] = npartner[i] + RESTART_VALUES;
  buf[m++] = npartner[i];
  for (int k = 0; k < npartner[i]; k++) buf[m++] = ubuf(partner[i][k]).d;
  buf[m++] = vinit[i];
  buf[m++] = ebroken[i];
  return m;
}

void FixBBPDBonds::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const int size = static_cast<int>(extra[nlocal][m++]);
  npartner[nlocal] = static_cast<int>(extra[nlocal][m++]);
  partner.resize(nlocal, npartner[nlocal]);
  for (int k = 0; k < npartner[nlocal]; k++) partner[nlocal][k] = (tagint) ubuf(extra[nlocal][m++]).i;
  vinit[nlocal] = extra[nlocal][m++];
  ebroken[nlocal] = size > npartner[nlocal] + RESTART_VALUES_OLD ? extra[nlocal][m++] : 0.0;
}

int FixBBPDBonds::size_restart(int i)
{
  return npartner[i] + RESTART_VALUES;
}

int FixBBPDBonds::maxsize_restart()
{
  return maxpartner + RESTART_VALUES;
}

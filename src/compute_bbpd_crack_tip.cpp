// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: compute bbpd/crack/tip (see header and doc/compute_bbpd_crack_tip.rst)
------------------------------------------------------------------------- */

#include "compute_bbpd_crack_tip.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_bbpd_bonds.h"
#include "force.h"
#include "modify.h"
#include "pair_bbpd.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>

using namespace LAMMPS_NS;
using BBPD::CrackTip::Node;

namespace {
// damage beside a notch between two rows of a square grid, horizon m spacings (measured,
// doc/compute_bbpd_crack_tip.rst): 0.38 / 0.41 / 0.44 in the first row of atoms at m = 2 / 3 / 5,
// 0.10 / 0.11 / 0.12 at the first atom ahead of the notch tip. 0.3 takes the first row of a
// crack and not the atoms ahead of its tip.
constexpr double THRESHOLD_DEFAULT = 0.3;
constexpr double SPAN_DEFAULT = 2.0;      // chord of the direction, in units of the link
constexpr double WINDOW_DEFAULT = 0.0;    // speed since the previous invocation
// least length of a branch beyond its split point, in units of the link: a tip must stand two
// horizons above where it leaves the crack, so that a bump of the damage band (a few grid
// spacings) is no branch (tests/unit/test_crack_branches.cpp)
constexpr double BRANCH_DEFAULT = 2.0;
constexpr int MAXTIPS_DEFAULT = 8;        // rows of the array
constexpr double UNSET = -1.0;
static_assert(std::is_trivially_copyable<Node>::value, "nodes are sent as bytes");
}    // namespace

/* ---------------------------------------------------------------------- */

ComputeBBPDCrackTip::ComputeBBPDCrackTip(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), values{0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    params{{0.0, 0.0}, {1.0, 0.0}, THRESHOLD_DEFAULT, UNSET, UNSET}, link_user(UNSET),
    span_user(UNSET), history(WINDOW_DEFAULT), bonds(nullptr), have_found(false),
    branches(false), maxtips(MAXTIPS_DEFAULT), branch_user(UNSET), min_length(UNSET),
    tracker(WINDOW_DEFAULT), invoked_branches(-1)
{
  if (narg < 5 || !utils::is_double(arg[3]) || !utils::is_double(arg[4]))
    error->all(FLERR, "Illegal compute bbpd/crack/tip command: expected 'compute ID group "
               "bbpd/crack/tip X Y [keyword value ...]' with X Y the notch tip");
  params.start[0] = utils::numeric(FLERR, arg[3], false, lmp);
  params.start[1] = utils::numeric(FLERR, arg[4], false, lmp);

  double window = WINDOW_DEFAULT;
  bool maxtips_given = false;
  int iarg = 5;
  auto value = [&](const char *key) {
    if (iarg + 1 >= narg) error->all(FLERR, "Compute bbpd/crack/tip: keyword {} needs a value", key);
    return utils::numeric(FLERR, arg[iarg + 1], false, lmp);
  };
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (key == "threshold") {
      params.threshold = value("threshold");
      if (params.threshold <= 0.0 || params.threshold > 1.0)
        error->all(FLERR, "Compute bbpd/crack/tip: threshold must lie in (0, 1], got {}",
                   params.threshold);
      iarg += 2;
    } else if (key == "link" || key == "span") {
      const double v = value(key.c_str());
      if (v <= 0.0) error->all(FLERR, "Compute bbpd/crack/tip: {} must be > 0, got {}", key, v);
      (key == "link" ? link_user : span_user) = v;
      iarg += 2;
    } else if (key == "window") {
      window = value("window");
      if (window < 0.0)
        error->all(FLERR, "Compute bbpd/crack/tip: window must be >= 0 (a time), got {}", window);
      iarg += 2;
    } else if (key == "direction") {
      if (iarg + 2 >= narg) error->all(FLERR, "Compute bbpd/crack/tip: direction needs DX DY");
      const double dx = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      const double dy = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      const double len = std::sqrt(dx * dx + dy * dy);
      if (len == 0.0)
        error->all(FLERR, "Compute bbpd/crack/tip: direction {} {} has zero length", dx, dy);
      params.dir[0] = dx / len;
      params.dir[1] = dy / len;
      iarg += 3;
    } else if (key == "branches") {
      if (iarg + 1 >= narg) error->all(FLERR, "Compute bbpd/crack/tip: keyword branches needs "
                                       "yes or no");
      branches = utils::logical(FLERR, arg[iarg + 1], false, lmp) == 1;
      iarg += 2;
    } else if (key == "branch") {
      branch_user = value("branch");
      if (branch_user <= 0.0)
        error->all(FLERR, "Compute bbpd/crack/tip: branch must be > 0 (a length), got {}",
                   branch_user);
      iarg += 2;
    } else if (key == "maxtips") {
      if (iarg + 1 >= narg) error->all(FLERR, "Compute bbpd/crack/tip: keyword maxtips needs a value");
      maxtips = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (maxtips < 1)
        error->all(FLERR, "Compute bbpd/crack/tip: maxtips must be >= 1 (rows of the array), "
                   "got {}", maxtips);
      maxtips_given = true;
      iarg += 2;
    } else {
      error->all(FLERR, "Compute bbpd/crack/tip: unknown keyword '{}' (expected threshold, "
                 "link, span, window, direction, branches, branch or maxtips)", key);
    }
  }
  history = BBPD::CrackTip::History(window);
  tracker = BBPD::CrackTip::BranchTracker(window);
  if (!branches && (branch_user > 0.0 || maxtips_given))
    error->all(FLERR, "Compute bbpd/crack/tip: keywords branch and maxtips need 'branches yes'");

  vector_flag = 1;
  size_vector = branches ? NBRANCHVALUES : NVALUES;
  extvector = 0;
  vector = values;
  if (branches) {
    array_flag = 1;
    size_array_rows = maxtips;
    size_array_cols = NCOLS;
    extarray = 0;
    block.assign(static_cast<std::size_t>(maxtips) * NCOLS, 0.0);
    for (int k = 0; k < maxtips; k++) rows.push_back(block.data() + k * NCOLS);
    array = rows.data();
  }
}

/* ---------------------------------------------------------------------- */

void ComputeBBPDCrackTip::init()
{
  if (domain->dimension != 2)
    error->all(FLERR, "Compute bbpd/crack/tip works in 2D only (dimension 2, the crack in the "
               "x-y plane)");
  if (!atom->peri_flag || !atom->x0)
    error->all(FLERR, "Compute bbpd/crack/tip requires atom_style peri (reference positions x0)");
  auto pair = dynamic_cast<PairBBPD *>(force->pair_match("^bbpd/", 0));
  bonds = dynamic_cast<FixBBPDBonds *>(modify->get_fix_by_id("BBPD_BONDS"));
  if (!pair || !bonds) error->all(FLERR, "Compute bbpd/crack/tip requires a bbpd/* pair style");

  // the link defaults to the largest horizon: atoms a crack separates lie within it
  double delta = 0.0;
  int dim = 0;
  auto horizon = static_cast<double **>(pair->extract("horizon", dim));
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) delta = std::max(delta, horizon[i][j]);
  params.link = link_user > 0.0 ? link_user : delta;
  if (pair->spacing > 0.0 && params.link < pair->spacing)
    error->all(FLERR, "Compute bbpd/crack/tip: link {} is below the grid spacing {}: no two "
               "atoms would be connected; increase link (default: the horizon)", params.link,
               pair->spacing);
  params.span = span_user > 0.0 ? span_user : SPAN_DEFAULT * params.link;
  min_length = branch_user > 0.0 ? branch_user : BRANCH_DEFAULT * params.link;
  have_found = false;    // the link may have changed with the pair style
  invoked_branches = -1;
}

/* the gathered crack atoms are those of the last search, in the same order */
bool ComputeBBPDCrackTip::same_nodes() const
{
  if (!have_found || all.size() != searched.size()) return false;
  for (std::size_t k = 0; k < all.size(); k++)
    if (all[k].tag != searched[k].tag || all[k].x != searched[k].x || all[k].y != searched[k].y)
      return false;
  return true;
}

/* ---------------------------------------------------------------------- */

void ComputeBBPDCrackTip::compute_vector()
{
  invoked_vector = update->ntimestep;
  if (branches) {
    compute_branches();
    return;
  }
  gather();

  // the damage of a crack atom does not enter the search: a new search only if the set changed
  if (!same_nodes()) {
    found = BBPD::CrackTip::find_tip(all, params);
    searched = all;
    have_found = true;
  }
  record_tip();
}

/* the speed's history and the first six values from the tip found; returns the time */
double ComputeBBPDCrackTip::record_tip()
{
  const BBPD::CrackTip::Result &r = found;
  const double time = update->atime + (update->ntimestep - update->atimestep) * update->dt;
  history.record(time, r.extension);
  values[0] = r.x;
  values[1] = r.y;
  values[2] = r.extension;
  values[3] = history.speed();
  values[4] = r.direction;
  values[5] = static_cast<double>(r.nodes);
  return time;
}

/* ---------------------------------------------------------------------- */

void ComputeBBPDCrackTip::compute_array()
{
  invoked_array = update->ntimestep;
  compute_branches();
}

/* the vector and the array of branches yes, once per step whichever is asked first */
void ComputeBBPDCrackTip::compute_branches()
{
  if (invoked_branches == update->ntimestep) return;
  invoked_branches = update->ntimestep;
  gather();
  if (!same_nodes()) {
    graph = BBPD::CrackTip::search(all, params);
    const std::size_t top = BBPD::CrackTip::tip_index(graph, params);
    found = top == graph.node.size() ? BBPD::CrackTip::no_tip(params, graph.reached)
                                     : BBPD::CrackTip::tip_at(graph, top, params);
    tips = BBPD::CrackTip::find_branches(graph, params, min_length);
    searched = all;
    have_found = true;
  }
  tracker.record(record_tip(), graph, tips);
  values[6] = static_cast<double>(tips.size());
  values[7] = static_cast<double>(tracker.splits().size());

  std::fill(block.begin(), block.end(), 0.0);    // rows past the tips
  const auto &tracks = tracker.tracks();
  for (std::size_t k = 0; k < tips.size() && k < static_cast<std::size_t>(maxtips); k++) {
    const BBPD::CrackTip::Result &t = tips[k].tip;
    const BBPD::CrackTip::Split &s = tracks[k].split;
    const bool split = s.time >= 0.0;
    const double row[NCOLS] = {t.x, t.y, t.extension, tracks[k].history.speed(), t.direction,
                               split ? s.x : params.start[0], split ? s.y : params.start[1],
                               s.time, s.length};
    std::copy(row, row + NCOLS, rows[k]);
  }
}

/* the candidate atoms of every rank, on every rank, in `all` */
void ComputeBBPDCrackTip::gather()
{
  mine.clear();
  double **x0 = atom->x0;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    const double phi = bonds->damage(i);
    if (BBPD::CrackTip::candidate(params, x0[i][0], x0[i][1], phi))
      mine.push_back({static_cast<std::int64_t>(tag[i]), x0[i][0], x0[i][1], phi});
  }

  // every rank gets every candidate: the damaged set is small
  bigint nmine = mine.size(), nall = 0;
  MPI_Allreduce(&nmine, &nall, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (nall > MAXSMALLINT / static_cast<bigint>(sizeof(Node)))
    error->all(FLERR, "Compute bbpd/crack/tip {}: {} damaged atoms are too many to gather; "
               "raise the threshold", id, nall);
  const int nprocs = comm->nprocs;
  std::vector<int> counts(nprocs), displs(nprocs);
  int nbytes = static_cast<int>(nmine * sizeof(Node));    // not const: the MPI stubs take void *
  MPI_Allgather(&nbytes, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  all.resize(nall);
  MPI_Allgatherv(mine.data(), nbytes, MPI_BYTE, all.data(), counts.data(), displs.data(),
                 MPI_BYTE, world);
}

/* ---------------------------------------------------------------------- */

double ComputeBBPDCrackTip::memory_usage()
{
  return static_cast<double>((mine.capacity() + all.capacity() + searched.capacity() +
                              graph.node.capacity()) * sizeof(Node) +
                             (graph.col.capacity() + graph.pred.capacity()) * sizeof(std::size_t) +
                             (graph.length.capacity() + graph.len.capacity() + block.size()) *
                                 sizeof(double));
}

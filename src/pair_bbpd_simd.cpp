// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: which path the bond loops of a bbpd pair style run (pair_style ... simd):
   the one forced, or (auto) the fastest of those every rank's CPU runs, timed on rank 0's own
   rows at the first setup and sent to every rank (bbpd_row_paths.h). The paths give the same
   bits, so the choice changes the speed alone.
------------------------------------------------------------------------- */

#include "pair_bbpd.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_bbpd_bonds.h"

#include <algorithm>
#include <chrono>
#include <limits>

using namespace LAMMPS_NS;
using BBPD::SimdPath;

// auto times each candidate on a block of consecutive rows from the middle of rank 0's atoms
// (interior rows, in the run's own layout) of at least this many bond ends: enough for the
// clock, and all of it a small fraction of a setup (doc/performance.md)
static constexpr long TIMED_BOND_ENDS = 1L << 16;
// fewer bond ends than this on rank 0 (a test's few atoms) are not timed: the clock and the
// per-row overheads would decide, not the kernels; the widest path runs
static constexpr long TIMED_BOND_ENDS_MIN = 4096;
// rounds in turn over the candidates, the fastest of each kept (the first also warms the
// caches and the wide units' clocks)
static constexpr int TIMED_ROUNDS = 3;

/* the paths every rank's CPU runs, as bits 1 << path */
static int supported_everywhere(MPI_Comm world)
{
  // one flag per path, the smallest over the ranks (MPI_MIN: LAMMPS's serial MPI stubs have
  // no bitwise reductions)
  int mine[BBPD::NPATHS], all[BBPD::NPATHS];
  for (int p = 0; p < BBPD::NPATHS; p++) mine[p] = BBPD::path_supported(static_cast<SimdPath>(p));
  MPI_Allreduce(mine, all, BBPD::NPATHS, MPI_INT, MPI_MIN, world);
  int mask = 0;
  for (int p = 0; p < BBPD::NPATHS; p++)
    if (all[p]) mask |= 1 << p;
  return mask;
}

static std::string path_list(int mask)
{
  std::string s;
  for (int p = 0; p < BBPD::NPATHS; p++)
    if (mask & (1 << p))
      s += std::string(s.empty() ? "" : ", ") + BBPD::path_name(static_cast<SimdPath>(p));
  return s;
}

/* a forced path must run on every rank's CPU: a clear ERROR at the pair_style command */
void PairBBPD::check_simd_request()
{
  if (simd_request == SimdPath::AUTO) return;
  const int mask = supported_everywhere(world);
  if (mask & (1 << static_cast<int>(simd_request))) return;
  const char *name = BBPD::path_name(simd_request);
  if (!BBPD::path_built(simd_request))
    error->all(FLERR, "Pair style {}: simd {}: this plugin was built without the {} path (its "
               "compiler does not take the flags): use simd auto or one of {}", style, name, name,
               path_list(mask));
  error->all(FLERR, "Pair style {}: simd {} needs a CPU with {}, which {} lacks{}: use simd auto "
             "or one of {}", style, name, BBPD::path_needs(simd_request),
             comm->nprocs > 1 ? "the CPU of a rank" : "this CPU",
             BBPD::path_hidden(simd_request) ? " (hidden by the environment variable "
                                               "BBPD_SIMD_HIDE)" : "",
             path_list(mask));
}

/* seconds for the row forces of rows first..last-1 on path p (results discarded) */
double PairBBPD::time_path(SimdPath p, int first, int last)
{
  const SimdPath kept = simd_path;
  simd_path = p;
  BBPD::CoefCache *cache = thread_coef_cache();
  double acc[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, sum = 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = first; i < last; i++) {
    double fi[3];
    row_force<0, 0, 0>(i, fi, nullptr, acc, cache);
    sum += fi[0];
  }
  const auto t1 = std::chrono::steady_clock::now();
  simd_path = kept;
  timing_sink = sum;    // kept, so that no loop is optimised away
  return std::chrono::duration<double>(t1 - t0).count();
}

/* the path of the bond loops and why (once per pair_style command with auto) */
void PairBBPD::choose_simd_path()
{
  if (simd_request != SimdPath::AUTO) {
    simd_path = simd_request;
    simd_reason = "forced by the simd keyword";
    return;
  }
  if (simd_decided) return;
  simd_decided = true;
  const int mask = supported_everywhere(world);
  int choice = 0;    // the portable loop, which every CPU runs
  for (int p = 0; p < BBPD::NPATHS; p++)
    if (mask & (1 << p)) choice = p;    // the widest, unless the timing below decides
  std::string why;
  if (mask == 1) {
    why = "auto: the only path every rank's CPU runs";
  } else if (comm->me == 0) {
    // a block of rows from the middle of the rank's atoms, TIMED_BOND_ENDS or all of them
    const int nlocal = atom->nlocal;
    long ends = 0;
    for (int i = 0; i < nlocal; i++) ends += bonds->nbond[i];
    int first = nlocal / 2, last = first;
    long timed = 0;
    if (ends <= TIMED_BOND_ENDS) {
      first = 0;
      last = nlocal;
      timed = ends;
    }
    while (timed < TIMED_BOND_ENDS && (first > 0 || last < nlocal)) {
      if (last < nlocal) timed += bonds->nbond[last++];
      if (timed < TIMED_BOND_ENDS && first > 0) timed += bonds->nbond[--first];
    }
    if (timed < TIMED_BOND_ENDS_MIN) {
      why = fmt::format("auto: rank 0 has {} bond ends, too few to time; the widest path every "
                        "rank's CPU runs", timed);
    } else {
      double best[BBPD::NPATHS];
      for (double &b : best) b = std::numeric_limits<double>::infinity();
      const auto t0 = std::chrono::steady_clock::now();
      for (int round = 0; round < TIMED_ROUNDS; round++)
        for (int p = 0; p < BBPD::NPATHS; p++)
          if (mask & (1 << p))
            best[p] = std::min(best[p], time_path(static_cast<SimdPath>(p), first, last));
      const auto t1 = std::chrono::steady_clock::now();
      const double spent = std::chrono::duration<double>(t1 - t0).count();
      std::string times;
      for (int p = BBPD::NPATHS - 1; p >= 0; p--)
        if (mask & (1 << p)) {
          if (best[p] < best[choice]) choice = p;
          times += fmt::format("{}{} {:.3g} ms", times.empty() ? "" : ", ",
                               BBPD::path_name(static_cast<SimdPath>(p)), 1e3 * best[p]);
        }
      why = fmt::format("auto: the fastest over {} bond ends of rank 0 ({}; fastest of {} "
                        "rounds, {:.3g} ms in all)", timed, times, TIMED_ROUNDS, 1e3 * spent);
    }
  }
  MPI_Bcast(&choice, 1, MPI_INT, 0, world);
  simd_path = static_cast<SimdPath>(choice);
  simd_reason = why;    // rank 0 reports it
}

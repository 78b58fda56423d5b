// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD: the path chooser of the bond loops (see bbpd_path_choice.h)
------------------------------------------------------------------------- */

#include "bbpd_path_choice.h"

#include "fmt/format.h"

#include <algorithm>
#include <chrono>
#include <limits>

namespace BBPD {

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
int paths_supported_everywhere(MPI_Comm world)
{
  // one flag per path, the smallest over the ranks (MPI_MIN: LAMMPS's serial MPI stubs have
  // no bitwise reductions)
  int mine[NPATHS], all[NPATHS];
  for (int p = 0; p < NPATHS; p++) mine[p] = path_supported(static_cast<SimdPath>(p));
  MPI_Allreduce(mine, all, NPATHS, MPI_INT, MPI_MIN, world);
  int mask = 0;
  for (int p = 0; p < NPATHS; p++)
    if (all[p]) mask |= 1 << p;
  return mask;
}

std::string path_list(int mask)
{
  std::string s;
  for (int p = 0; p < NPATHS; p++)
    if (mask & (1 << p))
      s += std::string(s.empty() ? "" : ", ") + path_name(static_cast<SimdPath>(p));
  return s;
}

std::string simd_request_problem(SimdPath request, MPI_Comm world, int nprocs,
                                 const std::string &style)
{
  if (request == SimdPath::AUTO) return "";
  const int mask = paths_supported_everywhere(world);
  if (mask & (1 << static_cast<int>(request))) return "";
  const char *name = path_name(request);
  if (!path_built(request))
    return fmt::format("Pair style {}: simd {}: this plugin was built without the {} path (its "
                       "compiler does not take the flags): use simd auto or one of {}",
                       style, name, name, path_list(mask));
  return fmt::format("Pair style {}: simd {} needs a CPU with {}, which {} lacks{}: use simd "
                     "auto or one of {}",
                     style, name, path_needs(request),
                     nprocs > 1 ? "the CPU of a rank" : "this CPU",
                     path_hidden(request) ? " (hidden by the environment variable "
                                            "BBPD_SIMD_HIDE)"
                                          : "",
                     path_list(mask));
}

PathChoice choose_path(SimdPath request, MPI_Comm world, int me, const int *nbond, int nlocal,
                       const std::function<double(SimdPath, int, int)> &seconds)
{
  if (request != SimdPath::AUTO) return {request, "forced by the simd keyword"};
  const int mask = paths_supported_everywhere(world);
  int choice = 0;    // the portable loop, which every CPU runs
  for (int p = 0; p < NPATHS; p++)
    if (mask & (1 << p)) choice = p;    // the widest, unless the timing below decides
  std::string why;
  if (mask == 1) {
    why = "auto: the only path every rank's CPU runs";
  } else if (me == 0) {
    // a block of rows from the middle of the rank's atoms, TIMED_BOND_ENDS or all of them
    long ends = 0;
    for (int i = 0; i < nlocal; i++) ends += nbond[i];
    int first = nlocal / 2, last = first;
    long timed = 0;
    if (ends <= TIMED_BOND_ENDS) {
      first = 0;
      last = nlocal;
      timed = ends;
    }
    while (timed < TIMED_BOND_ENDS && (first > 0 || last < nlocal)) {
      if (last < nlocal) timed += nbond[last++];
      if (timed < TIMED_BOND_ENDS && first > 0) timed += nbond[--first];
    }
    if (timed < TIMED_BOND_ENDS_MIN) {
      why = fmt::format("auto: rank 0 has {} bond ends, too few to time; the widest path every "
                        "rank's CPU runs",
                        timed);
    } else {
      double best[NPATHS];
      for (double &b : best) b = std::numeric_limits<double>::infinity();
      const auto t0 = std::chrono::steady_clock::now();
      for (int round = 0; round < TIMED_ROUNDS; round++)
        for (int p = 0; p < NPATHS; p++)
          if (mask & (1 << p))
            best[p] = std::min(best[p], seconds(static_cast<SimdPath>(p), first, last));
      const auto t1 = std::chrono::steady_clock::now();
      const double spent = std::chrono::duration<double>(t1 - t0).count();
      std::string times;
      for (int p = NPATHS - 1; p >= 0; p--)
        if (mask & (1 << p)) {
          if (best[p] < best[choice]) choice = p;
          times += fmt::format("{}{} {:.3g} ms", times.empty() ? "" : ", ",
                               path_name(static_cast<SimdPath>(p)), 1e3 * best[p]);
        }
      why = fmt::format("auto: the fastest over {} bond ends of rank 0 ({}; fastest of {} "
                        "rounds, {:.3g} ms in all)",
                        timed, times, TIMED_ROUNDS, 1e3 * spent);
    }
  }
  MPI_Bcast(&choice, 1, MPI_INT, 0, world);
  return {static_cast<SimdPath>(choice), why};    // rank 0 reports the reason
}

}    // namespace BBPD

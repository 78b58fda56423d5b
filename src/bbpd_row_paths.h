// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the paths of the bond loops, chosen at run time, with no LAMMPS dependency.

   One plugin holds every path its compiler can build: the portable loop (bbpd_row.h,
   compiled with the plugin's own flags), and the AVX2 and AVX-512 kernels of bbpd_row.h and
   bbpd_stretch_row.h, each compiled for its own instruction set in its own file
   (bbpd_row_avx2.cpp, bbpd_row_avx512.cpp; CMakeLists.txt sets their flags). The pair styles
   call a SIMD path only where path_supported() says the CPU runs it (cpuid), so no
   instruction the CPU lacks ever executes. All paths give the same bits (bbpd_simd.h).
------------------------------------------------------------------------- */

#ifndef BBPD_ROW_PATHS_H
#define BBPD_ROW_PATHS_H

#include "bbpd_bond_values.h"
#include "bbpd_partner_index.h"

#include <string>

namespace BBPD {

struct RowTally;    // bbpd_row.h

// what a row tallies besides its force (the EV argument of the kernels): nothing, each bond's
// energy and virial, or each bond's energy alone, the virial then coming from the rows' forces
// (PairBBPD::row_tally)
constexpr int TALLY_NONE = 0, TALLY_ENERGY_VIRIAL = 1, TALLY_ENERGY = 2;
constexpr bool tallies_virial(int ev) { return ev == TALLY_ENERGY_VIRIAL; }

namespace LPS {    // bbpd_lps.h, bbpd_lps_lanes.h
  struct AtomState;
  struct RowCoefficients;
  struct HistoryCoefficients;
  struct ForceLanes;
}    // namespace LPS

// in the order of preference where no timing decides (widest first), AUTO last
enum class SimdPath : int { PORTABLE = 0, AVX2 = 1, AVX512 = 2, AUTO = 3 };
constexpr int NPATHS = 3;    // PORTABLE, AVX2, AVX512

const char *path_name(SimdPath p);
// the path named by 'name' (auto, portable, avx2, avx512); false if none is
bool path_from_name(const std::string &name, SimdPath &p);
// compiled into this plugin (the compiler took the path's flags)
bool path_built(SimdPath p);
// the CPU runs it (cpuid, with the operating system's support of its registers), and the test
// hook BBPD_SIMD_HIDE (a comma-separated list of paths) does not hide it
bool path_supported(SimdPath p);
// named in BBPD_SIMD_HIDE
bool path_hidden(SimdPath p);
// the instructions a path needs, for messages
const char *path_needs(SimdPath p);

// the layouts of a row's values the kernels are instantiated for (bbpd_bond_values.h)
using CompactValues = RecomputedValues<CoefFunction, false>;
using UniformCompactValues = RecomputedValues<CoefFunction, true>;

// the kernels are called once per row: hidden, a call goes straight to them, not through the
// plugin's procedure linkage table
#if defined(__GNUC__)
#define BBPD_PATH_HIDDEN __attribute__((visibility("hidden")))
#else
#define BBPD_PATH_HIDDEN
#endif

/* the SIMD row kernels of one path (row_force_avx2/avx512 of bbpd_row.h,
   row_force_stretch_avx2/avx512 of bbpd_stretch_row.h, the LPS passes of bbpd_lps_lanes.h and
   bbpd_lps_history_lanes.h), defined and instantiated in the path's own
   file: a caller sees declarations only, so no copy of them is ever compiled for another
   instruction set */
struct BBPD_PATH_HIDDEN Avx2Path {
  template <int FRACTURE, int EV, class Model, class Idx, class Values>
  static bool row_force(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                        double s0, double margin, double *ax, double *ay, double *az,
                        RowTally *tally);
  template <int EV, class Model, class Rule, class Values, class Idx>
  static bool row_force_stretch(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                                const double *smin, double s00, double alpha, double margin,
                                double s0_floor, double *smin_row, double *ax, double *ay,
                                double *az, RowTally *tally);
  template <class Idx, class Values>
  static double lps_dilatation(const double *xx, int i, const Idx *bj, const Values &vals, int n);
  template <int EV, int CHECK, class Idx, class Values>
  static bool lps_force(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                        const LPS::AtomState *states, const LPS::RowCoefficients &c,
                        const double *smin, double *snew, LPS::ForceLanes &out);
  template <class F, int EV, class Idx, class Values>
  static bool lps_history_norm_force(const double *xx, int i, const Idx *bj, const Values &vals,
                                     int n, const LPS::AtomState *states, const F &fam,
                                     const LPS::HistoryCoefficients &c, const int *slot,
                                     double *hist, const double *smin, double *snew,
                                     LPS::ForceLanes &out, double *norm_sum);
  template <class F, int EV, int CHECK, int COMMIT, class Idx, class Values>
  static bool lps_history_force(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                                const LPS::AtomState *states, const F &fam,
                                const typename F::Plan &plan, const LPS::HistoryCoefficients &c,
                                const int *slot, double *hist, const double *smin, double *snew,
                                LPS::ForceLanes &out);
};
struct BBPD_PATH_HIDDEN Avx512Path {
  template <int FRACTURE, int EV, class Model, class Idx, class Values>
  static bool row_force(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                        double s0, double margin, double *ax, double *ay, double *az,
                        RowTally *tally);
  template <int EV, class Model, class Rule, class Values, class Idx>
  static bool row_force_stretch(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                                const double *smin, double s00, double alpha, double margin,
                                double s0_floor, double *smin_row, double *ax, double *ay,
                                double *az, RowTally *tally);
  template <class Idx, class Values>
  static double lps_dilatation(const double *xx, int i, const Idx *bj, const Values &vals, int n);
  template <int EV, int CHECK, class Idx, class Values>
  static bool lps_force(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                        const LPS::AtomState *states, const LPS::RowCoefficients &c,
                        const double *smin, double *snew, LPS::ForceLanes &out);
  template <class F, int EV, class Idx, class Values>
  static bool lps_history_norm_force(const double *xx, int i, const Idx *bj, const Values &vals,
                                     int n, const LPS::AtomState *states, const F &fam,
                                     const LPS::HistoryCoefficients &c, const int *slot,
                                     double *hist, const double *smin, double *snew,
                                     LPS::ForceLanes &out, double *norm_sum);
  template <class F, int EV, int CHECK, int COMMIT, class Idx, class Values>
  static bool lps_history_force(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                                const LPS::AtomState *states, const F &fam,
                                const typename F::Plan &plan, const LPS::HistoryCoefficients &c,
                                const int *slot, double *hist, const double *smin, double *snew,
                                LPS::ForceLanes &out);
};

/* simd(Avx2Path()) or simd(Avx512Path()) on a SIMD path p the plugin holds, else portable() */
template <class Simd, class Portable>
inline auto on_path(SimdPath p, Simd &&simd, Portable &&portable)
{
  switch (p) {
#ifdef BBPD_HAVE_AVX512
    case SimdPath::AVX512:
      return simd(Avx512Path());
#endif
#ifdef BBPD_HAVE_AVX2
    case SimdPath::AVX2:
      return simd(Avx2Path());
#endif
    default:
      return portable();
  }
}

}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the definitions and instantiations of one SIMD path's kernels of the linear
   peridynamic solid's rows and of its families with history (bbpd_lps_lanes.h,
   bbpd_lps_history_lanes.h; declared in bbpd_row_paths.h), included by
   bbpd_row_path_kernels.h inside namespace BBPD (after bbpd_lps_lanes.h), with BBPD_ROW_PATH
   and BBPD_FOR_LAYOUTS defined there: the bond-based kernels' file names no model family, this one is the LPS's.
------------------------------------------------------------------------- */

#ifndef BBPD_LPS_PATH_KERNELS_H
#define BBPD_LPS_PATH_KERNELS_H

#if !defined(BBPD_ROW_PATH) || !defined(BBPD_FOR_LAYOUTS)
#error "bbpd_lps_path_kernels.h is included by bbpd_row_path_kernels.h only"
#endif

template <class Idx, class Values>
double BBPD_ROW_PATH::lps_dilatation(const double *xx, int i, const Idx *bj, const Values &vals, int n)
{
  return lps_dilatation_simd(xx, i, bj, vals, n);
}

template <int EV, int CHECK, class Idx, class Values>
bool BBPD_ROW_PATH::lps_force(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                              const LPS::AtomState *states, const LPS::RowCoefficients &c,
                              const double *smin, double *snew, LPS::ForceLanes &out)
{
  return lps_force_simd<EV, CHECK>(xx, i, bj, vals, n, states, c, smin, snew, out);
}

template <class F, int EV, class Idx, class Values>
bool BBPD_ROW_PATH::lps_history_norm_force(const double *xx, int i, const Idx *bj,
                                           const Values &vals, int n, const LPS::AtomState *states,
                                           const F &fam, const LPS::HistoryCoefficients &c,
                                           const int *slot, double *hist, const double *smin,
                                           double *snew, LPS::ForceLanes &out, double *norm_sum)
{
  return lps_history_norm_force_simd<F, EV>(xx, i, bj, vals, n, states, fam, c, slot, hist, smin,
                                            snew, out, norm_sum);
}

template <class F, int EV, int CHECK, int COMMIT, class Idx, class Values>
bool BBPD_ROW_PATH::lps_history_force(const double *xx, int i, const Idx *bj, const Values &vals,
                                      int n, const LPS::AtomState *states, const F &fam,
                                      const typename F::Plan &plan,
                                      const LPS::HistoryCoefficients &c, const int *slot,
                                      double *hist, const double *smin, double *snew,
                                      LPS::ForceLanes &out)
{
  return lps_history_force_simd<F, EV, CHECK, COMMIT>(xx, i, bj, vals, n, states, fam, plan, c, slot,
                                                      hist, smin, snew, out);
}

#define BBPD_LPS_DILATATION(A, B, IDX, VALUES)                                               \
  template double BBPD_ROW_PATH::lps_dilatation<IDX, VALUES>(const double *, int, const IDX *, \
                                                             const VALUES &, int);
#define BBPD_LPS_FORCE(EV, CHECK, IDX, VALUES)                                                \
  template bool BBPD_ROW_PATH::lps_force<EV, CHECK, IDX, VALUES>(                             \
      const double *, int, const IDX *, const VALUES &, int, const LPS::AtomState *,          \
      const LPS::RowCoefficients &, const double *, double *, LPS::ForceLanes &);
BBPD_FOR_LAYOUTS(BBPD_LPS_DILATATION, 0, 0)
BBPD_FOR_LAYOUTS(BBPD_LPS_FORCE, 0, 0)
BBPD_FOR_LAYOUTS(BBPD_LPS_FORCE, 0, 1)
BBPD_FOR_LAYOUTS(BBPD_LPS_FORCE, 1, 0)
BBPD_FOR_LAYOUTS(BBPD_LPS_FORCE, 1, 1)
BBPD_FOR_LAYOUTS(BBPD_LPS_FORCE, 2, 0)
BBPD_FOR_LAYOUTS(BBPD_LPS_FORCE, 2, 1)
#undef BBPD_LPS_FORCE
#undef BBPD_LPS_DILATATION
// the families with history: EPS's norm and force pass in one (the first evaluation of a
// step), and the force pass of both with (CHECK, COMMIT) = (0, 0) and (1, 1), as their rows
// call them
#define BBPD_LPS_HISTORY_NORM_FORCE(F, EV, IDX, VALUES)                                      \
  template bool BBPD_ROW_PATH::lps_history_norm_force<F, EV, IDX, VALUES>(                   \
      const double *, int, const IDX *, const VALUES &, int, const LPS::AtomState *,         \
      const F &, const LPS::HistoryCoefficients &, const int *, double *, const double *,    \
      double *, LPS::ForceLanes &, double *);
#define BBPD_LPS_HISTORY_FORCE(F, EV, SWITCH, IDX, VALUES)                                   \
  template bool BBPD_ROW_PATH::lps_history_force<F, EV, SWITCH, SWITCH, IDX, VALUES>(        \
      const double *, int, const IDX *, const VALUES &, int, const LPS::AtomState *,         \
      const F &, const typename F::Plan &, const LPS::HistoryCoefficients &, const int *,    \
      double *, const double *, double *, LPS::ForceLanes &);
#define BBPD_LPS_HISTORY_FORCE_0(F, EV, IDX, VALUES) BBPD_LPS_HISTORY_FORCE(F, EV, 0, IDX, VALUES)
#define BBPD_LPS_HISTORY_FORCE_1(F, EV, IDX, VALUES) BBPD_LPS_HISTORY_FORCE(F, EV, 1, IDX, VALUES)
BBPD_FOR_LAYOUTS(BBPD_LPS_HISTORY_NORM_FORCE, EPS::Family, 0)
BBPD_FOR_LAYOUTS(BBPD_LPS_HISTORY_NORM_FORCE, EPS::Family, 1)
BBPD_FOR_LAYOUTS(BBPD_LPS_HISTORY_FORCE_0, VES::Family, 0)
BBPD_FOR_LAYOUTS(BBPD_LPS_HISTORY_FORCE_0, VES::Family, 1)
BBPD_FOR_LAYOUTS(BBPD_LPS_HISTORY_FORCE_1, VES::Family, 0)
BBPD_FOR_LAYOUTS(BBPD_LPS_HISTORY_FORCE_1, VES::Family, 1)
BBPD_FOR_LAYOUTS(BBPD_LPS_HISTORY_FORCE_0, EPS::Family, 0)
BBPD_FOR_LAYOUTS(BBPD_LPS_HISTORY_FORCE_0, EPS::Family, 1)
BBPD_FOR_LAYOUTS(BBPD_LPS_HISTORY_FORCE_1, EPS::Family, 0)
BBPD_FOR_LAYOUTS(BBPD_LPS_HISTORY_FORCE_1, EPS::Family, 1)
#undef BBPD_LPS_HISTORY_FORCE_1
#undef BBPD_LPS_HISTORY_FORCE_0
#undef BBPD_LPS_HISTORY_FORCE
#undef BBPD_LPS_HISTORY_NORM_FORCE

#endif

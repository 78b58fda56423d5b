// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the definitions and instantiations of one SIMD path's row kernels (bbpd_row_paths.h),
   included only by that path's file, which defines BBPD_ROW_PATH (Avx2Path, Avx512Path) and is
   compiled for the path's instruction set, so that bbpd_row.h's row_force_simd is the path's
   kernel. Nothing else is defined here: whatever this file compiles is the path's alone.
------------------------------------------------------------------------- */

#ifndef BBPD_ROW_PATH_KERNELS_H
#define BBPD_ROW_PATH_KERNELS_H

#include "bbpd_eps.h"
#include "bbpd_lps_history_lanes.h"
#include "bbpd_lps_lanes.h"
#include "bbpd_ves.h"
#include "bbpd_plugin_model.h"
#include "bbpd_row.h"
#include "bbpd_row_paths.h"
#include "bbpd_stretch_row.h"

#ifndef BBPD_SIMD
#error "bbpd_row_path_kernels.h: not compiled for a SIMD instruction set (its flags: CMakeLists.txt)"
#endif

namespace BBPD {

template <int FRACTURE, int EV, class Model, class Idx, class Values>
bool BBPD_ROW_PATH::row_force(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                              double s0, double margin, double *ax, double *ay, double *az,
                              RowTally *tally)
{
  return row_force_simd<FRACTURE, EV, Model>(xx, i, bj, vals, n, s0, margin, ax, ay, az, tally);
}

template <int EV, class Model, class Rule, class Values, class Idx>
bool BBPD_ROW_PATH::row_force_stretch(const double *xx, int i, const Idx *bj, const Values &vals,
                                      int n, const double *smin, double s00, double alpha,
                                      double margin, double s0_floor, double *smin_row, double *ax,
                                      double *ay, double *az, RowTally *tally)
{
  return row_force_stretch_simd<EV, Model, Rule>(xx, i, bj, vals, n, smin, s00, alpha, margin,
                                                s0_floor, smin_row, ax, ay, az, tally);
}

// every layout of a row (FixBBPDBonds::visit_row) with every switch, bond model and rule the
// loops use (bbpd_plugin_model.h)
#define BBPD_FOR_LAYOUTS(X, A, B)                                                           \
  X(A, B, int, PerBondValues) X(A, B, int, ClassValues) X(A, B, int, CompactValues)        \
  X(A, B, int, UniformCompactValues) X(A, B, PartnerOffset, PerBondValues)                  \
  X(A, B, PartnerOffset, ClassValues) X(A, B, PartnerOffset, CompactValues)                 \
  X(A, B, PartnerOffset, UniformCompactValues)
#define BBPD_ROW_FORCE(FRACTURE, EV, IDX, VALUES)                                            \
  template bool BBPD_ROW_PATH::row_force<FRACTURE, EV, BBPD::PluginBondModel, IDX, VALUES>(         \
      const double *, int, const IDX *, const VALUES &, int, double, double, double *,      \
      double *, double *, RowTally *);
#define BBPD_ROW_FORCE_STRETCH(EV, RULE, IDX, VALUES)                                        \
  template bool BBPD_ROW_PATH::row_force_stretch<EV, BBPD::PluginBondModel, RULE, VALUES, IDX>( \
      const double *, int, const IDX *, const VALUES &, int, const double *, double, double, \
      double, double, double *, double *, double *, double *, RowTally *);
BBPD_FOR_LAYOUTS(BBPD_ROW_FORCE, 0, 0)
BBPD_FOR_LAYOUTS(BBPD_ROW_FORCE, 0, 1)
BBPD_FOR_LAYOUTS(BBPD_ROW_FORCE, 1, 0)
BBPD_FOR_LAYOUTS(BBPD_ROW_FORCE, 1, 1)
BBPD_FOR_LAYOUTS(BBPD_ROW_FORCE, 0, 2)
BBPD_FOR_LAYOUTS(BBPD_ROW_FORCE, 1, 2)
#define BBPD_STRETCH_LAYOUTS(EV, RULE) BBPD_FOR_LAYOUTS(BBPD_ROW_FORCE_STRETCH, EV, RULE)
BBPD_FOR_STRETCH_RULES(BBPD_STRETCH_LAYOUTS, 0)
BBPD_FOR_STRETCH_RULES(BBPD_STRETCH_LAYOUTS, 1)
BBPD_FOR_STRETCH_RULES(BBPD_STRETCH_LAYOUTS, 2)
#undef BBPD_STRETCH_LAYOUTS
// the kernels of the state-based rows, with the same layouts
#include "bbpd_lps_path_kernels.h"
#undef BBPD_ROW_FORCE_STRETCH
#undef BBPD_ROW_FORCE
#undef BBPD_FOR_LAYOUTS

}    // namespace BBPD

#endif

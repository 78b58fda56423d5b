// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the stretch pass of the Silling-Askari bond loop over one row.

   For the bonds of atom i it returns the smallest stretch and whether a bond is past (or,
   in a periodic box, within 'margin' of) its critical stretch. What a bond does comes from
   the Model parameter (bbpd_bond_model.h), how its stretch is read and its critical stretch
   found from the Rule parameter (SillingAskariRule<CLAMP>, PeriPmbRule: bbpd_pmb_rules.h);
   the loops name neither. The SIMD kernels do the same IEEE operations (sqrt, division, min,
   max, compares) as the portable loop, so all give identical bits. They keep the row's
   largest stretch and test each bond against its critical stretch (past_avx2, past_avx512)
   only when that reaches the row's floor (critical_stretch_floor, bbpd_silling_askari.h): the
   gather of the partners' smallest stretches per group of bonds cost 14 % of the AVX2 kernel's
   instructions on the bpm/peri deck (bbpd/pmb; callgrind: 141 -> 118 per 8 bonds).
------------------------------------------------------------------------- */

#ifndef BBPD_STRETCH_ROW_H
#define BBPD_STRETCH_ROW_H

#include "bbpd_row.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace BBPD {

template <class Model, class Rule, class Idx, class Values>
inline bool row_stretch_portable(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                                 const double *smin, double s00, double alpha, double margin,
                                 double *smin_row)
{
  const double xi = xx[3 * i], yi = xx[3 * i + 1], zi = xx[3 * i + 2];
  double snew = std::numeric_limits<double>::max();
  bool broken = false;
  for (int k = 0; k < n; k++) {
    const int j = partner_index(bj, i, k);
    const double dx = xx[3 * j] - xi, dy = xx[3 * j + 1] - yi, dz = xx[3 * j + 2] - zi;
    const double xi0 = vals.xi0_at(k, j);
    const double elong =
        Rule::settled_elongation(Model::elongation(std::sqrt(dx * dx + dy * dy + dz * dz), xi0));
    const double s = Rule::stretch(elong, xi0);
    snew = std::min(snew, s);
    broken |= Rule::past_critical(s, Rule::critical_stretch(s00, alpha, smin[i], smin[j]), margin);
  }
  *smin_row = snew;
  return broken;
}

#ifdef BBPD_AVX512
/* the breaking test of row_stretch_portable in 8 lanes: is a bond past (or within margin of)
   its critical stretch with partner j (smallest stretches smin_i and smin[j])? The force
   kernels, these below and the LPS ones (bbpd_lps_lanes.h), run it when the row's largest
   stretch reaches its floor. */
template <class Model, class Rule, class Values, class Idx>
inline bool past_avx512(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                        const double *smin, double smin_i, double s00, double alpha, double margin)
{
  const __m512d xi = _mm512_set1_pd(xx[3 * i]), yi = _mm512_set1_pd(xx[3 * i + 1]),
                zi = _mm512_set1_pd(xx[3 * i + 2]), vsmin_i = _mm512_set1_pd(smin_i),
                one = _mm512_set1_pd(1.0);
  __mmask8 broken = 0;
  for (int k = 0; k < n; k += LANES) {
    const __mmask8 m = (n - k >= LANES) ? (__mmask8) 0xFF : (__mmask8) ((1u << (n - k)) - 1);
    const __m256i j1 = load_partners(bj, m, i, k);
    const BondLanes b = bond_lanes<Model>(xx, xi, yi, zi, j1, m, vals, k);
    const Vec8 s = Rule::stretch(Rule::settled_elongation(Vec8(b.elong)), Vec8(_mm512_mask_mov_pd(one, m, b.xi0)));
    const Vec8 s0 = Rule::critical_stretch(Vec8(s00), Vec8(alpha), Vec8(vsmin_i),
                                           Vec8(_mm512_mask_i32gather_pd(vsmin_i, m, j1, smin, 8)));
    broken |= m & Rule::past_critical(s, s0, Vec8(margin));
  }
  return broken != 0;
}

/* row_force_avx512 (bbpd_row.h) and row_stretch_portable in one pass over the row (reference
   lengths and coefficients from vals, as row_force_avx512 takes them): the force lanes and
   tallies are those of row_force_avx512, bit for bit (same operations in the same order), the
   smallest stretch and the breaking flag those of row_stretch_portable */
template <int EV, class Model, class Rule, class Values, class Idx>
inline bool row_force_stretch_avx512(const double *xx, int i, const Idx *bj, const Values &vals,
                                     int n, const double *smin, double s00, double alpha,
                                     double margin, double s0_floor, double *smin_row, double *ax,
                                     double *ay, double *az, RowTally *tally)
{
  const __m512d xi = _mm512_set1_pd(xx[3 * i]), yi = _mm512_set1_pd(xx[3 * i + 1]),
                zi = _mm512_set1_pd(xx[3 * i + 2]);
  const __m512d one = _mm512_set1_pd(1.0);
  RowLanes<EV, Model> lanes;
  __m512d vmin = _mm512_set1_pd(std::numeric_limits<double>::max()),
          vmax = _mm512_set1_pd(std::numeric_limits<double>::lowest());
  for (int k = 0; k < n; k += LANES) {
    const __mmask8 m = (n - k >= LANES) ? (__mmask8) 0xFF : (__mmask8) ((1u << (n - k)) - 1);
    const __m256i j1 = load_partners(bj, m, i, k);
    const BondLanes b = bond_lanes<Model>(xx, xi, yi, zi, j1, m, vals, k);
    lanes.add(m, b);    // the force: as row_force_avx512
    // the stretch: as row_stretch_portable
    const __m512d es = Rule::settled_elongation(Vec8(b.elong)).v;
    const __m512d s = Rule::stretch(Vec8(es), Vec8(_mm512_mask_mov_pd(one, m, b.xi0))).v;
    vmin = _mm512_mask_min_pd(vmin, m, s, vmin);
    vmax = _mm512_mask_max_pd(vmax, m, s, vmax);
  }
  *smin_row = _mm512_reduce_min_pd(vmin);
  lanes.store(ax, ay, az, tally);
  // no bond has a critical stretch below s0_floor (critical_stretch_floor)
  return _mm512_reduce_max_pd(vmax) + margin > s0_floor &&
      past_avx512<Model, Rule>(xx, i, bj, vals, n, smin, smin[i], s00, alpha, margin);
}
#define row_force_stretch_simd BBPD::row_force_stretch_avx512
#endif

#ifdef BBPD_AVX2
// past_avx512 in 4-wide groups
template <class Model, class Rule, class Values, class Idx>
inline bool past_avx2(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                      const double *smin, double smin_i, double s00, double alpha, double margin)
{
  const __m256d xi = _mm256_set1_pd(xx[3 * i]), yi = _mm256_set1_pd(xx[3 * i + 1]),
                zi = _mm256_set1_pd(xx[3 * i + 2]), vsmin_i = _mm256_set1_pd(smin_i),
                one = _mm256_set1_pd(1.0), all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  __m256d broken = _mm256_setzero_pd();
  // 4 lanes (m: in the row) with the partners' smallest stretches smin_j
  auto check = [&](__m256d m, bool masked, __m256d dx, __m256d dy, __m256d dz, __m256d xi0,
                   __m256d smin_j) BBPD_GROUPS_INLINE {
    const __m256d r = _mm256_sqrt_pd(
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz)));
    const Vec4 es = Rule::settled_elongation(Model::elongation(Vec4(r), Vec4(xi0)));
    const Vec4 s = Rule::stretch(es, Vec4(masked ? _mm256_blendv_pd(one, xi0, m) : xi0));
    const Vec4 s0 = Rule::critical_stretch(Vec4(s00), Vec4(alpha), Vec4(vsmin_i), Vec4(smin_j));
    broken = _mm256_or_pd(broken, _mm256_and_pd(m, Rule::past_critical(s, s0, Vec4(margin)).v));
  };
  auto full = [&](auto, int k) BBPD_GROUPS_INLINE {
    const int o = row_origin(bj, i);
    const std::ptrdiff_t j[4] = {bj[k], bj[k + 1], bj[k + 2], bj[k + 3]};
    __m256d x, y, z, xi0, coef;
    load_positions(xx + 3 * o, j, x, y, z);
    load_values_full(vals, bj, i, k, xi0, coef);
    const double *sm = smin + o;
    check(all, false, _mm256_sub_pd(x, xi), _mm256_sub_pd(y, yi), _mm256_sub_pd(z, zi), xi0,
          _mm256_setr_pd(sm[j[0]], sm[j[1]], sm[j[2]], sm[j[3]]));
  };
  auto tail = [&](auto, int k) BBPD_GROUPS_INLINE {
    const TailGroup4 g(xx, bj, i, n, k, xi, yi, zi);
    __m256d xi0, coef;
    load_values_tail(vals, g, k, xi0, coef);
    check(g.m, true, g.dx, g.dy, g.dz, xi0, _mm256_mask_i32gather_pd(vsmin_i, smin, g.j1, g.m, 8));
  };
  for_each_group4(n, full, tail);
  return _mm256_movemask_pd(broken) != 0;
}

/* row_force_stretch_avx512 in two 4-wide halves, as row_force_avx2 (bbpd_row.h) computes the
   force: the same bits (the smallest stretch is a minimum, exact in any order) */
template <int EV, class Model, class Rule, class Values, class Idx>
inline bool row_force_stretch_avx2(const double *xx, int i, const Idx *bj, const Values &vals,
                                   int n, const double *smin, double s00, double alpha,
                                   double margin, double s0_floor, double *smin_row, double *ax,
                                   double *ay, double *az, RowTally *tally)
{
  const __m256d xi = _mm256_set1_pd(xx[3 * i]), yi = _mm256_set1_pd(xx[3 * i + 1]),
                zi = _mm256_set1_pd(xx[3 * i + 2]), all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  const __m256d one = _mm256_set1_pd(1.0);
  Avx2Lanes<0, EV, Model> lanes(0.0, 0.0);
  __m256d vmin = _mm256_set1_pd(std::numeric_limits<double>::max()),
          vmax = _mm256_set1_pd(std::numeric_limits<double>::lowest());
  // the stretch of 4 lanes (m: in the row)
  auto stretch = [&](__m256d m, bool masked, __m256d elong, __m256d xi0) {
    const __m256d es = Rule::settled_elongation(Vec4(elong)).v;
    const __m256d s = Rule::stretch(Vec4(es), Vec4(masked ? _mm256_blendv_pd(one, xi0, m) : xi0)).v;
    vmin = masked ? _mm256_blendv_pd(vmin, _mm256_min_pd(s, vmin), m) : _mm256_min_pd(s, vmin);
    vmax = masked ? _mm256_blendv_pd(vmax, _mm256_max_pd(s, vmax), m) : _mm256_max_pd(s, vmax);
  };
  auto full = [&](auto half, int k) {
    const int o = row_origin(bj, i);
    const std::ptrdiff_t j[4] = {bj[k], bj[k + 1], bj[k + 2], bj[k + 3]};
    __m256d x, y, z, xi0, coef;
    load_positions(xx + 3 * o, j, x, y, z);
    load_values_full(vals, bj, i, k, xi0, coef);
    const __m256d elong = lanes.template add<decltype(half)::value, false>(
        all, _mm256_sub_pd(x, xi), _mm256_sub_pd(y, yi), _mm256_sub_pd(z, zi), xi0, coef);
    stretch(all, false, elong, xi0);
  };
  auto tail = [&](auto half, int k) {
    const TailGroup4 g(xx, bj, i, n, k, xi, yi, zi);
    __m256d xi0, coef;
    load_values_tail(vals, g, k, xi0, coef);
    const __m256d elong = lanes.template add<decltype(half)::value, true>(g.m, g.dx, g.dy, g.dz, xi0, coef);
    stretch(g.m, true, elong, xi0);
  };
  for_each_group4(n, full, tail);
  const __m128d m2 = _mm_min_pd(_mm256_castpd256_pd128(vmin), _mm256_extractf128_pd(vmin, 1));
  *smin_row = std::min(_mm_cvtsd_f64(m2), _mm_cvtsd_f64(_mm_unpackhi_pd(m2, m2)));
  const __m128d x2 = _mm_max_pd(_mm256_castpd256_pd128(vmax), _mm256_extractf128_pd(vmax, 1));
  lanes.store(ax, ay, az, tally);
  // no bond has a critical stretch below s0_floor (critical_stretch_floor)
  return std::max(_mm_cvtsd_f64(x2), _mm_cvtsd_f64(_mm_unpackhi_pd(x2, x2))) + margin > s0_floor &&
      past_avx2<Model, Rule>(xx, i, bj, vals, n, smin, smin[i], s00, alpha, margin);
}
#define row_force_stretch_simd BBPD::row_force_stretch_avx2
#endif


}    // namespace BBPD

#endif

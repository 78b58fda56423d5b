// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the stretch pass of the Silling-Askari bond loop over one row.

   For the bonds of atom i it returns the smallest stretch and whether a bond is past (or,
   in a periodic box, within 'margin' of) its critical stretch s00 - alpha max(smin_i, smin_j)
   (with 'clamp': only compression counts). The AVX-512 kernel does the same IEEE operations
   (sqrt, division, min, max, compares) as the portable loop, so both give identical bits.
------------------------------------------------------------------------- */

#ifndef BBPD_PMB_ROW_H
#define BBPD_PMB_ROW_H

#include "bbpd_pmb_rules.h"
#include "bbpd_row.h"

#include <cmath>
#include <limits>

namespace BBPD {

template <bool PMB, bool CLAMP>
inline bool row_stretch_portable(const double *xx, int i, const int *bj, const double *bxi0, int n,
                                 const double *smin, double s00, double alpha, double margin,
                                 double *smin_row)
{
  const double xi = xx[3 * i], yi = xx[3 * i + 1], zi = xx[3 * i + 2];
  double snew = std::numeric_limits<double>::max();
  bool broken = false;
  for (int k = 0; k < n; k++) {
    const int j = bj[k];
    const double dx = xx[3 * j] - xi, dy = xx[3 * j + 1] - yi, dz = xx[3 * j + 2] - zi;
    double elong = std::sqrt(dx * dx + dy * dy + dz * dz) - bxi0[k];
    if (PMB && std::fabs(elong) < BBPD::PMB::NEAR_ZERO) elong = 0.0;
    const double s = elong / bxi0[k];
    snew = std::min(snew, s);
    broken |= s + margin > BBPD::PMB::critical_stretch(s00, alpha, smin[i], smin[j], CLAMP);
  }
  *smin_row = snew;
  return broken;
}

#ifdef BBPD_AVX512
/* row_force_avx512 (bbpd_row.h) and row_stretch_portable in one pass over the row (reference
   lengths and coefficients from vals, as row_force_avx512 takes them): the force lanes and
   tallies are those of row_force_avx512, bit for bit (same operations in the same order), the
   smallest stretch and the breaking flag those of row_stretch_portable */
template <int EV, bool PMB, bool CLAMP, class Values>
inline bool row_force_stretch_avx512(const double *xx, int i, const int *bj, const Values &vals,
                                     int n, const double *smin, double s00, double alpha,
                                     double margin, double *smin_row, double *ax, double *ay,
                                     double *az, RowTally *tally)
{
  const __m512d xi = _mm512_set1_pd(xx[3 * i]), yi = _mm512_set1_pd(xx[3 * i + 1]),
                zi = _mm512_set1_pd(xx[3 * i + 2]);
  const __m512d vs00 = _mm512_set1_pd(s00), valpha = _mm512_set1_pd(alpha),
                vsmin_i = _mm512_set1_pd(smin[i]), zero = _mm512_setzero_pd(),
                near_zero = _mm512_set1_pd(BBPD::PMB::NEAR_ZERO), one = _mm512_set1_pd(1.0),
                vmargin = _mm512_set1_pd(margin);
  RowLanes<EV> lanes;
  __m512d vmin = _mm512_set1_pd(std::numeric_limits<double>::max());
  __mmask8 broken = 0;
  for (int k = 0; k < n; k += LANES) {
    const __mmask8 m = (n - k >= LANES) ? (__mmask8) 0xFF : (__mmask8) ((1u << (n - k)) - 1);
    const __m256i j1 = load_partners(bj, m, i, k);
    const BondLanes b = bond_lanes(xx, xi, yi, zi, j1, m, vals, k);
    lanes.add(m, b);    // the force: as row_force_avx512
    // the stretch: as row_stretch_portable
    __m512d es = b.elong;
    if (PMB) es = _mm512_mask_mov_pd(es, _mm512_cmp_pd_mask(_mm512_abs_pd(es), near_zero, _CMP_LT_OQ), zero);
    const __m512d s = _mm512_div_pd(es, _mm512_mask_mov_pd(one, m, b.xi0));
    vmin = _mm512_mask_min_pd(vmin, m, s, vmin);
    __m512d smax = _mm512_max_pd(_mm512_mask_i32gather_pd(vsmin_i, m, j1, smin, 8), vsmin_i);
    if (CLAMP) smax = _mm512_min_pd(smax, zero);
    const __m512d s0 = _mm512_sub_pd(vs00, _mm512_mul_pd(valpha, smax));
    broken |= _mm512_mask_cmp_pd_mask(m, _mm512_add_pd(s, vmargin), s0, _CMP_GT_OQ);
  }
  *smin_row = _mm512_reduce_min_pd(vmin);
  lanes.store(ax, ay, az, tally);
  return broken != 0;
}
#endif

/* the stretch pass without the force (the force then comes from row_force); bxi0 = null
   (compact storage) is handled by the caller */
template <bool PMB, bool CLAMP>
inline bool row_stretch(const double *xx, int i, const int *bj, const double *bxi0, int n,
                        const double *smin, double s00, double alpha, double margin,
                        double *smin_row)
{
  return row_stretch_portable<PMB, CLAMP>(xx, i, bj, bxi0, n, smin, s00, alpha, margin, smin_row);
}

}    // namespace BBPD

#endif

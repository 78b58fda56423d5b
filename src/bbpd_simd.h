// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the vector widths of the bond loops, with no LAMMPS dependency.

   The bond model (bbpd_bond_model.h) is written once over a value type V:
   double in the portable loop, Vec4 (AVX2, 4 doubles) or Vec8 (AVX-512, 8 doubles)
   in the SIMD kernels (bbpd_row.h). Each operator is one IEEE operation in every
   lane, so the same expression gives the same bits at every width. A comparison
   gives the width's mask: bool, Vec4 with all bits set in the true lanes, __mmask8.
------------------------------------------------------------------------- */

#ifndef BBPD_SIMD_H
#define BBPD_SIMD_H

#include <algorithm>
#include <cmath>

#if defined(__AVX512F__) && defined(__AVX512VL__)
#define BBPD_AVX512
#define BBPD_SIMD
#include <immintrin.h>
#elif defined(__AVX2__)
#define BBPD_AVX2
#define BBPD_SIMD
#include <immintrin.h>
#endif

namespace BBPD {

inline double vsqrt(double a) { return std::sqrt(a); }
inline double vmin(double a, double b) { return std::min(a, b); }
inline double vmax(double a, double b) { return std::max(a, b); }
inline double vabs(double a) { return std::fabs(a); }
// a in the lanes where m holds, else b
inline double vselect(bool m, double a, double b) { return m ? a : b; }
// vselect(m, a, 0) and vselect(m, 0, a), m from a compare: in the vector types one AND (GCC
// makes a blend with zero a sign test and an AND; about 2 % of an LPS step)
inline double vkeep(bool m, double a) { return m ? a : 0.0; }
inline double vdrop(bool m, double a) { return m ? 0.0 : a; }

#ifdef BBPD_AVX2
struct Vec4 {
  __m256d v;
  Vec4(__m256d x) : v(x) {}
  explicit Vec4(double d) : v(_mm256_set1_pd(d)) {}
};
inline Vec4 operator+(Vec4 a, Vec4 b) { return _mm256_add_pd(a.v, b.v); }
inline Vec4 operator-(Vec4 a, Vec4 b) { return _mm256_sub_pd(a.v, b.v); }
inline Vec4 operator*(Vec4 a, Vec4 b) { return _mm256_mul_pd(a.v, b.v); }
inline Vec4 operator/(Vec4 a, Vec4 b) { return _mm256_div_pd(a.v, b.v); }
inline Vec4 operator>(Vec4 a, Vec4 b) { return _mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ); }
inline Vec4 operator<(Vec4 a, Vec4 b) { return _mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ); }
inline Vec4 vselect(Vec4 m, Vec4 a, Vec4 b) { return _mm256_blendv_pd(b.v, a.v, m.v); }
inline Vec4 vkeep(Vec4 m, Vec4 a) { return _mm256_and_pd(m.v, a.v); }
inline Vec4 vdrop(Vec4 m, Vec4 a) { return _mm256_andnot_pd(m.v, a.v); }
inline Vec4 vsqrt(Vec4 a) { return _mm256_sqrt_pd(a.v); }
inline Vec4 vabs(Vec4 a) { return _mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v); }
// std::min and std::max lane by lane, NaN and signed zeros included: b < a ? b : a, a < b ? b : a
inline Vec4 vmin(Vec4 a, Vec4 b) { return _mm256_min_pd(b.v, a.v); }
inline Vec4 vmax(Vec4 a, Vec4 b) { return _mm256_max_pd(b.v, a.v); }
#endif

#ifdef BBPD_AVX512
struct Vec8 {
  __m512d v;
  Vec8(__m512d x) : v(x) {}
  explicit Vec8(double d) : v(_mm512_set1_pd(d)) {}
};
inline Vec8 operator+(Vec8 a, Vec8 b) { return _mm512_add_pd(a.v, b.v); }
inline Vec8 operator-(Vec8 a, Vec8 b) { return _mm512_sub_pd(a.v, b.v); }
inline Vec8 operator*(Vec8 a, Vec8 b) { return _mm512_mul_pd(a.v, b.v); }
inline Vec8 operator/(Vec8 a, Vec8 b) { return _mm512_div_pd(a.v, b.v); }
inline __mmask8 operator>(Vec8 a, Vec8 b) { return _mm512_cmp_pd_mask(a.v, b.v, _CMP_GT_OQ); }
inline __mmask8 operator<(Vec8 a, Vec8 b) { return _mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ); }
inline Vec8 vselect(__mmask8 m, Vec8 a, Vec8 b) { return _mm512_mask_mov_pd(b.v, m, a.v); }
inline Vec8 vkeep(__mmask8 m, Vec8 a) { return _mm512_maskz_mov_pd(m, a.v); }
inline Vec8 vdrop(__mmask8 m, Vec8 a) { return _mm512_maskz_mov_pd((__mmask8) ~m, a.v); }
inline Vec8 vsqrt(Vec8 a) { return _mm512_sqrt_pd(a.v); }
inline Vec8 vabs(Vec8 a) { return _mm512_abs_pd(a.v); }
inline Vec8 vmin(Vec8 a, Vec8 b) { return _mm512_min_pd(b.v, a.v); }
inline Vec8 vmax(Vec8 a, Vec8 b) { return _mm512_max_pd(b.v, a.v); }
#endif

}    // namespace BBPD

#endif

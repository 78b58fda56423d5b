// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the innermost bond loop of the bbpd pair styles, with no LAMMPS
   dependency (the unit test tests/unit/test_row.cpp runs it on plain arrays).

   Bond k of a row goes to lane k % LANES; lanes are summed in one fixed order
   (lane_sum). The AVX-512 and AVX2 kernels compute each bond with the same
   operations in the same order as the portable loop (row_force_portable; no FMA
   contraction), so all three give identical bits. What a bond does (elongation, force,
   energy, virial, breaking) comes from the Model parameter (bbpd_bond_model.h), written
   once for the three widths.
------------------------------------------------------------------------- */

#ifndef BBPD_ROW_H
#define BBPD_ROW_H

#include "bbpd_bond_model.h"
#include "bbpd_bond_table.h"
#include "bbpd_bond_values.h"
#include "bbpd_partner_index.h"
#include "bbpd_row_paths.h"
#include "bbpd_simd.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <vector>

namespace BBPD {

constexpr int LANES = 8;    // one AVX-512 register of doubles

// energy (half of each bond's micropotential) and virial lanes of a row, when tallied
struct RowTally {
  double eng[LANES];
  double vir[6][LANES];    // xx yy zz xy xz yz
};

inline double lane_total(const double *a)
{
  return ((a[0] + a[1]) + (a[2] + a[3])) + ((a[4] + a[5]) + (a[6] + a[7]));
}

inline void lane_sum(const double *ax, const double *ay, const double *az, double *f)
{
  f[0] = ((ax[0] + ax[1]) + (ax[2] + ax[3])) + ((ax[4] + ax[5]) + (ax[6] + ax[7]));
  f[1] = ((ay[0] + ay[1]) + (ay[2] + ay[3])) + ((ay[4] + ay[5]) + (ay[6] + ay[7]));
  f[2] = ((az[0] + az[1]) + (az[2] + az[3])) + ((az[4] + az[5]) + (az[6] + az[7]));
}

/* lanes of the force density on atom i (positions xx, 3 per atom) from its n bonds to the
   partners bj[k] (local indices, or offsets from i: bbpd_partner_index.h), in the portable
   loop: reference length xi0_of(k), coefficient coef_of(k, xi0) and the partner's critical
   stretch s0_of(j) come from callables (cached or recomputed, one s0 or per type). With
   FRACTURE it returns true if a bond is past s0 or within margin of it, and the lanes are then
   incomplete. */
template <int FRACTURE, int EV, class Model, class Idx, class Xi0,
          class Coef, class S0>
inline bool row_force_portable(const double *xx, int i, const Idx *bj, int n, Xi0 xi0_of,
                               Coef coef_of, S0 s0_of, double margin, double *ax, double *ay,
                               double *az, RowTally *tally)
{
  const double xi = xx[3 * i], yi = xx[3 * i + 1], zi = xx[3 * i + 2];
  int broken = 0;
  for (int k = 0; k < n; k++) {
    const int l = k % LANES;
    const int j = partner_index(bj, i, k);
    const double dx = xx[3 * j] - xi, dy = xx[3 * j + 1] - yi, dz = xx[3 * j + 2] - zi;
    const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double xi0 = xi0_of(k);
    const double coef = coef_of(k, xi0);
    const double elong = Model::elongation(r, xi0);
    if (FRACTURE) broken |= Model::past_critical(elong, xi0, s0_of(j), margin);
    const double fbond = Model::force_per_length(coef, elong, r);
    ax[l] += fbond * dx;
    ay[l] += fbond * dy;
    az[l] += fbond * dz;
    if (EV) tally->eng[l] += Model::energy_share(coef, elong);
    if (tallies_virial(EV)) {
      // the row's share of the bond's virial: the other end tallies the rest
      tally->vir[0][l] -= Model::virial_share(fbond, dx, dx);
      tally->vir[1][l] -= Model::virial_share(fbond, dy, dy);
      tally->vir[2][l] -= Model::virial_share(fbond, dz, dz);
      tally->vir[3][l] -= Model::virial_share(fbond, dx, dy);
      tally->vir[4][l] -= Model::virial_share(fbond, dx, dz);
      tally->vir[5][l] -= Model::virial_share(fbond, dy, dz);
    }
  }
  return FRACTURE && broken;
}

#if defined(__GNUC__)
#define BBPD_GROUPS_INLINE __attribute__((always_inline))
#else
#define BBPD_GROUPS_INLINE
#endif

#ifdef BBPD_SIMD
/* The rows read the partner positions and the class entries with plain loads, 4 partners at a
   time, the tails too (their lanes off read a partner of the row and are cleared): on AMD Zen 3
   a 4-wide gather, and on Zen 4 and Zen 5 an 8-wide one, costs more than the loads and unpacks
   that give the same values (doc/performance.md). */

// x, y and z of the partners j[0..3]: (x, y) and (y, z) of each partner, 16 bytes each, paired
// in 32-byte registers and unpacked (always inlined: a copy of its own in each path's file would
// be one symbol to the linker, who could hand the AVX-512 copy to the AVX2 kernels). The full
// groups hand j as std::ptrdiff_t: 3 j is then an address offset as it is, not an int widened.
template <class J>
BBPD_GROUPS_INLINE inline void load_positions(const double *xx, const J *j, __m256d &x, __m256d &y, __m256d &z)
{
  const double *p0 = xx + 3 * j[0], *p1 = xx + 3 * j[1], *p2 = xx + 3 * j[2], *p3 = xx + 3 * j[3];
  auto pair = [](const double *lo, const double *hi) {
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(lo)), _mm_loadu_pd(hi), 1);
  };
  const __m256d a02 = pair(p0, p2), a13 = pair(p1, p3);            // x0 y0 x2 y2, x1 y1 x3 y3
  const __m256d b02 = pair(p0 + 1, p2 + 1), b13 = pair(p1 + 1, p3 + 1);    // y z of the same
  x = _mm256_unpacklo_pd(a02, a13);
  y = _mm256_unpackhi_pd(a02, a13);
  z = _mm256_unpackhi_pd(b02, b13);
}

// reference lengths and coefficients of the classes c[0..3]: each class's pair (16 bytes, side
// by side in the table: ClassValues) paired in 32-byte registers and unpacked, as load_positions
template <class C>
BBPD_GROUPS_INLINE inline void load_class_values(const double *values, const C *c, __m256d &xi0, __m256d &coef)
{
  auto pair = [values](std::size_t lo, std::size_t hi) {
    return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(values + 2 * lo)),
                                _mm_loadu_pd(values + 2 * hi), 1);
  };
  const __m256d a02 = pair(c[0], c[2]), a13 = pair(c[1], c[3]);
  xi0 = _mm256_unpacklo_pd(a02, a13);
  coef = _mm256_unpackhi_pd(a02, a13);
}
#endif

#ifdef BBPD_AVX512
// two 4-wide halves (lanes 0-3, 4-7) as one 8-wide vector
inline __m512d join4(__m256d lo, __m256d hi)
{
  return _mm512_insertf64x4(_mm512_castpd256_pd512(lo), hi, 1);
}

// reference lengths and coefficients of bonds k..k+7 (lanes off in m: zero)
inline void load_values(const PerBondValues &v, __mmask8 m, int k, __m256i, __m512d &xi0,
                        __m512d &coef)
{
  xi0 = _mm512_maskz_loadu_pd(m, v.xi0 + k);
  coef = _mm512_maskz_loadu_pd(m, v.coef + k);
}
inline void load_values(const ClassValues &v, __mmask8 m, int k, __m256i, __m512d &xi0,
                        __m512d &coef)
{
  // a tail's classes by a masked load (class 0 in the lanes off: no entry past the row is
  // read), its entries then as a full vector's, the lanes off cleared
  alignas(16) BondClass tail[LANES];
  if (m != 0xFF) _mm_store_si128(reinterpret_cast<__m128i *>(tail), _mm_maskz_loadu_epi16(m, v.cls + k));
  const BondClass *c = m == 0xFF ? v.cls + k : tail;
  __m256d x[2], cf[2];
  load_class_values(v.values, c, x[0], cf[0]);
  load_class_values(v.values, c + 4, x[1], cf[1]);
  xi0 = _mm512_maskz_mov_pd(m, join4(x[0], x[1]));
  coef = _mm512_maskz_mov_pd(m, join4(cf[0], cf[1]));
}

template <class CoefFn, bool UNIFORM>
inline void load_values(const RecomputedValues<CoefFn, UNIFORM> &v, __mmask8 m, int, __m256i j,
                        __m512d &xi0, __m512d &coef)
{
  const __m256i j3 = _mm256_mullo_epi32(j, _mm256_set1_epi32(3));
  const double *xi = v.x0 + 3 * v.i;
  const __m512d x = _mm512_set1_pd(xi[0]), y = _mm512_set1_pd(xi[1]), z = _mm512_set1_pd(xi[2]);
  const __m512d dx = _mm512_sub_pd(_mm512_mask_i32gather_pd(x, m, j3, v.x0, 8), x);
  const __m512d dy = _mm512_sub_pd(_mm512_mask_i32gather_pd(y, m, j3, v.x0 + 1, 8), y);
  const __m512d dz = _mm512_sub_pd(_mm512_mask_i32gather_pd(z, m, j3, v.x0 + 2, 8), z);
  const __m512d rsq0 =
      _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy)), _mm512_mul_pd(dz, dz));
  const __m512d vj = UNIFORM ? _mm512_set1_pd(v.uniform_v)
                             : _mm512_mask_i32gather_pd(_mm512_setzero_pd(), m, j, v.vfrac, 8);
  const __m256i jtype = UNIFORM ? _mm256_set1_epi32(v.uniform_type)
                                : _mm256_mmask_i32gather_epi32(_mm256_setzero_si256(), m, j, v.type, 4);
  const __m256i tj = _mm256_add_epi32(jtype, _mm256_set1_epi32(v.type[v.i] * CoefCache::TYPE_STRIDE));
  // the cache slots, as CoefCache::slot
  const __m512i qb = _mm512_castpd_si512(rsq0), vb = _mm512_castpd_si512(vj);
  const __m512i h =
      _mm512_xor_si512(_mm512_xor_si512(qb, _mm512_srli_epi64(vb, CoefCache::VOLUME_SHIFT)),
                       _mm512_slli_epi64(_mm512_cvtepu32_epi64(tj), CoefCache::TYPES_SHIFT));
  __m512i fold = h;
  for (int b = CoefCache::SLOT_BITS; b < 64; b += CoefCache::SLOT_BITS)
    fold = _mm512_xor_si512(fold, _mm512_srli_epi64(h, b));
  const __m512i slot = _mm512_and_si512(fold, _mm512_set1_epi64(CoefCache::SIZE - 1));
  CoefCache &c = *v.cache;
  __mmask8 hit =
      _mm512_mask_cmp_pd_mask(m, rsq0, _mm512_mask_i64gather_pd(_mm512_setzero_pd(), m, slot, c.rsq0.data(), 8), _CMP_EQ_OQ);
  if (!UNIFORM)
    hit &= _mm512_mask_cmp_pd_mask(m, vj, _mm512_mask_i64gather_pd(_mm512_setzero_pd(), m, slot, c.vj.data(), 8), _CMP_EQ_OQ) &
        _mm256_mask_cmpeq_epi32_mask(m, tj, _mm512_mask_i64gather_epi32(_mm256_setzero_si256(), m, slot, c.types.data(), 4));
  xi0 = _mm512_mask_i64gather_pd(_mm512_setzero_pd(), hit, slot, c.xi0.data(), 8);
  coef = _mm512_mask_i64gather_pd(_mm512_setzero_pd(), hit, slot, c.coef.data(), 8);
  if (hit != m) {
    // looked up lane by lane (two lanes of this vector may share a slot)
    alignas(64) double lq[LANES], lv[LANES], lx[LANES], lc[LANES];
    alignas(32) int lt[LANES];
    _mm512_store_pd(lq, rsq0);
    _mm512_store_pd(lv, vj);
    _mm512_store_pd(lx, xi0);
    _mm256_store_si256(reinterpret_cast<__m256i *>(lt), jtype);
    for (int l = 0; l < LANES; l++)
      lc[l] = ((m & ~hit) & (1u << l)) ? v.lookup(lt[l], lq[l], lv[l], lx[l]) : 0.0;
    xi0 = _mm512_mask_blend_pd(m & ~hit, xi0, _mm512_load_pd(lx));
    coef = _mm512_mask_blend_pd(m & ~hit, coef, _mm512_load_pd(lc));
  }
}

// partner indices of bonds k..k+7 (lanes off in m: zero, or i)
inline __m256i load_partners(const int *bj, __mmask8 m, int, int k)
{
  return _mm256_maskz_loadu_epi32(m, bj + k);
}
inline __m256i load_partners(const PartnerOffset *bj, __mmask8 m, int i, int k)
{
  return _mm256_add_epi32(_mm256_cvtepi16_epi32(_mm_maskz_loadu_epi16(m, bj + k)), _mm256_set1_epi32(i));
}

/* the partners j1 of a tail (lanes m) with the lanes off reading lane 0's partner, an atom of
   the row: a tail is then read as a full vector, by plain loads, and its lanes off cleared. On
   AMD Zen 4 the 8-wide gathers of a tail (three for the positions, two for the class entries,
   two for LPS states) cost more than the loads (doc/performance.md). */
inline __m256i tail_partners(__m256i j1, __mmask8 m)
{
  return _mm256_mask_blend_epi32(m, _mm256_permutexvar_epi32(_mm256_setzero_si256(), j1), j1);
}
// the partners j1 of bonds k..k+7 (lanes m) into j, for plain loads: a tail's by tail_partners
inline void store_partners(__m256i j1, __mmask8 m, int *j)
{
  _mm256_store_si256(reinterpret_cast<__m256i *>(j), m == 0xFF ? j1 : tail_partners(j1, m));
}

/* one vector of bonds k..k+7 of atom i (position xi, yi, zi; partners j1, lanes off in m):
   partner differences, current and reference length, coefficient and elongation */
struct BondLanes {
  __m512d dx, dy, dz, r, xi0, coef, elong;
};
template <class Model, class Values>
BBPD_GROUPS_INLINE inline BondLanes bond_lanes(const double *xx, __m512d xi, __m512d yi, __m512d zi, __m256i j1,
                            __mmask8 m, const Values &vals, int k)
{
  BondLanes b;
  {
    // a tail is read as a full vector (tail_partners), its lanes off cleared
    alignas(32) int j[LANES];
    store_partners(j1, m, j);
    __m256d x[2], y[2], z[2];
    load_positions(xx, j, x[0], y[0], z[0]);
    load_positions(xx, j + 4, x[1], y[1], z[1]);
    b.dx = _mm512_maskz_sub_pd(m, join4(x[0], x[1]), xi);
    b.dy = _mm512_maskz_sub_pd(m, join4(y[0], y[1]), yi);
    b.dz = _mm512_maskz_sub_pd(m, join4(z[0], z[1]), zi);
  }
  const __m512d rsq = _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(b.dx, b.dx), _mm512_mul_pd(b.dy, b.dy)),
                                    _mm512_mul_pd(b.dz, b.dz));
  b.r = _mm512_sqrt_pd(rsq);
  load_values(vals, m, k, j1, b.xi0, b.coef);
  b.elong = Model::elongation(Vec8(b.r), Vec8(b.xi0)).v;
  return b;
}

/* the force lanes of a row and, with EV, its energy and virial lanes (RowTally) */
template <int EV, class Model> struct RowLanes {
  __m512d fx = _mm512_setzero_pd(), fy = _mm512_setzero_pd(), fz = _mm512_setzero_pd();
  __m512d eacc = _mm512_setzero_pd();
  __m512d vacc[6] = {_mm512_setzero_pd(), _mm512_setzero_pd(), _mm512_setzero_pd(),
                     _mm512_setzero_pd(), _mm512_setzero_pd(), _mm512_setzero_pd()};
  void add(__mmask8 m, const BondLanes &b)
  {
    // lanes off in m hold no bond (and may divide 0 by 0): masked out of every sum
    const __m512d fbond = Model::force_per_length(Vec8(b.coef), Vec8(b.elong), Vec8(b.r)).v;
    fx = _mm512_mask_add_pd(fx, m, fx, _mm512_mul_pd(fbond, b.dx));
    fy = _mm512_mask_add_pd(fy, m, fy, _mm512_mul_pd(fbond, b.dy));
    fz = _mm512_mask_add_pd(fz, m, fz, _mm512_mul_pd(fbond, b.dz));
    // as row_force_portable
    if (EV) eacc = _mm512_mask_add_pd(eacc, m, eacc, Model::energy_share(Vec8(b.coef), Vec8(b.elong)).v);
    if (tallies_virial(EV)) {
      const Vec8 d[3] = {b.dx, b.dy, b.dz};
      const int pa[6] = {0, 1, 2, 0, 0, 1}, pb[6] = {0, 1, 2, 1, 2, 2};
      for (int c = 0; c < 6; c++)
        vacc[c] = _mm512_mask_sub_pd(vacc[c], m, vacc[c],
                                     Model::virial_share(Vec8(fbond), d[pa[c]], d[pb[c]]).v);
    }
  }
  void store(double *ax, double *ay, double *az, RowTally *tally) const
  {
    _mm512_storeu_pd(ax, fx);
    _mm512_storeu_pd(ay, fy);
    _mm512_storeu_pd(az, fz);
    if (EV) _mm512_storeu_pd(tally->eng, eacc);
    for (int c = 0; c < 6 && tallies_virial(EV); c++) _mm512_storeu_pd(tally->vir[c], vacc[c]);
  }
};

/* lanes of the force density on atom i from n bonds (partner bj, reference length and
   coefficient from vals); with FRACTURE returns true if a bond is past s0 or within
   margin of it (elong + margin > s0 xi0; margin is 0 except in periodic boxes) */
template <int FRACTURE, int EV, class Model, class Values, class Idx>
inline bool row_force_avx512(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                             double s0, double margin, double *ax, double *ay, double *az,
                             RowTally *tally)
{
  const __m512d xi = _mm512_set1_pd(xx[3 * i]), yi = _mm512_set1_pd(xx[3 * i + 1]),
                zi = _mm512_set1_pd(xx[3 * i + 2]), vs0 = _mm512_set1_pd(s0),
                vmargin = _mm512_set1_pd(margin);
  RowLanes<EV, Model> lanes;
  __mmask8 broken = 0;
  for (int k = 0; k < n; k += LANES) {
    const __mmask8 m = (n - k >= LANES) ? (__mmask8) 0xFF : (__mmask8) ((1u << (n - k)) - 1);
    const BondLanes b = bond_lanes<Model>(xx, xi, yi, zi, load_partners(bj, m, i, k), m, vals, k);
    if (FRACTURE) broken |= m & Model::past_critical(Vec8(b.elong), Vec8(b.xi0), Vec8(vs0), Vec8(vmargin));
    lanes.add(m, b);
  }
  if (FRACTURE && broken) return true;
  lanes.store(ax, ay, az, tally);
  return false;
}
#define row_force_simd BBPD::row_force_avx512
#endif

#ifdef BBPD_AVX2
// reference lengths and coefficients of bonds k..k+3 with partners j (lanes off in m and m32:
// zero)
inline void load_values(const PerBondValues &v, __m256d m, __m128i, int k, __m128i, __m256d &xi0,
                        __m256d &coef)
{
  xi0 = _mm256_maskload_pd(v.xi0 + k, _mm256_castpd_si256(m));
  coef = _mm256_maskload_pd(v.coef + k, _mm256_castpd_si256(m));
}
inline void load_values(const ClassValues &v, __m256d m, __m128i, int k, __m128i, __m256d &xi0,
                        __m256d &coef)
{
  const __m128i c2 = _mm_slli_epi32(
      _mm_cvtepu16_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(v.cls + k))), 1);
  xi0 = _mm256_mask_i32gather_pd(_mm256_setzero_pd(), v.values, c2, m, 8);
  coef = _mm256_mask_i32gather_pd(_mm256_setzero_pd(), v.values + 1, c2, m, 8);
}

// compact storage: the AVX-512 load_values in 4 lanes (same operations, same bits)
template <class CoefFn, bool UNIFORM>
inline void load_values(const RecomputedValues<CoefFn, UNIFORM> &v, __m256d m, __m128i m32, int,
                        __m128i j, __m256d &xi0, __m256d &coef)
{
  const __m128i j3 = _mm_mullo_epi32(j, _mm_set1_epi32(3));
  const double *xi = v.x0 + 3 * v.i;
  const __m256d x = _mm256_set1_pd(xi[0]), y = _mm256_set1_pd(xi[1]), z = _mm256_set1_pd(xi[2]);
  const __m256d dx = _mm256_sub_pd(_mm256_mask_i32gather_pd(x, v.x0, j3, m, 8), x);
  const __m256d dy = _mm256_sub_pd(_mm256_mask_i32gather_pd(y, v.x0 + 1, j3, m, 8), y);
  const __m256d dz = _mm256_sub_pd(_mm256_mask_i32gather_pd(z, v.x0 + 2, j3, m, 8), z);
  const __m256d rsq0 =
      _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
  const __m256d vj = UNIFORM ? _mm256_set1_pd(v.uniform_v)
                             : _mm256_mask_i32gather_pd(_mm256_setzero_pd(), v.vfrac, j, m, 8);
  const __m128i jtype = UNIFORM ? _mm_set1_epi32(v.uniform_type)
                                : _mm_mask_i32gather_epi32(_mm_setzero_si128(), v.type, j, m32, 4);
  const __m128i tj = _mm_add_epi32(jtype, _mm_set1_epi32(v.type[v.i] * CoefCache::TYPE_STRIDE));
  // the cache slots, as CoefCache::slot
  const __m256i qb = _mm256_castpd_si256(rsq0), vb = _mm256_castpd_si256(vj);
  const __m256i h =
      _mm256_xor_si256(_mm256_xor_si256(qb, _mm256_srli_epi64(vb, CoefCache::VOLUME_SHIFT)),
                       _mm256_slli_epi64(_mm256_cvtepu32_epi64(tj), CoefCache::TYPES_SHIFT));
  __m256i fold = h;
  for (int b = CoefCache::SLOT_BITS; b < 64; b += CoefCache::SLOT_BITS)
    fold = _mm256_xor_si256(fold, _mm256_srli_epi64(h, b));
  const __m256i slot = _mm256_and_si256(fold, _mm256_set1_epi64x(CoefCache::SIZE - 1));
  CoefCache &c = *v.cache;
  const __m256d zero = _mm256_setzero_pd();
  __m256d hit = _mm256_and_pd(
      m, _mm256_cmp_pd(rsq0, _mm256_mask_i64gather_pd(zero, c.rsq0.data(), slot, m, 8), _CMP_EQ_OQ));
  if (!UNIFORM) {
    const __m128i ct = _mm256_mask_i64gather_epi32(_mm_setzero_si128(), c.types.data(), slot, m32, 4);
    hit = _mm256_and_pd(hit, _mm256_cmp_pd(vj, _mm256_mask_i64gather_pd(zero, c.vj.data(), slot, m, 8),
                                           _CMP_EQ_OQ));
    hit = _mm256_and_pd(hit, _mm256_castsi256_pd(_mm256_cvtepi32_epi64(_mm_cmpeq_epi32(tj, ct))));
  }
  xi0 = _mm256_mask_i64gather_pd(zero, c.xi0.data(), slot, hit, 8);
  coef = _mm256_mask_i64gather_pd(zero, c.coef.data(), slot, hit, 8);
  const int missed = _mm256_movemask_pd(m) & ~_mm256_movemask_pd(hit);
  if (missed) {
    // looked up lane by lane (two lanes of this vector may share a slot)
    alignas(32) double lq[4], lv[4], lx[4], lc[4];
    alignas(16) int lt[4];
    _mm256_store_pd(lq, rsq0);
    _mm256_store_pd(lv, vj);
    _mm256_store_pd(lx, xi0);
    _mm256_store_pd(lc, coef);
    _mm_store_si128(reinterpret_cast<__m128i *>(lt), jtype);
    for (int l = 0; l < 4; l++)
      if (missed & (1 << l)) lc[l] = v.lookup(lt[l], lq[l], lv[l], lx[l]);
    xi0 = _mm256_load_pd(lx);
    coef = _mm256_load_pd(lc);
  }
}

// partner indices of bonds k..k+3 (m32: the lanes in the row; offsets read 4 entries, which
// the storage pads past a row's end)
inline __m128i load_partners(const int *bj, __m128i m32, int, int k)
{
  return _mm_maskload_epi32(bj + k, m32);
}
inline __m128i load_partners(const PartnerOffset *bj, __m128i m32, int i, int k)
{
  const __m128i d = _mm_cvtepi16_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(bj + k)));
  return _mm_and_si128(_mm_add_epi32(d, _mm_set1_epi32(i)), m32);
}

/* Groups of 4 bonds read the partner positions (load_positions, above) and the class entries
   with plain loads, a row's masked tail as well (TailGroup4, load_values_tail, below). */

// reference lengths and coefficients of the full group k..k+3
template <class Idx>
BBPD_GROUPS_INLINE inline void load_values_full(const PerBondValues &v, const Idx *, int, int k, __m256d &xi0, __m256d &coef)
{
  xi0 = _mm256_loadu_pd(v.xi0 + k);
  coef = _mm256_loadu_pd(v.coef + k);
}
template <class Idx>
BBPD_GROUPS_INLINE inline void load_values_full(const ClassValues &v, const Idx *, int, int k, __m256d &xi0, __m256d &coef)
{
  load_class_values(v.values, v.cls + k, xi0, coef);
}
template <class CoefFn, bool UNIFORM, class Idx>
inline void load_values_full(const RecomputedValues<CoefFn, UNIFORM> &v, const Idx *bj, int i, int k,
                             __m256d &xi0, __m256d &coef)
{
  const __m128i all = _mm_set1_epi32(-1);
  load_values(v, _mm256_castsi256_pd(_mm256_set1_epi64x(-1)), all, k, load_partners(bj, all, i, k),
              xi0, coef);
}

/* the force lanes (and with EV the energy and virial lanes) of a row in two 4-wide halves,
   lanes 0-3 and 4-7, and the breaking test: the operations of row_force_portable */
template <int FRACTURE, int EV, class Model> struct Avx2Lanes {
  __m256d fx[2], fy[2], fz[2], eacc[2], vacc[6][2];
  __m256d broken = _mm256_setzero_pd();
  __m256d vs0, vmargin;
  Avx2Lanes(double s0, double margin) : vs0(_mm256_set1_pd(s0)), vmargin(_mm256_set1_pd(margin))
  {
    for (int h = 0; h < 2; h++) {
      fx[h] = fy[h] = fz[h] = eacc[h] = _mm256_setzero_pd();
      for (auto &v : vacc) v[h] = _mm256_setzero_pd();
    }
  }
  // acc + v in the lanes of m, or everywhere if not MASKED
  template <bool MASKED> static __m256d masked_add(__m256d acc, __m256d v, __m256d m)
  {
    return MASKED ? _mm256_blendv_pd(acc, _mm256_add_pd(acc, v), m) : _mm256_add_pd(acc, v);
  }
  // the bonds of 4 lanes into half H; returns their elongations
  template <int H, bool MASKED>
  __m256d add(__m256d m, __m256d dx, __m256d dy, __m256d dz, __m256d xi0, __m256d coef)
  {
    const __m256d rsq =
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz));
    const __m256d r = _mm256_sqrt_pd(rsq);
    const __m256d elong = Model::elongation(Vec4(r), Vec4(xi0)).v;
    if (FRACTURE) {
      __m256d past = Model::past_critical(Vec4(elong), Vec4(xi0), Vec4(vs0), Vec4(vmargin)).v;
      if (MASKED) past = _mm256_and_pd(m, past);
      broken = _mm256_or_pd(broken, past);
    }
    const __m256d fbond = Model::force_per_length(Vec4(coef), Vec4(elong), Vec4(r)).v;
    fx[H] = masked_add<MASKED>(fx[H], _mm256_mul_pd(fbond, dx), m);
    fy[H] = masked_add<MASKED>(fy[H], _mm256_mul_pd(fbond, dy), m);
    fz[H] = masked_add<MASKED>(fz[H], _mm256_mul_pd(fbond, dz), m);
    if (EV) eacc[H] = masked_add<MASKED>(eacc[H], Model::energy_share(Vec4(coef), Vec4(elong)).v, m);
    if (tallies_virial(EV)) {
      const Vec4 d[3] = {dx, dy, dz};
      const int pa[6] = {0, 1, 2, 0, 0, 1}, pb[6] = {0, 1, 2, 1, 2, 2};
      for (int c = 0; c < 6; c++) {
        const __m256d v = Model::virial_share(Vec4(fbond), d[pa[c]], d[pb[c]]).v;
        vacc[c][H] = MASKED ? _mm256_blendv_pd(vacc[c][H], _mm256_sub_pd(vacc[c][H], v), m)
                            : _mm256_sub_pd(vacc[c][H], v);
      }
    }
    return elong;
  }
  void store(double *ax, double *ay, double *az, RowTally *tally) const
  {
    for (int h = 0; h < 2; h++) {
      _mm256_storeu_pd(ax + 4 * h, fx[h]);
      _mm256_storeu_pd(ay + 4 * h, fy[h]);
      _mm256_storeu_pd(az + 4 * h, fz[h]);
      if (EV) _mm256_storeu_pd(tally->eng + 4 * h, eacc[h]);
      for (int c = 0; c < 6 && tallies_virial(EV); c++) _mm256_storeu_pd(tally->vir[c] + 4 * h, vacc[c][h]);
    }
  }
};

/* A row of n bonds in groups of 4 for the AVX2 kernels: full(half, k) takes bonds k..k+3 and
   tail(half, k) the last n - k < 4, masked; groups alternate between the two 4-wide halves of
   the 8-wide accumulators (half 0, 1, 0, ...), so the sums match the AVX-512 kernel's lanes. */
// inlined into the kernel: GCC left it a call, with the lambdas' captures built in memory for
// every row (instruction counts: doc/performance.md)
template <class Full, class Tail>
BBPD_GROUPS_INLINE inline void for_each_group4(int n, Full &&full, Tail &&tail)
{
  using H0 = std::integral_constant<int, 0>;
  using H1 = std::integral_constant<int, 1>;
  int k = 0;
  for (; k + 8 <= n; k += 8) {
    full(H0(), k);
    full(H1(), k + 4);
  }
  if (k + 4 <= n) {
    full(H0(), k);
    k += 4;
  }
  if (k < n) {
    if ((k / 4) & 1)
      tail(H1(), k);
    else
      tail(H0(), k);
  }
}

/* the last n - k < 4 bonds of the row of atom i (at xi, yi, zi), masked: their lanes (m, and
   m32 for 32-bit data), partners j1 (zero in the lanes off) and j (from row_origin; atom i
   itself in the lanes off) and partner differences d* (zero in the lanes off). The positions
   are read as a full group's, with plain loads: three gathers per tail cost about 2 % of an
   LPS step on LAMMPS's cylinder (AVX2, Sapphire Rapids). */
struct TailGroup4 {
  __m128i m32, j1;
  __m256d m, dx, dy, dz;
  std::ptrdiff_t j[4];
  template <class Idx>
  BBPD_GROUPS_INLINE TailGroup4(const double *xx, const Idx *bj, int i, int n, int k, __m256d xi, __m256d yi,
                            __m256d zi) :
      m32(_mm_cmpgt_epi32(_mm_set1_epi32(n - k), _mm_setr_epi32(0, 1, 2, 3))),
      j1(load_partners(bj, m32, i, k)), m(_mm256_castsi256_pd(_mm256_cvtepi32_epi64(m32)))
  {
    const int o = row_origin(bj, i);
    for (int l = 0; l < 4; l++) j[l] = l < n - k ? std::ptrdiff_t(bj[k + l]) : std::ptrdiff_t(i - o);
    __m256d x, y, z;
    load_positions(xx + 3 * o, j, x, y, z);
    dx = _mm256_sub_pd(x, xi);
    dy = _mm256_sub_pd(y, yi);
    dz = _mm256_sub_pd(z, zi);
  }
};

// a tail's reference lengths and coefficients (lanes off in m: zero), as load_values; a class
// table by plain loads (the class entries are readable past a row's end), the lanes off cleared
template <class Values>
BBPD_GROUPS_INLINE inline void load_values_tail(const Values &v, const TailGroup4 &g, int k, __m256d &xi0,
                                            __m256d &coef)
{
  load_values(v, g.m, g.m32, k, g.j1, xi0, coef);
}
BBPD_GROUPS_INLINE inline void load_values_tail(const ClassValues &v, const TailGroup4 &g, int k, __m256d &xi0,
                                            __m256d &coef)
{
  load_class_values(v.values, v.cls + k, xi0, coef);
  xi0 = _mm256_and_pd(g.m, xi0);
  coef = _mm256_and_pd(g.m, coef);
}

/* the same as row_force_avx512 with two 4-wide halves: lanes 0-3 and 4-7 */
template <int FRACTURE, int EV, class Model, class Values, class Idx>
inline bool row_force_avx2(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                           double s0, double margin, double *ax, double *ay, double *az,
                           RowTally *tally)
{
  const __m256d xi = _mm256_set1_pd(xx[3 * i]), yi = _mm256_set1_pd(xx[3 * i + 1]),
                zi = _mm256_set1_pd(xx[3 * i + 2]), all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
  Avx2Lanes<FRACTURE, EV, Model> lanes(s0, margin);
  // bonds k..k+3, every lane in the row, into half H
  auto full = [&](auto half, int k) {
    const std::ptrdiff_t j[4] = {bj[k], bj[k + 1], bj[k + 2], bj[k + 3]};    // from row_origin
    __m256d x, y, z, xi0, coef;
    load_positions(xx + 3 * row_origin(bj, i), j, x, y, z);
    load_values_full(vals, bj, i, k, xi0, coef);
    lanes.template add<decltype(half)::value, false>(all, _mm256_sub_pd(x, xi), _mm256_sub_pd(y, yi),
                                                     _mm256_sub_pd(z, zi), xi0, coef);
  };
  // the last n - k < 4 bonds, masked, into half H
  auto tail = [&](auto half, int k) {
    const TailGroup4 g(xx, bj, i, n, k, xi, yi, zi);
    __m256d xi0, coef;
    load_values_tail(vals, g, k, xi0, coef);
    lanes.template add<decltype(half)::value, true>(g.m, g.dx, g.dy, g.dz, xi0, coef);
  };
  for_each_group4(n, full, tail);
  if (FRACTURE && _mm256_movemask_pd(lanes.broken)) return true;
  lanes.store(ax, ay, az, tally);
  return false;
}
#define row_force_simd BBPD::row_force_avx2
#endif

}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the rows of the LPS families with a deviatoric history (VES, EPS: bbpd_ves.h,
   bbpd_eps.h) in lanes, with no LAMMPS dependency: the norm pass (EPS, fused with the force
   pass of its elastic plan in the SIMD kernels) and the force pass of
   bbpd_lps_history_row.h with bond k in lane k % LANES, as the LPS rows of bbpd_lps_lanes.h,
   so that the AVX2 and AVX-512 kernels give the portable loop's bits. A bond end's history is
   read from, and with COMMIT (ROLL) written back to, slot slot[k] of the row's blocks hist
   (bbpd_history_blocks.h) in every path: each bond end has a slot of its own, so the lanes
   never write the same place. As in
   the scalar row, a bond without weighted volume at both ends has no force and keeps its
   history.
------------------------------------------------------------------------- */

#ifndef BBPD_LPS_HISTORY_LANES_H
#define BBPD_LPS_HISTORY_LANES_H

#include "bbpd_history_blocks.h"
#include "bbpd_lps_history_row.h"
#include "bbpd_lps_lanes.h"

#include <cmath>
#include <limits>
#include <type_traits>

namespace BBPD {
namespace LPS {

  // what a history row reads of atom i: the LPS row's numbers and d K (split_dilatational)
  struct HistoryCoefficients : RowCoefficients {
    double bulk_term;
  };

  // the influence function 1 / |xi0| over any width (influence, bbpd_lps.h)
  template <class V> inline V influence_v(V xi0)
  {
    return vselect(vabs(xi0) < V(PMB::NEAR_ZERO), V(1.0 / PMB::NEAR_ZERO), V(1.0) / xi0);
  }

  // the force state of a bond end whose partner has a weighted volume (history_force_state)
  template <class F, bool COMMIT, class V>
  inline V history_force_v(const F &fam, const typename F::Plan &plan, const HistoryCoefficients &c,
                           V wv, V xi0, V e, V tom_j, V inv_m_j, V &h0, V &h1, V &energy)
  {
    const V ed = e - V(c.theta_third_i) * xi0;
    const V dil = V(c.bulk_term) * wv * (V(c.theta_over_m_i) + tom_j) * xi0;
    return dil + fam.template deviatoric_v<COMMIT>(plan, wv, influence_v(xi0), xi0, ed,
                                                   V(c.inv_m_i) + inv_m_j, h0, h1, energy);
  }

  /* the portable norm pass: the sum of the row's norm terms (ROLL: the first evaluation of a
     step, which rolls each bond end's history) */
  template <class F, bool ROLL, class Idx, class Values>
  inline double history_norm_portable(const double *xx, int i, const Idx *bj, const Values &vals,
                                      int n, const AtomState *states, double theta_third_i,
                                      const F &fam, const int *slot, double *hist)
  {
    const double xi = xx[3 * i], yi = xx[3 * i + 1], zi = xx[3 * i + 2];
    double lane[LANES] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (int k = 0; k < n; k++) {
      const int j = partner_index(bj, i, k);
      const double xi0 = vals.xi0_at(k, j), wv = vals.coef_at(k, j);
      const double dx = xx[3 * j] - xi, dy = xx[3 * j + 1] - yi, dz = xx[3 * j + 2] - zi;
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double ed = deviatoric_extension(elongation(r, xi0), xi0, theta_third_i);
      constexpr int B = F::BOND_HISTORY;
      lane[k % LANES] += fam.template norm_term_v<ROLL>(
          wv, influence(xi0), ed, states[i].inv_m + states[j].inv_m,
          history_value<B>(hist, slot[k], 0), history_value<B>(hist, slot[k], 1));
    }
    return lane_total(lane);
  }

  /* the portable force pass (force_row_portable of bbpd_lps_lanes.h with the family's force
     state; energy lanes: the family's energy terms) */
  template <class F, int EV, int CHECK, int COMMIT, class Idx, class Values, class S0>
  inline bool history_force_portable(const double *xx, int i, const Idx *bj, const Values &vals,
                                     int n, const AtomState *states, const F &fam,
                                     const typename F::Plan &plan, const HistoryCoefficients &c,
                                     const int *slot, double *hist, S0 s0_of, double *snew,
                                     ForceLanes &out)
  {
    const bool has_m = c.inv_m_i > 0.0;
    auto bond = [&](int k, int j, double r, double xi0, double wv, double e, double &energy) {
      double t = 0.0;
      if (has_m && states[j].inv_m > 0.0) {
        constexpr int B = F::BOND_HISTORY;
        t = history_force_v<F, COMMIT != 0>(fam, plan, c, wv, xi0, e, states[j].theta_over_m,
                                            states[j].inv_m, history_value<B>(hist, slot[k], 0),
                                            history_value<B>(hist, slot[k], 1), energy);
      }
      return r > 0.0 ? t / r : 0.0;
    };
    return force_pass_portable<EV, CHECK>(xx, i, bj, vals, n, bond, s0_of, c.margin, snew, out);
  }

  /* the first evaluation of a step of a family with a norm (EPS): the norm pass, which rolls
     the history (*norm_sum: its sum), then the force pass of the elastic plan, committed, with
     the breaking check. A row whose norm makes it plastic is summed again with its plan
     (history_force_*, COMMIT), which reads the rolled history: on the deck no row is plastic,
     and the SIMD kernels (history_norm_force_avx2, _avx512) do both passes' work in one pass
     over the row with these bits. */
  template <class F, int EV, class Idx, class Values, class S0>
  inline bool history_norm_force_portable(const double *xx, int i, const Idx *bj, const Values &vals,
                                          int n, const AtomState *states, const F &fam,
                                          const HistoryCoefficients &c, const int *slot,
                                          double *hist, S0 s0_of, double *snew, ForceLanes &out,
                                          double *norm_sum)
  {
    *norm_sum = history_norm_portable<F, true>(xx, i, bj, vals, n, states, c.theta_third_i, fam, slot, hist);
    const typename F::Plan elastic{};    // not plastic
    return history_force_portable<F, EV, 1, 1>(xx, i, bj, vals, n, states, fam, elastic, c, slot,
                                               hist, s0_of, snew, out);
  }

  /* A row none of whose partners was lost keeps its bonds in partner slots 0..n-1: the
     history of bonds k .. k+3 (k a multiple of 4) is then one block, and the vector paths load
     and store each value of it whole instead of gathering and scattering it lane by lane (the
     same values either way). A row's slots rise with k (PairBBPDLPS::find_bond_slots), so its
     last slot says it. (On the bpm/peri deck, VES on the AVX2 path: 2.64 -> 1.85 s; a check
     that read every slot cost the AVX-512 path 9 %.) */
  inline bool dense_slots(const int *slot, int n) { return n == 0 || slot[n - 1] == n - 1; }

#ifdef BBPD_AVX512
  // the place of value 0 of the slots k..k+7 of the row (lanes off in m: 0); value v at
  // HISTORY_BLOCK v further
  template <class F> inline __m256i history_index(const int *slot, __mmask8 m, int k)
  {
    const __m256i s = _mm256_maskz_loadu_epi32(m, slot + k);
    const __m256i block = _mm256_srli_epi32(s, 2), within = _mm256_and_si256(s, _mm256_set1_epi32(3));
    static_assert(HISTORY_BLOCK == 4, "slot / 4 and slot % 4 by shift and mask");
    return _mm256_add_epi32(_mm256_mullo_epi32(block, _mm256_set1_epi32(HISTORY_BLOCK * F::BOND_HISTORY)),
                            within);
  }

  /* the history (h0, h1) of bonds k..k+7 in the lanes of m (others 0), and writing it back: in a
     dense row (dense_slots) the two blocks of slots k..k+3 and k+4..k+7, one load or store each
     and a shuffle of 256-bit halves per value; else gathers by slot */
  inline __mmask8 block_mask(__mmask8 m, int half)    // the lanes of bonds 4 half .. 4 half + 3, twice
  {
    const unsigned q = (m >> (4 * half)) & 0xFu;
    return (__mmask8) (q | (q << 4));
  }
  template <class F>
  inline void read_history8(const int *slot, double *hist, int k, __mmask8 m, bool dense,
                            __m512d &h0, __m512d &h1)
  {
    if constexpr (F::BOND_HISTORY == 2) {
      if (dense) {
        const double *h = hist + 2 * k;    // history_offset<2>(k, 0), k a multiple of 8
        const __m512d lo = _mm512_maskz_loadu_pd(block_mask(m, 0), h);
        const __m512d hi = _mm512_maskz_loadu_pd(block_mask(m, 1), h + 2 * HISTORY_BLOCK);
        h0 = _mm512_shuffle_f64x2(lo, hi, 0x44);    // the first 256 bits of each
        h1 = _mm512_shuffle_f64x2(lo, hi, 0xEE);    // the last 256 bits of each
        return;
      }
    }
    const __m256i hi = history_index<F>(slot, m, k);
    h0 = _mm512_mask_i32gather_pd(_mm512_setzero_pd(), m, hi, hist, 8);
    h1 = _mm512_mask_i32gather_pd(_mm512_setzero_pd(), m, hi, hist + HISTORY_BLOCK, 8);
  }
  template <class F>
  inline void write_history8(const int *slot, double *hist, int k, __mmask8 m, bool dense,
                             __m512d h0, __m512d h1)
  {
    if constexpr (F::BOND_HISTORY == 2) {
      if (dense) {
        double *h = hist + 2 * k;
        _mm512_mask_storeu_pd(h, block_mask(m, 0), _mm512_shuffle_f64x2(h0, h1, 0x44));
        _mm512_mask_storeu_pd(h + 2 * HISTORY_BLOCK, block_mask(m, 1), _mm512_shuffle_f64x2(h0, h1, 0xEE));
        return;
      }
    }
    const __m256i hi = history_index<F>(slot, m, k);
    _mm512_mask_i32scatter_pd(hist, m, hi, h0, 8);
    _mm512_mask_i32scatter_pd(hist + HISTORY_BLOCK, m, hi, h1, 8);
  }

  /* the force pass, 8 lanes (one s00 and alpha); with NORM also the norm pass of
     history_norm_force_portable in the same pass over the row: every bond end's history read
     and rolled, its norm term summed into *norm_sum, and the commit of the force state (the
     elastic plan's) written where the bond has a force */
  template <class F, int EV, int CHECK, int COMMIT, bool NORM = false, class Idx, class Values>
  inline bool history_force_avx512(const double *xx, int i, const Idx *bj, const Values &vals_in,
                                   int n, const AtomState *states, const F &fam_in,
                                   const typename F::Plan &plan_in, const HistoryCoefficients &c_in,
                                   const int *slot, double *hist, const double *smin_all,
                                   double *snew, ForceLanes &out, double *norm_sum = nullptr)
  {
    /* copies of the coefficients and tables: the history is stored through a double *, which as
       far as the compiler knows may point into the callers' structs, so with references every
       group of bonds loaded each coefficient again and redid the sums made of them (1 - decay,
       1 - lambda): on the bpm/peri deck the AVX2 kernel ran 309 instructions per 8 VES bonds
       (callgrind) against LPS's 168, 255 with copies. The same operations, so the same bits. */
    const F fam = fam_in;
    const typename F::Plan plan = plan_in;
    const HistoryCoefficients c = c_in;
    const Values vals = vals_in;
    const __m512d xi = _mm512_set1_pd(xx[3 * i]), yi = _mm512_set1_pd(xx[3 * i + 1]),
                  zi = _mm512_set1_pd(xx[3 * i + 2]), zero = _mm512_setzero_pd();
    const __mmask8 row_ok = c.inv_m_i > 0.0 ? (__mmask8) 0xFF : (__mmask8) 0;
    const bool dense = dense_slots(slot, n);
    ForceSums8<EV, CHECK> sums;
    __m512d nacc = zero;
    for (int k = 0; k < n; k += LANES) {
      const __mmask8 m = (n - k >= LANES) ? (__mmask8) 0xFF : (__mmask8) ((1u << (n - k)) - 1);
      const __m256i j1 = load_partners(bj, m, i, k);
      const BondLanes b = bond_lanes<Elongation>(xx, xi, yi, zi, j1, m, vals, k);
      __m512d tom, inv_m;
      load_states(states, j1, m, tom, inv_m);
      // bonds with a weighted volume at both ends: force, energy, history
      const __mmask8 ok = m & row_ok & _mm512_cmp_pd_mask(inv_m, zero, _CMP_GT_OQ);
      const __mmask8 read = NORM ? m : ok;    // the norm pass rolls every bond end's history
      __m512d ha, hb;
      read_history8<F>(slot, hist, k, read, dense, ha, hb);
      Vec8 h0(ha), h1(hb);
      if constexpr (NORM) {
        const Vec8 ed = Vec8(b.elong) - Vec8(c.theta_third_i) * Vec8(b.xi0);
        const Vec8 term = fam.template norm_term_v<true>(Vec8(b.coef), influence_v(Vec8(b.xi0)), ed,
                                                         Vec8(c.inv_m_i) + Vec8(inv_m), h0, h1);
        nacc = _mm512_mask_add_pd(nacc, m, nacc, term.v);
      }
      Vec8 f0 = h0, f1 = h1, energy(0.0);
      const Vec8 t = history_force_v<F, COMMIT != 0>(fam, plan, c, Vec8(b.coef), Vec8(b.xi0),
                                                     Vec8(b.elong), Vec8(tom), Vec8(inv_m), f0, f1, energy);
      if (NORM)
        write_history8<F>(slot, hist, k, read, dense, h0.v, _mm512_mask_mov_pd(h1.v, ok, f1.v));
      else if (COMMIT)
        write_history8<F>(slot, hist, k, ok, dense, f0.v, f1.v);
      const __m512d t_ok = _mm512_maskz_mov_pd(ok, t.v);
      const __m512d fpl = vkeep(Vec8(b.r) > Vec8(zero), Vec8(t_ok) / Vec8(b.r)).v;
      sums.add(m, b, fpl, _mm512_maskz_mov_pd(ok, energy.v));
      sums.check(m, b);
    }
    if constexpr (NORM) {
      alignas(64) double lane[LANES];
      _mm512_store_pd(lane, nacc);
      *norm_sum = lane_total(lane);
    }
    return sums.store(out, snew, c) && past_avx512(xx, i, bj, vals, n, c, smin_all);
  }
  // history_norm_force_portable's pass in 8 lanes
  template <class F, int EV, class Idx, class Values>
  inline bool history_norm_force_avx512(const double *xx, int i, const Idx *bj, const Values &vals,
                                        int n, const AtomState *states, const F &fam,
                                        const HistoryCoefficients &c, const int *slot, double *hist,
                                        const double *smin_all, double *snew, ForceLanes &out,
                                        double *norm_sum)
  {
    const typename F::Plan elastic{};
    return history_force_avx512<F, EV, 1, 1, true>(xx, i, bj, vals, n, states, fam, elastic, c, slot,
                                                   hist, smin_all, snew, out, norm_sum);
  }
#define lps_history_norm_force_simd BBPD::LPS::history_norm_force_avx512
#define lps_history_force_simd BBPD::LPS::history_force_avx512
#endif

#ifdef BBPD_AVX2
  /* The history kernels in 4-wide groups as for_each_group4 hands them out (lanes 0-3, 4-7 of
     the 8-wide accumulators; group4 of bbpd_lps_lanes.h): a dense row's full group reads and
     writes its block whole, any other group its lanes one by one. */
  // the history of the lanes in 'lanes' (bits) of bonds k..k+3, and writing it back
  template <class F> BBPD_GROUPS_INLINE inline void read_history4(const int *slot, double *hist, int k, int lanes,
                                               bool dense, __m256d &h0, __m256d &h1)
  {
    if constexpr (F::BOND_HISTORY == 2) {
      if (dense && lanes == 0xF) {    // slots k..k+3: one block (dense_slots)
        h0 = _mm256_loadu_pd(hist + 2 * k);    // history_offset<2>(k, 0), k a multiple of 4
        h1 = _mm256_loadu_pd(hist + 2 * k + HISTORY_BLOCK);
        return;
      }
    }
    constexpr int B = F::BOND_HISTORY;
    alignas(32) double a[4] = {0.0, 0.0, 0.0, 0.0}, b[4] = {0.0, 0.0, 0.0, 0.0};
    for (int l = 0; l < 4; l++)
      if (lanes & (1 << l)) {
        a[l] = history_value<B>(hist, slot[k + l], 0);
        b[l] = history_value<B>(hist, slot[k + l], 1);
      }
    h0 = _mm256_load_pd(a);
    h1 = _mm256_load_pd(b);
  }
  template <class F> BBPD_GROUPS_INLINE inline void write_history4(const int *slot, double *hist, int k, int lanes,
                                                bool dense, __m256d h0, __m256d h1)
  {
    if constexpr (F::BOND_HISTORY == 2) {
      if (dense && lanes == 0xF) {
        _mm256_storeu_pd(hist + 2 * k, h0);
        _mm256_storeu_pd(hist + 2 * k + HISTORY_BLOCK, h1);
        return;
      }
    }
    constexpr int B = F::BOND_HISTORY;
    alignas(32) double a[4], b[4];
    _mm256_store_pd(a, h0);
    _mm256_store_pd(b, h1);
    for (int l = 0; l < 4; l++)
      if (lanes & (1 << l)) {
        history_value<B>(hist, slot[k + l], 0) = a[l];
        history_value<B>(hist, slot[k + l], 1) = b[l];
      }
  }

  template <class F, int EV, int CHECK, int COMMIT, bool NORM = false, class Idx, class Values>
  inline bool history_force_avx2(const double *xx, int i, const Idx *bj, const Values &vals_in, int n,
                                 const AtomState *states, const F &fam_in,
                                 const typename F::Plan &plan_in, const HistoryCoefficients &c_in,
                                 const int *slot, double *hist, const double *smin_all,
                                 double *snew, ForceLanes &out, double *norm_sum = nullptr)
  {
    // copies, as history_force_avx512's
    const F fam = fam_in;
    const typename F::Plan plan = plan_in;
    const HistoryCoefficients c = c_in;
    const Values vals = vals_in;
    const __m256d xi = _mm256_set1_pd(xx[3 * i]), yi = _mm256_set1_pd(xx[3 * i + 1]),
                  zi = _mm256_set1_pd(xx[3 * i + 2]), zero = _mm256_setzero_pd();
    // every lane if atom i has a weighted volume, else none (a mask, not a test per group)
    const __m256d row_ok = _mm256_castsi256_pd(_mm256_set1_epi64x(c.inv_m_i > 0.0 ? -1 : 0));
    const bool dense = dense_slots(slot, n);
    ForceSums4x2<EV, CHECK> sums;
    __m256d nacc[2] = {zero, zero};
    auto group = [&](auto half, int k, bool full) BBPD_GROUPS_INLINE {
      constexpr int H = decltype(half)::value;
      const Group4 g = group4(xx, bj, i, n, k, full, xi, yi, zi, vals, states);
      const __m256d ok = _mm256_and_pd(row_ok, _mm256_and_pd(g.m, _mm256_cmp_pd(g.inv_m, zero, _CMP_GT_OQ)));
      const int lanes = _mm256_movemask_pd(NORM ? g.m : ok);    // as history_force_avx512's read
      __m256d a, b;
      read_history4<F>(slot, hist, k, lanes, dense, a, b);
      Vec4 h0(a), h1(b);
      const __m256d r = lengths4(g.dx, g.dy, g.dz);
      const __m256d e = Elongation::elongation(Vec4(r), Vec4(g.xi0)).v;
      if constexpr (NORM) {
        const Vec4 ed = Vec4(e) - Vec4(c.theta_third_i) * Vec4(g.xi0);
        const Vec4 term = fam.template norm_term_v<true>(Vec4(g.wv), influence_v(Vec4(g.xi0)), ed,
                                                         Vec4(c.inv_m_i) + Vec4(g.inv_m), h0, h1);
        nacc[H] = lps_add<true>(nacc[H], term.v, g.m);
      }
      Vec4 f0 = h0, f1 = h1, energy(0.0);
      const Vec4 t = history_force_v<F, COMMIT != 0>(fam, plan, c, Vec4(g.wv), Vec4(g.xi0), Vec4(e),
                                                     Vec4(g.tom), Vec4(g.inv_m), f0, f1, energy);
      if (NORM)
        write_history4<F>(slot, hist, k, lanes, dense, h0.v, _mm256_blendv_pd(h1.v, f1.v, ok));
      else if (COMMIT)
        write_history4<F>(slot, hist, k, lanes, dense, f0.v, f1.v);
      const __m256d t_ok = _mm256_and_pd(ok, t.v);
      const __m256d fpl = vkeep(Vec4(r) > Vec4(zero), Vec4(t_ok) / Vec4(r)).v;
      sums.template add<H, true>(g.m, g.dx, g.dy, g.dz, fpl, _mm256_and_pd(ok, energy.v));
      sums.template check<true>(g.m, e, g.xi0);
    };
    for_each_group4(n, [&](auto half, int k) BBPD_GROUPS_INLINE { group(half, k, true); },
                    [&](auto half, int k) BBPD_GROUPS_INLINE { group(half, k, false); });
    if constexpr (NORM) {
      alignas(32) double lane[LANES];
      _mm256_store_pd(lane, nacc[0]);
      _mm256_store_pd(lane + 4, nacc[1]);
      *norm_sum = lane_total(lane);
    }
    return sums.store(out, snew, c) && past_avx2(xx, i, bj, vals, n, c, smin_all);
  }
  // history_norm_force_portable's pass in 4-wide groups
  template <class F, int EV, class Idx, class Values>
  inline bool history_norm_force_avx2(const double *xx, int i, const Idx *bj, const Values &vals,
                                      int n, const AtomState *states, const F &fam,
                                      const HistoryCoefficients &c, const int *slot, double *hist,
                                      const double *smin_all, double *snew, ForceLanes &out,
                                      double *norm_sum)
  {
    const typename F::Plan elastic{};
    return history_force_avx2<F, EV, 1, 1, true>(xx, i, bj, vals, n, states, fam, elastic, c, slot, hist,
                                                 smin_all, snew, out, norm_sum);
  }
#define lps_history_norm_force_simd BBPD::LPS::history_norm_force_avx2
#define lps_history_force_simd BBPD::LPS::history_force_avx2
#endif

}    // namespace LPS
}    // namespace BBPD

#endif

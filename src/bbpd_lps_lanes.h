// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the two passes of a row of the linear peridynamic solid (bbpd_lps.h) in lanes, with no
   LAMMPS dependency (tests/unit/test_lps_lanes.cpp runs them on plain arrays):
     the dilatation pass: the sum of w V xi0 e over the bonds of atom i;
     the force pass: the force density of the LPS force states of its bonds, the sums of its
       energy and virial, and with CHECK its smallest stretch and whether a bond is past (or
       within 'margin' of) its Silling-Askari critical stretch.
   As in the bond-based rows (bbpd_row.h), bond k goes to lane k % LANES and the lanes are summed
   in one fixed order (lane_total), the bond's terms are written once over the value type V
   (double, Vec4, Vec8: bbpd_simd.h) and the AVX2 and AVX-512 kernels do the portable loop's
   operations in its order, so all paths give the same bits. The current bond length is
   computed in each pass (a square root per bond end is cheaper than 8 bytes written and read
   again per bond end). The SIMD force passes keep the row's smallest and largest stretch and
   test each bond against its critical stretch only when the largest reaches the row's floor
   (RowCoefficients::s0_floor): a gather of the partners' smallest stretches per 4 bonds cost
   about 5 % of an LPS step on the bpm/peri deck (AVX2, Sapphire Rapids).
------------------------------------------------------------------------- */

#ifndef BBPD_LPS_LANES_H
#define BBPD_LPS_LANES_H

#include "bbpd_bond_model.h"
#include "bbpd_lps.h"
#include "bbpd_pmb_rules.h"
#include "bbpd_row.h"
#include "bbpd_silling_askari.h"
#include "bbpd_stretch_row.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace BBPD {
namespace LPS {

  using StretchRule = SillingAskariRule<false>;    // peri/lps: smin not clamped

  // what a row's force pass reads of atom i and of the breaking rule
  struct RowCoefficients {
    double dilatational, deviatoric;    // of i's type (Moduli)
    double theta_over_m_i, inv_m_i;     // i's state
    double theta_third_i;               // theta_i / d
    double s00, alpha, smin_i;          // the Silling-Askari rule (one s00 and alpha)
    double margin;                      // periodic box: a stretch this close to s0 is re-checked
    // no bond of the row has a smaller critical stretch (critical_stretch_floor): the SIMD
    // force passes test each bond only when the row's largest stretch reaches it
    double s0_floor = -std::numeric_limits<double>::infinity();
  };

  // BBPD::critical_stretch_floor (bbpd_silling_askari.h) of peri/lps's rule
  inline double critical_stretch_floor(double s00, double alpha, double smin_i, double smin_cap)
  {
    return BBPD::critical_stretch_floor<StretchRule>(s00, alpha, smin_i, smin_cap);
  }

  // the elongation of peri/lps over any width: round-off elongations are zero
  struct Elongation {
    template <class V> static V elongation(V r, V xi0)
    {
      const V e = r - xi0;
      return vdrop(vabs(e) < V(PMB::NEAR_ZERO), e);
    }
  };

  // a bond's term of the dilatation sum (dilatation_term)
  template <class V> inline V dilatation_term_v(V wv, V xi0, V e) { return wv * xi0 * e; }

  /* the force per current length of a bond (force_state / r), with partner state (tom_j,
     inv_m_j): zero unless the partner has a weighted volume (atom i's is checked per row) */
  template <class V>
  inline V force_per_length(const RowCoefficients &c, V wv, V xi0, V e, V r, V tom_j, V inv_m_j)
  {
    const V t = V(c.dilatational) * wv * (V(c.theta_over_m_i) + tom_j) * xi0 +
        V(c.deviatoric) * wv * (V(c.inv_m_i) + inv_m_j) * e;
    const V t_both = vkeep(inv_m_j > V(0.0), t);
    return vkeep(r > V(0.0), t_both / r);
  }

  // the row's energy lane term: w V ed^2 (deviatoric_energy_of multiplies the sum)
  template <class V> inline V energy_term(const RowCoefficients &c, V wv, V xi0, V e)
  {
    const V ed = e - V(c.theta_third_i) * xi0;
    return wv * (ed * ed);
  }

  // the lanes of a force pass: force density, and the energy (eng) and virial (vir: the sums of
  // (t / |y|) d_a d_b, xx yy zz xy xz yz) before their factors
  struct ForceLanes {
    double fx[LANES], fy[LANES], fz[LANES];
    RowTally tally;
  };

  /* the portable dilatation pass: the sum of the row's dilatation terms */
  template <class Idx, class Values>
  inline double dilatation_sum_portable(const double *xx, int i, const Idx *bj, const Values &vals,
                                        int n)
  {
    const double xi = xx[3 * i], yi = xx[3 * i + 1], zi = xx[3 * i + 2];
    double lane[LANES] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    for (int k = 0; k < n; k++) {
      const int j = partner_index(bj, i, k);
      const double dx = xx[3 * j] - xi, dy = xx[3 * j + 1] - yi, dz = xx[3 * j + 2] - zi;
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double xi0 = vals.xi0_at(k, j);
      lane[k % LANES] += dilatation_term_v(vals.coef_at(k, j), xi0, Elongation::elongation(r, xi0));
    }
    return lane_total(lane);
  }

  /* the portable force pass over the n bonds of atom i, the force state of a family:
     bond(k, j, r, xi0, wv, e, energy) gives the force per current length of bond k (partner j,
     current and reference length, w V, elongation) and sets its energy term (left 0: none);
     with CHECK the critical stretch of the bond to j is s0_of(j), the smallest stretch goes to
     *snew and the return value says whether a bond is past s0 or within 'margin' of it */
  template <int EV, int CHECK, class Idx, class Values, class Bond, class S0>
  inline bool force_pass_portable(const double *xx, int i, const Idx *bj, const Values &vals,
                                  int n, Bond bond, S0 s0_of, double margin, double *snew,
                                  ForceLanes &out)
  {
    const double xi = xx[3 * i], yi = xx[3 * i + 1], zi = xx[3 * i + 2];
    for (int l = 0; l < LANES; l++) {
      out.fx[l] = out.fy[l] = out.fz[l] = out.tally.eng[l] = 0.0;
      for (auto &v : out.tally.vir) v[l] = 0.0;
    }
    double smin = std::numeric_limits<double>::max();
    bool past = false;
    for (int k = 0; k < n; k++) {
      const int l = k % LANES;
      const int j = partner_index(bj, i, k);
      const double dx = xx[3 * j] - xi, dy = xx[3 * j + 1] - yi, dz = xx[3 * j + 2] - zi;
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
      const double xi0 = vals.xi0_at(k, j), wv = vals.coef_at(k, j);
      const double e = Elongation::elongation(r, xi0);
      double energy = 0.0;
      const double fpl = bond(k, j, r, xi0, wv, e, energy);
      out.fx[l] += fpl * dx;
      out.fy[l] += fpl * dy;
      out.fz[l] += fpl * dz;
      if (EV) out.tally.eng[l] += energy;
      if (tallies_virial(EV)) {
        const double d[3] = {dx, dy, dz};
        const int pa[6] = {0, 1, 2, 0, 0, 1}, pb[6] = {0, 1, 2, 1, 2, 2};
        for (int v = 0; v < 6; v++) out.tally.vir[v][l] += fpl * d[pa[v]] * d[pb[v]];
      }
      if (CHECK) {
        const double s = StretchRule::stretch(e, xi0);
        smin = std::min(smin, s);
        past |= StretchRule::past_critical(s, s0_of(j), margin);
      }
    }
    if (CHECK) *snew = smin;
    return past;
  }

  /* the portable force pass of the LPS (partner states 'states'), as force_pass_portable */
  template <int EV, int CHECK, class Idx, class Values, class S0>
  inline bool force_row_portable(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                                 const AtomState *states, const RowCoefficients &c, S0 s0_of,
                                 double *snew, ForceLanes &out)
  {
    const bool has_m = c.inv_m_i > 0.0;
    auto bond = [&](int, int j, double r, double xi0, double wv, double e, double &energy) {
      if (EV) energy = energy_term(c, wv, xi0, e);
      return has_m ? force_per_length(c, wv, xi0, e, r, states[j].theta_over_m, states[j].inv_m) : 0.0;
    };
    return force_pass_portable<EV, CHECK>(xx, i, bj, vals, n, bond, s0_of, c.margin, snew, out);
  }

#ifdef BBPD_SIMD
  // the smallest (or with MAX the largest) of 4 lanes
  template <bool MAX> inline double lane_extreme4(__m256d v)
  {
    const __m128d lo = _mm256_castpd256_pd128(v), hi = _mm256_extractf128_pd(v, 1);
    const __m128d b = MAX ? _mm_max_pd(lo, hi) : _mm_min_pd(lo, hi);
    const double x = _mm_cvtsd_f64(b), y = _mm_cvtsd_f64(_mm_unpackhi_pd(b, b));
    return MAX ? std::max(x, y) : std::min(x, y);
  }

  // theta / m and 1 / m of 4 partners j (16-byte loads, unpacked; always inlined, as
  // load_positions: each path's file has its own copy)
  template <class J>
  BBPD_GROUPS_INLINE inline void load_states4(const AtomState *states, const J *j, __m256d &tom, __m256d &inv_m)
  {
    auto pair = [&](J a, J b) {
      return _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(&states[a].theta_over_m)),
                                  _mm_loadu_pd(&states[b].theta_over_m), 1);
    };
    const __m256d a02 = pair(j[0], j[2]), a13 = pair(j[1], j[3]);
    tom = _mm256_unpacklo_pd(a02, a13);
    inv_m = _mm256_unpackhi_pd(a02, a13);
  }
#endif

#ifdef BBPD_AVX512
  // a vector of partner states: theta / m and 1 / m of partners j1 (lanes off in m: zero), by
  // 16-byte loads (as bond_lanes reads positions: cheaper than two gathers); a tail as a full
  // vector (tail_partners), its lanes off cleared
  inline void load_states(const AtomState *states, __m256i j1, __mmask8 m, __m512d &tom, __m512d &inv_m)
  {
    alignas(32) int j[LANES];
    store_partners(j1, m, j);
    __m256d t[2], v[2];
    load_states4(states, j, t[0], v[0]);
    load_states4(states, j + 4, t[1], v[1]);
    tom = join4(t[0], t[1]);
    inv_m = join4(v[0], v[1]);
    if (m != 0xFF) {
      tom = _mm512_maskz_mov_pd(m, tom);
      inv_m = _mm512_maskz_mov_pd(m, inv_m);
    }
  }

  /* the dilatation pass, 8 lanes (dilatation_sum_portable's operations) */
  template <class Idx, class Values>
  inline double dilatation_sum_avx512(const double *xx, int i, const Idx *bj, const Values &vals,
                                      int n)
  {
    const __m512d xi = _mm512_set1_pd(xx[3 * i]), yi = _mm512_set1_pd(xx[3 * i + 1]),
                  zi = _mm512_set1_pd(xx[3 * i + 2]);
    __m512d acc = _mm512_setzero_pd();
    for (int k = 0; k < n; k += LANES) {
      const __mmask8 m = (n - k >= LANES) ? (__mmask8) 0xFF : (__mmask8) ((1u << (n - k)) - 1);
      const BondLanes b = bond_lanes<Elongation>(xx, xi, yi, zi, load_partners(bj, m, i, k), m, vals, k);
      acc = _mm512_mask_add_pd(acc, m, acc, dilatation_term_v(Vec8(b.coef), Vec8(b.xi0), Vec8(b.elong)).v);
    }
    alignas(64) double lane[LANES];
    _mm512_store_pd(lane, acc);
    return lane_total(lane);
  }

  // the smallest and the largest of 8 lanes, through memory (GCC 12 warns of the undefined
  // register that _mm512_reduce_min_pd, _mm512_extractf64x4_pd and the like start from)
  template <bool MAX> inline double lane_extreme8(__m512d v)
  {
    alignas(64) double l[LANES];
    _mm512_store_pd(l, v);
    const __m256d lo = _mm256_load_pd(l), hi = _mm256_load_pd(l + 4);
    return lane_extreme4<MAX>(MAX ? _mm256_max_pd(lo, hi) : _mm256_min_pd(lo, hi));
  }

  /* the sums of a force pass in 8 lanes and, with CHECK, its breaking test: the LPS rows and
     the history rows (bbpd_lps_history_lanes.h) add their bonds' forces here (inlined into the
     kernels: GCC left add() a call per group, 5 % of a VES step) */
  template <int EV, int CHECK> struct ForceSums8 {
    __m512d fx = _mm512_setzero_pd(), fy = _mm512_setzero_pd(), fz = _mm512_setzero_pd();
    __m512d eng = _mm512_setzero_pd();
    __m512d vir[6] = {_mm512_setzero_pd(), _mm512_setzero_pd(), _mm512_setzero_pd(),
                      _mm512_setzero_pd(), _mm512_setzero_pd(), _mm512_setzero_pd()};
    __m512d vmin = _mm512_set1_pd(std::numeric_limits<double>::max());
    __m512d vmax = _mm512_set1_pd(std::numeric_limits<double>::lowest());
    // the bonds of lanes m (b) with force per length fpl and energy terms 'energy'
    BBPD_GROUPS_INLINE void add(__mmask8 m, const BondLanes &b, __m512d fpl, __m512d energy)
    {
      fx = _mm512_mask_add_pd(fx, m, fx, _mm512_mul_pd(fpl, b.dx));
      fy = _mm512_mask_add_pd(fy, m, fy, _mm512_mul_pd(fpl, b.dy));
      fz = _mm512_mask_add_pd(fz, m, fz, _mm512_mul_pd(fpl, b.dz));
      if (EV) eng = _mm512_mask_add_pd(eng, m, eng, energy);
      if (tallies_virial(EV)) {
        const __m512d d[3] = {b.dx, b.dy, b.dz};
        const int pa[6] = {0, 1, 2, 0, 0, 1}, pb[6] = {0, 1, 2, 1, 2, 2};
        for (int v = 0; v < 6; v++)
          vir[v] = _mm512_mask_add_pd(vir[v], m, vir[v],
                                      _mm512_mul_pd(_mm512_mul_pd(fpl, d[pa[v]]), d[pb[v]]));
      }
    }
    // their smallest and largest stretches (the breaking test: past_avx512)
    BBPD_GROUPS_INLINE void check(__mmask8 m, const BondLanes &b)
    {
      if (!CHECK) return;
      const Vec8 s = StretchRule::stretch(Vec8(b.elong), Vec8(_mm512_mask_mov_pd(_mm512_set1_pd(1.0), m, b.xi0)));
      vmin = _mm512_mask_min_pd(vmin, m, s.v, vmin);
      vmax = _mm512_mask_max_pd(vmax, m, s.v, vmax);
    }
    // the lanes into out, the smallest stretch into snew; whether a bond may be past breaking
    // (the largest stretch reaches c.s0_floor)
    bool store(ForceLanes &out, double *snew, const RowCoefficients &c) const
    {
      _mm512_storeu_pd(out.fx, fx);
      _mm512_storeu_pd(out.fy, fy);
      _mm512_storeu_pd(out.fz, fz);
      if (EV) _mm512_storeu_pd(out.tally.eng, eng);
      for (int v = 0; v < 6 && tallies_virial(EV); v++) _mm512_storeu_pd(out.tally.vir[v], vir[v]);
      if (!CHECK) return false;
      *snew = lane_extreme8<false>(vmin);
      return lane_extreme8<true>(vmax) + c.margin > c.s0_floor;
    }
  };

  /* the breaking test of each bond of the row: past its critical stretch with partner j (smallest
     stretch smin_all[j]) or within c.margin of it (the check of force_row_portable), that of
     the Silling-Askari rows (bbpd_stretch_row.h) with peri/lps's elongation and rule; the force
     passes run it when a row's largest stretch reaches its floor */
  template <class Idx, class Values>
  inline bool past_avx512(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                          const RowCoefficients &c, const double *smin_all)
  {
    return BBPD::past_avx512<Elongation, StretchRule>(xx, i, bj, vals, n, smin_all, c.smin_i, c.s00,
                                                       c.alpha, c.margin);
  }

  /* the force pass, 8 lanes (force_row_portable's operations; one s00 and alpha) */
  template <int EV, int CHECK, class Idx, class Values>
  inline bool force_row_avx512(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                               const AtomState *states, const RowCoefficients &c,
                               const double *smin_all, double *snew, ForceLanes &out)
  {
    const __m512d xi = _mm512_set1_pd(xx[3 * i]), yi = _mm512_set1_pd(xx[3 * i + 1]),
                  zi = _mm512_set1_pd(xx[3 * i + 2]), zero = _mm512_setzero_pd();
    const bool has_m = c.inv_m_i > 0.0;
    ForceSums8<EV, CHECK> sums;
    for (int k = 0; k < n; k += LANES) {
      const __mmask8 m = (n - k >= LANES) ? (__mmask8) 0xFF : (__mmask8) ((1u << (n - k)) - 1);
      const __m256i j1 = load_partners(bj, m, i, k);
      const BondLanes b = bond_lanes<Elongation>(xx, xi, yi, zi, j1, m, vals, k);
      __m512d tom, inv_m;
      load_states(states, j1, m, tom, inv_m);
      const __m512d fpl = has_m
          ? force_per_length(c, Vec8(b.coef), Vec8(b.xi0), Vec8(b.elong), Vec8(b.r), Vec8(tom), Vec8(inv_m)).v
          : zero;
      sums.add(m, b, fpl, energy_term(c, Vec8(b.coef), Vec8(b.xi0), Vec8(b.elong)).v);
      sums.check(m, b);
    }
    return sums.store(out, snew, c) && past_avx512(xx, i, bj, vals, n, c, smin_all);
  }
#define lps_dilatation_simd BBPD::LPS::dilatation_sum_avx512
#define lps_force_simd BBPD::LPS::force_row_avx512
#endif

#ifdef BBPD_AVX2
  // acc + v in the lanes of m, or everywhere if not MASKED
  template <bool MASKED> inline __m256d lps_add(__m256d acc, __m256d v, __m256d m)
  {
    return MASKED ? _mm256_blendv_pd(acc, _mm256_add_pd(acc, v), m) : _mm256_add_pd(acc, v);
  }
  inline __m256d lengths4(__m256d dx, __m256d dy, __m256d dz)
  {
    return _mm256_sqrt_pd(
        _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)), _mm256_mul_pd(dz, dz)));
  }

  // partner indices of the full group k..k+3
  inline __m128i full_partners4(const int *bj, int, int k)
  {
    return _mm_loadu_si128(reinterpret_cast<const __m128i *>(bj + k));
  }
  inline __m128i full_partners4(const PartnerOffset *bj, int i, int k)
  {
    const __m128i d = _mm_cvtepi16_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i *>(bj + k)));
    return _mm_add_epi32(d, _mm_set1_epi32(i));
  }

  /* bonds k..k+3 of atom i as for_each_group4 hands them out: a full group (plain loads) or the
     masked tail (gathers); their lanes m, partners, differences, values and partner states */
  struct Group4 {
    __m256d m, dx, dy, dz, xi0, wv, tom, inv_m;
    __m128i j1;
  };
  template <class Idx, class Values>
  BBPD_GROUPS_INLINE inline Group4 group4(const double *xx, const Idx *bj, int i, int n, int k, bool full,
                                      __m256d xi, __m256d yi, __m256d zi, const Values &vals,
                                      const AtomState *states)
  {
    Group4 g;
    if (full) {
      // the partners, counted from the row's origin o
      const int o = row_origin(bj, i);
      const std::ptrdiff_t j[4] = {bj[k], bj[k + 1], bj[k + 2], bj[k + 3]};
      // the partners as a vector read from the row itself: j's four scalar stores read back as
      // one vector would stall the load on store forwarding
      g.j1 = full_partners4(bj, i, k);
      __m256d x, y, z;
      load_positions(xx + 3 * o, j, x, y, z);
      g.dx = _mm256_sub_pd(x, xi);
      g.dy = _mm256_sub_pd(y, yi);
      g.dz = _mm256_sub_pd(z, zi);
      load_values_full(vals, bj, i, k, g.xi0, g.wv);
      load_states4(states + o, j, g.tom, g.inv_m);
      g.m = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    } else {
      const TailGroup4 t(xx, bj, i, n, k, xi, yi, zi);
      g.m = t.m;
      g.dx = t.dx;
      g.dy = t.dy;
      g.dz = t.dz;
      g.j1 = t.j1;
      load_values_tail(vals, t, k, g.xi0, g.wv);
      load_states4(states + row_origin(bj, i), t.j, g.tom, g.inv_m);
      g.tom = _mm256_and_pd(t.m, g.tom);
      g.inv_m = _mm256_and_pd(t.m, g.inv_m);
    }
    return g;
  }

  /* the dilatation pass in two 4-wide halves (lanes 0-3, 4-7), as the AVX-512 kernel */
  template <class Idx, class Values>
  inline double dilatation_sum_avx2(const double *xx, int i, const Idx *bj, const Values &vals, int n)
  {
    const __m256d xi = _mm256_set1_pd(xx[3 * i]), yi = _mm256_set1_pd(xx[3 * i + 1]),
                  zi = _mm256_set1_pd(xx[3 * i + 2]), all = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
    __m256d acc[2] = {_mm256_setzero_pd(), _mm256_setzero_pd()};
    auto add = [&](auto half, auto masked, __m256d m, __m256d dx, __m256d dy, __m256d dz,
                   __m256d xi0, __m256d wv) BBPD_GROUPS_INLINE {
      const __m256d e = Elongation::elongation(Vec4(lengths4(dx, dy, dz)), Vec4(xi0)).v;
      const __m256d t = dilatation_term_v(Vec4(wv), Vec4(xi0), Vec4(e)).v;
      constexpr int H = decltype(half)::value;
      acc[H] = lps_add<decltype(masked)::value>(acc[H], t, m);
    };
    auto full = [&](auto half, int k) BBPD_GROUPS_INLINE {
      const std::ptrdiff_t j[4] = {bj[k], bj[k + 1], bj[k + 2], bj[k + 3]};    // from row_origin
      __m256d x, y, z, xi0, wv;
      load_positions(xx + 3 * row_origin(bj, i), j, x, y, z);
      load_values_full(vals, bj, i, k, xi0, wv);
      add(half, std::false_type(), all, _mm256_sub_pd(x, xi), _mm256_sub_pd(y, yi), _mm256_sub_pd(z, zi), xi0, wv);
    };
    auto tail = [&](auto half, int k) BBPD_GROUPS_INLINE {
      const TailGroup4 g(xx, bj, i, n, k, xi, yi, zi);
      __m256d xi0, wv;
      load_values_tail(vals, g, k, xi0, wv);
      add(half, std::true_type(), g.m, g.dx, g.dy, g.dz, xi0, wv);
    };
    for_each_group4(n, full, tail);
    alignas(32) double lane[LANES];
    _mm256_store_pd(lane, acc[0]);
    _mm256_store_pd(lane + 4, acc[1]);
    return lane_total(lane);
  }

  /* the sums of a force pass in two 4-wide halves (lanes 0-3, 4-7) and, with CHECK, its
     breaking test: ForceSums8 of 4 lanes at a time (the same bits) */
  template <int EV, int CHECK> struct ForceSums4x2 {
    __m256d fx[2], fy[2], fz[2], eng[2], vir[6][2];
    __m256d vmin = _mm256_set1_pd(std::numeric_limits<double>::max()),
            vmax = _mm256_set1_pd(std::numeric_limits<double>::lowest());
    ForceSums4x2()
    {
      for (int h = 0; h < 2; h++) {
        fx[h] = fy[h] = fz[h] = eng[h] = _mm256_setzero_pd();
        for (auto &v : vir) v[h] = _mm256_setzero_pd();
      }
    }
    // bonds of the lanes m (every lane if not MASKED) into half H
    template <int H, bool MASKED>
    BBPD_GROUPS_INLINE void add(__m256d m, __m256d dx, __m256d dy, __m256d dz, __m256d fpl, __m256d energy)
    {
      fx[H] = lps_add<MASKED>(fx[H], _mm256_mul_pd(fpl, dx), m);
      fy[H] = lps_add<MASKED>(fy[H], _mm256_mul_pd(fpl, dy), m);
      fz[H] = lps_add<MASKED>(fz[H], _mm256_mul_pd(fpl, dz), m);
      if (EV) eng[H] = lps_add<MASKED>(eng[H], energy, m);
      if (tallies_virial(EV)) {
        const __m256d d[3] = {dx, dy, dz};
        const int pa[6] = {0, 1, 2, 0, 0, 1}, pb[6] = {0, 1, 2, 1, 2, 2};
        for (int v = 0; v < 6; v++)
          vir[v][H] = lps_add<MASKED>(vir[v][H], _mm256_mul_pd(_mm256_mul_pd(fpl, d[pa[v]]), d[pb[v]]), m);
      }
    }
    // the smallest and largest stretches of their elongations e (reference lengths xi0)
    template <bool MASKED> BBPD_GROUPS_INLINE void check(__m256d m, __m256d e, __m256d xi0)
    {
      if (!CHECK) return;
      const Vec4 s = StretchRule::stretch(Vec4(e), Vec4(MASKED ? _mm256_blendv_pd(_mm256_set1_pd(1.0), xi0, m) : xi0));
      vmin = MASKED ? _mm256_blendv_pd(vmin, _mm256_min_pd(s.v, vmin), m) : _mm256_min_pd(s.v, vmin);
      vmax = MASKED ? _mm256_blendv_pd(vmax, _mm256_max_pd(s.v, vmax), m) : _mm256_max_pd(s.v, vmax);
    }
    bool store(ForceLanes &out, double *snew, const RowCoefficients &c) const
    {
      for (int h = 0; h < 2; h++) {
        _mm256_storeu_pd(out.fx + 4 * h, fx[h]);
        _mm256_storeu_pd(out.fy + 4 * h, fy[h]);
        _mm256_storeu_pd(out.fz + 4 * h, fz[h]);
        if (EV) _mm256_storeu_pd(out.tally.eng + 4 * h, eng[h]);
        for (int v = 0; v < 6 && tallies_virial(EV); v++) _mm256_storeu_pd(out.tally.vir[v] + 4 * h, vir[v][h]);
      }
      if (!CHECK) return false;
      *snew = lane_extreme4<false>(vmin);
      return lane_extreme4<true>(vmax) + c.margin > c.s0_floor;
    }
  };

  // the breaking test in 4-wide groups, as past_avx512
  template <class Idx, class Values>
  inline bool past_avx2(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                        const RowCoefficients &c, const double *smin_all)
  {
    return BBPD::past_avx2<Elongation, StretchRule>(xx, i, bj, vals, n, smin_all, c.smin_i, c.s00,
                                                     c.alpha, c.margin);
  }

  /* the force pass in two 4-wide halves, as the AVX-512 kernel */
  template <int EV, int CHECK, class Idx, class Values>
  inline bool force_row_avx2(const double *xx, int i, const Idx *bj, const Values &vals, int n,
                             const AtomState *states, const RowCoefficients &c,
                             const double *smin_all, double *snew, ForceLanes &out)
  {
    // an atom without weighted volume (it never had a bond) has no bond force: the portable
    // loop's (no branch per group here)
    if (!(c.inv_m_i > 0.0))
      return force_row_portable<EV, CHECK>(xx, i, bj, vals, n, states, c, [&](int j) {
        return StretchRule::critical_stretch(c.s00, c.alpha, c.smin_i, smin_all[j]);
      }, snew, out);
    const __m256d xi = _mm256_set1_pd(xx[3 * i]), yi = _mm256_set1_pd(xx[3 * i + 1]),
                  zi = _mm256_set1_pd(xx[3 * i + 2]);
    ForceSums4x2<EV, CHECK> sums;
    auto add = [&](auto half, auto masked_c, __m256d m, __m256d dx, __m256d dy, __m256d dz,
                   __m256d xi0, __m256d wv, __m256d tom, __m256d inv_m) BBPD_GROUPS_INLINE {
      constexpr int H = decltype(half)::value;
      constexpr bool MASKED = decltype(masked_c)::value;
      const __m256d r = lengths4(dx, dy, dz);
      const __m256d e = Elongation::elongation(Vec4(r), Vec4(xi0)).v;
      const __m256d fpl = force_per_length(c, Vec4(wv), Vec4(xi0), Vec4(e), Vec4(r), Vec4(tom), Vec4(inv_m)).v;
      sums.template add<H, MASKED>(m, dx, dy, dz, fpl, energy_term(c, Vec4(wv), Vec4(xi0), Vec4(e)).v);
      sums.template check<MASKED>(m, e, xi0);
    };
    auto group = [&](auto half, auto masked, int k) BBPD_GROUPS_INLINE {
      const Group4 g = group4(xx, bj, i, n, k, !decltype(masked)::value, xi, yi, zi, vals, states);
      add(half, masked, g.m, g.dx, g.dy, g.dz, g.xi0, g.wv, g.tom, g.inv_m);
    };
    for_each_group4(n, [&](auto half, int k) BBPD_GROUPS_INLINE { group(half, std::false_type(), k); },
                    [&](auto half, int k) BBPD_GROUPS_INLINE { group(half, std::true_type(), k); });
    return sums.store(out, snew, c) && past_avx2(xx, i, bj, vals, n, c, smin_all);
  }
#define lps_dilatation_simd BBPD::LPS::dilatation_sum_avx2
#define lps_force_simd BBPD::LPS::force_row_avx2
#endif

}    // namespace LPS
}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_lps_lanes.h: the two passes of an LPS row in lanes, on plain arrays (peri/lps's lattice,
   122 partners, randomly displaced, random partner states). The portable lanes agree with the
   single-accumulator loop of bbpd_lps_row.h to round-off (another summation order); the SIMD
   kernel of this build's CPU (compiled with -march=native) gives the portable lanes' bits for
   rows of every length mod 8, with and without tallies and the breaking check, with index and
   offset partners, and with an atom that has no weighted volume. */

#include "bbpd_lps_lanes.h"
#include "bbpd_lps_row.h"
#include "bbpd_test_family.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>
#include <type_traits>
#include <vector>

namespace LPS = BBPD::LPS;
using namespace BBPD::test;    // the family: LC, DELTA, VOLUME, K, G, for_each_partner

namespace {

// displacements up to this share of the lattice constant: stretches of about 1e-2
constexpr double JIGGLE = 0.01;
// portable lanes against one accumulator: the same terms summed in another order
constexpr double ROUND_OFF = 1e-13;

struct Scene {
  std::vector<double> x;    // atom 0, then its partners, 3 per atom
  std::vector<int> partner;
  std::vector<BBPD::PartnerOffset> offset;
  std::vector<double> xi0, wv, smin;
  std::vector<LPS::AtomState> states;
  int n() const { return static_cast<int>(partner.size()); }
};

Scene scene(int nbonds, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Scene s;
  s.x = {0.0, 0.0, 0.0};
  for_each_partner([&](const double *p, double xi0) {
    if (s.n() == nbonds) return;
    for (int i = 0; i < 3; i++) s.x.push_back(p[i] + JIGGLE * LC * u(gen));
    s.offset.push_back(static_cast<BBPD::PartnerOffset>(s.n() + 1));
    s.partner.push_back(s.n() + 1);
    s.xi0.push_back(xi0);
    s.wv.push_back(LPS::weighted_partner_volume(xi0, DELTA, LC, VOLUME));
  });
  // padding the SIMD loads of offsets may read past the row (as the bond storage pads)
  for (int l = 0; l < BBPD::LANES; l++) s.offset.push_back(0);
  const int natoms = s.n() + 1;
  for (int j = 0; j < natoms; j++) {
    // some partners without weighted volume (zero state), the rest with m near the lattice's
    const double m = (j % 7 == 3) ? 0.0 : 5e-15 * (1.0 + 0.1 * u(gen));
    s.states.push_back(LPS::atom_state(1e-3 * u(gen), m));
    s.smin.push_back(1e-3 * u(gen));
  }
  return s;
}

// the largest smallest stretch of the scene's atoms (what the pair style hands the floor)
double smin_cap(const Scene &s) { return *std::max_element(s.smin.begin(), s.smin.end()); }

// the row's coefficients with s00 and the floor of its critical stretches that s00 gives
LPS::RowCoefficients coefficients(const Scene &s, double margin = 0.0, double s00 = 0.012)
{
  const LPS::Moduli mod = LPS::moduli(K, G);
  const double alpha = 0.25;
  return {mod.dilatational, mod.deviatoric, s.states[0].theta_over_m, s.states[0].inv_m,
          LPS::third(0.7e-3), s00, alpha, s.smin[0], margin,
          LPS::critical_stretch_floor(s00, alpha, s.smin[0], smin_cap(s))};
}

bool same_bits(const double *a, const double *b, int n)
{
  return std::memcmp(a, b, sizeof(double) * n) == 0;
}

// the force lanes, and with EV the tallies (filled only then)
bool same_lanes(const LPS::ForceLanes &a, const LPS::ForceLanes &b, bool ev)
{
  const int L = BBPD::LANES;
  bool same = same_bits(a.fx, b.fx, L) && same_bits(a.fy, b.fy, L) && same_bits(a.fz, b.fz, L);
  if (!ev) return same;
  same = same && same_bits(a.tally.eng, b.tally.eng, L);
  for (int v = 0; v < 6; v++) same = same && same_bits(a.tally.vir[v], b.tally.vir[v], L);
  return same;
}

template <int EV, int CHECK, class Idx>
bool portable(const Scene &s, const Idx *bj, const LPS::RowCoefficients &c, double *snew,
              LPS::ForceLanes &out)
{
  const BBPD::PerBondValues vals{s.xi0.data(), s.wv.data()};
  auto s0_of = [&](int j) {
    return LPS::StretchRule::critical_stretch(c.s00, c.alpha, c.smin_i, s.smin[j]);
  };
  return LPS::force_row_portable<EV, CHECK>(s.x.data(), 0, bj, vals, s.n(), s.states.data(), c,
                                            s0_of, snew, out);
}

}    // namespace

TEST(LpsLanes, PortableLanesAgreeWithOneAccumulator)
{
  const Scene s = scene(122, 1);
  ASSERT_EQ(s.n(), 122);
  const LPS::RowCoefficients c = coefficients(s);
  LPS::ForceLanes lanes;
  double snew = 0.0;
  portable<1, 0>(s, s.partner.data(), c, &snew, lanes);
  double f[3];
  BBPD::lane_sum(lanes.fx, lanes.fy, lanes.fz, f);

  const LPS::Moduli mod = LPS::moduli(K, G);
  const BBPD::PerBondValues vals{s.xi0.data(), s.wv.data()};
  LPS::RowSums ref;
  auto never = [](int, double, double) { return false; };
  LPS::row_sums<true, false, false>(s.x.data(), 0, s.partner.data(), vals, s.n(), nullptr,
                                     s.states.data(), mod, c.theta_third_i, never, ref);
  const double fscale = std::fabs(ref.f[0]) + std::fabs(ref.f[1]) + std::fabs(ref.f[2]);
  ASSERT_GT(fscale, 0.0);
  for (int a = 0; a < 3; a++) EXPECT_NEAR(f[a], ref.f[a], ROUND_OFF * fscale);
  EXPECT_NEAR(BBPD::lane_total(lanes.tally.eng), ref.wv_ed2, ROUND_OFF * ref.wv_ed2);
  for (int v = 0; v < 6; v++)
    EXPECT_NEAR(BBPD::lane_total(lanes.tally.vir[v]), ref.fdd[v],
                ROUND_OFF * (std::fabs(ref.fdd[0]) + std::fabs(ref.fdd[1]) + std::fabs(ref.fdd[2])));

  // the dilatation sum: the same terms as bbpd_lps.h's
  double sum = 0.0;
  for (int k = 0; k < s.n(); k++) {
    const double *xj = &s.x[3 * s.partner[k]];
    const double r = std::sqrt(xj[0] * xj[0] + xj[1] * xj[1] + xj[2] * xj[2]);
    sum += LPS::dilatation_term(s.wv[k], s.xi0[k], LPS::elongation(r, s.xi0[k]));
  }
  EXPECT_NEAR(LPS::dilatation_sum_portable(s.x.data(), 0, s.partner.data(), vals, s.n()), sum,
              ROUND_OFF * std::fabs(sum));
}

TEST(LpsLanes, CheckFindsTheSmallestStretchAndTheBondsPastBreaking)
{
  const Scene s = scene(122, 2);
  double smallest = 1e300;
  for (int k = 0; k < s.n(); k++) {
    const double *xj = &s.x[3 * s.partner[k]];
    const double r = std::sqrt(xj[0] * xj[0] + xj[1] * xj[1] + xj[2] * xj[2]);
    smallest = std::min(smallest, LPS::elongation(r, s.xi0[k]) / s.xi0[k]);
  }
  LPS::ForceLanes lanes;
  double snew = 0.0;
  // s00 far above every stretch: nothing past; then s00 below the largest: past
  LPS::RowCoefficients c = coefficients(s);
  EXPECT_FALSE((portable<0, 1>(s, s.partner.data(), c, &snew, lanes)));
  EXPECT_EQ(snew, smallest);
  c.s00 = -1.0;
  EXPECT_TRUE((portable<0, 1>(s, s.partner.data(), c, &snew, lanes)));
}

#ifdef BBPD_SIMD
// every row length mod 8 (full vectors and every tail), index and offset partners, each switch
template <int EV, int CHECK> void expect_simd_bits(double margin)
{
  for (int n : {0, 1, 3, 4, 5, 7, 8, 9, 12, 13, 16, 31, 64, 121, 122}) {
    const Scene s = scene(n, 100 + n);
    for (bool no_m : {false, true}) {
      Scene t = s;
      if (no_m) t.states[0] = LPS::atom_state(0.0, 0.0);
      const LPS::RowCoefficients c = coefficients(t, margin);
      const BBPD::PerBondValues vals{t.xi0.data(), t.wv.data()};
      LPS::ForceLanes a, b, o;
      double sa = 0.0, sb = 0.0, so = 0.0;
      const bool pa = portable<EV, CHECK>(t, t.partner.data(), c, &sa, a);
      const bool pb = lps_force_simd<EV, CHECK>(t.x.data(), 0, t.partner.data(), vals, n,
                                                t.states.data(), c, t.smin.data(), &sb, b);
      const bool po = lps_force_simd<EV, CHECK>(t.x.data(), 0, t.offset.data(), vals, n,
                                                t.states.data(), c, t.smin.data(), &so, o);
      EXPECT_TRUE(same_lanes(a, b, EV)) << "n = " << n;
      EXPECT_TRUE(same_lanes(a, o, EV)) << "n = " << n << " (offsets)";
      if (CHECK) {
        EXPECT_EQ(pa, pb) << "n = " << n;
        EXPECT_EQ(pa, po) << "n = " << n;
        EXPECT_EQ(sa, sb) << "n = " << n;
        EXPECT_EQ(sa, so) << "n = " << n;
      }
      const double d = LPS::dilatation_sum_portable(t.x.data(), 0, t.partner.data(), vals, n);
      EXPECT_EQ(d, lps_dilatation_simd(t.x.data(), 0, t.partner.data(), vals, n)) << "n = " << n;
      EXPECT_EQ(d, lps_dilatation_simd(t.x.data(), 0, t.offset.data(), vals, n)) << "n = " << n;
    }
  }
}

TEST(LpsLanes, SimdKernelGivesThePortableBits)
{
  expect_simd_bits<0, 0>(0.0);
  expect_simd_bits<1, 0>(0.0);
  expect_simd_bits<0, 1>(0.0);
  expect_simd_bits<1, 1>(1e-12);
}

TEST(LpsLanes, SimdCheckSeesTheMargin)
{
  // a critical stretch just above the largest stretch: past only with a margin that reaches it
  const Scene s = scene(122, 3);
  LPS::RowCoefficients c = coefficients(s);
  const BBPD::PerBondValues vals{s.xi0.data(), s.wv.data()};
  LPS::ForceLanes lanes;
  double snew = 0.0;
  double largest = -1e300;
  for (int k = 0; k < s.n(); k++) {
    const double *xj = &s.x[3 * s.partner[k]];
    const double r = std::sqrt(xj[0] * xj[0] + xj[1] * xj[1] + xj[2] * xj[2]);
    const double st = LPS::elongation(r, s.xi0[k]) / s.xi0[k];
    const double s0 = LPS::StretchRule::critical_stretch(0.0, c.alpha, c.smin_i, s.smin[k + 1]);
    largest = std::max(largest, st - s0);    // s00 at which bond k is at its critical stretch
  }
  c = coefficients(s, 0.0, largest + 1e-6);
  EXPECT_FALSE((lps_force_simd<0, 1>(s.x.data(), 0, s.partner.data(), vals, s.n(), s.states.data(),
                                     c, s.smin.data(), &snew, lanes)));
  c.margin = 2e-6;
  EXPECT_TRUE((lps_force_simd<0, 1>(s.x.data(), 0, s.partner.data(), vals, s.n(), s.states.data(),
                                    c, s.smin.data(), &snew, lanes)));
}

TEST(LpsLanes, SimdCheckTestsEachBondOnlyAtTheFloor)
{
  // s00 between the row's largest stretch and that plus the floor's slack: the floor (from the
  // scene's largest smin) is reached, each bond's own critical stretch is not: nothing past
  const Scene s = scene(122, 4);
  const BBPD::PerBondValues vals{s.xi0.data(), s.wv.data()};
  double largest = -1e300, need = -1e300;
  for (int k = 0; k < s.n(); k++) {
    const double *xj = &s.x[3 * s.partner[k]];
    const double r = std::sqrt(xj[0] * xj[0] + xj[1] * xj[1] + xj[2] * xj[2]);
    const double st = LPS::elongation(r, s.xi0[k]) / s.xi0[k];
    largest = std::max(largest, st);
    need = std::max(need, st - LPS::StretchRule::critical_stretch(0.0, 0.25, s.smin[0], s.smin[k + 1]));
  }
  const double s00 = need + 1e-7;    // every bond's s0 just above its stretch
  LPS::RowCoefficients c = coefficients(s, 0.0, s00);
  ASSERT_GE(largest, c.s0_floor);    // the floor is reached
  LPS::ForceLanes a, b;
  double sa = 0.0, sb = 0.0;
  EXPECT_FALSE((portable<0, 1>(s, s.partner.data(), c, &sa, a)));
  EXPECT_FALSE((lps_force_simd<0, 1>(s.x.data(), 0, s.partner.data(), vals, s.n(), s.states.data(),
                                     c, s.smin.data(), &sb, b)));
  EXPECT_EQ(sa, sb);
  // just below: past, in the portable loop and past the floor in the kernel
  c = coefficients(s, 0.0, need - 1e-7);
  EXPECT_TRUE((portable<0, 1>(s, s.partner.data(), c, &sa, a)));
  EXPECT_TRUE((lps_force_simd<0, 1>(s.x.data(), 0, s.partner.data(), vals, s.n(), s.states.data(),
                                    c, s.smin.data(), &sb, b)));
  // a floor above a bond's critical stretch (a cap below a partner's smin) hides the bond: the
  // kernel trusts its floor, so the pair style must hand it the largest smin of every partner
  c.s0_floor = largest + 1.0;
  EXPECT_FALSE((lps_force_simd<0, 1>(s.x.data(), 0, s.partner.data(), vals, s.n(), s.states.data(),
                                     c, s.smin.data(), &sb, b)));
  // no floor (-infinity): every bond tested
  c.s0_floor = -std::numeric_limits<double>::infinity();
  EXPECT_TRUE((lps_force_simd<0, 1>(s.x.data(), 0, s.partner.data(), vals, s.n(), s.states.data(),
                                    c, s.smin.data(), &sb, b)));
}

TEST(LpsLanes, CriticalStretchFloorIsBelowEveryBondsCriticalStretch)
{
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1e-2, 1e-2);
  for (int t = 0; t < 10000; t++) {
    const double s00 = 1e-3 + std::fabs(u(gen)), alpha = 0.25 + 10.0 * std::fabs(u(gen));
    const double smin_i = u(gen), smin_j = u(gen), cap = smin_j + std::fabs(u(gen)) * (t % 2);
    ASSERT_LE(LPS::critical_stretch_floor(s00, alpha, smin_i, cap),
              LPS::StretchRule::critical_stretch(s00, alpha, smin_i, smin_j));
  }
  // a negative alpha: no floor
  EXPECT_EQ(LPS::critical_stretch_floor(1e-3, -0.25, 0.0, 1.0), -std::numeric_limits<double>::infinity());
}
#endif

// ---------------------------------------------------------------- the families with history

#include "bbpd_eps.h"
#include "bbpd_lps_history_lanes.h"
#include "bbpd_ves.h"

namespace {

namespace VES = BBPD::VES;
namespace EPS = BBPD::EPS;

// a bond end's history: random, in slots of their own with gaps (partners lost), rising with k
// as PairBBPDLPS::find_bond_slots makes them
std::vector<double> history(int n, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1e-6, 1e-6);
  std::vector<double> h(BBPD::history_length(2, 2 * n + 1));    // slots up to 2 n (slots())
  for (double &v : h) v = u(gen);
  return h;
}
std::vector<int> slots(int n, bool dense = false)
{
  std::vector<int> s(n);
  for (int k = 0; k < n; k++) s[k] = 2 * k + (k % 3 == 0 ? 1 : 0);    // rising, every gap > 0
  if (dense) std::iota(s.begin(), s.end(), 0);    // a row that lost no partner (dense_slots)
  return s;
}

LPS::HistoryCoefficients history_coefficients(const Scene &s, double margin)
{
  return {coefficients(s, margin), 3.0 * K};
}

}    // namespace

#ifdef BBPD_SIMD
template <class F, int EV, int CHECK> void expect_history_bits(const F &fam, const typename F::Plan &plan)
{
  for (int n : {0, 1, 3, 4, 5, 7, 8, 9, 13, 16, 31, 121, 122})
  for (bool dense : {false, true}) {
    for (bool no_m : {false, true}) {
      Scene t = scene(n, 200 + n);
      if (no_m) t.states[0] = LPS::atom_state(0.0, 0.0);
      // a dense row with a partner of no weighted volume: its lane is neither read nor written
      if (dense && n > 2) t.states[t.partner[2]] = LPS::atom_state(0.0, 0.0);
      const LPS::HistoryCoefficients c = history_coefficients(t, 1e-12);
      const BBPD::PerBondValues vals{t.xi0.data(), t.wv.data()};
      const std::vector<int> slot = slots(n, dense);
      std::vector<double> ha = history(n, n), hb = ha;
      auto s0_of = [&](int j) {
        return LPS::StretchRule::critical_stretch(c.s00, c.alpha, c.smin_i, t.smin[j]);
      };
      LPS::ForceLanes a, b;
      double sa = 0.0, sb = 0.0;
      const bool pa = LPS::history_force_portable<F, EV, CHECK, CHECK>(
          t.x.data(), 0, t.partner.data(), vals, n, t.states.data(), fam, plan, c, slot.data(),
          ha.data(), s0_of, &sa, a);
      const bool pb = lps_history_force_simd<F, EV, CHECK, CHECK>(
          t.x.data(), 0, t.offset.data(), vals, n, t.states.data(), fam, plan, c, slot.data(),
          hb.data(), t.smin.data(), &sb, b);
      EXPECT_TRUE(same_lanes(a, b, EV)) << "n = " << n << " dense " << dense << " no_m " << no_m;
      EXPECT_TRUE(same_bits(ha.data(), hb.data(), static_cast<int>(ha.size())))
          << "n = " << n << " dense " << dense << " no_m " << no_m;
      if (CHECK) {
        EXPECT_EQ(pa, pb) << "n = " << n;
        EXPECT_EQ(sa, sb) << "n = " << n;
      }
    }
  }
}

TEST(LpsLanes, HistoryKernelsGiveThePortableBits)
{
  const VES::Family ves{VES::coeffs(15.0 * G, 0.5, 1e-5, 1e-7)};
  expect_history_bits<VES::Family, 0, 0>(ves, {});
  expect_history_bits<VES::Family, 1, 1>(ves, {});
  const EPS::Family eps{{15.0 * G, EPS::pointwise_yield_value(1e8, DELTA), 5e-15}};
  for (const EPS::Family::Plan plan : {EPS::Family::Plan{false, 1.0, 0.0}, EPS::Family::Plan{true, 0.7, 1e-3}}) {
    expect_history_bits<EPS::Family, 0, 0>(eps, plan);
    expect_history_bits<EPS::Family, 1, 1>(eps, plan);
  }
  // the first evaluation of an EPS step: the norm pass (rolling the history) and the elastic
  // plan's force pass in one pass over the row (history_norm_force)
  for (int n : {0, 1, 5, 8, 13, 121, 122})
  for (bool dense : {false, true})
  for (bool ev : {false, true}) {
    Scene t = scene(n, 300 + n);
    if (dense && n > 2) t.states[t.partner[2]] = LPS::atom_state(0.0, 0.0);    // rolled, no force
    const LPS::HistoryCoefficients c = history_coefficients(t, 1e-12);
    const BBPD::PerBondValues vals{t.xi0.data(), t.wv.data()};
    const std::vector<int> slot = slots(n, dense);
    std::vector<double> ha = history(n, n), hb = ha;
    auto s0_of = [&](int j) {
      return LPS::StretchRule::critical_stretch(c.s00, c.alpha, c.smin_i, t.smin[j]);
    };
    LPS::ForceLanes a, b;
    double sa = 0.0, sb = 0.0, na = 0.0, nb = 0.0;
    bool pa, pb;
    auto both = [&](auto ev_c) {    // with (1) or without (0) the energy and virial lanes
      constexpr int EV = decltype(ev_c)::value;
      pa = LPS::history_norm_force_portable<EPS::Family, EV>(t.x.data(), 0, t.partner.data(), vals, n,
                                                             t.states.data(), eps, c, slot.data(),
                                                             ha.data(), s0_of, &sa, a, &na);
      pb = lps_history_norm_force_simd<EPS::Family, EV>(t.x.data(), 0, t.offset.data(), vals, n,
                                                        t.states.data(), eps, c, slot.data(), hb.data(),
                                                        t.smin.data(), &sb, b, &nb);
    };
    if (ev)
      both(std::integral_constant<int, 1>());
    else
      both(std::integral_constant<int, 0>());
    EXPECT_EQ(na, nb) << "n = " << n;
    if (n > 0) {
      EXPECT_GT(na, 0.0);
    }
    EXPECT_TRUE(same_lanes(a, b, ev)) << "n = " << n << " dense " << dense;
    EXPECT_TRUE(same_bits(ha.data(), hb.data(), static_cast<int>(ha.size())))
        << "n = " << n << " dense " << dense;
    EXPECT_EQ(pa, pb) << "n = " << n;
    EXPECT_EQ(sa, sb) << "n = " << n;
  }
}
#endif

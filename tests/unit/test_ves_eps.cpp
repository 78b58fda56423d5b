// SPDX-License-Identifier: GPL-2.0-or-later
/* bbpd_ves.h and bbpd_eps.h: the families with history of peri/ves and peri/eps on plain
   numbers, against identities derived by hand: the back extension of VES is the exact
   integral of its dashpot (relaxation at a held extension, the closed form under a ramp), and
   EPS returns a plastic row onto its yield surface and keeps or forgets the plastic extension
   as peri/eps does. */

#include "bbpd_bond_slots.h"
#include "bbpd_bond_values.h"
#include "bbpd_eps.h"
#include "bbpd_history_blocks.h"
#include "bbpd_lps.h"
#include "bbpd_lps_history_row.h"
#include "bbpd_pmb_rules.h"
#include "bbpd_test_family.h"
#include "bbpd_ves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace VES = BBPD::VES;
namespace EPS = BBPD::EPS;
namespace LPS = BBPD::LPS;

namespace {

constexpr double G = 14.9e9;
constexpr double DEVIATORIC = 15.0 * G;    // d (d + 2) G of the 3D force state (Moduli::deviatoric)
constexpr double DT = 1.0e-7;
constexpr double TAU = 20 * DT;
constexpr double WV = 3.0e-7, INV_SUM = 2.0e10;    // a bond's w V and 1/m_i + 1/m_j

// the back extension reached after n steps of the extension ed(step), from a zero history
template <class Ed> double back_extension_after(const VES::Coeffs &c, int n, Ed ed)
{
  double h[2] = {0.0, 0.0};
  for (int s = 1; s <= n; s++) h[1] = VES::back_extension(c, ed(s), h[0], h[1]), h[0] = ed(s);
  return h[1];
}

}    // namespace

TEST(Ves, HeldExtensionRelaxesByDecayPerStep)
{
  const VES::Coeffs c = VES::coeffs(DEVIATORIC, 0.5, TAU, DT);
  EXPECT_DOUBLE_EQ(c.decay, std::exp(-DT / TAU));
  const double e = 1.0e-6;
  // ed jumps to e at step 1 and is held: e - edb shrinks by decay every further step
  for (int n = 2; n < 60; n++) {
    const double a = e - back_extension_after(c, n, [&](int) {
                       return e;
                     });
    const double b = e - back_extension_after(c, n + 1, [&](int) {
                       return e;
                     });
    EXPECT_NEAR(b / a, c.decay, 1e-12);
  }
}

TEST(Ves, RampIsTheDashpotsClosedForm)
{
  // ed = r t: the dashpot edb' = (ed - edb) / tau gives edb = r (t - tau (1 - exp(-t / tau)))
  const VES::Coeffs c = VES::coeffs(DEVIATORIC, 0.5, TAU, DT);
  const double rate = 10.0;    // 1/s of extension
  for (int n : {1, 5, 20, 100, 400}) {
    const double t = n * DT;
    const double exact = rate * (t - TAU * (1.0 - std::exp(-t / TAU)));
    EXPECT_NEAR(back_extension_after(c, n,
                                     [&](int s) {
                                       return rate * s * DT;
                                     }),
                exact, 1e-9 * rate * t);
  }
}

TEST(Ves, ForceStateAndEnergyOfTheTwoSprings)
{
  const double ed = 2.0e-6;
  for (double lambda : {0.0, 0.3, 1.0}) {
    const VES::Family f{VES::coeffs(DEVIATORIC, lambda, TAU, DT)};
    double h[2] = {1.0e-6, 0.5e-6}, energy = 0.0;
    const double td = f.deviatoric<true>({}, WV, 0.0, 0.0, ed, INV_SUM, h, energy);
    const double edb = VES::back_extension(f.c, ed, 1.0e-6, 0.5e-6);
    EXPECT_EQ(h[0], ed);    // the history advanced
    EXPECT_EQ(h[1], edb);
    const double k = 15.0 * G * WV * INV_SUM;
    EXPECT_NEAR(td, k * (ed - lambda * edb), 1e-12 * k * ed);
    EXPECT_NEAR(energy, WV * ((1 - lambda) * ed * ed + lambda * (ed - edb) * (ed - edb)),
                1e-12 * WV * ed * ed);
    // a second evaluation of the step: the same force, the history untouched
    double again = 0.0;
    EXPECT_EQ(f.deviatoric<false>({}, WV, 0.0, 0.0, ed, INV_SUM, h, again), td);
    EXPECT_EQ(h[0], ed);
    EXPECT_EQ(h[1], edb);
  }
}

TEST(Eps, PointwiseYieldValue)
{
  const double y = 1.0e9, delta = 1.5001e-3;
  EXPECT_NEAR(EPS::pointwise_yield_value(y, delta),
              25.0 * y * y / (8.0 * M_PI * std::pow(delta, 5)),
              1e-12 * 25.0 * y * y / std::pow(delta, 5));
}

TEST(Eps, PlasticRowReturnsToTheYieldSurface)
{
  // a row of bonds with different deviatoric extensions
  const std::vector<double> ed = {3e-6, -1e-6, 2e-6, 0.5e-6, -2.5e-6};
  const double xi0 = 1.0e-3, omega = BBPD::LPS::influence(xi0), m = 4.0e-13;
  for (double yield : {1.0e6, 1.0e12}) {
    const EPS::Family f{{DEVIATORIC, EPS::pointwise_yield_value(yield, 1.5e-3), m}};
    std::vector<double> h(2 * ed.size(), 0.0);
    for (std::size_t k = 0; k < ed.size(); k++) h[2 * k + 1] = 1.0e-7 * k;    // last step's edp
    double sum = 0.0;
    for (std::size_t k = 0; k < ed.size(); k++)
      sum += f.norm_term<true>(WV, omega, ed[k], INV_SUM, &h[2 * k]);
    for (std::size_t k = 0; k < ed.size(); k++) EXPECT_EQ(h[2 * k], 1.0e-7 * k);    // rolled
    const double norm = std::sqrt(sum);
    const EPS::Family::Plan p = f.plan(norm);
    EXPECT_EQ(p.plastic, 0.5 * norm * norm > f.c.psi0);
    EXPECT_EQ(p.plastic, yield < 1.0e9);    // both branches are exercised
    // the returned state: norm sqrt(2 psi0) when plastic, unchanged when elastic
    double returned = 0.0;
    for (std::size_t k = 0; k < ed.size(); k++) {
      double energy = 0.0;
      const double td = f.deviatoric<true>(p, WV, omega, xi0, ed[k], INV_SUM, &h[2 * k], energy);
      const double d = ed[k] - 1.0e-7 * k;
      EXPECT_NEAR(energy, WV * d * d, 1e-12 * WV * 1e-11);
      returned += (td / WV * omega) * (td / WV) * WV;    // (td without V)^2 V
      const double trial = 15.0 * G * INV_SUM * d * omega;
      if (p.plastic)
        EXPECT_NEAR(h[2 * k + 1], 1.0e-7 * k + p.scale * trial * p.delta_lambda * 0.5 * xi0,
                    1e-12 * std::fabs(h[2 * k + 1]) + 1e-30);
      else
        EXPECT_EQ(h[2 * k + 1], 0.0);    // peri/eps: an elastic step forgets edp
    }
    if (p.plastic) {
      EXPECT_NEAR(std::sqrt(returned), std::sqrt(2.0 * f.c.psi0),
                  1e-12 * std::sqrt(2.0 * f.c.psi0));
      EXPECT_NEAR(p.delta_lambda, (norm / std::sqrt(2.0 * f.c.psi0) - 1.0) * m / (15.0 * G),
                  1e-12 * p.delta_lambda);
    } else {
      EXPECT_NEAR(returned, sum, 1e-12 * sum);
    }
  }
}

/* the history row (bbpd_lps_history_row.h) on atom 0 of peri/ves's example lattice (122
   partners) in a uniform simple shear: every atom has the state of the body */
namespace {

using BBPD::test::DELTA;
using BBPD::test::LC;
using BBPD::test::VOLUME;
constexpr double K = 14.9e9;

struct ShearedRow {
  std::vector<double> x;    // 3 per atom, atom 0 at the origin
  std::vector<int> partner;
  std::vector<double> xi0, wv, r;
  std::vector<LPS::AtomState> states;
  std::vector<int> slot;
  double theta = 0.0;
  int n() const { return static_cast<int>(partner.size()); }
};

ShearedRow sheared_row(double gamma)
{
  ShearedRow row;
  row.x = {0.0, 0.0, 0.0};
  BBPD::test::for_each_partner([&](const double *p, double xi0) {
    row.x.insert(row.x.end(), {p[0] + gamma * p[1], p[1], p[2]});
    row.partner.push_back(row.n() + 1);
    row.xi0.push_back(xi0);
    row.wv.push_back(LPS::weighted_partner_volume(xi0, DELTA, LC, VOLUME));
  });
  double m = 0.0, sum = 0.0;
  for (int k = 0; k < row.n(); k++) {
    const double *y = &row.x[3 * row.partner[k]];
    row.r.push_back(std::sqrt(y[0] * y[0] + y[1] * y[1] + y[2] * y[2]));
    m += LPS::weighted_volume_term(row.wv[k], row.xi0[k]);
    sum += LPS::dilatation_term(row.wv[k], row.xi0[k], LPS::elongation(row.r[k], row.xi0[k]));
    row.slot.push_back(2 * k + 1);    // slots need not be consecutive
  }
  row.theta = LPS::dilatation(sum, m);
  row.states.assign(row.n() + 1, LPS::atom_state(row.theta, m));
  return row;
}

auto no_check = [](int, double, double) {
  return false;
};

template <class F, bool COMMIT>
LPS::RowSums sums_of(const ShearedRow &row, const F &fam, const typename F::Plan &plan,
                     std::vector<double> &hist)
{
  LPS::RowSums s;
  LPS::history_row_sums<F, true, false, true, COMMIT>(
      row.x.data(), 0, row.partner.data(), BBPD::PerBondValues{row.xi0.data(), row.wv.data()}, row.n(),
      row.r.data(), row.states.data(), 3.0 * K, fam, plan, LPS::third(row.theta), row.slot.data(),
      hist.data(), no_check, s);
  return s;
}

void expect_same_bits(const LPS::RowSums &a, const LPS::RowSums &b)
{
  for (int c = 0; c < 3; c++) EXPECT_EQ(a.f[c], b.f[c]);
  EXPECT_EQ(a.wv_ed2, b.wv_ed2);
  for (int c = 0; c < 6; c++) EXPECT_EQ(a.fdd[c], b.fdd[c]);
}

}    // namespace

TEST(HistoryRow, VesSecondEvaluationRepeatsTheStepAndTheBodyStaysInBalance)
{
  const ShearedRow row = sheared_row(1.0e-5);
  ASSERT_EQ(row.n(), 122);
  const VES::Family f{VES::coeffs(DEVIATORIC, 0.5, TAU, DT)};
  std::vector<double> hist(2 * 2 * row.n() + 2, 0.0);
  LPS::RowSums first{};
  for (int step = 0; step < 30; step++) first = sums_of<VES::Family, true>(row, f, {}, hist);
  const std::vector<double> kept = hist;
  const LPS::RowSums again = sums_of<VES::Family, false>(row, f, {}, hist);
  expect_same_bits(first, again);
  EXPECT_EQ(hist, kept);    // a second evaluation leaves the history as it is
  // a uniform shear: each bond and its opposite carry the same history, so no net force
  double scale = 0.0;
  for (int k = 0; k < row.n(); k++)
    scale += 15.0 * G * row.wv[k] * 2.0 * row.states[0].inv_m * 1e-5 * row.xi0[k];
  for (int c = 0; c < 3; c++) EXPECT_LT(std::fabs(first.f[c]), 1e-12 * scale);
  // the back extension has relaxed towards ed: less deviatoric energy than lambda = 0 (elastic)
  const VES::Family elastic{VES::coeffs(DEVIATORIC, 0.0, TAU, DT)};
  std::vector<double> h0(hist.size(), 0.0);
  const LPS::RowSums e = sums_of<VES::Family, true>(row, elastic, {}, h0);
  EXPECT_LT(first.wv_ed2, 0.75 * e.wv_ed2);
}

TEST(HistoryRow, EpsPlasticRowReturnsToTheYieldSurfaceAndRepeats)
{
  const ShearedRow row = sheared_row(1.0e-3);
  const double m = 1.0 / row.states[0].inv_m;
  const EPS::Family f{{DEVIATORIC, EPS::pointwise_yield_value(1.0e7, DELTA), m}};
  std::vector<double> hist(2 * 2 * row.n() + 2, 0.0);
  const double norm = LPS::history_row_norm<EPS::Family, true, false>(
      row.x.data(), 0, row.partner.data(), BBPD::PerBondValues{row.xi0.data(), row.wv.data()}, row.n(),
      row.r.data(), row.states.data(), LPS::third(row.theta), f, row.slot.data(), hist.data());
  const EPS::Family::Plan plan = f.plan(norm);
  ASSERT_TRUE(plan.plastic);
  const LPS::RowSums first = sums_of<EPS::Family, true>(row, f, plan, hist);
  const LPS::RowSums again = sums_of<EPS::Family, false>(row, f, plan, hist);
  expect_same_bits(first, again);
  // the returned deviatoric state of every bond: |t|^2 summed with V_j ramp is 2 psi0
  double returned = 0.0;
  for (int k = 0; k < row.n(); k++) {
    const double ed = LPS::deviatoric_extension(LPS::elongation(row.r[k], row.xi0[k]), row.xi0[k],
                                                LPS::third(row.theta));
    const double t =
        plan.scale * 15.0 * G * 2.0 * row.states[0].inv_m * LPS::influence(row.xi0[k]) * ed;
    returned += t * t * row.wv[k] / LPS::influence(row.xi0[k]);
  }
  EXPECT_NEAR(std::sqrt(returned), std::sqrt(2.0 * f.c.psi0), 1e-12 * std::sqrt(2.0 * f.c.psi0));
  // the plastic extensions were written where the slots say, and nowhere else
  for (int k = 0; k < row.n(); k++) EXPECT_NE(BBPD::history_value<2>(hist.data(), row.slot[k], 1), 0.0);
  EXPECT_EQ(BBPD::history_value<2>(hist.data(), 0, 0), 0.0);    // slot 0 holds no bond
  EXPECT_EQ(BBPD::history_value<2>(hist.data(), 0, 1), 0.0);
}

// the blocks of bbpd_history_blocks.h: every value of every slot a place of its own within the
// row's length, 4 consecutive slots' value v side by side, and the pairs of a restart file
// back as they were
TEST(HistoryBlocks, EachValueHasItsOwnPlaceAndPairsComeBack)
{
  for (int n = 0; n <= 13; n++) {
    const int len = BBPD::history_length(2, n);
    EXPECT_EQ(len % (2 * BBPD::HISTORY_BLOCK), 0);
    EXPECT_GE(len, 2 * n);
    EXPECT_LT(len, 2 * (n + BBPD::HISTORY_BLOCK));
    std::vector<int> seen(len, 0);
    for (int m = 0; m < n; m++)
      for (int v = 0; v < 2; v++) {
        const int at = BBPD::history_offset<2>(m, v);
        ASSERT_GE(at, 0);
        ASSERT_LT(at, len);
        seen[at]++;
      }
    for (int x = 0; x < len; x++) EXPECT_LE(seen[x], 1);
    std::vector<double> pairs(2 * n), blocks(len, -1.0), back(2 * n);
    for (int x = 0; x < 2 * n; x++) pairs[x] = 1.0 + x;
    BBPD::history_from_pairs(2, n, pairs.data(), blocks.data());
    BBPD::history_to_pairs(2, n, blocks.data(), back.data());
    EXPECT_EQ(back, pairs);
    for (int x = 0; x < len; x++) {    // the slots past n are zero, not left as they were
      if (!seen[x]) {
        EXPECT_EQ(blocks[x], 0.0);
      }
    }
  }
  // slots 4..7: value 0 at 8..11, value 1 at 12..15 (one 4-wide load each)
  for (int m = 4; m < 8; m++) {
    EXPECT_EQ(BBPD::history_offset<2>(m, 0), 8 + m - 4);
    EXPECT_EQ(BBPD::history_offset<2>(m, 1), 12 + m - 4);
  }
  EXPECT_EQ(BBPD::history_offset<3>(5, 2), 4 * (3 + 2) + 1);
}

// bbpd_bond_slots.h: rows that lost no partner read 0, 1, 2, ... and store nothing; a row with
// slots of its own keeps them where they are when it loses more
TEST(BondSlots, OnlyRowsWithLostPartnersKeepSlots)
{
  BBPD::BondSlots slots;
  slots.reset(3, 6);
  const double none = slots.bytes();
  for (int i = 0; i < 3; i++) {
    EXPECT_TRUE(slots.dense(i));
    for (int k = 0; k < 6; k++) EXPECT_EQ(slots.of(i)[k], k);
  }
  int *own = slots.own(1, 4);    // row 1 lost partner 2 of 0..4
  const int lost2[4] = {0, 1, 3, 4};
  std::copy(lost2, lost2 + 4, own);
  EXPECT_FALSE(slots.dense(1));
  EXPECT_TRUE(slots.dense(0));
  EXPECT_GT(slots.bytes(), none);
  for (int k = 0; k < 4; k++) EXPECT_EQ(slots.of(1)[k], lost2[k]);
  for (int k = 0; k < 6; k++) EXPECT_EQ(slots.of(2)[k], k);
  EXPECT_EQ(slots.own(1, 3), slots.of(1));    // fewer bonds: the same place
  slots.reset(3, 6);
  EXPECT_TRUE(slots.dense(1));
}

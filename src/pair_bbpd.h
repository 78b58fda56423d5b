// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: kernel-weighted bond-based peridynamics pair styles
   bbpd/constant, bbpd/triangular, bbpd/gaussian (one class, the kernel is a
   constructor parameter). Bouaraquia & Mabssout (2026), eqs. 6-9, 19, 21-22.

   The pair style creates its bond storage (fix bbpd/bonds), calibrates c0 and
   s0 in init_style() (calibrate()) and then hands the storage the bond law
   with the calibrated values (by value), the storage policy and the run
   limits; init_one() only reports the cutoffs. It evaluates the
   forces over the storage's rows and breaks bonds through remove_bonds_if(); the
   storage never calls back (doc/architecture.rst).

   A style with other breaking rules derives from this class, gives its Rules at
   construction and overrides the hooks below "rules of a derived style"; what styles
   share is held or called, not inherited: the Silling-Askari state
   (pair_bbpd_silling_askari_state.h, bbpd_silling_askari.h) and the pieces of LAMMPS's
   peri/pmb rules (pair_bbpd_peri_rules.cpp). No style sits more than two classes
   below Pair (doc/architecture.rst).
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_H
#define LMP_PAIR_BBPD_H

#include "bbpd_bond_hold.h"
#include "bbpd_bond_law.h"
#include "bbpd_bond_model.h"
#include "bbpd_bond_storage.h"
#include "bbpd_close_pairs.h"
#include "bbpd_kernel.h"
#include "bbpd_plugin_model.h"
#include "bbpd_row_paths.h"
#include "atom.h"
#include "pair.h"

#include <string>
#include <type_traits>
#include <vector>

namespace BBPD {
struct CoefCache;    // bbpd_row.h
struct RowTally;     // bbpd_row.h
}

namespace LAMMPS_NS {

class SillingAskariState;    // pair_bbpd_silling_askari_state.h

class PairBBPD : public Pair {
 public:
  // what the shared code must know of a style's rules, given by the style at construction
  // (the base class asks no derived class what it is)
  struct Rules {
    bool silling_askari;    // alpha is a rule of the style (pair_bbpd_alpha.h)
    bool pmb_rules;         // peri/pmb's families, volumes and numbers (pair_bbpd_pmb.h)
    bool short_range;       // short-range forces whatever 'contact' says (stable step)
    // each row reads the history of its own end of a bond (bbpd/ves, bbpd/eps), so the two
    // rows of a bond give it forces that differ (row_tally)
    bool own_end_history;
  };
  // peri/pmb's rules: Silling-Askari breaking, its families and numbers, short-range forces
  // (bbpd/pmb and the LPS styles)
  static constexpr Rules PERI_PMB_RULES{true, true, true, false};
  PairBBPD(class LAMMPS *, BBPD::KernelInfo, const char *style = nullptr,
           Rules = Rules{false, false, false, false});
  ~PairBBPD() override;

  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  double memory_usage() override;
  // what the fixes of the style's state hold (the state-based styles), for the setup report
  virtual double state_memory() { return 0.0; }
  void *extract(const char *, int &) override;

  void setup() override;

  // the engineering constants of type itype's bonds, for the crack computes (DSIF, J): the
  // bond-based styles' E from c0 and the Poisson's ratio their model implies
  virtual double youngs_modulus(int itype) const;
  virtual double poisson_ratio(int itype) const;

  const BBPD::KernelInfo kernel;
  const std::string style;    // the style's name, for messages (bbpd/KERNEL, bbpd/pmb, ...)
  BBPD::Model model;
  double geom;       // thickness h (2D) or cross-section area A (1D); 1 in 3D
  double spacing;    // grid spacing used in the partial-volume correction (eq. 19)
  double dt_safety;  // warn when timestep > dt_safety * stable bound
  int contact;       // short-range repulsion between non-bonded close atoms
  BBPD::BondStorage storage;    // what the bond cache keeps per bond (bond/storage keyword)
  double contact_factor;    // contact distance = contact_factor * spacing
  BBPD::SimdPath simd_request;    // the simd keyword: a path, or AUTO (bbpd_row_paths.h)
  BBPD::BondHold hold;    // no breaking while minimizing or relaxing (bbpd_bond_hold.h)

 protected:
  int spacing_user;    // 1 if the spacing keyword was given
  int fracture_any;    // any type pair with finite critical stretch
  double **youngs, **fracture_energy, **horizon, **micromodulus, **critical_stretch;
  int **s0_user;       // 1 if critical_stretch was given directly
  int **bondless;      // 1 if the type pair forms no bonds (pair_coeff ... bonds no): two bodies
  class FixBBPDBonds *bonds;
  class FixBBPDWatchdog *watchdog;
  class Fix *hold_report = nullptr;    // fix bbpd/hold: the held bonds of a minimize
  double dt_bound_paper, dt_bound;    // eq. 25 and with the factor 2 (velocity Verlet limit)

  int report_due;    // setup() was called: report once the setup's notches are cut
  // the path the bond loops run, the same on every rank and thread, and why (for the report)
  BBPD::SimdPath simd_path;
  std::string simd_reason;
  bool simd_decided;    // auto: timed once per pair_style command, at its first setup
  void check_simd_request();
  void choose_simd_path();
  virtual double time_path(BBPD::SimdPath p, int first, int last);
  double timing_sink = 0.0;
  void report();
  BBPD::BondLaw law;    // what the bond fix builds and caches with, filled in init_style()
  // what one bond does (elongation, force, energy, breaking): every loop of the style takes it
  // (doc/architecture.rst, "Adding a bond model"; bbpd_plugin_model.h names it)
  using BondModel = BBPD::PluginBondModel;
  double **alpha;       // Silling-Askari: s0 = s00 - alpha * smallest stretch (pair_bbpd_alpha.h)
  void calibrate();     // c0 and s0 of every type pair (init_style)
  BBPD::RunLimits run_limits() const
  {
    return {fracture_any != 0, spacing, dt_bound, dt_safety};
  }
  void send_run_limits();    // to the bond fix and the watchdog
  // the style's internal fixes (args: the fix's own arguments)
  class Fix *own_fix(const char *id, const char *fix_style, const std::string &args = "");
  void release_fix(const void *owned, const char *id);
  void allocate();
  void compute_contact();
  void tally_short_range(int i, double e, double fpair, double dx, double dy, double dz);
  // the threaded loop over the local atoms' rows that every bond loop runs in:
  // row(i, fi, acc, cache) sums the force density of atom i into fi (and, with EVFLAG, its
  // energy and virial into acc); defined in pair_bbpd_rows.h
  template <int EVFLAG, class Row> void for_each_row(Row row);
  // the one row driver of the bond forces and breaking over for_each_row: row_of(i, acc, cache)
  // gives the style's view of row i (bond model, breaking rule, state); pair_bbpd_rows.h
  template <int EVFLAG, class RowOf> void eval_rows(RowOf row_of);
  template <class Row> void count_held(int i, Row row);    // pair_bbpd_hold.h
  friend class FixBBPDHold;     // reports the held bonds of a minimize (fracture on?)
  friend class FixBBPDRelax;    // its fictitious density from bond_stiffness()
  [[noreturn]] void nonfinite_error(int i);
  void add_row_force(int i, const double *fi, int &bad);
  void finish_eval(int bad, bool evflag_on, const double *totals);
  void add_thread_totals(double *totals, const double *acc);
  void tally_lanes(int i, const BBPD::RowTally &lanes, double *acc, bool virial);
  // what the rows tally this step (BBPD::TALLY_*, bbpd_row.h): with TALLY_ENERGY and a global
  // virial asked, for_each_row takes it from the rows' forces (add_row_virial)
  int row_tally() const;
  // f(std::integral_constant<int, row_tally()>())
  template <class F> void with_row_tally(F &&f) const
  {
    switch (row_tally()) {
      case BBPD::TALLY_NONE: f(std::integral_constant<int, BBPD::TALLY_NONE>()); break;
      case BBPD::TALLY_ENERGY: f(std::integral_constant<int, BBPD::TALLY_ENERGY>()); break;
      default: f(std::integral_constant<int, BBPD::TALLY_ENERGY_VIRIAL>());
    }
  }
  // a bond end's virial terms (xx yy zz xy xz yz) at force per length fpl along (dx, dy, dz)
  static void bond_end_virial(double fpl, double dx, double dy, double dz, double *vir)
  {
    const double d[3] = {dx, dy, dz};
    const int a[6] = {0, 1, 2, 0, 0, 1}, b[6] = {0, 1, 2, 1, 2, 2};
    for (int m = 0; m < 6; m++) vir[m] = -BondModel::virial_share(fpl, d[a[m]], d[b[m]]);
  }
  // after a second evaluation of a step (replay) whose rows tallied the bonds' virial (EV): the
  // virial of the bonds that broke in that step, which it re-applies from fbroken
  void add_replayed_virial(bool replay, int ev, const class SillingAskariState &state);
  double virial_origin[3];    // of add_row_virial: the box centre (round-off of x (x) f)
  void add_row_virial(int i, const double *fi, double *vir) const
  {
    const double *x = atom->x[i];
    const double dx = x[0] - virial_origin[0], dy = x[1] - virial_origin[1], dz = x[2] - virial_origin[2];
    vir[0] += dx * fi[0];
    vir[1] += dy * fi[1];
    vir[2] += dz * fi[2];
    vir[3] += dx * fi[1];
    vir[4] += dx * fi[2];
    vir[5] += dy * fi[2];
  }
  bool bonded(int i, tagint jtag) const;
  int multi_s0;           // critical stretch differs between type pairs
  double s0_single;       // the critical stretch when it does not
  // multi_s0: per local atom the critical stretch all its bonds share, or NaN where they differ
  // (a row beside a band of another type); rebuilt with the bond cache. A row of one critical
  // stretch runs the SIMD kernels, which take one
  std::vector<double> row_s0;
  bigint row_s0_generation = -1;
  void refresh_row_s0();
  double break_margin;    // periodic box: bonds this close to s0 are re-checked canonically
  bool past_critical(int i, int j, double xi0, double s0) const;
  // bond k of atom i breaks at the critical stretch s0: book atom i's share of the energy it
  // carries away (fix bbpd/bonds' ebroken, term 3 of compute bbpd/energy)
  void book_broken_bond(int i, int k, double s0);
  double breaking_length(int i, int j) const;
  // the stretch within which a row's quick test (local lengths) hands its bonds to
  // breaking_length() in a periodic box; 0 otherwise (pair_bbpd_silling_askari.cpp)
  double stretch_margin() const;
  template <int EVFLAG, int FRACTURE, int MULTI> void eval();
  // the row force of atom i; cache: the calling thread's coefficient cache (compact storage)
  template <int EVFLAG, int FRACTURE, int MULTI>
  bool row_force(int i, double *fi, const double *s0row, double *acc, BBPD::CoefCache *cache);
  static BBPD::CoefCache *thread_coef_cache();
  void coeff_from_file(const char *file, const char *material, double &E, double &Gc);

  // rules of a derived style (pair_bbpd_alpha.h, pair_bbpd_pmb.h)
  virtual void eval_bonds();                      // bond forces and breaking of one step
  virtual void init_rules() {}                    // init_style: after the bond fix exists
  const Rules rules;
  // short-range contact stiffness 15 c0, as LAMMPS peri/pmb (Silling, EMU theory manual, 2005,
  // p. 18): the forces and the stable time step
  static constexpr double CONTACT_STIFFNESS_FACTOR = 15.0;
  bool short_range_forces() const { return rules.short_range || contact != 0; }    // stable step
  virtual std::string report_type_pair(int i, int j) const;
  virtual std::string report_rules() const { return {}; }
  // a bond's stiffness in the stable time step (eq. 26): its coefficient c C_v V_j / xi0
  virtual double bond_stiffness(int i, int k) const;

  // the Silling-Askari loop (pair_bbpd_silling_askari.cpp): bond forces and breaking with
  // the critical stretch of Rule (bbpd_plugin_model.h lists the rules) over a style's state;
  // bbpd/KERNEL/alpha and bbpd/pmb call it
  template <int EVFLAG, class Rule> void eval_silling_askari(SillingAskariState &);
  template <int EVFLAG>
  double broken_bond_force(int i, int k, double *fb, double *acc, class SillingAskariState &);

  // the pieces of peri/pmb's rules its styles call (bbpd/pmb, the LPS styles;
  // pair_bbpd_peri_rules.cpp): no 'contact' keyword, the lattice constant lc, the
  // short-range forces with lc and the report line
  void forbid_contact() const;
  double peri_lattice_constant() const;
  void compute_short_range(double lc);
  std::string peri_rules_report(double lc) const;
  // the short-range stiffness of types i j per partner volume (peri/pmb: 15 c)
  virtual double short_range_stiffness(int itype, int jtype) const;

  // candidates of the short-range forces ('contact', bbpd/pmb's): pairs that can come in
  // range before the atoms move half the search's skin, searched again when stale
  BBPD::ClosePairs close_pairs;
  bigint close_generation = -1;    // of the bond cache the candidates' indices belong to
  // distance(i, j): the pair's distance, called for every pair the search meets (inlined)
  template <class Distance>
  void update_close_pairs(double max_distance, double skin, Distance distance)
  {
    int nlocal, nall;
    const double *xx = stale_close_pairs(nlocal, nall);
    if (xx && !close_pairs.build(xx, nlocal, nall, max_distance, skin, distance))
      nonfinite_positions_error();
  }
  // the positions to search the candidates at, or null while they are current
  const double *stale_close_pairs(int &nlocal, int &nall);
  [[noreturn]] void nonfinite_positions_error();
};

}    // namespace LAMMPS_NS

#endif

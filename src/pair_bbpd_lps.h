// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: pair style bbpd/lps, the linear peridynamic solid of LAMMPS's
   peri/lps (bbpd_lps.h) in the bbpd bond storage.

   'pair_style bbpd/lps 3d' takes 'pair_coeff I J K G delta s00 alpha' as peri/lps does
   and follows its rules: peri/pmb's families, volume ramp, short-range forces
   (pair_bbpd_peri_rules.cpp) and Silling-Askari breaking (bbpd_silling_askari.h,
   pair_bbpd_silling_askari_state.h), the influence function 1/|xi|, and per step
     1. the dilatation theta_i of every local atom over its intact bonds, sent with
        theta_i / m_i and 1 / m_i to the ghost atoms (one forward communication);
     2. the bond forces of the LPS force state; a bond past s00 - alpha max(smin_i, smin_j)
        acts in this step and breaks (the order of peri/lps);
     3. the short-range forces.
   The weighted volumes m_i are summed once, at the first force evaluation after the families
   were built, and kept with the dilatation of the last step in fix bbpd/lps (fix_bbpd_lps.h).

   The same class runs the LPS families whose deviatoric part has a history: 'pair_style
   bbpd/ves 3d' (peri/ves, bbpd_ves.h) and 'bbpd/eps 3d' (peri/eps, bbpd_eps.h). The family is
   a value handed to the row (pair_bbpd_lps_history.cpp, bbpd_lps_history_row.h); its history
   lives per bond end and per atom in fix bbpd/history (fix_bbpd_history.h).

   Where the coefficients come from is another value, chosen at construction (bbpdplugin.cpp):
   Coefficients::PERI, the numbers of peri/* above, or Coefficients::KERNEL, pair styles
   bbpd/lps/constant, bbpd/lps/triangular, bbpd/lps/gaussian (pair_bbpd_lps_kernel.cpp): the
   kernel shape W(|xi| / delta) of bbpd_kernel.h as influence function and the engineering
   constants of the bond-based styles (bbpd_lps_kernel.h),
     pair_style bbpd/lps/KERNEL MODEL [thickness h] [keywords of bbpd/lps]
     pair_coeff I J E nu Gc|none delta
   MODEL is 3d, plane/strain or plane/stress (the 2D LPS of Le, Chan & Schwartz 2014); atom i
   tallies its whole deviatoric energy; a bond breaks past the s0 derived from G_c
   (Silling-Askari alpha 0), 'none' never. The bond storage, dilatation pass, ghost exchange,
   force loop, short-range forces, fix bbpd/lps state and restart are the same. With
   Family::VES the same coefficients give bbpd/ves/KERNEL ('pair_coeff I J E nu Gc delta lambda
   tau'); the history row takes d K and d (d + 2) G from the model, so it runs in 2D as well.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_LPS_H
#define LMP_PAIR_BBPD_LPS_H

#include "bbpd_bond_slots.h"
#include "bbpd_lps.h"
#include "bbpd_silling_askari.h"
#include "bbpd_ves.h"
#include "pair_bbpd.h"
#include "pair_bbpd_silling_askari_state.h"

#include <array>
#include <mutex>
#include <vector>

namespace LAMMPS_NS {

class PairBBPDLPS : public PairBBPD {
 public:
  // the force state: peri/lps's, or one with a deviatoric history (peri/ves, peri/eps)
  enum class Family { LPS, VES, EPS };
  // where the coefficients come from: peri/*'s numbers (K G delta s00 alpha, the 3D solid,
  // influence function 1/|xi|) or the kernel calibration (E nu Gc delta, bbpd_lps_kernel.h)
  enum class Coefficients { PERI, KERNEL };
  // every style of the class has peri/pmb's rules; the rows run on the path of the bond loops
  // (bbpd_lps_lanes.h)
  // bbpd/lps, bbpd/ves, bbpd/eps: a family with peri/*'s numbers
  PairBBPDLPS(class LAMMPS *, Family = Family::LPS);
  // bbpd/lps/KERNEL, bbpd/ves/KERNEL: the family with the kernel as influence function and
  // its calibration
  PairBBPDLPS(class LAMMPS *, BBPD::KernelInfo, Family = Family::LPS);
  ~PairBBPDLPS() override;

  void settings(int, char **) override;
  void coeff(int, char **) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  void *extract(const char *, int &) override;
  double memory_usage() override;
  double state_memory() override;

  // bbpd/eps: the plastic multiplier lambda of local atom i (compute bbpd/plasticity/atom)
  double plastic_multiplier(int i) const;

  // the crack computes' constants: E and nu of the 3D solid of K and G, or (KERNEL) those of
  // pair_coeff (in 2D kappa' is not the 3D bulk modulus)
  double youngs_modulus(int itype) const override;
  double poisson_ratio(int itype) const override;

 protected:
  SillingAskariState silling_askari;    // smin of this step and fix bbpd/alpha
  // the largest smin of the local and ghost atoms at this step (the rows' critical stretch floors)
  double smin_cap = 0.0;
  double lattice_constant;              // lc of the lattice command, as in peri/pmb
  double **bulk, **shear;           // K and G of peri/lps, per type pair (2D: kappa' and G)
  double dimension;                 // d of the LPS (3; 2 for the 2D models of the kernel styles)
  double deviatoric_share;          // of atom i's deviatoric energy tallied at i: peri/lps 1/2
  class FixBBPDLPS *lps_state;      // weighted volumes and the last step's dilatations
  int nmax_lps;
  Family family;
  const Coefficients coefficients;
  double **relax_share, **relax_time;    // VES: lambda and tau per type pair
  double **yield_stress;                 // EPS: the yield stress per type pair
  class FixBBPDHistory *history;         // VES, EPS: the history of bonds and atoms
  BBPD::BondSlots bond_slots;    // per row of this step: its intact bonds' partner slots
  // the rows that lost their first partners in this step's rows (slots of their own after it)
  std::vector<int> rows_to_own;
  std::mutex rows_to_own_mutex;    // rows run in threads (package omp)
  // the bonds bond_slots were found for: cache generation, row removals, local atoms
  bigint slot_generation = -1;
  long slot_removals = -1;
  int slot_nlocal = -1;
  bigint history_generation = -1;    // the cache generation fix bbpd/history's rows were fit at
  BBPD::LPS::AtomState *atom_states;    // theta / m, 1 / m of every local and ghost atom, this step

  void eval_bonds() override;
  void init_rules() override;
  double short_range_stiffness(int itype, int jtype) const override;
  double bond_stiffness(int i, int k) const override;
  std::string report_type_pair(int i, int j) const override;
  std::string report_rules() const override;

  // the common constructor: the family, where its coefficients come from, the kernel, the name
  PairBBPDLPS(class LAMMPS *, Family, Coefficients, BBPD::KernelInfo, const std::string &style);

  void allocate_moduli();
  // Coefficients::KERNEL (pair_bbpd_lps_kernel.cpp): the models, pair_coeff E nu Gc delta, the
  // stable time step's bond, the report
  void kernel_settings(int, char **);
  void kernel_coeff(int, char **);
  double kernel_bond_stiffness(int i, int k) const;
  std::string kernel_report_type_pair(int i, int j) const;
  std::string kernel_report_rules() const;
  BBPD::LPS::Moduli moduli_of_type(int itype) const
  {
    return BBPD::LPS::moduli(bulk[itype][itype], shear[itype][itype], dimension);
  }
  void sum_weighted_volumes();
  bool begin_state();    // the dilatation pass of a step; true for a second evaluation
  void end_state();
  BBPD::SillingAskariCoefficients breaking_rule() const;
  int family_args() const;
  const char *family_coeffs() const;
  void check_family_coeffs(char **own);
  void check_history_solver() const;    // VES, EPS: no minimize, no fix bbpd/relax
  void set_family_coeffs(int i, int j, char **own);
  std::string family_report(int i, int j) const;
  std::string history_report() const;
  void find_bond_slots();
  bool row_dense(int i) const;    // the intact bonds of row i in partner slots 0 .. nbond - 1
  int find_row_slots(int i);
  int intact_slots(int i, int *s) const;
  double slot_bytes_when_found() const;
  template <int EVFLAG, class F> void eval_history();
  template <int EVFLAG, class F> struct HistoryRow;
  template <class F> F family_of(int i) const;
  BBPD::VES::Family ves_of_type(int itype) const;
  std::vector<BBPD::VES::Family> ves_types;    // VES: ves_of_type of every type, this step
  std::array<int, 2> history_widths() const;    // VES, EPS: doubles per atom, per bond end
  void fit_history();    // VES, EPS: a row of fix bbpd/history per local atom
  // the force row of local atom i of a family with history on the current path, with
  // stand-in states and a scratch history, nothing kept (time_path's probe); a force of it
  double history_row_probe(int i, const BBPD::LPS::AtomState *states, BBPD::CoefCache *cache,
                           double *hist);
  // the probe's scratch history, a row of it per timed row (so that the timing streams through
  // as much history as the step does), and its slots
  std::vector<double> probe_history;
  std::vector<int> probe_slot;
  static constexpr int PROBE_BOND_HISTORY = 2;    // BOND_HISTORY of VES and EPS (history_row_probe asserts it)
  double dilatation_of(int i);
  double time_path(BBPD::SimdPath p, int first, int last) override;
  template <int EVFLAG> void eval_lps();
  // the row of an atom in eval_lps: its force state and breaking (pair_bbpd_lps.cpp)
  template <int EVFLAG> struct Row;
  template <int EVFLAG>
  void add_bond_force(int i, int j, double xi0, double wv, double *f, double *acc);
};

}    // namespace LAMMPS_NS

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: fix bbpd/relax, quasi-static loading by adaptive dynamic
   relaxation (Kilic & Madenci, Theor. Appl. Fract. Mech. 53 (2010) 194),
   with bonds that break only between converged states.

   fix ID group bbpd/relax tol TOL

   It replaces fix nve for its group: one timestep is one iteration of the
   damped central-difference scheme
     v(n+1/2) = [(2 - c dt) v(n-1/2) + 2 dt f(n) / lambda] / (2 + c dt),
     x(n+1) = x(n) + dt v(n+1/2),  v(1/2) = dt f(0) / (2 lambda),
   with a fictitious density lambda_i per atom from its bonds' stiffnesses (a
   Gershgorin bound that makes dt stable whatever its value) and the damping c
   from the local Rayleigh quotient of the last step's force change. One run is
   one load step: the script changes the load between runs (displace_atoms,
   the value of fix addforce or fix setforce), 'run N' relaxes for at most N
   iterations. While it iterates the pair style holds its bonds
   (bbpd_bond_hold.h); once the residual has fallen below tol times the
   reference (the residual at the start of the load step: the out-of-balance
   force of the load increment), one force evaluation at rest lets the bonds
   past breaking break, and if any did, the body relaxes again at the same
   load. When an evaluation breaks nothing the load step is done: the fix logs
   it and ends the run (as fix halt does). doc/fix_bbpd_relax.rst.
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_RELAX_H
#define LMP_FIX_BBPD_RELAX_H

#include "fix.h"

namespace LAMMPS_NS {

class FixBBPDRelax : public Fix {
 public:
  FixBBPDRelax(class LAMMPS *, int, char **);
  ~FixBBPDRelax() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void end_of_step() override;
  void post_run() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;

 private:
  // per atom: the fictitious density and the last iteration's f / lambda
  enum { LAMBDA, APREV, NSTATE = APREV + 3 };
  // what the next timestep does: the first iteration of a relaxation, a further one, a force
  // evaluation at rest that lets bonds break, the final evaluation at rest (with output) of a
  // load step; DONE once it has ended
  enum Phase { START, ITERATE, BREAK, FINAL, DONE };

  double tol;
  double **state;
  class PairBBPD *pair;
  class FixBBPDBonds *bonds;
  Phase phase;
  double reference;    // the residual tol is relative to: the last load increment's
  double residual;     // residual now
  bigint broken_ends;  // broken bond ends (fix bbpd/bonds) before the breaking evaluation
  // the load step: its number, iterations, relaxations, bonds broken, start time
  bigint load_step, iterations, nbroken;
  int relaxations;
  double wall_start;
  bool halted;       // this fix ended the run (and resets LAMMPS's timeout)
  bool converged;    // the last load step ended in an equilibrium that breaks no bond

  void hold_bonds(bool on);
  void start_relaxation();
  double damping();
  double residual_now();
  void finish_load_step(bool converged);
};

}    // namespace LAMMPS_NS

#endif

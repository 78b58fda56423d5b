// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the work done on atoms by everything but the pair style.

   Created by compute bbpd/energy (ID BBPD_WORK_<compute ID>, the compute's group);
   not meant for input scripts. Per atom i and step n -> n+1 it adds

     W_i += [KE_i(n+1) - KE_i(n)] - 1/2 [fp_i(n) + fp_i(n+1)] . [x_i(n+1) - x_i(n)]

   times the atom's volume: the change of the atom's kinetic energy less the work of
   the pair force fp along the atom's actual displacement (trapezoidal rule; velocity
   Verlet makes the two agree to O(dt^2) where nothing else acts). What is left is the
   work of every other agent: forces that fixes add (fix addforce, gravity), and the
   agent of a prescribed motion (velocity layers under fix setforce 0, fix move). An
   atom that does not move does no work. The pair force is read where only the pair
   style has written the forces (pre_reverse: after the force evaluation, before the
   reverse communication and before any fix's post_force). Per atom it keeps
     state[i] = {W, KE, fp(3), dx(3), x(3)}
   carried through atom migration; W (an energy, not a density) is in restart files.
   Each run's setup starts the steps afresh from the positions and forces then (what
   commands between runs do to the atoms is no work done during a run).
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_WORK_H
#define LMP_FIX_BBPD_WORK_H

#include "fix_bbpd_atom_state.h"

namespace LAMMPS_NS {

class FixBBPDWork : public FixBBPDAtomState {
 public:
  FixBBPDWork(class LAMMPS *, int, char **);
  int setmask() override;
  void init() override;
  void setup_pre_reverse(int, int) override;
  void setup(int) override;
  void post_integrate() override;
  void pre_reverse(int, int) override;
  void end_of_step() override;

  void set_arrays(int) override;

  // the cumulative work on local atom i (an energy); 0 outside the group
  double work(int i) const { return state[i][W]; }

  enum { W, KE, FP, DX = FP + 3, XOLD = DX + 3, NSTATE = XOLD + 3 };

 private:
  double **&state = values;    // [i][W .. NSTATE-1]; W alone in restart files
  double kinetic(int i) const;     // 1/2 rho v^2 V of local atom i
  void start_steps();              // KE and position now, no work
};

}    // namespace LAMMPS_NS

#endif

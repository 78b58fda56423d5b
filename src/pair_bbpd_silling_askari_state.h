// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: the per-step state of the Silling-Askari critical stretch
   (bbpd_silling_askari.h), held by every style that breaks bonds with it
   (bbpd/KERNEL/alpha, bbpd/pmb, bbpd/lps and its families, bbpd/lps/KERNEL).

   smin, the smallest bond stretch of each atom at the last step, lives in the
   per-atom s0 of atom_style peri (sent to the ghosts, carried through migration
   and restart files); the step's new values collect in smin_new and take effect
   at the end of the step. fix bbpd/alpha keeps what a second evaluation of the
   same step needs (fix_bbpd_alpha.h): the step and the forces of the bonds that
   broke in it.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_SILLING_ASKARI_STATE_H
#define LMP_PAIR_BBPD_SILLING_ASKARI_STATE_H

#include "lmptype.h"

namespace LAMMPS_NS {

class SillingAskariState {
 public:
  static constexpr const char *FIX_ID = "BBPD_ALPHA";    // the style's fix bbpd/alpha

  int nmax = 0;
  double *smin_new = nullptr;           // smallest bond stretch of each local atom in this step
  class FixBBPDAlpha *fix = nullptr;    // what a second evaluation of the same step needs

  // init_style: the style's fix bbpd/alpha; before the families exist no atom has a bond, so
  // no atom has a smallest stretch yet (as peri/pmb)
  void attach(class FixBBPDAlpha *, class Atom *, bool families_built);
  // the start of a step: smin_new grown to the local atoms; true for a second evaluation of
  // the last step (setup of a new run, read_restart: no breaking, no new smallest stretches)
  bool begin_step(class Memory *, class Atom *, class Update *);
  // the new smin takes effect at the next step, once sent to the ghosts
  void end_step(class Atom *, class Update *);
  // the virial of a bond breaking in a first evaluation (vir: the row's tally), summed per rank
  // (threads: one at a time); a second evaluation of that step in this process re-applies the
  // forces of those bonds (fbroken) without the bonds, so add_broken_virial() adds their sum to
  // the bonds' tally (virial: the pair style's). Restart files keep no record of it.
  void book_broken_virial(const double *vir);
  void add_broken_virial(double *virial, class Update *) const;
  double broken_virial[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  bigint broken_virial_step = -1;
  void destroy(class Memory *);
};

}    // namespace LAMMPS_NS

#endif

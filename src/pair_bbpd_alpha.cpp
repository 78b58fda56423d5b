// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: pair styles bbpd/KERNEL/alpha (pair_bbpd_alpha.h): their state,
   rule and report; the loop that breaks bonds is PairBBPD's Silling-Askari
   loop (pair_bbpd_silling_askari.cpp).
------------------------------------------------------------------------- */

#include "pair_bbpd_alpha.h"
#include "bbpd_silling_askari.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_bbpd_alpha.h"
#include "fix_bbpd_bonds.h"

#include <string>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

// the Silling-Askari rule is the style's; families, volumes and numbers are bbpd's
static constexpr PairBBPD::Rules ALPHA_RULES{true, false, false};

PairBBPDAlpha::PairBBPDAlpha(LAMMPS *lmp, BBPD::KernelInfo k) :
    PairBBPD(lmp, k, (std::string("bbpd/") + k.name + "/alpha").c_str(), ALPHA_RULES)
{
}

PairBBPDAlpha::~PairBBPDAlpha()
{
  if (copymode) return;
  silling_askari.destroy(memory);
  release_fix(silling_askari.fix, SillingAskariState::FIX_ID);
}

/* part of init_style: the state fix and the starting smin */
void PairBBPDAlpha::init_rules()
{
  silling_askari.attach(
      static_cast<FixBBPDAlpha *>(own_fix(SillingAskariState::FIX_ID, "bbpd/alpha")), atom,
      bonds->families_built());
  if (comm->me != 0) return;
  bool any = false;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && alpha[i][j] > 0.0) any = true;
  if (!any)
    error->warning(FLERR, "Pair style {}: alpha is 0 for every type pair, which turns the "
                   "Silling-Askari rule off: pair style bbpd/{} breaks bonds alike, faster",
                   style, kernel.name);
}

std::string PairBBPDAlpha::report_rules() const
{
  return "  Silling-Askari critical stretch: s0 - alpha min(0, smallest stretch of the atom)\n";
}

/* the bond forces and breaking of one step, in the bbpd order */
void PairBBPDAlpha::eval_bonds()
{
  // only compression lowers s0: a body in pure tension keeps the calibrated s00
  with_row_tally([&](auto ev) {
    eval_silling_askari<decltype(ev)::value, BBPD::SillingAskariRule<true>>(silling_askari);
  });
}

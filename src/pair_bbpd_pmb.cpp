// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: pair style bbpd/pmb, the rules of LAMMPS's peri/pmb
   (pair_bbpd_pmb.h): its coefficients and lattice constant; the bonds are
   evaluated and broken by PairBBPD's Silling-Askari loop
   (pair_bbpd_silling_askari.cpp) in peri/pmb's order, then the short-range
   forces of pair_bbpd_peri_rules.cpp act.
------------------------------------------------------------------------- */

#include "pair_bbpd_pmb.h"
#include "bbpd_pmb_rules.h"

#include "atom.h"
#include "error.h"
#include "fix_bbpd_alpha.h"
#include "fix_bbpd_bonds.h"
#include "memory.h"

#include <cmath>
#include <limits>

using namespace LAMMPS_NS;
using namespace BBPD::PMB;

/* ---------------------------------------------------------------------- */

PairBBPDPMB::PairBBPDPMB(LAMMPS *lmp) :
    PairBBPD(lmp, BBPD::kernel_info<BBPD::ConstantKernel>(), "bbpd/pmb", PERI_PMB_RULES),
    lattice_constant(0.0)
{
}

PairBBPDPMB::~PairBBPDPMB()
{
  if (copymode) return;
  silling_askari.destroy(memory);
  release_fix(silling_askari.fix, SillingAskariState::FIX_ID);
}

/* pair_style bbpd/pmb MODEL [thickness h] [area A] [spacing dx] [dt/safety f] [bond/storage s]:
   the keywords of the kernel styles, without contact (peri/pmb's short-range forces act) */
void PairBBPDPMB::settings(int narg, char **arg)
{
  PairBBPD::settings(narg, arg);
  forbid_contact();
}

/* the bond forces and breaking of one step in peri/pmb's order, then its short-range forces */
void PairBBPDPMB::eval_bonds()
{
  with_row_tally([&](auto ev) { eval_silling_askari<decltype(ev)::value, BBPD::PeriPmbRule>(silling_askari); });
  compute_short_range(lattice_constant);
}

std::string PairBBPDPMB::report_type_pair(int i, int j) const
{
  return fmt::format("  types {} {}: peri/pmb: c = {:.8g}  horizon = {:.6g}  s00 = {:.8g}  "
                     "alpha = {:.6g}\n", i, j, micromodulus[i][j], horizon[i][j],
                     critical_stretch[i][j], alpha[i][j]);
}

std::string PairBBPDPMB::report_rules() const
{
  return peri_rules_report(lattice_constant);
}

/* ----------------------------------------------------------------------
   pair_coeff I J c delta s00 alpha (peri/pmb's four numbers)
------------------------------------------------------------------------- */

void PairBBPDPMB::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  if (narg != 6)
    error->all(FLERR, "Pair coeff for bbpd/pmb: expected 'I J c delta s00 alpha' "
               "(the numbers of pair_coeff peri/pmb), got {} arguments", narg);
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double c = utils::numeric(FLERR, arg[2], false, lmp);
  const double delta = utils::numeric(FLERR, arg[3], false, lmp);
  const double s00 = utils::numeric(FLERR, arg[4], false, lmp);
  const double a = utils::numeric(FLERR, arg[5], false, lmp);
  if (!(c > 0.0)) error->all(FLERR, "Pair coeff for bbpd/pmb: c must be > 0");
  if (!(delta > 0.0)) error->all(FLERR, "Pair coeff for bbpd/pmb: delta must be > 0");
  if (!(s00 > 0.0)) error->all(FLERR, "Pair coeff for bbpd/pmb: s00 must be > 0");
  if (!(a >= 0.0) || !std::isfinite(a))
    error->all(FLERR, "Pair coeff for bbpd/pmb: alpha must be >= 0");

  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      youngs[i][j] = 0.0;    // not used: c is given
      fracture_energy[i][j] = std::numeric_limits<double>::infinity();
      horizon[i][j] = delta;
      micromodulus[i][j] = c;
      critical_stretch[i][j] = s00;
      s0_user[i][j] = 1;
      alpha[i][j] = a;
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* part of init_style: the Silling-Askari state and the lattice constant */
void PairBBPDPMB::init_rules()
{
  silling_askari.attach(
      static_cast<FixBBPDAlpha *>(own_fix(SillingAskariState::FIX_ID, "bbpd/alpha")), atom,
      bonds->families_built());
  lattice_constant = peri_lattice_constant();
  law.weighting = BBPD::PmbWeighting{lattice_constant};    // the families and volume ramp of the bond fix
}

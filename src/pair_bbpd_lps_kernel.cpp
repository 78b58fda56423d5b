// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: pair styles bbpd/lps/KERNEL and bbpd/ves/KERNEL, PairBBPDLPS with
   Coefficients::KERNEL
   (pair_bbpd_lps.h): the model and the coefficients E nu Gc delta, turned into the LPS moduli
   and critical stretch of bbpd_lps_kernel.h, the stable time step's bond and the report; the
   rest is bbpd/lps (pair_bbpd_lps.cpp).
------------------------------------------------------------------------- */

#include "pair_bbpd_lps.h"

#include "bbpd_lps_kernel.h"

#include "atom.h"
#include "error.h"
#include "fix_bbpd_bonds.h"

#include <cstring>
#include <limits>
#include <string>

using namespace LAMMPS_NS;
namespace LPS = BBPD::LPS;

// pair_coeff I J E nu Gc delta: the arguments before a family's own (bbpd/ves/KERNEL: lambda tau)
static constexpr int KERNEL_COEFFS = 6;

/* pair_style bbpd/lps/KERNEL MODEL [thickness h] [keywords]: the models of the LPS */
void PairBBPDLPS::kernel_settings(int narg, char **arg)
{
  PairBBPD::settings(narg, arg);    // model, thickness and keywords of bbpd/pmb
  forbid_contact();
  if (model == BBPD::Model::Bar1D)
    error->all(FLERR, "Pair style {}: model 1d is not available: the LPS has 3d, plane/strain "
               "and plane/stress", style);
}

/* ----------------------------------------------------------------------
   pair_coeff I J E nu Gc|none delta (SI, as the bond-based styles) [lambda tau (VES)]
------------------------------------------------------------------------- */

void PairBBPDLPS::kernel_coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  allocate_moduli();
  if (narg != KERNEL_COEFFS + family_args())
    error->all(FLERR, "Pair coeff for {}: expected 'I J E nu Gc delta{}' (Young's modulus, "
               "Poisson's ratio, fracture energy or 'none', horizon{}), got {} arguments",
               style, family == Family::VES ? " lambda tau" : "",
               family == Family::VES ? ", relaxing share of G, relaxation time" : "", narg);
  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  const double E = utils::numeric(FLERR, arg[2], false, lmp);
  const double nu = utils::numeric(FLERR, arg[3], false, lmp);
  const bool unbreakable = strcmp(arg[4], "none") == 0;
  const double Gc = unbreakable ? std::numeric_limits<double>::infinity()
                                : utils::numeric(FLERR, arg[4], false, lmp);
  const double delta = utils::numeric(FLERR, arg[5], false, lmp);
  if (!(E > 0.0)) error->all(FLERR, "Pair coeff for {}: Young's modulus E must be > 0", style);
  if (!LPS::admissible_poisson_ratio(model, nu))
    error->all(FLERR, "Pair coeff for {}: Poisson's ratio {} is outside {} < nu < {} of model {} "
               "(K and G must be positive)", style, nu, LPS::NU_MIN, LPS::nu_max(model),
               BBPD::model_name(model));
  if (!unbreakable && !(Gc > 0.0 && std::isfinite(Gc)))
    error->all(FLERR, "Pair coeff for {}: the fracture energy Gc must be > 0 (or 'none' for "
               "bonds that never break)", style);
  if (!(delta > 0.0)) error->all(FLERR, "Pair coeff for {}: the horizon delta must be > 0", style);
  check_family_coeffs(arg + KERNEL_COEFFS);

  const LPS::Moduli mod = LPS::moduli_of(model, E, nu);
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      youngs[i][j] = E;
      fracture_energy[i][j] = Gc;
      horizon[i][j] = delta;
      // the bond-based c0 of the same E: short-range forces and the stable time step estimate
      micromodulus[i][j] = BBPD::micromodulus(kernel, model, E, delta, geom);
      critical_stretch[i][j] = unbreakable ? std::numeric_limits<double>::infinity()
                                           : LPS::critical_stretch_of(kernel, model, mod.shear, Gc, delta);
      s0_user[i][j] = 1;    // derived here, not by the bond-based calibration
      alpha[i][j] = 0.0;    // a fixed critical stretch
      bulk[i][j] = bulk[j][i] = mod.bulk;
      shear[i][j] = shear[j][i] = mod.shear;
      set_family_coeffs(i, j, arg + KERNEL_COEFFS);
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* the stable time step estimate: the bond as the bond-based bond of the same E and kernel,
   c0 W V ramp / |xi| (the stored coefficient is W V ramp) */
double PairBBPDLPS::kernel_bond_stiffness(int i, int k) const
{
  const int j = bonds->partner_of(i, k);
  const double xi0 = bonds->xi0_of(i, k);
  return micromodulus[atom->type[i]][atom->type[j]] * bonds->coef_of(i, k, xi0) / xi0;
}

std::string PairBBPDLPS::kernel_report_type_pair(int i, int j) const
{
  // E and Gc first, as the bond-based styles print them (scripts read the line)
  return fmt::format("  types {} {}: E = {:.8g}  Gc = {:.6g}  nu = {:.6g}  LPS: K = {:.8g}  "
                     "G = {:.8g}  horizon = {:.6g}  critical_stretch s0 = {:.8g}{}\n", i, j,
                     youngs[i][j], fracture_energy[i][j],
                     youngs[i][j] / (2.0 * shear[i][j]) - 1.0,    // G = E / (2 (1 + nu))
                     bulk[i][j], shear[i][j], horizon[i][j], critical_stretch[i][j],
                     family_report(i, j));
}

std::string PairBBPDLPS::kernel_report_rules() const
{
  return peri_rules_report(lattice_constant) +
      fmt::format("  LPS state: influence function the {} kernel W(|xi|/delta), dilatation "
                  "factor d = {}, weighted volume m fixed at the first evaluation; stable time "
                  "step estimated as for the bond-based bond of the same E\n", kernel.name,
                  dimension) + history_report();
}

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: registers every style of bbpdplugin.so with LAMMPS.
------------------------------------------------------------------------- */

#include "lammpsplugin.h"

#include "comm.h"
#include "compute_bbpd_crack_tip.h"
#include "compute_bbpd_damage_atom.h"
#include "compute_bbpd_dilatation_atom.h"
#include "compute_bbpd_plasticity_atom.h"
#include "compute_bbpd_dsif.h"
#include "compute_bbpd_energy.h"
#include "compute_bbpd_jintegral.h"
#include "error.h"
#include "fix_bbpd_alpha.h"
#include "fix_bbpd_bonds.h"
#include "fix_bbpd_history.h"
#include "fix_bbpd_hold.h"
#include "fix_bbpd_lps.h"
#include "fix_bbpd_notch.h"
#include "fix_bbpd_relax.h"
#include "fix_bbpd_watchdog.h"
#include "fix_bbpd_work.h"
#include "info.h"
#include "lammps.h"
#include "pair_bbpd.h"
#include "pair_bbpd_alpha.h"
#include "pair_bbpd_lps.h"
#include "pair_bbpd_pmb.h"
#include "utils.h"
#include "version.h"

#include <cstring>

using namespace LAMMPS_NS;

#ifndef BBPD_VERSION
#define BBPD_VERSION "unknown"
#endif

namespace {
const char *AUTHOR = "BBPD developers";

template <class K> Pair *pair_creator(LAMMPS *lmp)
{
  return new PairBBPD(lmp, BBPD::kernel_info<K>());
}
template <class K> Pair *alpha_pair_creator(LAMMPS *lmp)
{
  return new PairBBPDAlpha(lmp, BBPD::kernel_info<K>());
}
Pair *pmb_pair_creator(LAMMPS *lmp)
{
  return new PairBBPDPMB(lmp);
}
Pair *lps_pair_creator(LAMMPS *lmp)
{
  return new PairBBPDLPS(lmp);
}
Pair *ves_pair_creator(LAMMPS *lmp)
{
  return new PairBBPDLPS(lmp, PairBBPDLPS::Family::VES);
}
Pair *eps_pair_creator(LAMMPS *lmp)
{
  return new PairBBPDLPS(lmp, PairBBPDLPS::Family::EPS);
}
Fix *history_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixBBPDHistory(lmp, narg, arg);
}
// the LPS with the kernel as influence function and the kernel's calibration of its
// coefficients (PairBBPDLPS::Coefficients::KERNEL), not a class of its own
template <class K> Pair *lps_kernel_pair_creator(LAMMPS *lmp)
{
  return new PairBBPDLPS(lmp, BBPD::kernel_info<K>());
}
template <class K> Pair *ves_kernel_pair_creator(LAMMPS *lmp)
{
  return new PairBBPDLPS(lmp, BBPD::kernel_info<K>(), PairBBPDLPS::Family::VES);
}
Fix *lps_state_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixBBPDLPS(lmp, narg, arg);
}
Fix *bonds_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixBBPDBonds(lmp, narg, arg);
}
Fix *alpha_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixBBPDAlpha(lmp, narg, arg);
}
Fix *watchdog_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixBBPDWatchdog(lmp, narg, arg);
}
Fix *hold_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixBBPDHold(lmp, narg, arg);
}
Fix *notch_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixBBPDNotch(lmp, narg, arg);
}
Fix *relax_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixBBPDRelax(lmp, narg, arg);
}
Compute *damage_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeBBPDDamageAtom(lmp, narg, arg);
}
Compute *dilatation_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeBBPDDilatationAtom(lmp, narg, arg);
}
Compute *plasticity_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeBBPDPlasticityAtom(lmp, narg, arg);
}
Compute *dsif_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeBBPDDsif(lmp, narg, arg);
}
Compute *jintegral_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeBBPDJIntegral(lmp, narg, arg);
}
Compute *crack_tip_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeBBPDCrackTip(lmp, narg, arg);
}
Fix *work_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new FixBBPDWork(lmp, narg, arg);
}
Compute *energy_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new ComputeBBPDEnergy(lmp, narg, arg);
}
}    // namespace

extern "C" void lammpsplugin_init(void *ptr, void *handle, void *regfunc)
{
  auto *lmp = (LAMMPS *) ptr;
  auto register_plugin = (lammpsplugin_regfunc) regfunc;

  // our styles derive from atom_style peri: without PERI they cannot work
  if (!Info::has_package("PERI")) {
    if (lmp->comm->me == 0)
      utils::logmesg(lmp, "ERROR: bbpdplugin.so (BBPD " BBPD_VERSION ") needs a LAMMPS built with "
                          "the PERI package (cmake -D PKG_PERI=on); no styles registered\n");
    return;
  }
  if (strcmp(LAMMPS_VERSION, lmp->version) != 0 && lmp->comm->me == 0)
    utils::logmesg(lmp, "WARNING: bbpdplugin.so was compiled for LAMMPS {} but runs in LAMMPS {}; "
                        "rebuild it against this LAMMPS if anything misbehaves\n",
                   LAMMPS_VERSION, lmp->version);

  lammpsplugin_t plugin;
  plugin.version = LAMMPS_VERSION;
  plugin.author = AUTHOR;
  plugin.handle = handle;

  plugin.style = "pair";
  plugin.name = "bbpd/constant";
  plugin.info = "BBPD pair style, constant kernel, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_creator<BBPD::ConstantKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/triangular";
  plugin.info = "BBPD pair style, triangular kernel, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_creator<BBPD::TriangularKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/gaussian";
  plugin.info = "BBPD pair style, Gaussian kernel, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_creator<BBPD::GaussianKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/constant/alpha";
  plugin.info = "BBPD pair style, constant kernel, Silling-Askari critical stretch, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &alpha_pair_creator<BBPD::ConstantKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/triangular/alpha";
  plugin.info = "BBPD pair style, triangular kernel, Silling-Askari critical stretch, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &alpha_pair_creator<BBPD::TriangularKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/gaussian/alpha";
  plugin.info = "BBPD pair style, Gaussian kernel, Silling-Askari critical stretch, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &alpha_pair_creator<BBPD::GaussianKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/pmb";
  plugin.info = "BBPD pair style, the rules of peri/pmb, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pmb_pair_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/lps";
  plugin.info = "BBPD pair style, the linear peridynamic solid of peri/lps, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &lps_pair_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/ves";
  plugin.info = "BBPD pair style, the viscoelastic solid of peri/ves, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &ves_pair_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/eps";
  plugin.info = "BBPD pair style, the elastic-plastic solid of peri/eps, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &eps_pair_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/lps/constant";
  plugin.info = "BBPD pair style, the linear peridynamic solid with the constant influence function, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &lps_kernel_pair_creator<BBPD::ConstantKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/lps/triangular";
  plugin.info = "BBPD pair style, the linear peridynamic solid with the triangular influence function, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &lps_kernel_pair_creator<BBPD::TriangularKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/lps/gaussian";
  plugin.info = "BBPD pair style, the linear peridynamic solid with the Gaussian influence function, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &lps_kernel_pair_creator<BBPD::GaussianKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/ves/constant";
  plugin.info = "BBPD pair style, the viscoelastic solid of peri/ves with the constant influence function, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &ves_kernel_pair_creator<BBPD::ConstantKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/ves/triangular";
  plugin.info = "BBPD pair style, the viscoelastic solid of peri/ves with the triangular influence function, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &ves_kernel_pair_creator<BBPD::TriangularKernel>;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/ves/gaussian";
  plugin.info = "BBPD pair style, the viscoelastic solid of peri/ves with the Gaussian influence function, v" BBPD_VERSION;
  plugin.creator.v1 = (lammpsplugin_factory1 *) &ves_kernel_pair_creator<BBPD::GaussianKernel>;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "bbpd/bonds";
  plugin.info = "BBPD bond families (internal, created by the pair style) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &bonds_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/alpha";
  plugin.info = "BBPD Silling-Askari breaking state (internal, created by the pair style) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &alpha_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/lps";
  plugin.info = "BBPD linear peridynamic solid state (internal, created by the pair style) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &lps_state_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/history";
  plugin.info = "BBPD bond and atom history of bbpd/ves and bbpd/eps (internal, created by the pair style) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &history_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/watchdog";
  plugin.info = "BBPD run-explosion watchdog (internal, created by the pair style) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &watchdog_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/hold";
  plugin.info = "BBPD log of the bonds a minimize holds (internal, created by the pair style) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &hold_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/work";
  plugin.info = "BBPD work of external loads (internal, created by compute bbpd/energy) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &work_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/notch";
  plugin.info = "BBPD pre-cracks by broken bonds v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &notch_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/relax";
  plugin.info = "BBPD quasi-static load steps by adaptive dynamic relaxation v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &relax_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "compute";
  plugin.name = "bbpd/damage/atom";
  plugin.info = "BBPD local damage (eq. 17) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &damage_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/dilatation/atom";
  plugin.info = "BBPD dilatation of the state-based styles (LAMMPS's dilatation/atom) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &dilatation_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/plasticity/atom";
  plugin.info = "BBPD plastic multiplier of bbpd/eps (LAMMPS's plasticity/atom) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &plasticity_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/dsif";
  plugin.info = "BBPD dynamic stress intensity factors (eqs. 39-40) v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &dsif_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/jintegral";
  plugin.info = "BBPD dynamic J-integral and K_I, K_II by the domain integral v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &jintegral_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/crack/tip";
  plugin.info = "BBPD crack tip, extension, speed and direction of a growing crack v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &crack_tip_creator;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "bbpd/energy";
  plugin.info = "BBPD energy account: elastic, kinetic, broken bonds, external work v" BBPD_VERSION;
  plugin.creator.v2 = (lammpsplugin_factory2 *) &energy_creator;
  (*register_plugin)(&plugin, lmp);
}

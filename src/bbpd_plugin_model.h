// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: the bond model and the breaking rules the plugin's loops are compiled with, with no
   LAMMPS dependency.

   The loops take the bond model as their Model parameter and the Silling-Askari rule as their
   Rule parameter, and name none (doc/architecture.rst); this is the one place that lists
   them for the loops (a style picks its rule where it calls the loop). A test build may put
   another in its place (cmake -D BBPD_TEST_BOND_MODEL=NAME: tests/unit/toy_bond_models.h,
   which the build includes ahead of every file, so its models are declared here).
------------------------------------------------------------------------- */

#ifndef BBPD_PLUGIN_MODEL_H
#define BBPD_PLUGIN_MODEL_H

#include "bbpd_bond_model.h"
#include "bbpd_pmb_rules.h"

namespace BBPD {

#ifdef BBPD_BOND_MODEL
using PluginBondModel = BBPD_BOND_MODEL;
#else
using PluginBondModel = CriticalStretchBond;
#endif

}    // namespace BBPD

// X(A, RULE) for every rule the Silling-Askari loop (pair_bbpd_silling_askari.cpp) is
// compiled with: bbpd/KERNEL/alpha's (only compression lowers s0) and peri/pmb's (bbpd/pmb)
#define BBPD_FOR_STRETCH_RULES(X, A) X(A, BBPD::SillingAskariRule<true>) X(A, BBPD::PeriPmbRule)

#endif

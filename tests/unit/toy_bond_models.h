// SPDX-License-Identifier: GPL-2.0-or-later
/* Two toy bond models (doc/architecture.rst, "Adding a bond model"): each a struct of a few
   lines in the form of bbpd_bond_model.h. tests/unit/test_bond_model.cpp runs them through the
   row kernels; tests/lammps/test_bond_model_build.py builds the plugin with one of them
   (cmake -D BBPD_TEST_BOND_MODEL=SymmetricStretchBond) and runs it in LAMMPS. */

#ifndef BBPD_TOY_BOND_MODELS_H
#define BBPD_TOY_BOND_MODELS_H

#include "bbpd_bond_model.h"

namespace BBPDToy {

// a toy breaking rule: the critical stretch holds in compression as in tension
struct SymmetricStretchBond : BBPD::CriticalStretchBond {
  template <class V> static auto past_critical(V elong, V xi0, V s0, V margin)
  {
    return BBPD::vabs(elong) + margin > s0 * xi0;
  }
};

// a toy force: every bond twice as stiff
struct DoubleStiffnessBond : BBPD::CriticalStretchBond {
  template <class V> static V force_per_length(V coef, V elong, V r)
  {
    return V(2.0) * coef * elong / r;
  }
};

}    // namespace BBPDToy

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: what the crack computes bbpd/dsif and bbpd/jintegral share:

     compute ID group STYLE tip X Y ... [direction DX DY] [E E] [nu NU]
             [plane stress|strain] ...

   the crack tip (numbers or v_name equal-style variables), the crack
   direction, the elastic constants and their defaults from the pair style
   (E inverted from the calibrated c0, nu implied by the model, the plane of
   the model), and the reading of the computes' own keywords with a value > 0.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_BBPD_CRACK_ARGS_H
#define LMP_COMPUTE_BBPD_CRACK_ARGS_H

#include "bbpd_jintegral.h"
#include "pointers.h"

#include <initializer_list>
#include <string>

namespace LAMMPS_NS {

class CrackComputeArgs : protected Pointers {
 public:
  enum Plane { PLANE_UNSET, PLANE_STRESS, PLANE_STRAIN };
  static constexpr double UNSET = -1.0;    // a length or E not given: default from the pair

  // reads 'tip X Y' from arg[3..5]; style names the compute in messages
  CrackComputeArgs(class LAMMPS *, const char *style, int narg, char **arg);

  // a keyword of the compute's own with a value > 0, and where the value goes
  struct Positive {
    const char *key;
    double *value;
  };
  // reads the keyword at arg[iarg] (direction, E, nu, plane, or one of own) and steps iarg
  // past it; false for any other keyword
  bool parse(int narg, char **arg, int &iarg, std::initializer_list<Positive> own);

  void init_tip();                        // resolves the tip variables (compute init())
  void current_tip(double *tip) const;    // the tip now
  // E (given, or c0 / c0(E = 1) of type itype), nu (given, or implied by the model) and the
  // plane (given, or that of the model); pair may be null if E, nu and plane were given
  BBPD::JIntegral::Elastic elastic(class PairBBPD *pair, int itype) const;
  // E, nu and plane all given: no pair style needed for them
  bool elastic_given() const
  {
    return youngs != UNSET && poisson != UNSET && plane != PLANE_UNSET;
  }

  const std::string style;    // "bbpd/dsif", "bbpd/jintegral"
  double dir[2];              // unit crack direction (ahead of the tip)
  double youngs, poisson;     // UNSET: from the pair style
  int plane;                  // Plane

 private:
  double tip_value[2];       // tip coordinates when given as numbers
  std::string tip_var[2];    // equal-style variable names ("" if a number)
  int tip_ivar[2];
  // the value of keyword arg[iarg] (in arg[iarg + 1]), which must be > 0
  double positive(int narg, char **arg, int iarg) const;
};

}    // namespace LAMMPS_NS

#endif

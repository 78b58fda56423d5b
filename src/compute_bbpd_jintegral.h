// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: compute bbpd/jintegral -- dynamic J-integral of a stationary
   crack and the stress intensity factors K_I, K_II from it, by the domain
   integral of Moran & Shih (1987) over the disc r <= rout around the tip, with
   the interaction integral (auxiliary Williams fields) for mode separation.
   The math is in bbpd_jintegral.h.

   compute ID group bbpd/jintegral tip X Y [rin R1] [rout R2] [gradient RG]
           [direction DX DY] [E E] [nu NU] [plane stress|strain] [thickness H]

   The crack runs along -direction from the tip. Fields at each atom from the
   reference positions x0: displacement gradient and velocity gradient by least
   squares over the atoms within RG that do not face it across the crack,
   stress by Hooke's law, acceleration f/rho. X and Y may be v_name.
   The atoms of the disc and their gradient neighbours (fixed while the tip
   does not move) are gathered to every rank in the order of their reference
   positions, so every rank sums the same numbers in the same order: the
   result does not depend on the number of ranks.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_BBPD_JINTEGRAL_H
#define LMP_COMPUTE_BBPD_JINTEGRAL_H

#include "bbpd_jintegral.h"
#include "compute.h"
#include "compute_bbpd_crack_args.h"
#include "lmptype.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeBBPDJIntegral : public Compute {
 public:
  ComputeBBPDJIntegral(class LAMMPS *, int, char **);
  void init() override;
  void compute_vector() override;
  double memory_usage() override;

 private:
  double jvec[3];
  CrackComputeArgs args;    // tip, crack direction, E, nu, plane
  double rin_user, rout_user, grad_user;    // < 0: default from the horizon / grid spacing
  double thickness_user;                    // < 0: the pair style's thickness
  class PairBBPD *pair;

  // resolved parameters (init)
  double rin, rout, rgrad, thickness;

  // cache: atoms within rout + rgrad of the tip, sorted by reference position; valid while
  // the tip does not move
  int cached;
  double cached_tip[2];
  std::vector<tagint> tags;
  std::vector<double> xloc;          // reference position in crack-tip coordinates, 2 per atom
  std::vector<double> area, rho;     // per atom
  std::vector<int> points;           // atoms with r <= rout and a valid stencil
  std::vector<int> nbr_start, nbr;   // stencil of each point (CSR)
  std::vector<double> kinv;          // inverse moment of each point's stencil, 3 per point
  std::vector<BBPD::JIntegral::Aux> aux;    // q and auxiliary fields of each point
  double aux_elastic[3];                    // E, nu, plane stress the auxiliary fields belong to
  int itype_tip;                     // type of the atom nearest to the tip
  std::vector<double> fields;        // gathered u, v, a (crack-tip coordinates) and owner count

  void build_cache(const double *tip);
};

}    // namespace LAMMPS_NS

#endif

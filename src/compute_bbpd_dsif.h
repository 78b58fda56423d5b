// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: compute bbpd/dsif -- dynamic stress intensity factors
   (K_I, K_II) by two-point displacement extrapolation, eqs. 39-40.

   compute ID group bbpd/dsif tip X Y [r1 R1] [r2 R2] [direction DX DY]
           [offset H] [E E] [nu NU] [plane stress|strain] [tolerance T]

   The crack runs along -direction from the tip; the face nodes are the nodes
   of the group nearest (in the reference configuration x0) to the points
   tip - r d +- H n (n = direction rotated by +90 degrees), for r = r1, r2.
   K uses the opening and sliding between the two faces, so rigid motion
   cancels. X and Y may be v_name equal-style variables (a moving tip).
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_BBPD_DSIF_H
#define LMP_COMPUTE_BBPD_DSIF_H

#include "compute.h"
#include "compute_bbpd_crack_args.h"
#include "lmptype.h"

namespace LAMMPS_NS {

class ComputeBBPDDsif : public Compute {
 public:
  ComputeBBPDDsif(class LAMMPS *, int, char **);
  void init() override;
  void compute_vector() override;

  // eq. 39 written with the face jumps (upper minus lower face): for a pure
  // mode the jump is twice the single-face displacement of eq. 39.
  // Public and static for unit tests.
  static double extrapolate(double jump1, double jump2, double r1, double r2, double mu,
                            double kappa);

 private:
  static constexpr int NPOINT = 4;    // upper r1, lower r1, upper r2, lower r2

  double kvec[2];
  CrackComputeArgs args;    // tip, crack direction, E, nu, plane
  double r_user[2], offset_user, tolerance_user;    // < 0: default from the grid spacing
  class PairBBPD *pair;

  // cached face nodes: valid while the tip has not moved
  tagint tags[NPOINT];
  double cached_tip[2];
  int cached;

  void face_points(const double *tip, double pts[NPOINT][2]) const;
  void find_face_nodes(const double *tip);
  double grid_spacing() const;
};

}    // namespace LAMMPS_NS

#endif

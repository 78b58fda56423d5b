// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: compute bbpd/crack/tip -- the tip of the crack that grows
   from a notch tip (X, Y), its extension along the crack path, its speed and
   the direction of the newest part of the path. The graph search is in
   bbpd_crack_tip.h (no LAMMPS dependency).

   compute ID group bbpd/crack/tip X Y [threshold T] [link L] [span S]
           [window W] [direction DX DY] [branches yes|no] [branch B] [maxtips N]

   The atoms of the group with damage (eq. 17, FixBBPDBonds::damage) >= T
   at or ahead of the start line are gathered to every rank (tag, x0, damage)
   and searched in tag order on each: every rank, for any number of ranks,
   gets the same bits. Computed only when an output asks for it; the speed
   comes from the (time, extension) of those invocations. With branches yes
   the compute also has a global array, one row per tip of the branched
   crack (bbpd_crack_branches.h), and two more vector values.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_BBPD_CRACK_TIP_H
#define LMP_COMPUTE_BBPD_CRACK_TIP_H

#include "bbpd_crack_branches.h"
#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeBBPDCrackTip : public Compute {
 public:
  ComputeBBPDCrackTip(class LAMMPS *, int, char **);
  void init() override;
  void compute_vector() override;
  void compute_array() override;
  double memory_usage() override;

 private:
  static constexpr int NVALUES = 6;
  static constexpr int NBRANCHVALUES = 8;    // with branches: + tips, splits
  static constexpr int NCOLS = 9;            // of the array: tip (5), split (4)
  double values[NBRANCHVALUES];
  BBPD::CrackTip::Params params;    // link and span < 0 until init() resolves the defaults
  double link_user, span_user;
  BBPD::CrackTip::History history;
  class FixBBPDBonds *bonds;
  std::vector<BBPD::CrackTip::Node> mine, all;
  // the last search: reused while the same atoms (ID and position) are crack atoms
  std::vector<BBPD::CrackTip::Node> searched;
  BBPD::CrackTip::Result found;
  bool have_found;
  bool same_nodes() const;
  void gather();

  // branches yes: every tip, followed from call to call; array rows in one block
  bool branches;
  int maxtips;
  double branch_user;    // least length of a branch beyond its split point (< 0: default)
  double min_length;
  BBPD::CrackTip::Graph graph;
  std::vector<BBPD::CrackTip::Branch> tips;
  BBPD::CrackTip::BranchTracker tracker;
  std::vector<double> block;
  std::vector<double *> rows;
  bigint invoked_branches;
  void compute_branches();
  double record_tip();
};

}    // namespace LAMMPS_NS

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: compute bbpd/crack/tip -- the tip of the crack that grows
   from a notch tip (X, Y), its extension along the crack path, its speed and
   the direction of the newest part of the path. The graph search is in
   bbpd_crack_tip.h (no LAMMPS dependency).

   compute ID group bbpd/crack/tip X Y [threshold T] [link L] [span S]
           [window W] [direction DX DY]

   The atoms of the group with damage (eq. 17, FixBBPDBonds::damage) >= T
   at or ahead of the start line are gathered to every rank (tag, x0, damage)
   and searched in tag order on each: every rank, for any number of ranks,
   gets the same bits. Computed only when an output asks for it; the speed
   comes from the (time, extension) of those invocations.
------------------------------------------------------------------------- */

#ifndef LMP_COMPUTE_BBPD_CRACK_TIP_H
#define LMP_COMPUTE_BBPD_CRACK_TIP_H

#include "bbpd_crack_tip.h"
#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeBBPDCrackTip : public Compute {
 public:
  ComputeBBPDCrackTip(class LAMMPS *, int, char **);
  void init() override;
  void compute_vector() override;
  double memory_usage() override;

 private:
  static constexpr int NVALUES = 6;
  double values[NVALUES];
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
};

}    // namespace LAMMPS_NS

#endif

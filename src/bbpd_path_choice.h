// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: which path the bond loops of a bbpd pair style run (pair_style ... simd): the one
   forced, or (auto) the fastest of those every rank's CPU runs, timed on rank 0's own rows at
   the first setup and sent to every rank (bbpd_row_paths.h). The paths give the same bits, so
   the choice changes the speed alone.

   The chooser knows no pair style: it is handed the rows' sizes and a callable that times the
   rows' forces on a path (PairBBPD::choose_simd_path, pair_bbpd.cpp, passes its row_force).
------------------------------------------------------------------------- */

#ifndef BBPD_PATH_CHOICE_H
#define BBPD_PATH_CHOICE_H

#include "bbpd_row_paths.h"

#include <functional>
#include <mpi.h>
#include <string>

namespace BBPD {

// the paths every rank's CPU runs, as bits 1 << path, and their names
int paths_supported_everywhere(MPI_Comm world);
std::string path_list(int mask);

/* why a forced path cannot run here ("" if it can): the message of the ERROR at the
   pair_style command (style: the style's name) */
std::string simd_request_problem(SimdPath request, MPI_Comm world, int nprocs,
                                 const std::string &style);

struct PathChoice {
  SimdPath path;
  std::string reason;    // for the setup report (rank 0's)
};
/* the path of the bond loops: the forced one, or (AUTO) the fastest every rank runs, timed on
   rank 0 over a block of its rows (nbond[i] bond ends of row i, nlocal rows) with
   seconds(path, first, last), the time of the row forces of rows first..last-1 on a path */
PathChoice choose_path(SimdPath request, MPI_Comm world, int me, const int *nbond, int nlocal,
                       const std::function<double(SimdPath, int, int)> &seconds);

}    // namespace BBPD

#endif

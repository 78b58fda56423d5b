// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: PairBBPD::eval_rows, the one row driver of the pair styles' bond
   forces and breaking, and for_each_row, the threaded loop over the rows of the
   local atoms it runs in (pair_bbpd.cpp, pair_bbpd_alpha.cpp, pair_bbpd_lps.cpp
   include it). Every atom sums only its own bonds, so the threads share nothing
   but the energy/virial totals, and the forces are the same bits for any number
   of threads.
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_BBPD_ROWS_H
#define LMP_PAIR_BBPD_ROWS_H

#include "pair_bbpd.h"
#include "pair_bbpd_hold.h"

#include "atom.h"
#include "comm.h"
#include "fix_bbpd_bonds.h"
#include "update.h"

// a row body passed to for_each_row is inlined into the loop, as a loop body written there is
// (as a call per row, the bbpd/pmb cylinder ran 4 % more instructions under callgrind)
#if defined(__GNUC__)
#define BBPD_ROW_BODY __attribute__((always_inline))
#else
#define BBPD_ROW_BODY
#endif

namespace LAMMPS_NS {

template <int EVFLAG, class Row> void PairBBPD::for_each_row(Row row)
{
  const int nlocal = atom->nlocal;
  double totals[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  int bad = -1;    // an atom whose force is not finite (errors are raised outside the threads)
#if defined(_OPENMP)
#pragma omp parallel num_threads(comm->nthreads) if (comm->nthreads > 1)
#endif
  {
    double acc[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double vir[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};    // add_row_virial's (not in acc: in registers)
    BBPD::CoefCache *cache = thread_coef_cache();
#if defined(_OPENMP)
    // chunks of 512 atoms dealt out in turn: rows differ in length near surfaces and cracks
    // (plate, 2 threads: 1.92x speed-up; one half per thread: 1.65x)
#pragma omp for schedule(static, 512)
#endif
    for (int i = 0; i < nlocal; i++) {
      double fi[3];
      row(i, fi, acc, cache);
      if (EVFLAG == BBPD::TALLY_ENERGY && vflag_global) add_row_virial(i, fi, vir);
      add_row_force(i, fi, bad);
    }
    for (int m = 0; m < 6; m++) acc[1 + m] += vir[m];
    if (EVFLAG) add_thread_totals(totals, acc);
  }
  finish_eval(bad, EVFLAG, totals);
}

/* The bond forces and breaking of one step, for every style. row_of(i, acc, cache) returns the
   row of atom i as its style sees it (its bond model, breaking rule and per-atom state: a small
   value type of the style's eval function), which provides
     bool sum_and_check(fi): sum the row's force density into fi (its tallies into acc); true if
         a bond of the row may be past breaking, and fi is then to be summed again;
     bool breaks(k): does bond k break now? (and book what it carries away);
     void sum(fi): sum the row again, over the bonds left;
     void finish(fi): what the row adds after its bonds (forces of broken bonds, state).
   A style without breaking returns false from sum_and_check at compile time, and the removal
   is compiled out. */
template <int EVFLAG, class RowOf> void PairBBPD::eval_rows(RowOf row_of)
{
  // minimize and fix bbpd/relax hold the bonds (bbpd_bond_hold.h): none breaks, those past
  // breaking are counted (pair_bbpd_hold.h)
  const bool held = hold.holds(update->whichflag);
  if (held) hold.held_ends = 0;
  for_each_row<EVFLAG>([&](int i, double *fi, double *acc, BBPD::CoefCache *cache) BBPD_ROW_BODY {
    auto row = row_of(i, acc, cache);
    if (row.sum_and_check(fi)) {
      // remove the bonds that break (irreversibly, in row order), then sum the row again
      if (held)
        count_held(i, row);
      else
        bonds->remove_bonds_if(i, [&](int k) BBPD_ROW_BODY { return row.breaks(k); });
      row.sum(fi);
    }
    row.finish(fi);
  });
}

}    // namespace LAMMPS_NS

#endif

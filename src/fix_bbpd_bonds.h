/* -*- c++ -*- ----------------------------------------------------------
   BBPD plugin: bond families of the bbpd/* pair styles.

   Created by the pair style (ID BBPD_BONDS); not meant for input scripts.
   Persistent per-atom data, carried through atom migration and restart files:
     npartner[i]       number of bonds the atom started with
     partner[i][k]     tag of partner k, sorted ascending; negative = broken
     vinit[i]          sum of C_v V_j over the initial family (damage, eq. 17)
   Cached per bond, rebuilt only when LAMMPS reneighbors (post_neighbor):
     jlocal[i][k]      local/ghost index of the partner (-1 if broken)
     xi0[i][k]         reference bond length |x0_j - x0_i|
     coef[i][k]        c(xi0) C_v V_j / xi0: force density per unit elongation
     rbreak2[i][k]     ((1 + s0) xi0)^2: squared length at which the bond breaks
     cvv[i][k]         C_v V_j: partner volume inside the horizon
------------------------------------------------------------------------- */

#ifndef LMP_FIX_BBPD_BONDS_H
#define LMP_FIX_BBPD_BONDS_H

#include "fix.h"

namespace LAMMPS_NS {

class PairBBPD;

class FixBBPDBonds : public Fix {
 public:
  FixBBPDBonds(class LAMMPS *, int, char **);
  ~FixBBPDBonds() override;
  int setmask() override;
  void init() override;
  void init_list(int, class NeighList *) override;
  void setup_post_neighbor() override;
  void post_neighbor() override;
  void min_setup_post_neighbor() { setup_post_neighbor(); }

  double memory_usage() override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

  // used by the pair style, the computes and fix bbpd/notch
  bool families_built() const { return !first; }
  int maxpartner;
  int *npartner;
  tagint **partner;
  double *vinit;
  int **jlocal;
  double **xi0, **coef, **rbreak2, **cvv;

  void break_bond(int i, int k)
  {
    if (partner[i][k] > 0) partner[i][k] = -partner[i][k];
    jlocal[i][k] = -1;
  }
  bigint count_broken() const;

 protected:
  int first;    // 1 until bond families exist
  int nmax_cache;
  class NeighList *list;
  PairBBPD *pair;

  void build_families();
  void refresh_cache();
  void apply_notches();
  void report_setup();
  void grow_cache();
};

}    // namespace LAMMPS_NS

#endif

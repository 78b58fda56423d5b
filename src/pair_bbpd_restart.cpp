// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: the settings and coefficients of the bbpd pair styles in restart files
   (pair_bbpd.h)
------------------------------------------------------------------------- */

#include "pair_bbpd.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_bbpd_bonds.h"
#include "memory.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

void PairBBPD::write_restart_settings(FILE *fp)
{
  int m = static_cast<int>(model);
  fwrite(&m, sizeof(int), 1, fp);
  fwrite(&geom, sizeof(double), 1, fp);
  fwrite(&spacing, sizeof(double), 1, fp);
  fwrite(&spacing_user, sizeof(int), 1, fp);
  fwrite(&dt_safety, sizeof(double), 1, fp);
  fwrite(&contact, sizeof(int), 1, fp);
  fwrite(&contact_factor, sizeof(double), 1, fp);
  const int storage_code = storage.code();
  fwrite(&storage_code, sizeof(int), 1, fp);
  const int pmb = rules.pmb_rules;
  fwrite(&pmb, sizeof(int), 1, fp);
}

void PairBBPD::read_restart_settings(FILE *fp)
{
  int m = 0, storage_code = 0, pmb = 0;
  if (comm->me == 0) {
    utils::sfread(FLERR, &m, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &geom, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &spacing, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &spacing_user, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &dt_safety, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &contact, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &contact_factor, sizeof(double), 1, fp, nullptr, error);
    utils::sfread(FLERR, &storage_code, sizeof(int), 1, fp, nullptr, error);
    utils::sfread(FLERR, &pmb, sizeof(int), 1, fp, nullptr, error);
  }
  MPI_Bcast(&m, 1, MPI_INT, 0, world);
  MPI_Bcast(&geom, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&spacing, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&spacing_user, 1, MPI_INT, 0, world);
  MPI_Bcast(&dt_safety, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&contact, 1, MPI_INT, 0, world);
  MPI_Bcast(&contact_factor, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&storage_code, 1, MPI_INT, 0, world);
  storage = BBPD::BondStorage::from_code(storage_code);
  MPI_Bcast(&pmb, 1, MPI_INT, 0, world);
  // written by an older version with 'compat pmb': peri/pmb's rules are now pair style bbpd/pmb
  if (pmb != (int) rules.pmb_rules)
    error->all(FLERR, "Pair style {}: the restart file has the pair coefficients of {}: "
               "redefine the pair style and its coefficients after read_restart", style,
               pmb ? "peri/pmb's rules (compat pmb, now pair style bbpd/pmb)" : "another bbpd style");
  model = static_cast<BBPD::Model>(m);
}

void PairBBPD::write_restart(FILE *fp)
{
  write_restart_settings(fp);
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      fwrite(&setflag[i][j], sizeof(int), 1, fp);
      if (setflag[i][j]) {
        fwrite(&youngs[i][j], sizeof(double), 1, fp);
        fwrite(&fracture_energy[i][j], sizeof(double), 1, fp);
        fwrite(&horizon[i][j], sizeof(double), 1, fp);
        fwrite(&micromodulus[i][j], sizeof(double), 1, fp);
        fwrite(&critical_stretch[i][j], sizeof(double), 1, fp);
        fwrite(&s0_user[i][j], sizeof(int), 1, fp);
        fwrite(&alpha[i][j], sizeof(double), 1, fp);
        fwrite(&bondless[i][j], sizeof(int), 1, fp);
      }
    }
}

void PairBBPD::read_restart(FILE *fp)
{
  read_restart_settings(fp);
  allocate();
  const int me = comm->me;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (me == 0) utils::sfread(FLERR, &setflag[i][j], sizeof(int), 1, fp, nullptr, error);
      MPI_Bcast(&setflag[i][j], 1, MPI_INT, 0, world);
      if (!setflag[i][j]) continue;
      double v[5];
      if (me == 0) {
        utils::sfread(FLERR, v, sizeof(double), 5, fp, nullptr, error);
        utils::sfread(FLERR, &s0_user[i][j], sizeof(int), 1, fp, nullptr, error);
        utils::sfread(FLERR, &alpha[i][j], sizeof(double), 1, fp, nullptr, error);
        utils::sfread(FLERR, &bondless[i][j], sizeof(int), 1, fp, nullptr, error);
      }
      MPI_Bcast(v, 5, MPI_DOUBLE, 0, world);
      MPI_Bcast(&alpha[i][j], 1, MPI_DOUBLE, 0, world);
      MPI_Bcast(&bondless[i][j], 1, MPI_INT, 0, world);
      MPI_Bcast(&s0_user[i][j], 1, MPI_INT, 0, world);
      youngs[i][j] = v[0];
      fracture_energy[i][j] = v[1];
      horizon[i][j] = v[2];
      micromodulus[i][j] = v[3];
      critical_stretch[i][j] = v[4];
    }
}

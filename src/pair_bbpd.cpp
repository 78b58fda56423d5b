// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD plugin: kernel-weighted bond-based peridynamics pair styles.

   Force density on atom i from partner j (eqs. 19, 21, 22):
     f_ij = c0 W(xi/delta) s C_v V_j (y_j - y_i)/|y_j - y_i|,   s = (|y| - xi)/xi
   Every bond is evaluated from both ends (full bond lists, no Newton's third
   law across ranks): each atom sums its own partners in the order of their
   reference offsets, so the result depends neither on the domain
   decomposition nor on the atom numbering.
------------------------------------------------------------------------- */

#include "pair_bbpd.h"
#include "bbpd_compat.h"
#include "bbpd_path_choice.h"
#include "bbpd_row.h"
#include "pair_bbpd_rows.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "fix_bbpd_bonds.h"
#include "fix_bbpd_watchdog.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "potential_file_reader.h"
#include "update.h"

#include <algorithm>
#include <array>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

using namespace LAMMPS_NS;
using BBPD::LANES;
using BBPD::RowTally;
using BBPD::lane_sum;
using BBPD::lane_total;

static constexpr double DT_SAFETY_DEFAULT = 0.8;    // fraction of the stable bound before a warning
static constexpr const char *BONDS_FIX_ID = "BBPD_BONDS";
static constexpr const char *WATCHDOG_FIX_ID = "BBPD_WATCHDOG";
static constexpr const char *HOLD_FIX_ID = "BBPD_HOLD";
// short-range contact as in LAMMPS peri/pmb: distance 0.9 x grid spacing (Parks et al., Comput.
// Phys. Commun. 179 (2008) 777); its stiffness: CONTACT_STIFFNESS_FACTOR (pair_bbpd.h)
static constexpr double CONTACT_FACTOR_DEFAULT = 0.9;
// skin of the contact candidates' search, in grid spacings: the search runs again when an atom
// has moved half of it (a performance choice: any value > 0 gives the same forces)
static constexpr double CONTACT_CANDIDATE_SKIN = 0.6;
// margin of the quick bond-failure test in periodic boxes, in units of DBL_EPSILON x the largest
// coordinate: covers the round-off of x + L and of the minimum image (2 ulps each) per component
static constexpr double BREAK_MARGIN_ULPS = 16.0;

/* ---------------------------------------------------------------------- */

PairBBPD::PairBBPD(LAMMPS *lmp, BBPD::KernelInfo k, const char *style_name, Rules r) :
    Pair(lmp), kernel(k), style(style_name ? style_name : std::string("bbpd/") + k.name),
    model(BBPD::Model::Solid3D), geom(1.0), spacing(0.0), dt_safety(DT_SAFETY_DEFAULT), contact(0),
    contact_factor(CONTACT_FACTOR_DEFAULT), simd_request(BBPD::SimdPath::AUTO), spacing_user(0), fracture_any(0), youngs(nullptr),
    fracture_energy(nullptr), horizon(nullptr), micromodulus(nullptr), critical_stretch(nullptr),
    s0_user(nullptr), bondless(nullptr), bonds(nullptr), watchdog(nullptr), dt_bound_paper(0.0), dt_bound(0.0),
    report_due(0), simd_path(BBPD::SimdPath::PORTABLE), simd_decided(false), rules(r), alpha(nullptr), multi_s0(0), s0_single(0.0), break_margin(0.0)
{
  single_enable = 0;
  restartinfo = 1;
  // pvector: stable time steps, for 'compute pair' and so for variables (e.g. timestep)
  nextra = 2;
  pvector = new double[nextra];
  pvector[0] = pvector[1] = 0.0;
  one_coeff = 0;
  no_virial_fdotr_compute = 1;    // ghost forces are never set: tally the virial per bond
  manybody_flag = 1;              // bonds outlive the cutoff: no tail or shift logic applies
}

PairBBPD::~PairBBPD()
{
  if (copymode) return;
  delete[] pvector;
  release_fix(hold_report, HOLD_FIX_ID);
  release_fix(watchdog, WATCHDOG_FIX_ID);
  release_fix(bonds, BONDS_FIX_ID);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    memory->destroy(youngs);
    memory->destroy(fracture_energy);
    memory->destroy(horizon);
    memory->destroy(micromodulus);
    memory->destroy(critical_stretch);
    memory->destroy(s0_user);
    memory->destroy(bondless);
    memory->destroy(alpha);
  }
}

void PairBBPD::allocate()
{
  allocated = 1;
  const int n = atom->ntypes + 1;
  memory->create(setflag, n, n, "pair:setflag");
  memory->create(cutsq, n, n, "pair:cutsq");
  memory->create(youngs, n, n, "pair:youngs");
  memory->create(fracture_energy, n, n, "pair:fracture_energy");
  memory->create(horizon, n, n, "pair:horizon");
  memory->create(micromodulus, n, n, "pair:micromodulus");
  memory->create(critical_stretch, n, n, "pair:critical_stretch");
  memory->create(s0_user, n, n, "pair:s0_user");
  memory->create(bondless, n, n, "pair:bondless");
  memory->create(alpha, n, n, "pair:alpha");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      setflag[i][j] = 0;
      s0_user[i][j] = 0;
      bondless[i][j] = 0;
      alpha[i][j] = 0.0;
    }
}

/* ----------------------------------------------------------------------
   pair_style bbpd/KERNEL [model] MODEL [thickness h] [area A] [spacing dx] [dt/safety f]
     [contact yes|no] [contact/distance f] [bond/storage fast|compact]
     [simd auto|portable|avx2|avx512]
------------------------------------------------------------------------- */

void PairBBPD::settings(int narg, char **arg)
{
  int iarg = 0;
  if (iarg < narg && strcmp(arg[iarg], "model") == 0) iarg++;
  if (iarg >= narg)
    error->all(FLERR, "Pair style {} needs a model: 1d, plane/stress, plane/strain or 3d", style);
  const std::string m = arg[iarg++];
  if (m == "1d") model = BBPD::Model::Bar1D;
  else if (m == "plane/stress") model = BBPD::Model::PlaneStress;
  else if (m == "plane/strain") model = BBPD::Model::PlaneStrain;
  else if (m == "3d") model = BBPD::Model::Solid3D;
  else
    error->all(FLERR, "Pair style {}: unknown model '{}' (use 1d, plane/stress, plane/strain or 3d)",
               style, m);

  geom = 0.0;
  spacing_user = 0;
  dt_safety = DT_SAFETY_DEFAULT;
  contact = 0;
  contact_factor = CONTACT_FACTOR_DEFAULT;
  storage = BBPD::BondStorage::FAST;
  simd_request = BBPD::SimdPath::AUTO;
  simd_decided = false;    // a new pair_style command times its rows again
  while (iarg < narg) {
    const std::string key = arg[iarg];
    if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style " + style + " " + key, error);
    if (key == "compat")
      error->all(FLERR, "Pair style {}: 'compat pmb' is now its own style: write 'pair_style "
                 "bbpd/pmb {}' (same keywords and pair_coeff numbers)", style, m);
    if (key == "contact") {
      contact = utils::logical(FLERR, arg[iarg + 1], false, lmp);
      iarg += 2;
      continue;
    }
    if (key == "bond/storage") {
      const std::string v = arg[iarg + 1];
      if (v != "fast" && v != "compact")
        error->all(FLERR, "Pair style {}: bond/storage must be 'fast' (16 bytes per bond on a "
                   "grid, 44 on irregular ones) or 'compact' (12 bytes per bond, slower)", style);
      storage = v == "compact" ? BBPD::BondStorage::COMPACT : BBPD::BondStorage::FAST;
      iarg += 2;
      continue;
    }
    if (key == "simd") {
      if (!BBPD::path_from_name(arg[iarg + 1], simd_request))
        error->all(FLERR, "Pair style {}: simd must be auto (the fastest path this CPU runs), "
                   "portable, avx2 or avx512, got '{}'", style, arg[iarg + 1]);
      iarg += 2;
      continue;
    }
    const double value = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
    if (key == "contact/distance") {
      if (value <= 0.0 || value > 1.0)
        error->all(FLERR, "Pair style {}: contact/distance must be in (0,1] (a fraction of the "
                   "grid spacing)", style);
      contact_factor = value;
    } else if (key == "thickness" || key == "area") {
      if (model == BBPD::Model::Solid3D)
        error->all(FLERR, "Pair style {}: keyword {} does not apply to model 3d", style, key);
      if ((key == "thickness") != (BBPD::family_dimension(model) == 2))
        error->all(FLERR, "Pair style {}: keyword {} does not apply to model {} (thickness for "
                   "plane models, area for 1d)", style, key, m);
      if (value <= 0.0) error->all(FLERR, "Pair style {}: {} must be > 0", style, key);
      geom = value;
    } else if (key == "spacing") {
      if (value <= 0.0) error->all(FLERR, "Pair style {}: spacing must be > 0", style);
      spacing = value;
      spacing_user = 1;
    } else if (key == "dt/safety") {
      if (value <= 0.0 || value > 1.0)
        error->all(FLERR, "Pair style {}: dt/safety must be in (0,1]", style);
      dt_safety = value;
    } else {
      error->all(FLERR, "Unknown pair_style {} keyword: {} (expected thickness, area, spacing, "
                 "dt/safety, contact, contact/distance, bond/storage or simd)", style, key);
    }
    iarg += 2;
  }
  check_simd_request();
  if (model == BBPD::Model::Solid3D) geom = 1.0;
  else if (geom == 0.0)
    error->all(FLERR, "Pair style {} model {} needs {} (e.g. '{} 1.0')", style, m,
               model == BBPD::Model::Bar1D ? "the cross-section: area A" : "the thickness: thickness h",
               model == BBPD::Model::Bar1D ? "area" : "thickness");
}

/* ----------------------------------------------------------------------
   pair_coeff I J E Gc delta [critical_stretch s0] [alpha A] [bonds yes|no]
   pair_coeff I J FILE MATERIAL delta [critical_stretch s0] [alpha A] [bonds yes|no]
   Gc = none: elastic (bonds never break) unless critical_stretch is given
   bonds no: types I and J form no bonds (two bodies); E and delta set only their contact
------------------------------------------------------------------------- */

void PairBBPD::coeff(int narg, char **arg)
{
  if (!allocated) allocate();
  if (narg < 5 || narg > 11 || narg % 2 == 0)
    error->all(FLERR, "Pair coeff for {}: expected 'I J E Gc delta [critical_stretch s0] [alpha A] "
               "[bonds yes|no]' or 'I J file material delta [critical_stretch s0] [alpha A] "
               "[bonds yes|no]', got {} arguments", style, narg);

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);

  double E = 0.0, Gc = 0.0;
  if (utils::is_double(arg[2]) || utils::is_integer(arg[2])) {
    E = utils::numeric(FLERR, arg[2], false, lmp);
    if (strcmp(arg[3], "none") == 0) Gc = std::numeric_limits<double>::infinity();
    else Gc = utils::numeric(FLERR, arg[3], false, lmp);
  } else {
    if (comm->me == 0 && utils::get_potential_file_path(arg[2]).empty())
      error->one(FLERR, "Pair coeff for {}: '{}' is not a number (Young's modulus E) nor a "
                 "readable potential file", style, arg[2]);
    coeff_from_file(arg[2], arg[3], E, Gc);
  }
  const double delta = utils::numeric(FLERR, arg[4], false, lmp);
  double s0 = -1.0, a = 0.0;
  int with_bonds = 1;
  for (int iarg = 5; iarg + 1 < narg; iarg += 2) {
    if (strcmp(arg[iarg], "critical_stretch") == 0) {
      s0 = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (s0 <= 0.0) error->all(FLERR, "Pair coeff for {}: critical_stretch must be > 0", style);
    } else if (strcmp(arg[iarg], "alpha") == 0) {
      if (!rules.silling_askari)
        error->all(FLERR, "Pair coeff for {}: alpha is the Silling-Askari critical stretch, a "
                   "rule of pair style {}/alpha: use that style", style, style);
      a = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (a < 0.0 || !std::isfinite(a))
        error->all(FLERR, "Pair coeff for {}: alpha must be >= 0 (Silling-Askari: 0.25 is "
                   "typical, 0 turns the rule off)", style);
    } else if (strcmp(arg[iarg], "bonds") == 0) {
      with_bonds = utils::logical(FLERR, arg[iarg + 1], false, lmp);
    } else {
      error->all(FLERR, "Unknown pair_coeff {} keyword: {} (expected critical_stretch, alpha or "
                 "bonds)", style, arg[iarg]);
    }
  }
  if (!with_bonds) {
    if (s0 > 0.0 || a > 0.0)
      error->all(FLERR, "Pair coeff for {}: a type pair with 'bonds no' has no bonds to break: "
                 "drop critical_stretch and alpha", style);
    if (MAX(ilo, jlo) <= MIN(ihi, jhi))
      error->all(FLERR, "Pair coeff for {}: 'bonds no' is for two different types (e.g. "
                 "'pair_coeff 1 2 ... bonds no'); types {} {} include a type paired with itself, "
                 "and atoms of one type form one body", style, arg[0], arg[1]);
  }
  if (E <= 0.0) error->all(FLERR, "Pair coeff for {}: Young's modulus E must be > 0", style);
  if (Gc <= 0.0)
    error->all(FLERR, "Pair coeff for {}: fracture energy Gc must be > 0 (or 'none' for an "
               "elastic body)", style);
  if (delta <= 0.0) error->all(FLERR, "Pair coeff for {}: horizon delta must be > 0", style);

  int count = 0;
  for (int i = ilo; i <= ihi; i++) {
    for (int j = MAX(jlo, i); j <= jhi; j++) {
      youngs[i][j] = E;
      fracture_energy[i][j] = Gc;
      horizon[i][j] = delta;
      // c0 and s0 (unless given) are calibrated in init_style(), from the model and thickness
      // of the pair_style in force then
      micromodulus[i][j] = 0.0;
      s0_user[i][j] = s0 > 0.0;
      critical_stretch[i][j] = s0 > 0.0 ? s0 : 0.0;
      alpha[i][j] = a;
      bondless[i][j] = !with_bonds;
      setflag[i][j] = 1;
      count++;
    }
  }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients");
}

/* read E and Gc of one material from a potential file with a UNITS: header */
void PairBBPD::coeff_from_file(const char *file, const char *material, double &E, double &Gc)
{
  if (comm->me == 0) {
    PotentialFileReader reader(lmp, file, "bbpd");
    char *line;
    bool found = false;
    while ((line = reader.next_line(3))) {
      const std::string text = utils::trim(line);
      ValueTokenizer values(line);
      if (values.next_string() != material) continue;
      try {
        E = values.next_double();
        const std::string g = values.next_string();
        Gc = (g == "none") ? std::numeric_limits<double>::infinity() : std::stod(g);
      } catch (std::exception &e) {
        error->one(FLERR, "Material {} in potential file {}: E and Gc must be numbers (Gc may be "
                   "'none'), got '{}'", material, file, text);
      }
      found = true;
      break;
    }
    if (!found) error->one(FLERR, "Material {} not found in potential file {}", material, file);
  }
  MPI_Bcast(&E, 1, MPI_DOUBLE, 0, world);
  MPI_Bcast(&Gc, 1, MPI_DOUBLE, 0, world);
}

/* ---------------------------------------------------------------------- */

void PairBBPD::init_style()
{
  if (!atom->peri_flag)
    error->all(FLERR, "Pair style {} requires atom_style peri (per-atom volume and density)", style);
  if (atom->map_style == Atom::MAP_NONE)
    error->all(FLERR, "Pair style {} requires an atom map, see atom_modify", style);
  if (BBPD::family_dimension(model) == 2 && domain->dimension != 2)
    error->all(FLERR, "Pair style {} model {} requires 'dimension 2' (use model 3d for a 3D body)",
               style, BBPD::model_name(model));
  if (!storage.caches_geometry() && (domain->xperiodic || domain->yperiodic || (domain->zperiodic && domain->dimension == 3)))
    error->all(FLERR, "Pair style {}: bond/storage compact does not support periodic boundaries "
               "(reference lengths are recomputed from x0, which is not unwrapped): use "
               "bond/storage fast", style);
  if (model == BBPD::Model::Solid3D && domain->dimension != 3)
    error->all(FLERR, "Pair style {} model 3d requires 'dimension 3' (use plane/stress or "
               "plane/strain in 2D)", style);

  // grid spacing for eq. 19: the largest spacing implied by any atom's volume
  if (!spacing_user) {
    double local = 0.0;
    for (int i = 0; i < atom->nlocal; i++) local = MAX(local, BBPD::grid_spacing_of(model, geom, atom->vfrac[i]));
    MPI_Allreduce(&local, &spacing, 1, MPI_DOUBLE, MPI_MAX, world);
    if (spacing <= 0.0)
      error->all(FLERR, "Pair style {}: atoms have no volume; set it with 'set ... volume'", style);
  }
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j] && horizon[i][j] < spacing)
        error->all(FLERR, "Pair style {}: horizon {} for types {} {} is smaller than the grid "
                   "spacing {} ({}): use delta = m * spacing with m >= 1 (the paper uses m = 5)",
                   style, horizon[i][j], i, j, spacing,
                   spacing_user ? "given by the spacing keyword"
                                : "derived from the atom volumes: check 'set ... volume' and thickness/area");

  bonds = static_cast<FixBBPDBonds *>(own_fix(BONDS_FIX_ID, "bbpd/bonds"));
  watchdog = static_cast<FixBBPDWatchdog *>(own_fix(WATCHDOG_FIX_ID, "bbpd/watchdog"));
  hold_report = own_fix(HOLD_FIX_ID, "bbpd/hold");
  law.weighting = BBPD::KernelWeighting();    // a style of another family sets its own in init_rules()
  init_rules();

  calibrate();
  // the bond fix builds and caches with the bond law: the calibrated values, by value
  law.kernel = kernel;
  law.model = model;
  law.geom = geom;
  law.spacing = spacing;
  law.micromodulus = BBPD::TypePairTable(atom->ntypes, micromodulus);
  law.horizon = BBPD::TypePairTable(atom->ntypes, horizon);
  law.bondless = BBPD::TypePairTable(atom->ntypes, bondless);
  bonds->set_rules(law, storage);
  send_run_limits();
}

/* c0 and s0 of every type pair, at every init, so that a re-issued pair_style (model,
   thickness, area) applies; bbpd/pmb takes peri/pmb's c and s00 as given */
void PairBBPD::calibrate()
{
  fracture_any = 0;
  multi_s0 = 0;
  bool s0_seen = false;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++) {
      if (setflag[i][j] == 0)
        error->all(FLERR, "Pair style {}: pair_coeff for types {} {} is missing (bbpd "
                   "styles do not mix coefficients)", style, i, j);
      // e.g. from a restart file of an older version, where alpha was a keyword of every style
      if (alpha[i][j] > 0.0 && !rules.silling_askari)
        error->all(FLERR, "Pair style {}: types {} {} have a Silling-Askari alpha {}, a rule of "
                   "pair style {}/alpha: use that style", style, i, j, alpha[i][j], style);
      if (!rules.pmb_rules)
        micromodulus[i][j] = BBPD::micromodulus(kernel, model, youngs[i][j], horizon[i][j], geom);
      if (bondless[i][j])
        critical_stretch[i][j] = std::numeric_limits<double>::infinity();    // nothing to break
      else if (!s0_user[i][j])
        critical_stretch[i][j] = std::isinf(fracture_energy[i][j])
            ? std::numeric_limits<double>::infinity()
            : BBPD::critical_stretch(kernel, model, micromodulus[i][j], fracture_energy[i][j],
                                     horizon[i][j], geom);
      if (std::isfinite(critical_stretch[i][j])) fracture_any = 1;
      // a pair without bonds needs no critical stretch: it does not make the stretches differ
      if (!bondless[i][j]) {
        if (!s0_seen) s0_single = critical_stretch[i][j];
        else if (critical_stretch[i][j] != s0_single) multi_s0 = 1;
        s0_seen = true;
      }
      youngs[j][i] = youngs[i][j];
      fracture_energy[j][i] = fracture_energy[i][j];
      horizon[j][i] = horizon[i][j];
      micromodulus[j][i] = micromodulus[i][j];
      critical_stretch[j][i] = critical_stretch[i][j];
      s0_user[j][i] = s0_user[i][j];
      bondless[j][i] = bondless[i][j];
      alpha[j][i] = alpha[i][j];
    }
}

/* the internal fix 'id' of style fix_style, created if missing: the style's own */
Fix *PairBBPD::own_fix(const char *id, const char *fix_style, const std::string &args)
{
  Fix *fix = modify->get_fix_by_id(id);
  if (!fix) fix = modify->add_fix(fmt::format("{} all {} {}", id, fix_style, args));
  if (!fix || strcmp(fix->style, fix_style) != 0)
    error->all(FLERR, "Pair style {} needs its internal fix {} of style {}: do not define a fix "
               "with that ID", style, id, fix_style);
  return fix;
}

/* with the style goes the fix it created (owned: its pointer, null if never created) */
void PairBBPD::release_fix(const void *owned, const char *id)
{
  if (owned && modify->get_fix_by_id(id)) modify->delete_fix(id);
}

void PairBBPD::send_run_limits()
{
  bonds->set_limits(run_limits());
  watchdog->set_limits(run_limits());
}

/* calibrated in init_style() (LAMMPS calls init_one() for every type pair after it) */
double PairBBPD::init_one(int i, int j)
{
  return law.family_cutoff(i, j);
}

/* ----------------------------------------------------------------------
   the path of the bond loops (bbpd_path_choice.h): the chooser is handed this style's rows
   and a callable that times them, and needs nothing else of the pair style
------------------------------------------------------------------------- */

/* a forced path must run on every rank's CPU: a clear ERROR at the pair_style command */
void PairBBPD::check_simd_request()
{
  const std::string problem = BBPD::simd_request_problem(simd_request, world, comm->nprocs, style);
  if (!problem.empty()) error->all(FLERR, problem);
}

/* seconds for the row forces of rows first..last-1 on path p (results discarded) */
double PairBBPD::time_path(BBPD::SimdPath p, int first, int last)
{
  const BBPD::SimdPath kept = simd_path;
  simd_path = p;
  BBPD::CoefCache *cache = thread_coef_cache();
  double acc[7] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, sum = 0.0;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = first; i < last; i++) {
    double fi[3];
    row_force<0, 0, 0>(i, fi, nullptr, acc, cache);
    sum += fi[0];
  }
  const auto t1 = std::chrono::steady_clock::now();
  simd_path = kept;
  timing_sink = sum;    // kept, so that no loop is optimised away
  return std::chrono::duration<double>(t1 - t0).count();
}

/* the path of the bond loops and why (once per pair_style command with auto) */
void PairBBPD::choose_simd_path()
{
  if (simd_request == BBPD::SimdPath::AUTO) {
    if (simd_decided) return;
    simd_decided = true;
  }
  const BBPD::PathChoice choice = BBPD::choose_path(
      simd_request, world, comm->me, bonds->nbond, atom->nlocal,
      [this](BBPD::SimdPath p, int first, int last) { return time_path(p, first, last); });
  simd_path = choice.path;
  simd_reason = choice.reason;
}

/* ---------------------------------------------------------------------- */

void PairBBPD::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  if (!bonds || !bonds->families_built()) return;
  if (report_due) {
    report_due = 0;
    choose_simd_path();
    report();
  }
  break_margin = 0.0;
  if (fracture_any && bonds->raw_positions()) {
    // the local and the canonical bond length differ by the round-off of one periodic shift
    // per component: a few ulps of the largest coordinate (box corner + ghost cutoff, and the
    // tilts of a triclinic box, whose ghost cutoff is in box fractions)
    const double cut = MAX(comm->cutghost[0], MAX(comm->cutghost[1], comm->cutghost[2]));
    double big = 0.0;
    for (int m = 0; m < 3; m++)
      big = MAX(big, std::fabs(domain->boxlo[m]) + std::fabs(domain->boxhi[m]) + cut);
    big += std::fabs(domain->xy) + std::fabs(domain->xz) + std::fabs(domain->yz);
    break_margin = BREAK_MARGIN_ULPS * DBL_EPSILON * big;
  }
  for (int m = 0; m < 3; m++) virial_origin[m] = 0.5 * (domain->boxlo[m] + domain->boxhi[m]);
  eval_bonds();
  if (contact) compute_contact();
}

/* the bond forces and breaking of one step, with the critical stretch rule */
void PairBBPD::eval_bonds()
{
  with_row_tally([&](auto ev) {
    constexpr int EV = decltype(ev)::value;
    if (!fracture_any) eval<EV, 0, 0>();
    else if (!multi_s0) eval<EV, 1, 0>();
    else eval<EV, 1, 1>();
  });
}

/* is tag jtag an intact partner of local atom i? (asked only for atoms closer than the contact
   distance, a few per atom at most) */
bool PairBBPD::bonded(int i, tagint jtag) const
{
  const tagint *p = bonds->partner[i];
  for (int k = 0; k < bonds->npartner[i]; k++)
    if (p[k] == jtag) return true;
  return false;
}

/* the candidates of the short-range forces, searched again when the bond cache was rebuilt
   (atoms moved to other indices) or an atom has moved half the search's skin */
const double *PairBBPD::stale_close_pairs(int &nlocal, int &nall)
{
  const double *xx = atom->x[0];
  nlocal = atom->nlocal;
  nall = nlocal + atom->nghost;
  if (close_generation == bonds->cache_generation() && close_pairs.current(xx, nlocal, nall))
    return nullptr;
  close_generation = bonds->cache_generation();
  return xx;
}

void PairBBPD::nonfinite_positions_error()
{
  error->one(FLERR, "Pair style {}: non-finite atom positions at step {}: the run is unstable, "
             "reduce the timestep", force->pair_style, update->ntimestep);
}

/* repulsion between atoms closer than the contact distance that share no intact bond; each
   atom sums its own contacts and ghosts get no force */
void PairBBPD::compute_contact()
{
  double **x = atom->x;
  double **f = atom->f;
  const int *type = atom->type;
  const tagint *tag = atom->tag;
  const double *vfrac = atom->vfrac;
  const double dc = contact_factor * spacing;
  // candidates within dc and a skin that the ghost atoms cover (they reach every family cutoff)
  double cut_min = std::numeric_limits<double>::infinity();
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (setflag[i][j]) cut_min = MIN(cut_min, law.family_cutoff(i, j));
  update_close_pairs(dc, MIN(CONTACT_CANDIDATE_SKIN * spacing, cut_min - dc),
                     [dc](int, int) { return dc; });
  std::vector<std::pair<std::array<double, 4>, int>> close;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!close_pairs.may_be_close(i)) continue;
    close.clear();
    for (int m = close_pairs.first[i]; m < close_pairs.first[i + 1]; m++) {
      const int j = close_pairs.pairs[m];
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      if (rsq < dc * dc && rsq > 0.0 && !bonded(i, tag[j]))
        close.push_back({{dx, dy, dz, (double) tag[j]}, j});
    }
    // sum in the order of the offsets (exact; tags only break ties of coincident atoms): the
    // neighbour-list order depends on the domain decomposition, tags on the numbering
    std::sort(close.begin(), close.end());
    for (const auto &c : close) {
      const int j = c.second;
      const double dx = x[i][0] - x[j][0], dy = x[i][1] - x[j][1], dz = x[i][2] - x[j][2];
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz);
      const int itype = type[i], jtype = type[j];
      const double k = CONTACT_STIFFNESS_FACTOR * micromodulus[itype][jtype] * vfrac[j] / horizon[itype][jtype];
      const double fpair = k * (dc - r) / r;
      f[i][0] += fpair * dx;
      f[i][1] += fpair * dy;
      f[i][2] += fpair * dz;
      if (evflag) tally_short_range(i, 0.25 * k * (dc - r) * (dc - r), fpair, dx, dy, dz);
    }
  }
}

/* energy e and virial of the short-range force fpair (dx, dy, dz) on local atom i: each end of
   the pair tallies half */
void PairBBPD::tally_short_range(int i, double e, double fpair, double dx, double dy, double dz)
{
  if (eflag_global) eng_vdwl += e;
  if (eflag_atom) eatom[i] += e;
  const double v[6] = {0.5 * fpair * dx * dx, 0.5 * fpair * dy * dy, 0.5 * fpair * dz * dz,
                       0.5 * fpair * dx * dy, 0.5 * fpair * dx * dz, 0.5 * fpair * dy * dz};
  for (int m = 0; m < 6; m++) {
    if (vflag_global) virial[m] += v[m];
    if (vflag_atom) vatom[i][m] += v[m];
  }
}

/* the rows of the critical-stretch rule (eq. 24): a bond breaks once its stretch passes s0,
   one for every type pair or (MULTI) per type pair, and exerts no force from then on; without
   FRACTURE nothing breaks */
template <int EVFLAG, int FRACTURE, int MULTI> void PairBBPD::eval()
{
  struct Row {
    PairBBPD &p;
    int i;
    double *acc;
    BBPD::CoefCache *cache;
    const double *s0row;    // MULTI: the critical stretches of atom i's type with each type
    bool sum_and_check(double *fi) { return p.row_force<EVFLAG, FRACTURE, MULTI>(i, fi, s0row, acc, cache); }
    bool breaks(int k)
    {
      const int j = p.bonds->partner_of(i, k);
      const double s0 = MULTI ? s0row[p.atom->type[j]] : p.s0_single;
      if (!p.past_critical(i, j, p.bonds->xi0_of(i, k), s0)) return false;
      p.book_broken_bond(i, k, s0);
      return true;
    }
    void sum(double *fi) { p.row_force<EVFLAG, 0, MULTI>(i, fi, s0row, acc, cache); }
    void finish(double *) {}
  };
  const int *type = atom->type;
  if (MULTI) refresh_row_s0();
  eval_rows<EVFLAG>([&](int i, double *acc, BBPD::CoefCache *cache) BBPD_ROW_BODY {
    return Row{*this, i, acc, cache, MULTI ? critical_stretch[type[i]] : nullptr};
  });
}

/* ----------------------------------------------------------------------
   the bond loop of one row, shared by eval() and the loops of derived styles:
   dispatch to the SIMD or portable kernel of bbpd_row.h over the rows of fix
   bbpd/bonds, the energy and virial tallies, adding a row's force, the breaking
   test both ends of a bond agree on, and the diagnosis of a non-finite force
------------------------------------------------------------------------- */

/* explain a non-finite force on atom i and stop */
void PairBBPD::nonfinite_error(int i)
{
  const double *xx = atom->x[0];
  const tagint *tag = atom->tag;
  const std::string cause = fmt::format(
      "timestep {:.6g} vs stable bound {:.6g}: reduce the timestep, or check the input for "
      "atoms placed on top of each other", update->dt, dt_bound);
  for (int m = 0; m < 3; m++)
    if (!std::isfinite(xx[3 * i + m]))
      error->one(FLERR, "Atom {} has a non-finite position at step {} (the run became unstable; {})",
                 tag[i], update->ntimestep, cause);
  for (int k = bonds->bond_start[i]; k < bonds->bond_start[i] + bonds->nbond[i]; k++) {
    const int j = bonds->partner_of(i, k);
    const double dx = xx[3 * j] - xx[3 * i], dy = xx[3 * j + 1] - xx[3 * i + 1],
                 dz = xx[3 * j + 2] - xx[3 * i + 2];
    const double rsq = dx * dx + dy * dy + dz * dz;
    if (!std::isfinite(rsq))
      error->one(FLERR, "Bond partner {} of atom {} has a non-finite position at step {} (the run "
                 "became unstable; {})", tag[j], tag[i], update->ntimestep, cause);
    if (rsq == 0.0)
      error->one(FLERR, "Atoms {} and {} coincide at step {}: a bond of zero length has no "
                 "direction ({})", tag[i], tag[j], update->ntimestep, cause);
  }
  error->one(FLERR, "Non-finite force on atom {} at step {} ({})", tag[i], update->ntimestep, cause);
}

/* compact storage: a cache per thread of the coefficients (bbpd_bond_values.h), taken once per
   thread and force evaluation (a thread-local variable of a plugin costs a call at every access) */
BBPD::CoefCache *PairBBPD::thread_coef_cache()
{
  static thread_local BBPD::CoefCache cache;
  return &cache;
}

/* Force density on atom i from its intact bonds (eq. 21). The sum runs in
   LANES fixed partial sums (bond k goes to lane k % LANES) combined in a fixed
   order, in the SIMD (AVX-512, AVX2) and portable paths alike: the result depends
   only on the row, never on the domain decomposition or on whether energy is
   tallied. With FRACTURE it returns true, and tallies nothing, if a bond of the
   row is past its critical stretch. */
template <int EVFLAG, int FRACTURE, int MULTI>
bool PairBBPD::row_force(int i, double *fi, const double *s0row, double *acc,
                         BBPD::CoefCache *cache)
{
  const double *xx = atom->x[0];
  const int *type = atom->type;
  const int n = bonds->nbond[i];
  double ax[LANES] = {0.0}, ay[LANES] = {0.0}, az[LANES] = {0.0};
  RowTally lanes;    // energy and virial in the same lanes in every kernel (filled with EVFLAG)
  // the row in whatever layout the storage keeps it (FixBBPDBonds::visit_row)
  const bool broken = bonds->visit_row(i, *cache, [&](const auto *bj, const auto &vals) {
    auto portable = [&] {
      auto xi0_of = [&](int k) { return vals.xi0_at(k, BBPD::partner_index(bj, i, k)); };
      auto coef_of = [&](int k, double) { return vals.coef_at(k, BBPD::partner_index(bj, i, k)); };
      auto s0_of = [&](int j) { return MULTI ? s0row[type[j]] : s0_single; };
      if (EVFLAG) lanes = {};    // the portable loop adds to the lanes, the SIMD kernels store them
      return BBPD::row_force_portable<FRACTURE, EVFLAG, BondModel>(
          xx, i, bj, n, xi0_of, coef_of, s0_of, break_margin, ax, ay, az, &lanes);
    };
    // the SIMD kernels take one critical stretch: a row whose bonds have several runs portable
    const double s0 = MULTI ? row_s0[i] : s0_single;
    if (MULTI && std::isnan(s0)) return portable();
    return BBPD::on_path(simd_path, [&](auto path) {
      return decltype(path)::template row_force<FRACTURE, EVFLAG, BondModel>(
          xx, i, bj, vals, n, s0, break_margin, ax, ay, az, &lanes);
    }, portable);
  });
  if (broken) return true;
  lane_sum(ax, ay, az, fi);
  if (EVFLAG) tally_lanes(i, lanes, acc, BBPD::tallies_virial(EVFLAG));
  return false;
}

/* energy and virial of the row of atom i: per atom where LAMMPS asked for them, and the
   global totals into acc (energy, then the six virial components) */
void PairBBPD::tally_lanes(int i, const RowTally &lanes, double *acc, bool virial)
{
  const double eng = lane_total(lanes.eng);
  acc[0] += eng;
  if (eflag_atom) eatom[i] += eng;
  if (!virial) return;
  double vir[6];
  for (int c = 0; c < 6; c++) vir[c] = lane_total(lanes.vir[c]);
  for (int m = 0; m < 6; m++) {
    acc[1 + m] += vir[m];
    if (vflag_atom) vatom[i][m] += vir[m];
  }
}

/* What the rows tally this step. The virial sum_bonds 1/2 (x_i - x_j) (x) f_ij (each end's row
   tallies its half) is also sum_i x_i (x) f_i over the rows' forces f_i, summed over the ranks,
   when the two rows of every bond give it opposite forces and see its ends where they are: no
   periodic boundary (a ghost image is its owner shifted by a box vector), and atoms of one type
   and one volume on every rank (the bond-based families and the LPS are then antisymmetric,
   f_ij = -f_ji). A ghost's position is its owner's, so the bonds between ranks count as the
   others do, once every rank takes the rows' forces: the choice is made for all ranks at once.
   The rows then tally each bond's energy only: the six products per bond and their sums were
   15 % of a step of the bbpd/lps and bbpd/pmb cylinders, whose fix indent asks for the virial
   at every step. */
int PairBBPD::row_tally() const
{
  if (!evflag) return BBPD::TALLY_NONE;
  if (vflag_atom) return BBPD::TALLY_ENERGY_VIRIAL;
  if (!vflag_global) return BBPD::TALLY_ENERGY;
  if (domain->xperiodic || domain->yperiodic || domain->zperiodic || rules.own_end_history)
    return BBPD::TALLY_ENERGY_VIRIAL;
  // the smallest and (negated) largest type and volume of the atoms, over the ranks
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  const double *vfrac = atom->vfrac;
  const double inf = std::numeric_limits<double>::infinity();
  double lo[4] = {inf, inf, inf, inf};
  for (int i = 0; i < nlocal; i++) {
    lo[0] = std::min(lo[0], (double) type[i]);
    lo[1] = std::min(lo[1], -(double) type[i]);
    lo[2] = std::min(lo[2], vfrac[i]);
    lo[3] = std::min(lo[3], -vfrac[i]);
  }
  if (comm->nprocs > 1) {
    double all[4];
    MPI_Allreduce(lo, all, 4, MPI_DOUBLE, MPI_MIN, world);
    std::copy(all, all + 4, lo);
  }
  const bool uniform = lo[0] == -lo[1] && lo[2] == -lo[3];
  return uniform ? BBPD::TALLY_ENERGY : BBPD::TALLY_ENERGY_VIRIAL;
}

/* the critical stretch of each row's bonds, where they share one (types are fixed during a
   run; a row only loses bonds, so one that shares keeps sharing until the cache is rebuilt) */
void PairBBPD::refresh_row_s0()
{
  if (row_s0_generation == bonds->cache_generation()) return;
  row_s0_generation = bonds->cache_generation();
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  row_s0.assign(nlocal, std::numeric_limits<double>::quiet_NaN());
  for (int i = 0; i < nlocal; i++) {
    const double *s0row = critical_stretch[type[i]];
    const int beg = bonds->bond_start[i], n = bonds->nbond[i];
    const double s0 = n ? s0row[type[bonds->partner_of(i, beg)]] : s0row[type[i]];
    bool shared = true;
    for (int k = beg + 1; k < beg + n && shared; k++) shared = s0row[type[bonds->partner_of(i, k)]] == s0;
    if (shared) row_s0[i] = s0;
  }
}

/* a row's force into f; the lowest atom with a non-finite force is kept for finish_eval()
   (three compares per atom turn the first NaN/inf into an ERROR that names its cause) */
void PairBBPD::add_row_force(int i, const double *fi, int &bad)
{
  if (!std::isfinite(fi[0]) || !std::isfinite(fi[1]) || !std::isfinite(fi[2])) {
#if defined(_OPENMP)
#pragma omp critical(bbpd_nonfinite)
#endif
    if (bad < 0 || i < bad) bad = i;
  }
  double *fi_atom = atom->f[i];
  fi_atom[0] += fi[0];
  fi_atom[1] += fi[1];
  fi_atom[2] += fi[2];
}

/* a thread's energy and virial sums (acc) into the loop's totals, one thread at a time */
void PairBBPD::add_thread_totals(double *totals, const double *acc)
{
#if defined(_OPENMP)
#pragma omp critical(bbpd_totals)
#endif
  for (int m = 0; m < 7; m++) totals[m] += acc[m];
}

/* after the loop over rows: the ERROR of a non-finite force, then the global tallies */
void PairBBPD::finish_eval(int bad, bool evflag_on, const double *totals)
{
  if (bad >= 0) nonfinite_error(bad);
  if (evflag_on) {
    if (eflag_global) eng_vdwl += totals[0];
    if (vflag_global)
      for (int m = 0; m < 6; m++) virial[m] += totals[1 + m];
  }
}

/* is bond i-j past its critical stretch? Decided from breaking_length(), the same at both ends */
bool PairBBPD::past_critical(int i, int j, double xi0, double s0) const
{
  return BondModel::past_critical(BondModel::elongation(breaking_length(i, j), xi0), xi0, s0, 0.0);
}

/* atom i's share of the energy that bond k carries away as it breaks at the critical stretch s0
   (bbpd_bond_model.h), times the atom's volume: a density times a volume, an energy */
void PairBBPD::book_broken_bond(int i, int k, double s0)
{
  const double xi0 = bonds->xi0_of(i, k);
  bonds->ebroken[i] += BondModel::broken_energy_share(bonds->coef_of(i, k, xi0), xi0, s0) * atom->vfrac[i];
}

/* the current length of bond i-j from which breaking is decided: in a periodic box from the
   minimum-image difference of the owners' unshifted positions, identical at both ends (the
   ghost image x +- L rounds differently at the two ends, and one end could break a bond the
   other keeps) */
double PairBBPD::breaking_length(int i, int j) const
{
  const double *xi = atom->x[i];
  const double *xj = bonds->raw_positions() ? bonds->raw_x(j) : atom->x[j];
  double d[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
  if (bonds->raw_positions()) BBPDCompat::minimum_image(domain, d);
  return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
}

// the plain loop (eval) and the Silling-Askari loop (pair_bbpd_silling_askari.cpp) sum rows
// with these
template bool PairBBPD::row_force<0, 0, 0>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<1, 0, 0>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<0, 1, 0>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<1, 1, 0>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<0, 0, 1>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<1, 0, 1>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<0, 1, 1>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);
template bool PairBBPD::row_force<1, 1, 1>(int, double *, const double *, double *,
                                           BBPD::CoefCache *);

double PairBBPD::memory_usage()
{
  const int n = atom->ntypes + 1;
  return Pair::memory_usage() + 6.0 * n * n * sizeof(double) + 2.0 * n * n * sizeof(int);
}

/* extract: "dt_bound" (velocity-Verlet stable step), "dt_bound_paper" (eq. 25) */
void *PairBBPD::extract(const char *name, int &dim)
{
  dim = 0;
  if (strcmp(name, "dt_bound") == 0) return (void *) &dt_bound;
  if (strcmp(name, "dt_bound_paper") == 0) return (void *) &dt_bound_paper;
  dim = 2;
  if (strcmp(name, "micromodulus") == 0) return (void *) micromodulus;
  if (strcmp(name, "critical_stretch") == 0) return (void *) critical_stretch;
  if (strcmp(name, "horizon") == 0) return (void *) horizon;
  return nullptr;
}

/* ---------------------------------------------------------------------- */

double PairBBPD::youngs_modulus(int itype) const
{
  // c0 is linear in E: E = c0 / c0(E = 1)
  return micromodulus[itype][itype] /
      BBPD::micromodulus(kernel, model, 1.0, horizon[itype][itype], geom);
}

double PairBBPD::poisson_ratio(int) const
{
  return BBPD::implied_poisson_ratio(model);
}

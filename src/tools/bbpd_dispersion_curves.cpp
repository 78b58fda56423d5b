// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   bbpd-dispersion-curves: dispersion of a 1D BBPD bar for each kernel, the
   data of Figs. 4-6 of Bouaraquia & Mabssout (2026), k from 0 to pi/dx.

   usage: bbpd-dispersion-curves --m 5 --delta 1e-3 [--E 1] [--rho 1]
            [--dt DT] [--volume-correction] [--points 201] --out DIR

   Writes DIR/dispersion_<kernel>.csv, '#' header lines then one row per k:
     k, k dx, omega continuous (eq. 29), omega discrete (eq. 31),
     phase and group velocities / v for both, and with --dt the discrete
     relation after central differences / velocity Verlet (NaN if unstable).
------------------------------------------------------------------------- */

#include "bbpd_dispersion.h"

#include "bbpd_cli.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

using namespace BBPD;

namespace {

struct Options {
  double m = 5.0;           // paper Figs. 4-6
  double delta = 1.0e-3;    // 1 mm, paper Figs. 4-6
  double E = 1.0;
  double rho = 1.0;
  double dt = 0.0;          // 0: no time discretisation
  bool volume_correction = false;
  int points = 201;
  std::string out;
};

void usage(std::ostream &os)
{
  os << "usage: bbpd-dispersion-curves --m M --delta DELTA [--E E] [--rho RHO] [--dt DT]\n"
        "         [--volume-correction] [--points N] --out DIR\n";
}

[[noreturn]] void fail(const std::string &msg)
{
  usage(std::cerr);
  cli::fail(msg);
}

using cli::to_double;

Options parse(int argc, char **argv)
{
  Options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      usage(std::cout);
      std::exit(0);
    }
    if (a == "--volume-correction") {
      opt.volume_correction = true;
      continue;
    }
    if (i + 1 >= argc) fail("missing value after " + a);
    const char *val = argv[++i];
    if (a == "--m") opt.m = to_double(a, val);
    else if (a == "--delta") opt.delta = to_double(a, val);
    else if (a == "--E") opt.E = to_double(a, val);
    else if (a == "--rho") opt.rho = to_double(a, val);
    else if (a == "--dt") opt.dt = to_double(a, val);
    else if (a == "--points") opt.points = static_cast<int>(to_double(a, val));
    else if (a == "--out") opt.out = val;
    else fail("unknown option " + a);
  }
  if (opt.out.empty()) fail("--out DIR is required");
  if (!(opt.m >= 1.0)) fail("--m must be at least 1");
  if (!(opt.delta > 0.0 && opt.E > 0.0 && opt.rho > 0.0)) fail("--delta, --E, --rho must be > 0");
  if (!(opt.dt >= 0.0)) fail("--dt must be >= 0");
  if (opt.points < 2) fail("--points must be at least 2");
  return opt;
}

void write_kernel(const Options &opt, const KernelInfo &kernel, const std::string &path)
{
  DispersionBar bar{kernel, opt.m, opt.delta};
  bar.E = opt.E;
  bar.rho = opt.rho;
  bar.volume_correction = opt.volume_correction;
  const double dx = bar.dx();
  const double v = bar.wave_speed();

  std::ofstream os(path);
  if (!os) fail("cannot write " + path);
  os.precision(12);
  os << "# bbpd-dispersion-curves: 1D bar, kernel " << kernel.name << "\n"
     << "# m " << opt.m << " delta " << opt.delta << " dx " << dx << " E " << opt.E << " rho "
     << opt.rho << " v " << v << " c0*A " << bar.bond_constant() << "\n"
     << "# volume_correction " << (opt.volume_correction ? 1 : 0) << " dt " << opt.dt << "\n"
     << "# velocities are divided by v = sqrt(E/rho); omega in rad per time unit\n"
     << "k,k_dx,omega_continuous,omega_discrete,phase_continuous,phase_discrete,"
        "group_continuous,group_discrete";
  if (opt.dt > 0.0) os << ",omega_discrete_dt,phase_discrete_dt,group_discrete_dt";
  os << "\n";

  for (int i = 0; i < opt.points; ++i) {
    const double k = PI / dx * i / (opt.points - 1);
    const DispersionPoint c = dispersion_continuous(bar, k);
    const DispersionPoint d = dispersion_discrete(bar, k);
    os << k << ',' << k * dx << ',' << c.omega << ',' << d.omega << ',' << c.phase_velocity / v
       << ',' << d.phase_velocity / v << ',' << c.group_velocity / v << ','
       << d.group_velocity / v;
    if (opt.dt > 0.0) {
      const DispersionPoint t = time_discrete(d, k, opt.dt);
      os << ',' << t.omega << ',' << t.phase_velocity / v << ',' << t.group_velocity / v;
    }
    os << '\n';
  }
}

}    // namespace

int main(int argc, char **argv)
{
  cli::program = "bbpd-dispersion-curves";
  const Options opt = parse(argc, argv);
  std::error_code ec;
  std::filesystem::create_directories(opt.out, ec);
  if (ec) fail("cannot create " + opt.out + ": " + ec.message());

  for (const char *name : {ConstantKernel::name, TriangularKernel::name, GaussianKernel::name}) {
    const std::string path = opt.out + "/dispersion_" + name + ".csv";
    write_kernel(opt, kernel_by_name(name), path);
    std::cout << "wrote " << path << "\n";
  }
  return 0;
}

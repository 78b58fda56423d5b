// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   bbpd-measure-dispersion: measured dispersion relation omega(k) of a 1D
   field u(x,t) sampled on a uniform grid (x_i = i dx, t_n = n dt_s), e.g. the
   displacements of a periodic BBPD bar dumped by LAMMPS.

   usage: bbpd-measure-dispersion --dx DX --sample-dt DT [--column NAME]
            [--window hann|none] [--pad P] --out FILE.csv INPUT

   INPUT is either
     a LAMMPS text dump ('dump custom'): one snapshot per sample, the atom's
       grid index from the 'id' column (id = i + 1) if present, else from the
       line order; the value from column NAME (default: the last column);
       the TIMESTEP values must be equally spaced;
     or a plain matrix: one sample per line, nx values per line, '#' comments.

   Method: the time series is multiplied by a window, zero-padded to P times
   its length, and transformed in x and t with one 2-D real FFT (FFTW). For a
   real field the power at (k, omega) equals that at (-k, -omega), so for each
   k >= 0 the powers at +omega (waves running to -x) and -omega (to +x) are
   added. The ridge omega(k) is the frequency of maximum power, refined by a
   parabola through the log power of the peak bin and its two neighbours
   (exact for a Gaussian-shaped peak, close to it for the Hann window).

   Writes one CSV row per k = 2 pi n/(nx dx), n = 1..nx/2:
     k, k dx, omega (rad per time unit), power of the ridge relative to the
     largest ridge power; '#' lines give the grid and the bin widths.
------------------------------------------------------------------------- */

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include "bbpd_cli.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr double PI = 3.14159265358979323846;

struct Options {
  double dx = 0.0;           // grid spacing
  double sample_dt = 0.0;    // time between two samples
  std::string column;        // dump column, empty: the last one
  std::string window = "hann";
  int pad = 4;               // zero-padding factor in time: finer bins, smaller interpolation bias
  std::string out;
  std::string input;
};

// u(x_i, t_n) stored row by row: u[n * nx + i]
struct Field {
  int nx = 0;
  int nt = 0;
  std::vector<double> u;
};

void usage(std::ostream &os)
{
  os << "usage: bbpd-measure-dispersion --dx DX --sample-dt DT [--column NAME]\n"
        "         [--window hann|none] [--pad P] --out FILE.csv INPUT\n";
}

using BBPD::cli::fail;
using BBPD::cli::to_double;

Options parse(int argc, char **argv)
{
  Options opt;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help") {
      usage(std::cout);
      std::exit(0);
    }
    if (a.rfind("--", 0) != 0) {
      if (!opt.input.empty()) fail("more than one input file: " + opt.input + ", " + a);
      opt.input = a;
      continue;
    }
    if (i + 1 >= argc) fail("missing value after " + a);
    const char *val = argv[++i];
    if (a == "--dx") opt.dx = to_double(a, val);
    else if (a == "--sample-dt") opt.sample_dt = to_double(a, val);
    else if (a == "--column") opt.column = val;
    else if (a == "--window") opt.window = val;
    else if (a == "--pad") opt.pad = static_cast<int>(to_double(a, val));
    else if (a == "--out") opt.out = val;
    else fail("unknown option " + a);
  }
  if (opt.input.empty() || opt.out.empty()) {
    usage(std::cerr);
    fail("an INPUT file and --out FILE are required");
  }
  if (!(opt.dx > 0.0)) fail("--dx must be > 0 (the grid spacing)");
  if (!(opt.sample_dt > 0.0)) fail("--sample-dt must be > 0 (the time between two samples)");
  if (opt.window != "hann" && opt.window != "none") fail("--window must be hann or none");
  if (opt.pad < 1) fail("--pad must be at least 1");
  return opt;
}

/* ---------------------------------------------------------------------- */
// input

std::vector<double> numbers(const std::string &line)
{
  std::istringstream is(line);
  std::vector<double> v;
  double x;
  while (is >> x) v.push_back(x);
  if (!is.eof()) fail("not a number in line '" + line + "'");
  return v;
}

std::vector<std::string> words(const std::string &line)
{
  std::istringstream is(line);
  std::vector<std::string> w;
  std::string s;
  while (is >> s) w.push_back(s);
  return w;
}

std::string next_line(std::istream &is, const std::string &what)
{
  std::string line;
  if (!std::getline(is, line)) fail("dump ends inside a snapshot (" + what + ")");
  return line;
}

// one snapshot after its 'ITEM: TIMESTEP' line; returns the timestep
long read_snapshot(std::istream &is, const Options &opt, Field &f)
{
  const long step = std::stol(next_line(is, "timestep"));
  if (next_line(is, "atom count").rfind("ITEM: NUMBER OF ATOMS", 0) != 0)
    fail("expected 'ITEM: NUMBER OF ATOMS' after the timestep: is this a 'dump custom' file?");
  const int n = std::stoi(next_line(is, "atom count"));
  if (f.nt == 0) f.nx = n;
  else if (n != f.nx) fail("snapshot at step " + std::to_string(step) + " has " +
                           std::to_string(n) + " atoms, the first had " + std::to_string(f.nx));
  std::string line = next_line(is, "box");
  while (line.rfind("ITEM: ATOMS", 0) != 0) line = next_line(is, "box");
  const std::vector<std::string> item = words(line);    // ITEM: ATOMS col1 col2 ...
  const std::vector<std::string> cols(item.begin() + 2, item.end());
  int col = static_cast<int>(cols.size()) - 1, idcol = -1;
  for (int c = 0; c < static_cast<int>(cols.size()); ++c) {
    if (cols[c] == "id") idcol = c;
    if (!opt.column.empty() && cols[c] == opt.column) col = c;
  }
  if (!opt.column.empty() && cols[col] != opt.column)
    fail("dump has no column '" + opt.column + "' (columns: " + line.substr(12) + ")");

  f.u.resize(f.u.size() + f.nx, std::nan(""));
  double *row = f.u.data() + static_cast<size_t>(f.nt) * f.nx;
  for (int a = 0; a < n; ++a) {
    const std::vector<double> v = numbers(next_line(is, "atoms"));
    if (v.size() != cols.size()) fail("atom line with " + std::to_string(v.size()) + " values");
    const long i = idcol >= 0 ? std::lround(v[idcol]) - 1 : a;
    if (i < 0 || i >= n) fail("atom id " + std::to_string(i + 1) + " outside 1.." +
                              std::to_string(n) + ": ids must number the grid points");
    row[i] = v[col];
  }
  for (int i = 0; i < n; ++i)
    if (std::isnan(row[i])) fail("atom id " + std::to_string(i + 1) + " missing at step " +
                                 std::to_string(step));
  f.nt++;
  return step;
}

Field read_field(const Options &opt)
{
  std::ifstream is(opt.input);
  if (!is) fail("cannot read " + opt.input);
  Field f;
  std::string line;
  std::vector<long> steps;
  while (std::getline(is, line)) {
    if (line.rfind("ITEM: TIMESTEP", 0) == 0) {
      steps.push_back(read_snapshot(is, opt, f));
      continue;
    }
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.erase(hash);
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (!steps.empty()) fail("plain data line in a LAMMPS dump: '" + line + "'");
    const std::vector<double> v = numbers(line);
    if (f.nt == 0) f.nx = static_cast<int>(v.size());
    else if (static_cast<int>(v.size()) != f.nx)
      fail("line " + std::to_string(f.nt + 1) + " has " + std::to_string(v.size()) +
           " values, the first had " + std::to_string(f.nx));
    f.u.insert(f.u.end(), v.begin(), v.end());
    f.nt++;
  }
  for (size_t s = 2; s < steps.size(); ++s)
    if (steps[s] - steps[s - 1] != steps[1] - steps[0])
      fail("dump timesteps are not equally spaced (" + std::to_string(steps[s - 1]) + ", " +
           std::to_string(steps[s]) + ")");
  if (f.nx < 4 || f.nt < 8)
    fail("need at least 4 grid points and 8 samples, got " + std::to_string(f.nx) + " x " +
         std::to_string(f.nt));
  return f;
}

/* ---------------------------------------------------------------------- */
// spectrum and ridge

struct RidgePoint {
  double omega;
  double power;
};

// vertex of the parabola through (-1, a), (0, b), (1, c): offset and value
void parabola_peak(double a, double b, double c, double &offset, double &value)
{
  const double curv = a - 2.0 * b + c;
  offset = curv < 0.0 ? 0.5 * (a - c) / curv : 0.0;
  value = b - 0.25 * (a - c) * offset;
}

std::vector<RidgePoint> ridge(const Field &f, const Options &opt, double &domega)
{
  const int nx = f.nx, ntp = f.nt * opt.pad, nkx = nx / 2 + 1;
  double *in = fftw_alloc_real(static_cast<size_t>(ntp) * nx);
  fftw_complex *out = fftw_alloc_complex(static_cast<size_t>(ntp) * nkx);
  if (!in || !out) fail("out of memory for a " + std::to_string(ntp) + " x " +
                        std::to_string(nx) + " transform: reduce --pad or the samples");
  fftw_plan plan = fftw_plan_dft_r2c_2d(ntp, nx, in, out, FFTW_ESTIMATE);

  std::fill(in, in + static_cast<size_t>(ntp) * nx, 0.0);
  for (int n = 0; n < f.nt; ++n) {
    // periodic Hann: sidelobes fall as 1/omega^3, so the -omega image and distant k leak little
    const double w = opt.window == "hann" ? 0.5 - 0.5 * std::cos(2.0 * PI * n / f.nt) : 1.0;
    const size_t row = static_cast<size_t>(n) * nx;
    for (int i = 0; i < nx; ++i) in[row + i] = w * f.u[row + i];
  }
  fftw_execute(plan);

  auto power = [&](int q, int n) {
    const fftw_complex &z = out[static_cast<size_t>(q) * nkx + n];
    return z[0] * z[0] + z[1] * z[1];
  };
  const int nq = ntp / 2;    // omega bins 0..nq after folding +-omega
  std::vector<double> p(nq + 1);
  std::vector<RidgePoint> r;
  for (int n = 1; n <= nx / 2; ++n) {
    for (int q = 0; q <= nq; ++q)
      p[q] = power(q, n) + (q > 0 && q < ntp - q ? power(ntp - q, n) : 0.0);
    // omega = 0 is never a wave of k > 0; the peak needs a neighbour on both sides
    const int qmax = static_cast<int>(std::max_element(p.begin() + 1, p.begin() + nq) - p.begin());
    double offset = 0.0, logp = std::log(p[qmax]);
    if (p[qmax - 1] > 0.0 && p[qmax + 1] > 0.0)
      parabola_peak(std::log(p[qmax - 1]), logp, std::log(p[qmax + 1]), offset, logp);
    r.push_back({qmax + offset, std::exp(logp)});
  }
  fftw_destroy_plan(plan);
  fftw_free(in);
  fftw_free(out);

  domega = 2.0 * PI / (ntp * opt.sample_dt);
  for (RidgePoint &pt : r) pt.omega *= domega;
  return r;
}

}    // namespace

int main(int argc, char **argv)
{
  BBPD::cli::program = "bbpd-measure-dispersion";
  const Options opt = parse(argc, argv);
  const Field field = read_field(opt);
  double domega = 0.0;
  const std::vector<RidgePoint> r = ridge(field, opt, domega);

  double pmax = 0.0;
  for (const RidgePoint &pt : r) pmax = std::max(pmax, pt.power);
  const double dk = 2.0 * PI / (field.nx * opt.dx);

  std::ofstream os(opt.out);
  if (!os) fail("cannot write " + opt.out);
  os.precision(12);
  os << "# bbpd-measure-dispersion: " << opt.input << "\n"
     << "# nx " << field.nx << " nt " << field.nt << " dx " << opt.dx << " sample_dt "
     << opt.sample_dt << " window " << opt.window << " pad " << opt.pad << "\n"
     << "# dk " << dk << " omega bin " << domega << " (unpadded " << domega * opt.pad
     << ") omega Nyquist " << PI / opt.sample_dt << "\n"
     << "# power: ridge power / largest ridge power " << pmax << "\n"
     << "k,k_dx,omega,power\n";
  for (size_t n = 0; n < r.size(); ++n) {
    const double k = dk * (n + 1);
    os << k << ',' << k * opt.dx << ',' << r[n].omega << ',' << r[n].power / pmax << '\n';
  }
  std::cout << "wrote " << opt.out << " (" << r.size() << " wave numbers, " << field.nt
            << " samples)\n";
  return 0;
}

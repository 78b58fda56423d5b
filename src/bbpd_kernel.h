// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: kernel-weighted bond-based peridynamics for LAMMPS.

   Kernel math with no LAMMPS dependency: kernel shapes W(xi,delta), the
   micromodulus constant c0 and the critical stretch s0 calibrated from E and
   G_c (Bouaraquia & Mabssout 2026, Table 1 and eqs. 14-16, extended here to
   plane strain and 3D), the partial-volume correction (eq. 19) and the stable
   time step (eq. 25).

   A kernel is one small struct with
     name         style suffix, e.g. "gaussian"
     shape(r)     W as a function of r = |xi|/delta, >= 0; also evaluated a little past
                  r = 1 for the partial-volume bonds (eq. 19)
     moment(n)    M_n = int_0^1 W(r) r^n dr, n = 1..4 (closed form)
------------------------------------------------------------------------- */

#ifndef BBPD_KERNEL_H
#define BBPD_KERNEL_H

#include <cmath>
#include <stdexcept>
#include <string>

namespace BBPD {

constexpr double PI = 3.14159265358979323846;

// W = 1 (classical PMB, eq. 10)
struct ConstantKernel {
  static constexpr const char *name = "constant";
  static double shape(double) { return 1.0; }
  static double moment(int n) { return 1.0 / (n + 1); }
};

// W = 1 - |xi|/delta, and 0 beyond the horizon (eq. 11: W >= 0). The partial-volume bonds
// with delta < xi < delta + dx/2 would otherwise get a negative stiffness.
struct TriangularKernel {
  static constexpr const char *name = "triangular";
  static double shape(double r) { return r < 1.0 ? 1.0 - r : 0.0; }
  static double moment(int n) { return 1.0 / ((n + 1.0) * (n + 2.0)); }
};

// W = exp(-(2 xi/delta)^2)
struct GaussianKernel {
  static constexpr const char *name = "gaussian";
  static constexpr double a = 4.0;    // exponent: W = exp(-a r^2), a = 2^2
  static double shape(double r) { return std::exp(-a * r * r); }
  // M_n = -e^-a/(2a) + (n-1)/(2a) M_{n-2}, from integration by parts
  static double moment(int n)
  {
    if (n == 0) return 0.5 * std::sqrt(PI / a) * std::erf(std::sqrt(a));
    if (n == 1) return (1.0 - std::exp(-a)) / (2.0 * a);
    return -std::exp(-a) / (2.0 * a) + (n - 1) / (2.0 * a) * moment(n - 2);
  }
};

// Runtime description of a kernel, for code that chooses the kernel by name.
struct KernelInfo {
  const char *name;
  double (*shape)(double);
  double (*moment)(int);
};

template <class K> constexpr KernelInfo kernel_info() { return {K::name, &K::shape, &K::moment}; }

inline KernelInfo kernel_by_name(const std::string &name)
{
  if (name == ConstantKernel::name) return kernel_info<ConstantKernel>();
  if (name == TriangularKernel::name) return kernel_info<TriangularKernel>();
  if (name == GaussianKernel::name) return kernel_info<GaussianKernel>();
  throw std::invalid_argument("unknown BBPD kernel '" + name + "'");
}

enum class Model { Bar1D, PlaneStress, PlaneStrain, Solid3D };

inline const char *model_name(Model m)
{
  switch (m) {
    case Model::Bar1D: return "1d";
    case Model::PlaneStress: return "plane/stress";
    case Model::PlaneStrain: return "plane/strain";
    default: return "3d";
  }
}

// Poisson's ratio fixed by bond-based PD for each model (Silling 2000; Madenci & Oterkus 2014)
inline double implied_poisson_ratio(Model m)
{
  switch (m) {
    case Model::PlaneStress: return 1.0 / 3.0;
    case Model::PlaneStrain:
    case Model::Solid3D: return 0.25;
    default: return 0.0;
  }
}

// Spatial dimension of the bond family integral (1, 2 or 3)
inline int family_dimension(Model m)
{
  return m == Model::Bar1D ? 1 : (m == Model::Solid3D ? 3 : 2);
}

/* Micromodulus constant c0 from strain-energy equivalence under isotropic
   expansion (eq. 12 = eq. 13 and its 1D/plane-strain/3D analogues):
     1D            c0 = E / (A delta^2 M1)
     plane stress  c0 = 3 E / (pi h delta^3 M2)        (nu = 1/3)
     plane strain  c0 = 16 E / (5 pi h delta^3 M2)     (nu = 1/4)
     3D            c0 = 3 E / (pi delta^4 M3)          (nu = 1/4)
   geom is the cross-section A (1D), the thickness h (2D), ignored in 3D. */
inline double micromodulus(const KernelInfo &k, Model m, double E, double delta, double geom = 1.0)
{
  switch (m) {
    case Model::Bar1D: return E / (geom * delta * delta * k.moment(1));
    case Model::PlaneStress: return 3.0 * E / (PI * geom * std::pow(delta, 3) * k.moment(2));
    case Model::PlaneStrain:
      return 16.0 * E / (5.0 * PI * geom * std::pow(delta, 3) * k.moment(2));
    default: return 3.0 * E / (PI * std::pow(delta, 4) * k.moment(3));
  }
}

/* Critical stretch from the fracture energy: G_c equals the work to break
   every bond crossing a unit area of a plane (Silling & Askari 2005):
     1D    G_c = A c0 s0^2 delta^3 M2 / 2
     2D    G_c = h c0 s0^2 delta^4 M3              (eqs. 14-16)
     3D    G_c = pi c0 s0^2 delta^5 M4 / 2 */
inline double critical_stretch(const KernelInfo &k, Model m, double c0, double Gc, double delta,
                               double geom = 1.0)
{
  switch (m) {
    case Model::Bar1D: return std::sqrt(2.0 * Gc / (geom * c0 * std::pow(delta, 3) * k.moment(2)));
    case Model::PlaneStress:
    case Model::PlaneStrain:
      return std::sqrt(Gc / (geom * c0 * std::pow(delta, 4) * k.moment(3)));
    default: return std::sqrt(2.0 * Gc / (PI * c0 * std::pow(delta, 5) * k.moment(4)));
  }
}

/* Partial-volume correction C_v of eq. 19: the fraction of a cell of width dx
   centred at distance xi that lies inside the horizon. */
inline double partial_volume(double xi, double delta, double dx)
{
  if (xi <= delta - 0.5 * dx) return 1.0;
  if (xi >= delta + 0.5 * dx) return 0.0;
  return (delta + 0.5 * dx - xi) / dx;
}

/* Stable time step from sum_j V_j c(xi_ij)/|xi_ij| (eq. 26) at one atom:
   eq. 25 as printed, and Silling & Askari's bound with the factor 2, which is
   the von Neumann limit of central differences (velocity Verlet). */
inline double stable_timestep_paper(double rho, double sum_vc) { return std::sqrt(rho / sum_vc); }
inline double stable_timestep_silling(double rho, double sum_vc)
{
  return std::sqrt(2.0 * rho / sum_vc);
}

}    // namespace BBPD

#endif

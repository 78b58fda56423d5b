// SPDX-License-Identifier: GPL-2.0-or-later
/* Shared helpers for the BBPD unit tests. */

#ifndef BBPD_TEST_UTIL_H
#define BBPD_TEST_UTIL_H

#include "bbpd_kernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace BBPD::test {

// relative agreement |a - b| <= tol |b|
inline ::testing::AssertionResult rel_near(double a, double b, double tol)
{
  const double err = std::fabs(a - b) / std::fabs(b);
  if (err <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b << ": relative error " << err
                                       << " > " << tol;
}

inline std::vector<std::string> kernel_names()
{
  return {ConstantKernel::name, TriangularKernel::name, GaussianKernel::name};
}

inline std::vector<Model> all_models()
{
  return {Model::Bar1D, Model::PlaneStress, Model::PlaneStrain, Model::Solid3D};
}

// gtest-safe suffix: "plane/stress" -> "plane_stress"
inline std::string test_label(const std::string &s)
{
  std::string out = s;
  for (char &c : out)
    if (c == '/') c = '_';
  return out;
}

// The material and geometry of the kernel and calibration tests, deliberately not 1 so that a
// wrong power of delta shows
namespace material {
constexpr double E = 3.7;
constexpr double DELTA = 0.8;
constexpr double A = 0.6;     // bar cross-section
constexpr double H = 0.35;    // plate thickness
constexpr double GC = 2.3;
}    // namespace material

}    // namespace BBPD::test

#endif

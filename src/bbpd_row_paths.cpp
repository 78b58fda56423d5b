// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD: which paths of the bond loops this plugin holds and this CPU runs (bbpd_row_paths.h).
------------------------------------------------------------------------- */

#include "bbpd_row_paths.h"

#include <cstdlib>
#include <sstream>

namespace BBPD {

static constexpr const char *PATH_NAMES[] = {"portable", "avx2", "avx512", "auto"};
// a test hook: paths named here count as unsupported, as on a CPU without them (it can only
// take paths away; doc/pair_bbpd.rst)
static constexpr const char *HIDE_VARIABLE = "BBPD_SIMD_HIDE";

const char *path_name(SimdPath p)
{
  return PATH_NAMES[static_cast<int>(p)];
}

bool path_from_name(const std::string &name, SimdPath &p)
{
  for (int k = 0; k <= NPATHS; k++)
    if (name == PATH_NAMES[k]) {
      p = static_cast<SimdPath>(k);
      return true;
    }
  return false;
}

bool path_built(SimdPath p)
{
  switch (p) {
    case SimdPath::PORTABLE:
      return true;
#ifdef BBPD_HAVE_AVX2
    case SimdPath::AVX2:
      return true;
#endif
#ifdef BBPD_HAVE_AVX512
    case SimdPath::AVX512:
      return true;
#endif
    default:
      return false;
  }
}

const char *path_needs(SimdPath p)
{
  switch (p) {
    case SimdPath::AVX2:
      return "AVX2 and FMA";
    case SimdPath::AVX512:
      return "AVX-512 F, VL, BW and DQ (and AVX2, FMA)";
    default:
      return "nothing beyond x86-64";
  }
}

bool path_hidden(SimdPath p)
{
  const char *list = std::getenv(HIDE_VARIABLE);
  if (!list) return false;
  std::stringstream items(list);
  std::string item;
  while (std::getline(items, item, ','))
    if (item == path_name(p)) return true;
  return false;
}

// the CPU's features, as the compiler's runtime library reads them (cpuid and xgetbv: the
// operating system saves the wide registers)
static bool cpu_runs(SimdPath p)
{
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();
  const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  switch (p) {
    case SimdPath::AVX2:
      return avx2;
    case SimdPath::AVX512:
      return avx2 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
          __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq");
    default:
      return p == SimdPath::PORTABLE;
  }
#else
  return p == SimdPath::PORTABLE;
#endif
}

bool path_supported(SimdPath p)
{
  if (p == SimdPath::PORTABLE) return true;
  return path_built(p) && cpu_runs(p) && !path_hidden(p);
}

}    // namespace BBPD

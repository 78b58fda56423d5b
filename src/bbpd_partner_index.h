// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: how a bond end names its partner atom in the force loop.

   LAMMPS keeps atoms spatially sorted, so the local index of a bond partner is close to the
   atom's own: a 2-byte signed offset j - i reaches every partner as long as a horizon spans
   fewer than 32,768 atoms in memory order (a 3D grid of up to about 90 x 90 atoms per plane at
   4.5 spacings per horizon). A rank whose partners all lie within that reach stores offsets
   (2 bytes per bond end, less to stream each step); otherwise it stores the indices themselves
   (4 bytes). The partner is the same atom either way, so the forces are the same bits. No
   LAMMPS dependency.
------------------------------------------------------------------------- */

#ifndef BBPD_PARTNER_INDEX_H
#define BBPD_PARTNER_INDEX_H

#include <cstdint>
#include <limits>

namespace BBPD {

using PartnerOffset = std::int16_t;

// can bond partner j of atom i be stored as an offset?
inline bool fits_offset(int i, int j)
{
  const long d = static_cast<long>(j) - i;
  return d >= std::numeric_limits<PartnerOffset>::min() && d <= std::numeric_limits<PartnerOffset>::max();
}

// local index of partner k of atom i, from indices or offsets
inline int partner_index(const int *bj, int, int k)
{
  return bj[k];
}
inline int partner_index(const PartnerOffset *bj, int i, int k)
{
  return i + bj[k];
}

/* the index bj[k] counts from: partner k is row_origin(bj, i) + bj[k]. The SIMD rows offset
   their arrays by it once per row, so a partner's address is one sign extension and one scaled
   add from the entry (no 32-bit sum to widen per partner) */
inline int row_origin(const int *, int) { return 0; }
inline int row_origin(const PartnerOffset *, int i) { return i; }

}    // namespace BBPD

#endif

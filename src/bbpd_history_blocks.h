// SPDX-License-Identifier: GPL-2.0-or-later
/* -*- c++ -*- ----------------------------------------------------------
   BBPD: where a bond end's history lies in its atom's row of fix bbpd/history
   (fix_bbpd_history.h), with no LAMMPS dependency. B doubles per bond end (a family's
   BOND_HISTORY, bbpd_ves.h, bbpd_eps.h), in blocks of HISTORY_BLOCK slots: value v of slots
   4g .. 4g+3 side by side, then value v + 1 of the same slots, i.e. value v of slot m at
     HISTORY_BLOCK (B floor(m / HISTORY_BLOCK) + v) + m mod HISTORY_BLOCK.
   A row that lost no partner (dense_slots, bbpd_lps_history_lanes.h) so reads and writes a
   value of 4 consecutive bonds with one 4-wide load or store. With the pairs side by side
   (the layout of restart files, history_to_pairs) each value took two shuffles each way: the
   AVX2 VES kernel ran 256 instructions per 8 bonds on the bpm/peri deck (callgrind), 235 with
   blocks. A row holds whole blocks: at most HISTORY_BLOCK - 1 slots more than its bonds.
------------------------------------------------------------------------- */

#ifndef BBPD_HISTORY_BLOCKS_H
#define BBPD_HISTORY_BLOCKS_H

namespace BBPD {

constexpr int HISTORY_BLOCK = 4;    // slots per block: the AVX2 kernels' group of bonds

// the place of value v of slot m (m >= 0), b values per slot
constexpr int history_offset(int b, int m, int v)
{
  return HISTORY_BLOCK * (b * (m / HISTORY_BLOCK) + v) + m % HISTORY_BLOCK;
}
template <int B> constexpr int history_offset(int m, int v)
{
  return history_offset(B, m, v);
}

// value v of slot m of a row's bond history hist
template <int B> inline double &history_value(double *hist, int m, int v)
{
  return hist[history_offset<B>(m, v)];
}

// the doubles of the blocks holding slots 0 .. nslots - 1, b values per slot
constexpr int history_length(int b, int nslots)
{
  return b * HISTORY_BLOCK * ((nslots + HISTORY_BLOCK - 1) / HISTORY_BLOCK);
}

// nslots slots of b values from pairs side by side (value v of slot m at b m + v) into blocks
// (history_length(b, nslots) doubles; the slots past nslots zero)
inline void history_from_pairs(int b, int nslots, const double *pairs, double *blocks)
{
  const int len = history_length(b, nslots);
  for (int x = 0; x < len; x++) blocks[x] = 0.0;
  for (int m = 0; m < nslots; m++)
    for (int v = 0; v < b; v++)
      blocks[history_offset(b, m, v)] = pairs[b * m + v];
}

// the blocks' nslots slots as pairs side by side (b nslots doubles)
inline void history_to_pairs(int b, int nslots, const double *blocks, double *pairs)
{
  for (int m = 0; m < nslots; m++)
    for (int v = 0; v < b; v++)
      pairs[b * m + v] = blocks[history_offset(b, m, v)];
}

}    // namespace BBPD

#endif

// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD: the AVX-512 path of the bond loops (bbpd_row_paths.h). CMakeLists.txt compiles this
   file alone with -mavx512f -mavx512vl -mavx512bw -mavx512dq -mavx2 -mfma (and
   -ffp-contract=off: no fused multiply-adds, the bits of the portable loop); the pair styles
   call it only where the CPU has all of them.
------------------------------------------------------------------------- */

#if !defined(__AVX512F__) || !defined(__AVX512VL__) || !defined(__AVX512BW__)
#error "bbpd_row_avx512.cpp must be compiled with -mavx512f -mavx512vl -mavx512bw -mavx512dq"
#endif

#define BBPD_ROW_PATH Avx512Path
#include "bbpd_row_path_kernels.h"

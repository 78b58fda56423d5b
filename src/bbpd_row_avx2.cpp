// SPDX-License-Identifier: GPL-2.0-or-later
/* ----------------------------------------------------------------------
   BBPD: the AVX2 path of the bond loops (bbpd_row_paths.h). CMakeLists.txt compiles this file
   alone with -mavx2 -mfma -mno-avx512f (and -ffp-contract=off: no fused multiply-adds, the
   bits of the portable loop); the pair styles call it only where the CPU has AVX2 and FMA.
------------------------------------------------------------------------- */

#if !defined(__AVX2__) || defined(__AVX512F__)
#error "bbpd_row_avx2.cpp must be compiled with -mavx2 -mfma -mno-avx512f"
#endif

#define BBPD_ROW_PATH Avx2Path
#include "bbpd_row_path_kernels.h"

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Constants of the MCADSW algorithm and architecture (docs/algorithm.md).
//
// This header is the single source of truth for every number shared by the C++
// reference and the RTL. The RTL parameter package is checked against it by a
// test (or generated from it); nothing here is typed twice.
#pragma once

#include <array>
#include <cstdint>

namespace mcadsw {

// ---- Mini-census transform (paper Sec. III-B, Fig. 2) ---------------------
// Six neighbours in a 5x5 window around the centre. Bit (kCensusBits-1-i) of
// the code is neighbour i, so the code reads in raster order, MSB first.
struct Offset {
  int dx;
  int dy;
};
inline constexpr int kCensusBits = 6;
inline constexpr std::array<Offset, kCensusBits> kCensusTaps = {{
    {0, -2},   // bit 5
    {-2, -1},  // bit 4
    {+2, -1},  // bit 3
    {-2, +1},  // bit 2
    {+2, +1},  // bit 1
    {0, +2},   // bit 0
}};
inline constexpr int kCensusRadius = 2;  // 5x5 template

// ---- Support window (paper Sec. III-D, 31x31) ------------------------------
inline constexpr int kWindow = 31;
inline constexpr int kRadius = kWindow / 2;  // 15: k, j in -15..15

// ---- Weights (paper Sec. III-C, Fig. 5) ------------------------------------
inline constexpr int kWeightShiftMax = 6;                  // w in {64,32,...,1,0}
inline constexpr int kWeightMax = 1 << kWeightShiftMax;    // 64
inline constexpr int kColorDistMax = 3 * 255;              // |dY|+|dU|+|dV|
inline constexpr int kWeightTableSize = kColorDistMax + 1;  // 766 entries
// Weight buffers and the RTL hold a weight as a 3-bit code: 0 -> 0, e -> 2^(e-1),
// so the multiply by a weight is a shift (paper Sec. III-C).
inline constexpr int kWeightCodeBits = 3;
constexpr int weight_code(int w) {
  int e = 0;
  while (w > 0) { w >>= 1; ++e; }
  return e;
}
constexpr int weight_from_code(int e) { return e == 0 ? 0 : 1 << (e - 1); }
static_assert(weight_code(kWeightMax) < (1 << kWeightCodeBits), "64 needs code 7");
inline constexpr int kColorDistBits = 10;  // 0..765
// The engine holds a (non-increasing) table as the colour distances at which
// the weight code drops: code(dC) = 7 - #{i : dC >= threshold[i]}.
inline constexpr int kWeightThresholds = (1 << kWeightCodeBits) - 1;  // 7
static_assert((1 << kColorDistBits) > kColorDistMax);
inline constexpr int kDefaultGamma = 22;  // chosen by the sweep of scripts/eval_pairs.sh, docs/algorithm.md

// ---- Architecture (paper Sec. V) -------------------------------------------
// Largest disparity range D (d = 0..D-1): a build parameter (CMake MCADSW_DMAX,
// `make sim-build DMAX=<n>`), 64 by default (the paper's); at most 128.
#ifndef MCADSW_DMAX
#define MCADSW_DMAX 64
#endif
inline constexpr int kDmax = MCADSW_DMAX;
inline constexpr int kDmaxDefault = 64;  // the configuration of rtl/mcadsw_pkg.sv and the budgets
static_assert(kDmax >= 1 && kDmax <= 128, "MCADSW_DMAX must be 1..128");
// Disparities the engine evaluates a step (CMake MCADSW_PAR, `make sim-build
// PAR=<p>`): 1 (the paper's), 2 or 4. The RTL only; the disparities are the same.
#ifndef MCADSW_PAR
#define MCADSW_PAR 1
#endif
inline constexpr int kPar = MCADSW_PAR;
static_assert(kPar == 1 || kPar == 2 || kPar == 4, "MCADSW_PAR must be 1, 2 or 4");
static_assert(kDmax % kPar == 0, "MCADSW_DMAX must be a multiple of MCADSW_PAR");
inline constexpr int kBlock = 18;     // output block is kBlock x kBlock
inline constexpr int kLanes = 8;      // columns aggregated per cycle (Fig. 14)
inline constexpr int kHorzAggregators = 3;  // horizontal aggregators fed 33 Ev (Fig. 12)
// Columns of vertical costs per block row: 18 outputs + 30 window columns = 48
// (the paper's 31x48 window), processed 8 a cycle in 6 cycles.
inline constexpr int kBlockCols = kBlock + 2 * kRadius;
inline constexpr int kGroups = kBlockCols / kLanes;  // 6
static_assert(kBlockCols % kLanes == 0, "48 columns split into 8-lane groups");
static_assert(kBlock % kHorzAggregators == 0, "18 outputs split over 3 aggregators");
static_assert(kBlock / kHorzAggregators == kGroups,
              "horizontal side keeps pace with the vertical side: 6 cycles per disparity");
inline constexpr int kMaxWidth = 2048;
inline constexpr int kMaxHeight = 2048;
// Build target of the RTL (CMake MCADSW_FPGA, `make sim FPGA=1`; docs/blocks/fpga_target.md):
// 0 the ASIC, 1 an FPGA (block-RAM shapes). The RTL only; the values are the same.
#ifndef MCADSW_FPGA
#define MCADSW_FPGA 0
#endif
inline constexpr bool kFpga = MCADSW_FPGA != 0;
// The rectifier in the RTL (CMake MCADSW_RECT, `make sim RECT=0`; docs/blocks/fpga_target.md,
// "Without the rectifier"): 1 built in, 0 left out (a smaller engine that rejects RECT_CTRL.ENABLE, code 24).
#ifndef MCADSW_RECT
#define MCADSW_RECT 1
#endif
inline constexpr bool kRect = MCADSW_RECT != 0;

// ---- Exact integer widths ----------------------------------------------------
// Each bound is the largest value the quantity can take; the bit widths follow.
constexpr int bits_for(long long max_value) {
  int b = 0;
  while ((1LL << b) <= max_value) ++b;
  return b;
}
inline constexpr long long kCostMax = kCensusBits;                          // 6
inline constexpr long long kVertCostMax = kWindow * kCostMax * kWeightMax;  // 11904
inline constexpr long long kFinalCostMax = kWindow * kVertCostMax * kWeightMax;  // 23617536
inline constexpr int kCostBits = bits_for(kCostMax);            // 3
inline constexpr int kWeightBits = bits_for(kWeightMax);        // 7
inline constexpr int kVertCostBits = bits_for(kVertCostMax);    // 14
inline constexpr int kFinalCostBits = bits_for(kFinalCostMax);  // 25
inline constexpr int kDispBits = bits_for(kDmax - 1);           // 6
static_assert(kVertCostBits <= 16, "vertical costs are held in uint16_t");
static_assert(kFinalCostBits <= 32, "final costs are held in uint32_t");

// ---- Post-processing beyond the paper (docs/algorithm.md section 12) ---------
inline constexpr int kLrToleranceMax = 63;     // T of the left-right check: 0..63
inline constexpr int kLrToleranceDefault = 1;
inline constexpr int kSubpixelScale = 16;      // sub-pixel value = 16 d + offset (OpenCV's scale)
inline constexpr int kSubpixelOffsetMax = kSubpixelScale / 2;  // |offset| <= 8 (section 12.6)
// The LR mode's post-processing stage keeps rows of the maps on chip: its buffers
// are sized for this width (docs/blocks/post.md); wider frames are a
// configuration error in the LR mode only.
inline constexpr int kPostMaxWidth = 1024;
static_assert(kPostMaxWidth <= kMaxWidth && (kPostMaxWidth & (kPostMaxWidth - 1)) == 0,
              "the post stage's row buffers: a power of two, at most the largest width");

// ---- Rectification (docs/algorithm.md section 13) -------------------
inline constexpr int kMeshFracBits = 5;          // node and sample positions in 1/32 pixel
inline constexpr int kMeshStepLog2Min = 3;       // S = 8 ..
inline constexpr int kMeshStepLog2Max = 5;       // .. 32
inline constexpr int kMeshCoordLimit = 4096 << kMeshFracBits;  // nodes in [-limit, limit)
inline constexpr int kRectInvalidY = 0;          // an invalid rectified pixel: black
inline constexpr int kRectInvalidUV = 128;
// The rectifier's tiles and tile buffers (docs/blocks/rectifier.md).
inline constexpr int kRectTileW = 32;            // output tile 32 x 16 pixels
inline constexpr int kRectTileH = 16;
inline constexpr int kRectBufW = 64;             // a tile's source rectangle: at most 64 x 32
inline constexpr int kRectBufH = 32;
inline constexpr int kRectInvalidDisp16 = 0xFFFF;  // the depth of an invalid base pixel (13.4)
inline constexpr int kRectInvalidDisp8 = 255;
// The LR mode's scratch maps at invalid pixels after rectification (docs/algorithm.md
// 13.4, docs/blocks/rectifier.md 1): dR holds kRectInvalidDisp8 (|dL - 255| > T), dL a
// flag the post stage's check fails: bit 7 of a byte, bit 15 of a scratch halfword.
inline constexpr int kRectFlagDisp8 = 0x80;
inline constexpr int kRectFlagDisp16 = 0x8000;
static_assert(kSubpixelScale * (kDmax - 1) + kSubpixelOffsetMax < kRectInvalidDisp16 && kDmax - 1 < kRectInvalidDisp8,
              "the invalid codes lie above every disparity");

}  // namespace mcadsw

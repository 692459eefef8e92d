// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The register map's read-write bits, as docs/registers.md and
// sw_ref/include/mcadsw/regs.hpp give them: the register block's test
// (rtl_regs_test) and the whole SoC's (rtl_axi_test) check against it.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "mcadsw/regs.hpp"

namespace mcadsw::test {

inline uint32_t low_bits(int width) { return width >= 32 ? ~0u : (1u << width) - 1; }

// The bits each read-write register keeps (the rest read 0), by offset.
inline std::map<uint32_t, uint32_t> writable_bits() {
  using namespace regs;
  std::map<uint32_t, uint32_t> m;
  for (uint32_t o = kBaseLy; o <= kBaseMask; o += 4) m[o] = ~0u;
  m[kStride] = m[kOutStride] = m[kTileStride] = ~0u;
  m[kSize] = (low_bits(kSizeBits) << kSizeWidthLsb) | (low_bits(kSizeBits) << kSizeHeightLsb);
  m[kDisp] = low_bits(kDispBitsReg);
  m[kLrT] = low_bits(kLrTBits);
  for (int i = 0; i < kWeightThresholds; ++i) m[kThr0 + 4 * uint32_t(i)] = low_bits(kThrBits);
  m[kIrqEnable] = (1u << kIrqDoneLsb) | (1u << kIrqErrorLsb);
  m[kCtrl] = low_bits(kCtrlModeWidth) << kCtrlModeLsb;
  // Rectification (register map 1.2)
  m[kRectCtrl] = (1u << kRectEnableLsb) | (low_bits(kRectStepWidth) << kRectStepLsb);
  m[kRawSize] = m[kSize];
  m[kRawStride] = ~0u;
  for (uint32_t o = kRawLy; o < kMeshL; o += 4) m[o] = ~0u;
  m[kMeshL] = m[kMeshR] = ~0u;
  m[kMeshNodes] = (low_bits(kSizeBits) << kMeshNxLsb) | (low_bits(kSizeBits) << kMeshNyLsb);
  m[kValidL] = m[kValidR] = ~0u;
  return m;
}

// The offsets that must answer SLVERR (reads 0, writes dropped): every word slot
// of the window not in the map, and a sample of the misaligned offsets.
inline std::vector<uint32_t> unmapped_offsets() {
  using namespace regs;
  std::vector<bool> mapped(kSpan / 4, false);
  for (const Reg& r : kRegs) mapped[r.offset / 4] = true;
  std::vector<uint32_t> offs;
  for (uint32_t off = 0; off < kSpan; ++off) {
    if (off % 4 == 0 && mapped[off / 4]) continue;
    if (off % 4 != 0 && off % 7 != 1) continue;
    offs.push_back(off);
  }
  return offs;
}

}  // namespace mcadsw::test

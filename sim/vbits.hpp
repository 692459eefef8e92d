// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Bit-field access to Verilator ports of any width (CData..QData and VlWide),
// for the flattened array ports of the RTL (the port tables of docs/blocks/).
#pragma once

#include <verilated.h>

#include <cstdint>

namespace mcadsw::sim {

template <typename Port>
inline void set_bits(Port& port, int lsb, int width, uint64_t value) {
  if constexpr (sizeof(Port) <= sizeof(uint64_t)) {
    const uint64_t mask = (width >= 64 ? ~0ULL : ((1ULL << width) - 1)) << lsb;
    port = Port((uint64_t(port) & ~mask) | ((value << lsb) & mask));
  } else {
    for (int b = 0; b < width; ++b) {
      const int bit = lsb + b;
      const uint32_t m = 1u << (bit % 32);
      if ((value >> b) & 1) port[bit / 32] |= m;
      else port[bit / 32] &= ~m;
    }
  }
}

template <typename Port>
inline uint64_t get_bits(const Port& port, int lsb, int width) {
  if constexpr (sizeof(Port) <= sizeof(uint64_t)) {
    return (uint64_t(port) >> lsb) & (width >= 64 ? ~0ULL : ((1ULL << width) - 1));
  } else {
    uint64_t v = 0;
    for (int b = 0; b < width; ++b) {
      const int bit = lsb + b;
      v |= uint64_t((port[bit / 32] >> (bit % 32)) & 1) << b;
    }
    return v;
  }
}

}  // namespace mcadsw::sim

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Helpers shared by the rectifier's block benches.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "mcadsw/rectify.hpp"
#include "random_mesh.hpp"
#include "verilated.h"

namespace mcadsw::sim {

// Sets `bits` bits of a wide Verilator signal from bit `lsb` on.
template <size_t N>
void set_bits(VlWide<N>& w, int lsb, int bits, uint32_t v) {
  for (int b = 0; b < bits; ++b) {
    const int i = lsb + b;
    const uint32_t bit = (v >> b) & 1u;
    w[size_t(i / 32)] = (w[size_t(i / 32)] & ~(1u << (i % 32))) | (bit << (i % 32));
  }
}
template <size_t N>
uint32_t get_bits(const VlWide<N>& w, int lsb, int bits) {
  uint32_t v = 0;
  for (int b = 0; b < bits; ++b) v |= ((w[size_t((lsb + b) / 32)] >> ((lsb + b) % 32)) & 1u) << b;
  return v;
}

}  // namespace mcadsw::sim

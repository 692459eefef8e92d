// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Helpers shared by the RTL block benches.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "mcadsw/params.hpp"
#include "mcadsw/win_geom.hpp"  // floor_div4
#include "verilated.h"

namespace mcadsw::sim {

// The window row (0 .. WINDOW-1) of lane tap t (0 .. WINDOW-1) for block row `row`:
// tap t itself on the ASIC target; on the FPGA target the census buffer's folded
// order (mcadsw_census): column row t + WINDOW when t < row, row t otherwise.
inline int window_tap(int t, int row) {
  if (!kFpga) return t;
  return t < row ? t + kWindow - row : t - row;
}

// Flip-flops without a reset start at random values (the models are verilated with
// --x-initial unique) in the models constructed after this call: a block that reads
// such a register before writing it then fails its bench.
inline void random_initial_values(int seed) {
  Verilated::threadContextp()->randSeed(seed);
  Verilated::threadContextp()->randReset(2);
}

template <typename V>
void tick(V& t) {
  t.clk_i = 0;
  t.eval();
  t.clk_i = 1;
  t.eval();
}

struct StreamResult {
  size_t consumed = 0;   // words accepted
  int done_pulses = 0;
  long cycles = 0;       // until done and not busy
};

// Streams `words` into a block's pix_valid_i/pix_ready_o/pix_data_i input,
// withholding valid with probability `stall` each cycle (valid never depends
// on ready), until the block pulses done_o and drops busy_o, or `limit` cycles.
template <typename V>
StreamResult stream_words(V& t, const std::vector<uint32_t>& words, double stall,
                          std::mt19937& rng, long limit) {
  StreamResult r;
  for (; r.cycles < limit; ++r.cycles) {
    const bool offer = r.consumed < words.size() && !std::bernoulli_distribution(stall)(rng);
    t.pix_valid_i = offer;
    if (offer) t.pix_data_i = words[r.consumed];
    t.clk_i = 0;
    t.eval();
    if (offer && t.pix_ready_o) ++r.consumed;
    r.done_pulses += t.done_o;
    if (r.done_pulses && !t.busy_o) break;
    t.clk_i = 1;
    t.eval();
  }
  t.pix_valid_i = 0;
  return r;
}

// Partial column reuse (docs/blocks/engine.md 4): the first strip a window
// reader delivers when a block continues its left neighbour, whose input
// window started `block` columns earlier. A window of `strips` strips starts at
// the aligned word at or left of its first input column `xin`; the strips both
// windows hold are already in the block's input buffer.
inline int first_strip(int xin, bool cont, int strips, int block = 18) {
  if (!cont) return 0;
  return strips - (floor_div4(xin) - floor_div4(xin - block));
}

}  // namespace mcadsw::sim

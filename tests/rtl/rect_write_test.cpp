// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_rect_write (docs/blocks/rectifier.md 6): random tiles (sizes 1..32 x 1..16),
// raster and column-tiled addressing, random pixels and validity bits streamed in strip
// order with random gaps, random write grants. Every pixel byte must be written once at
// its address and no other byte; each validity word once, with the tile's bits.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Vrect_write.h"
#include "rtl_bench.hpp"

namespace mcadsw {
namespace {

std::string run_tile(Vrect_write& t, std::mt19937& rng, long& words, long& cycles) {
  const int tw = 1 + int(rng() % 32), th = 1 + int(rng() % 16);
  const bool tiled = rng() % 2, ven = rng() % 3 != 0;
  const uint32_t top = 4u * (rng() % 100000), vtop = 0x40000000u + 4u * (rng() % 1000);
  const uint32_t step_row = tiled ? 4u : 4u * (10 + rng() % 500), step_strip = tiled ? 4u * (16 + rng() % 600) : 4u;
  const uint32_t vstep = 4u * (2 + rng() % 256);
  std::vector<uint8_t> pix(size_t(tw * th)), ok(size_t(tw * th));
  for (size_t i = 0; i < pix.size(); ++i) {
    pix[i] = uint8_t(rng());
    ok[i] = rng() % 4 != 0;
  }
  std::vector<std::pair<int, int>> order;
  for (int k = 0; 4 * k < tw; ++k)
    for (int y = 0; y < th; ++y)
      for (int x = 4 * k; x < std::min(4 * k + 4, tw); ++x) order.push_back({x, y});
  t.top_i = top;
  t.step_row_i = step_row;
  t.step_strip_i = step_strip;
  t.tile_w_i = uint32_t(tw);
  t.tile_h_i = uint32_t(th);
  t.valid_en_i = ven;
  t.vtop_i = vtop;
  t.vstep_strip_i = vstep;
  t.start_i = 1;
  t.pix_valid_i = 0;
  sim::tick(t);
  t.start_i = 0;
  std::map<uint32_t, uint8_t> mem;  // byte address -> value
  std::map<uint32_t, int> writes;   // byte address -> times written
  size_t sent = 0;
  int dones = 0;
  const double gnt = rng() % 2 ? 1.0 : 0.5;
  long cyc = 0;
  for (; cyc < 5000; ++cyc) {
    const bool offer = sent < order.size() && rng() % 4 != 0;
    if (offer) {
      const auto [x, y] = order[sent];
      t.pix_valid_i = 1;
      t.pix_i = pix[size_t(y * tw + x)];
      t.pix_ok_i = ok[size_t(y * tw + x)];
      t.pix_x_i = uint32_t(x);
      t.pix_y_i = uint32_t(y);
      t.pix_last_i = sent + 1 == order.size();
    } else {
      t.pix_valid_i = 0;
    }
    t.wr_gnt_i = t.wr_req_o && std::bernoulli_distribution(gnt)(rng);
    t.clk_i = 0;
    t.eval();
    if (offer && t.ready_o) ++sent;
    if (t.wr_req_o && t.wr_gnt_i) {
      if (t.wr_addr_o % 4) return "unaligned write";
      for (int b = 0; b < 4; ++b)
        if ((t.wr_be_o >> b) & 1) {
          mem[t.wr_addr_o + uint32_t(b)] = uint8_t(t.wr_data_o >> (8 * b));
          ++writes[t.wr_addr_o + uint32_t(b)];
        }
      ++words;
    }
    t.clk_i = 1;
    t.eval();
    dones += t.done_o;
    if (sent == order.size() && t.idle_o && dones) break;
  }
  t.pix_valid_i = 0;
  std::ostringstream e;
  e << (tiled ? "tiled" : "raster") << " tile " << tw << "x" << th << (ven ? " with validity" : "") << ": ";
  if (dones != 1) return e.str() + std::to_string(dones) + " done pulses";
  size_t expected = 0;
  for (int y = 0; y < th; ++y)
    for (int x = 0; x < tw; ++x) {
      const uint32_t a = top + uint32_t(x / 4) * step_strip + uint32_t(y) * step_row + uint32_t(x % 4);
      ++expected;
      if (writes[a] != 1 || mem[a] != pix[size_t(y * tw + x)]) {
        e << "pixel (" << x << "," << y << ") at " << a << ": written " << writes[a] << " times, value "
          << int(mem[a]) << ", expected " << int(pix[size_t(y * tw + x)]);
        return e.str();
      }
    }
  if (ven) {
    for (int k = 0; 4 * k < tw; ++k)
      for (int g = 0; 8 * g < th; ++g) {
        const uint32_t a = vtop + uint32_t(k) * vstep + 4u * uint32_t(g);
        uint32_t want = 0, got = 0;
        for (int yy = 0; yy < 8; ++yy)
          for (int xx = 0; xx < 4; ++xx) {
            const int x = 4 * k + xx, y = 8 * g + yy;
            if (x < tw && y < th && ok[size_t(y * tw + x)]) want |= 1u << (4 * yy + xx);
          }
        for (int b = 0; b < 4; ++b) {
          if (writes[a + uint32_t(b)] != 1) return e.str() + "validity word written " + std::to_string(writes[a]) + " times";
          got |= uint32_t(mem[a + uint32_t(b)]) << (8 * b);
        }
        expected += 4;
        if (got != want) {
          e << "validity word of strip " << k << ", rows " << 8 * g << "..: " << std::hex << got << ", expected "
            << want;
          return e.str();
        }
      }
  }
  size_t total = 0;
  for (const auto& [a, n] : writes) total += size_t(n);
  if (total != expected) return e.str() + std::to_string(total) + " bytes written, " + std::to_string(expected) + " expected";
  cycles += cyc;
  return "";
}

TEST(RectWrite, WordsAndValidityLandOnce) {
  sim::random_initial_values(4);
  Vrect_write t;
  t.rst_ni = 0;
  sim::tick(t);
  t.rst_ni = 1;
  std::mt19937 rng(3206);
  long words = 0, cycles = 0;
  for (int n = 0; n < 500; ++n) ASSERT_EQ(run_tile(t, rng, words, cycles), "") << "tile " << n;
  std::printf("500 tiles, %ld words written\n", words);
}

}  // namespace
}  // namespace mcadsw

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_rect_load (docs/blocks/rectifier.md 5): random source rectangles of raster and
// column-tiled planes (random bases, strides, rectangles up to 64 x 32, some across 4 KiB
// boundaries), a memory with random grants and latency. Every pixel of the rectangle
// must land in its bank word and byte; every word of the rectangle must be read once
// and no other; bursts of at most 8 words within a 4 KiB page.
#include <gtest/gtest.h>

#include <cstdio>
#include <deque>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "Vrect_load.h"
#include "mcadsw/params.hpp"
#include "rtl_bench.hpp"

namespace mcadsw {
namespace {

constexpr int kBankWords = kRectBufH / 2 * kRectBufW / 4;

uint32_t mem_word(uint32_t addr) {  // the memory's content: a hash of the address
  uint32_t x = addr * 2654435761u;
  return x ^ (x >> 15) ^ (addr << 7);
}
uint8_t mem_byte(uint32_t addr) { return uint8_t(mem_word(addr & ~3u) >> (8 * (addr & 3))); }

struct Plane {
  uint32_t base, stride;
  bool tiled;
  uint32_t addr(int x, int y) const {
    return tiled ? base + uint32_t(x / 4) * stride + 4u * uint32_t(y) + uint32_t(x % 4)
                 : base + uint32_t(y) * stride + uint32_t(x);
  }
};

std::string run_load(Vrect_load& t, const Plane& p, int x0, int y0, int cols, int rows, std::mt19937& rng,
                     long& words, long& cycles) {
  t.base_i = p.base;
  t.tiled_i = p.tiled;
  t.stride_i = p.stride;
  t.x0_i = uint32_t(x0);
  t.y0_i = uint32_t(y0);
  t.cols_i = uint32_t(cols);
  t.rows_i = uint32_t(rows);
  t.start_i = 1;
  std::vector<uint16_t> bank[4];
  for (auto& b : bank) b.assign(kBankWords, 0xeeee);
  std::set<uint32_t> want;  // words of the rectangle
  for (int y = y0; y < y0 + rows; ++y)
    for (int x = x0; x < x0 + ((cols + 3) & ~3); x += 4) want.insert(p.addr(x, y) & ~3u);
  std::multiset<uint32_t> read;
  std::deque<std::pair<long, uint32_t>> inflight;  // (cycle it answers, address)
  const int latency = int(rng() % 9);
  const double grant = rng() % 3 == 0 ? 1.0 : 0.6;
  bool done = false;
  long cyc = 0;
  std::ostringstream e;
  e << (p.tiled ? "tiled" : "raster") << " base " << p.base << " stride " << p.stride << " rect (" << x0 << ","
    << y0 << ") " << cols << "x" << rows << ": ";
  for (; cyc < 20000 && !done; ++cyc) {
    t.mem_gnt_i = t.mem_req_o && std::bernoulli_distribution(grant)(rng);
    const bool rv = !inflight.empty() && inflight.front().first <= cyc;
    t.mem_rvalid_i = rv;
    t.mem_rdata_i = rv ? mem_word(inflight.front().second) : 0x12345678;
    t.clk_i = 0;
    t.eval();
    if (t.mem_req_o && t.mem_gnt_i) {
      const uint32_t a = t.mem_addr_o, n = t.mem_len_o + 1u;
      if (a % 4) return e.str() + "unaligned read";
      if ((a & 4095u) + 4 * n > 4096u) return e.str() + "a burst across 4 KiB";
      for (uint32_t i = 0; i < n; ++i) {
        read.insert(a + 4 * i);
        inflight.push_back({cyc + 1 + latency + long(i), a + 4 * i});
      }
    }
    if (rv) inflight.pop_front();
    t.clk_i = 1;
    t.eval();
    t.start_i = 0;
    if (t.bank_we_o) {
      const int par = t.bank_row_par_o, a = int(t.bank_waddr_o);
      bank[par * 2][size_t(a)] = uint16_t(t.bank_wdata_even_o);
      bank[par * 2 + 1][size_t(a)] = uint16_t(t.bank_wdata_odd_o);
    }
    done = t.done_o;
  }
  if (!done) return e.str() + "no done";
  t.mem_rvalid_i = 0;
  t.mem_gnt_i = 0;
  for (int i = 0; i < 3; ++i) sim::tick(t);  // busy falls
  if (t.busy_o) return e.str() + "still busy";
  if (!inflight.empty()) return e.str() + "done with reads in flight";
  if (read.size() != want.size() || std::set<uint32_t>(read.begin(), read.end()) != want)
    return e.str() + std::to_string(read.size()) + " words read, " + std::to_string(want.size()) + " in the rectangle";
  for (int ly = 0; ly < rows; ++ly)
    for (int lx = 0; lx < cols; ++lx) {
      const uint16_t w = bank[(ly & 1) * 2 + (lx & 1)][size_t((ly >> 1) * (kRectBufW / 4) + (lx >> 2))];
      const uint8_t got = (lx >> 1) & 1 ? uint8_t(w >> 8) : uint8_t(w);
      const uint8_t exp = mem_byte(p.addr(x0 + lx, y0 + ly));
      if (got != exp) {
        e << "pixel (" << lx << "," << ly << "): " << int(got) << ", memory " << int(exp);
        return e.str();
      }
    }
  words += long(want.size());
  cycles += cyc;
  return "";
}

TEST(RectLoad, RectanglesLandInTheBanks) {
  sim::random_initial_values(1);
  Vrect_load t;
  t.start_i = 0;
  t.mem_gnt_i = 0;
  t.mem_rvalid_i = 0;
  t.rst_ni = 0;
  sim::tick(t);
  t.rst_ni = 1;
  std::mt19937 rng(3205);
  long words = 0, cycles = 0;
  for (int n = 0; n < 400; ++n) {
    const bool tiled = n % 2;
    const int cols = n % 7 == 0 ? kRectBufW : 1 + int(rng() % kRectBufW);
    const int rows = n % 5 == 0 ? kRectBufH : 1 + int(rng() % kRectBufH);
    const int x0 = 4 * int(rng() % 300), y0 = int(rng() % 2000);
    // Bases near 4 KiB boundaries now and then; strides raster >= the row, tiled >= 4 x height.
    const uint32_t base = (rng() % 4 == 0 ? 4096u * (1 + rng() % 1000) - 4u * (rng() % 40) : 4u * (rng() % 1000000));
    const uint32_t stride = tiled ? 4u * (2048 + rng() % 500) : 4u * ((1300 + rng() % 800) / 4 + (rng() % 3));
    const Plane p{base, stride, tiled};
    const std::string e = run_load(t, p, x0, y0, cols, rows, rng, words, cycles);
    ASSERT_EQ(e, "") << "load " << n;
  }
  std::printf("400 loads, %ld words, %.2f cycles a word with random grants and latency 0..8\n", words,
              double(cycles) / double(words));
}

}  // namespace
}  // namespace mcadsw

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_rect_sample (docs/blocks/rectifier.md 3) against mcadsw::rectify: every tile of
// random frames, random smooth meshes (scaled, rotated, jittered; some reaching outside
// the raw view), S = 8, 16 and 32, Y and U planes, the consumer's back pressure random.
// Each tile's pixels must come in strip order with the reference's value and validity;
// the tile buffer holds the raw view around the tile's source rectangle and random
// bytes elsewhere (where the weight is 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Vrect_sample.h"
#include "mcadsw/params.hpp"
#include "mcadsw/rectify.hpp"
#include "rect_bench.hpp"
#include "rtl_bench.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

constexpr int kNodeBits = kMeshFracBits + 13;
constexpr int kNodeCols = kRectTileW / 8 + 1, kNodeRows = kRectTileH / 8 + 1;
constexpr int kBankWords = kRectBufH / 2 * kRectBufW / 4;
constexpr int kBankAddrBits = 8;  // log2(kBankWords)
static_assert(kBankWords == 1 << kBankAddrBits);

struct Counts {
  int tiles = 0, skipped = 0, pixels = 0, valid = 0;
  long free_cycles = 0, free_pixels = 0;  // tiles run without back pressure
};

// One tile through the block; "" or the first difference.
std::string run_tile(Vrect_sample& t, const Mesh& m, const Plane& raw, const Plane& ref, const Plane& ref_valid,
                     bool uv, int tx0, int ty0, std::mt19937& rng, Counts& n) {
  const int s = m.step_log2, tw = std::min(kRectTileW, m.out_width - tx0), th = std::min(kRectTileH, m.out_height - ty0);
  // The source rectangle: what the valid pixels' taps with a weight need.
  int ulo = 1 << 30, uhi = -1, vlo = 1 << 30, vhi = -1;
  for (int y = ty0; y < ty0 + th; ++y)
    for (int x = tx0; x < tx0 + tw; ++x) {
      if (!ref_valid.at(x, y)) continue;
      const auto [pu, pv] = mesh_position(m, x, y);
      ulo = std::min(ulo, pu >> 5);
      uhi = std::max(uhi, (pu >> 5) + ((pu & 31) != 0));
      vlo = std::min(vlo, pv >> 5);
      vhi = std::max(vhi, (pv >> 5) + ((pv & 31) != 0));
    }
  int bx0 = 0, by0 = 0;
  if (uhi >= 0) {
    bx0 = ulo & ~3;
    by0 = vlo;
    if (uhi - bx0 >= kRectBufW || vhi - by0 >= kRectBufH) {
      ++n.skipped;
      return "";
    }
    // Some slack, so the rectangle is not always tight against the taps.
    bx0 = std::max(0, bx0 - 4 * int(rng() % std::max(1, (kRectBufW - 1 - (uhi - bx0)) / 4 + 1)));
    by0 = std::max(0, by0 - int(rng() % std::max(1, kRectBufH - (vhi - by0))));
  }
  // The banks: the raw view from (bx0, by0), random bytes outside it.
  std::vector<uint16_t> bank[4];
  for (auto& b : bank) b.assign(kBankWords, 0);
  for (int ly = 0; ly < kRectBufH; ++ly)
    for (int lx = 0; lx < kRectBufW; ++lx) {
      const int x = bx0 + lx, y = by0 + ly;
      const uint8_t v = (x < raw.width && y < raw.height) ? raw.at(x, y) : uint8_t(rng());
      uint16_t& w = bank[(ly & 1) * 2 + (lx & 1)][size_t((ly >> 1) * (kRectBufW / 4) + (lx >> 2))];
      w = (lx >> 1) & 1 ? uint16_t((w & 0x00ff) | v << 8) : uint16_t((w & 0xff00) | v);
    }
  // Nodes relative to the tile's first node.
  for (int j = 0; j < kNodeRows; ++j)
    for (int i = 0; i < kNodeCols; ++i) {
      const int gi = (tx0 >> s) + i, gj = (ty0 >> s) + j;
      const bool in = gi < m.nx && gj < m.ny;
      const uint32_t mask = (1u << kNodeBits) - 1;
      const int k = j * kNodeCols + i;
      sim::set_bits(t.node_u_i, k * kNodeBits, kNodeBits, in ? uint32_t(m.u[size_t(gj * m.nx + gi)]) & mask : 0);
      sim::set_bits(t.node_v_i, k * kNodeBits, kNodeBits, in ? uint32_t(m.v[size_t(gj * m.nx + gi)]) & mask : 0);
    }
  t.step_log2_i = uint32_t(s);
  t.tile_y0_i = uint32_t(ty0);
  t.tile_w_i = uint32_t(tw);
  t.tile_h_i = uint32_t(th);
  t.src_x0_i = uint32_t(bx0);
  t.src_y0_i = uint32_t(by0);
  t.raw_w_i = uint32_t(raw.width);
  t.raw_h_i = uint32_t(raw.height);
  t.uv_i = uv;
  // Expected stream: strip order.
  std::vector<std::pair<int, int>> order;
  for (int k = 0; 4 * k < tw; ++k)
    for (int y = 0; y < th; ++y)
      for (int x = 4 * k; x < std::min(4 * k + 4, tw); ++x) order.push_back({x, y});
  const double stall = rng() % 3 == 0 ? 0.0 : 0.3;
  size_t got = 0;
  bool started = false;
  for (long cyc = 0; cyc < 4000; ++cyc) {
    const bool en = !std::bernoulli_distribution(stall)(rng);
    t.en_i = en;
    t.start_i = !started && en;
    t.clk_i = 0;
    t.eval();
    if (en && t.pix_valid_o) {
      if (got >= order.size()) return "more pixels than the tile has";
      const auto [x, y] = order[got];
      std::ostringstream e;
      e << "S " << m.step() << " tile (" << tx0 << "," << ty0 << ") " << tw << "x" << th << " pixel " << got << ": ";
      if (int(t.pix_x_o) != x || int(t.pix_y_o) != y) {
        e << "at (" << t.pix_x_o << "," << t.pix_y_o << "), expected (" << x << "," << y << ")";
        return e.str();
      }
      const auto [pu, pv] = mesh_position(m, tx0 + x, ty0 + y);
      if (bool(t.pix_ok_o) != bool(ref_valid.at(tx0 + x, ty0 + y)) || t.pix_o != ref.at(tx0 + x, ty0 + y)) {
        e << "(" << tx0 + x << "," << ty0 + y << ") position (" << pu << "," << pv << ")/32: RTL " << int(t.pix_o)
          << (t.pix_ok_o ? " valid" : " invalid") << ", reference " << int(ref.at(tx0 + x, ty0 + y))
          << (ref_valid.at(tx0 + x, ty0 + y) ? " valid" : " invalid") << " (buffer at " << bx0 << "," << by0 << ")";
        return e.str();
      }
      if (bool(t.pix_last_o) != (got + 1 == order.size())) return e.str() + "last flag wrong";
      ++got;
      n.valid += ref_valid.at(tx0 + x, ty0 + y);
    }
    if (started && !t.busy_o && !t.start_i) {
      if (stall == 0.0) {
        n.free_cycles += cyc;
        n.free_pixels += long(order.size());
      }
      break;
    }
    // The banks: synchronous read.
    uint64_t next = t.bank_rdata_i;
    for (int b = 0; b < 4; ++b)
      if ((t.bank_re_o >> b) & 1) {
        const uint32_t a = (t.bank_addr_o >> (b * kBankAddrBits)) & ((1u << kBankAddrBits) - 1);
        next = (next & ~(uint64_t(0xffff) << (16 * b))) | uint64_t(bank[b][a]) << (16 * b);
      }
    started |= bool(t.start_i);
    t.clk_i = 1;
    t.eval();
    t.bank_rdata_i = next;
  }
  t.start_i = 0;
  if (got != order.size()) return "tile (" + std::to_string(tx0) + "," + std::to_string(ty0) + "): " +
                                  std::to_string(got) + " of " + std::to_string(order.size()) + " pixels";
  ++n.tiles;
  n.pixels += int(got);
  return "";
}

TEST(RectSample, TilesMatchTheReference) {
  sim::random_initial_values(3);
  Vrect_sample t;
  t.rst_ni = 0;
  t.en_i = 1;
  sim::tick(t);
  t.rst_ni = 1;
  std::mt19937 rng(32);
  Counts n;
  for (int frame = 0; frame < 36; ++frame) {
    const int s = 3 + frame % 3;
    const int w = 8 + int(rng() % 90), h = 5 + int(rng() % 60);
    const int rw = 10 + int(rng() % 110), rh = 10 + int(rng() % 80);
    const Mesh m = sim::random_mesh(w, h, s, rw, rh, rng);
    const YuvImage raw = test::random_yuv(rw, rh, rng);
    const Rectified ref = rectify(raw, m);
    const bool uv = frame % 2;
    for (int ty0 = 0; ty0 < h; ty0 += kRectTileH)
      for (int tx0 = 0; tx0 < w; tx0 += kRectTileW) {
        const std::string e = run_tile(t, m, uv ? raw.u : raw.y, uv ? ref.image.u : ref.image.y, ref.valid, uv, tx0,
                                       ty0, rng, n);
        ASSERT_EQ(e, "") << "frame " << frame << " (" << w << "x" << h << " from " << rw << "x" << rh << ")";
      }
  }
  std::printf("%d tiles, %d pixels (%d valid), %d tiles skipped (source beyond the buffer); without back "
              "pressure %.3f cycles a pixel, start to idle\n",
              n.tiles, n.pixels, n.valid, n.skipped, double(n.free_cycles) / double(n.free_pixels));
  EXPECT_GT(n.valid, n.pixels / 3);
  EXPECT_LT(n.valid, n.pixels) << "some meshes reach outside the raw view";
  EXPECT_LT(n.skipped, n.tiles / 10);
}

}  // namespace
}  // namespace mcadsw

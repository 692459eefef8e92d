// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_rect_nodes (docs/blocks/rectifier.md 4) against mcadsw::tile_source
// (docs/algorithm.md 13.8): every tile of random frames and meshes (S = 8, 16, 32; some
// steep enough not to fit the tile buffer, some far off the raw view, some with a node
// word outside the 18-bit range), the node words handed in with random gaps. The
// node count and origin, every stored node, the range flag and the source rectangle
// must match.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Vrect_nodes.h"
#include "mcadsw/params.hpp"
#include "mcadsw/rectify.hpp"
#include "rect_bench.hpp"
#include "rtl_bench.hpp"

namespace mcadsw {
namespace {

constexpr int kNodeBits = kMeshFracBits + 13;
constexpr int kNodeCols = kRectTileW / 8 + 1;

struct Counts {
  int tiles = 0, empty = 0, too_big = 0, range = 0;
};

std::string run_tile(Vrect_nodes& t, const Mesh& m, int rw, int rh, int a, int b, std::mt19937& rng, Counts& n) {
  const TileSource want = tile_source(m, a, b, rw, rh);
  t.step_log2_i = uint32_t(m.step_log2);
  t.tile_x0_i = uint32_t(a * kRectTileW);
  t.tile_y0_i = uint32_t(b * kRectTileH);
  t.width_i = uint32_t(m.out_width);
  t.height_i = uint32_t(m.out_height);
  t.raw_w_i = uint32_t(rw);
  t.raw_h_i = uint32_t(rh);
  t.start_i = 1;
  sim::tick(t);
  t.start_i = 0;
  std::ostringstream e;
  e << "S " << m.step() << " tile (" << a << "," << b << "): ";
  if (int(t.node_i0_o) != want.node_i0 || int(t.node_j0_o) != want.node_j0 ||
      int(t.ncols_o) != want.node_i1 - want.node_i0 + 1 || int(t.nrows_o) != want.node_j1 - want.node_j0 + 1) {
    e << "nodes from (" << t.node_i0_o << "," << t.node_j0_o << ") " << t.ncols_o << "x" << t.nrows_o
      << ", expected (" << want.node_i0 << "," << want.node_j0 << ") " << want.node_i1 - want.node_i0 + 1 << "x"
      << want.node_j1 - want.node_j0 + 1;
    return e.str();
  }
  // The words, now and then one out of range.
  std::vector<uint32_t> words;
  for (int j = want.node_j0; j <= want.node_j1; ++j)
    for (int i = want.node_i0; i <= want.node_i1; ++i) {
      words.push_back(uint32_t(m.u[size_t(j * m.nx + i)]));
      words.push_back(uint32_t(m.v[size_t(j * m.nx + i)]));
    }
  bool bad = false;
  if (rng() % 8 == 0) {
    const uint32_t outside[] = {1u << 17, uint32_t(-(1 << 17) - 1), 0x80000000u, 0x7fffffffu, 0x00100000u};
    words[rng() % words.size()] = outside[rng() % 5];
    bad = true;
  }
  size_t k = 0;
  int done = 0;
  for (int cyc = 0; cyc < 200 && !done; ++cyc) {
    const bool give = k < words.size() && rng() % 3 != 0;
    t.word_valid_i = give;
    t.word_i = give ? words[k] : 0xdeadbeef;
    t.clk_i = 0;
    t.eval();
    done = t.done_o;
    if (done) break;
    k += give;
    t.clk_i = 1;
    t.eval();
  }
  t.word_valid_i = 0;
  if (!done) return e.str() + "no done";
  if (bool(t.range_err_o) != bad) return e.str() + "range flag " + std::to_string(t.range_err_o);
  ++n.tiles;
  if (bad) {
    ++n.range;
    return "";  // the rectangle of a rejected mesh does not matter
  }
  for (int j = 0; j <= want.node_j1 - want.node_j0; ++j)
    for (int i = 0; i <= want.node_i1 - want.node_i0; ++i) {
      const size_t g = size_t((want.node_j0 + j) * m.nx + want.node_i0 + i);
      const uint32_t mask = (1u << kNodeBits) - 1;
      const int idx = (j * kNodeCols + i) * kNodeBits;
      if (sim::get_bits(t.node_u_o, idx, kNodeBits) != (uint32_t(m.u[g]) & mask) ||
          sim::get_bits(t.node_v_o, idx, kNodeBits) != (uint32_t(m.v[g]) & mask))
        return e.str() + "node (" + std::to_string(i) + "," + std::to_string(j) + ") stored wrong";
    }
  const bool fits = want.fits();
  if (bool(t.empty_o) != want.empty || bool(t.fits_o) != fits ||
      (!want.empty && (int(t.src_x0_o) != want.x0 || int(t.src_y0_o) != want.y0 || int(t.src_cols_o) != want.cols ||
                       int(t.src_rows_o) != want.rows))) {
    e << "RTL " << (t.empty_o ? "empty" : "") << " (" << t.src_x0_o << "," << t.src_y0_o << ") " << t.src_cols_o
      << "x" << t.src_rows_o << (t.fits_o ? " fits" : " too big") << "; reference " << (want.empty ? "empty" : "")
      << " (" << want.x0 << "," << want.y0 << ") " << want.cols << "x" << want.rows << (fits ? " fits" : " too big")
      << " (box u " << want.umin << ".." << want.umax << ", v " << want.vmin << ".." << want.vmax << ")";
    return e.str();
  }
  n.empty += want.empty;
  n.too_big += !fits;
  return "";
}

TEST(RectNodes, TileSourcesMatchTheReference) {
  sim::random_initial_values(2);
  Vrect_nodes t;
  t.rst_ni = 0;
  sim::tick(t);
  t.rst_ni = 1;
  std::mt19937 rng(3208);
  Counts n;
  for (int frame = 0; frame < 60; ++frame) {
    const int s = 3 + frame % 3;
    const bool big = frame % 5 == 4;  // now and then a large frame or raw view
    const int w = 1 + int(rng() % (big ? 700 : 120)), h = 1 + int(rng() % (big ? 300 : 80));
    const int rw = 1 + int(rng() % (big ? 2048 : 150)), rh = 1 + int(rng() % (big ? 2048 : 100));
    const Mesh m = sim::random_mesh(w, h, s, rw, rh, rng, frame % 4 == 3 ? 3.0 : 1.1);
    for (int b = 0; b * kRectTileH < h; ++b)
      for (int a = 0; a * kRectTileW < w; ++a) {
        const std::string e = run_tile(t, m, rw, rh, a, b, rng, n);
        ASSERT_EQ(e, "") << "frame " << frame << " (" << w << "x" << h << " from " << rw << "x" << rh << ")";
      }
  }
  std::printf("%d tiles: %d empty, %d too big for the buffer, %d with a node out of range\n", n.tiles, n.empty,
              n.too_big, n.range);
  EXPECT_GT(n.empty, 0);
  EXPECT_GT(n.too_big, 0);
  EXPECT_GT(n.range, 0);
  EXPECT_GT(n.tiles - n.empty - n.too_big - n.range, n.tiles / 2);
}

}  // namespace
}  // namespace mcadsw

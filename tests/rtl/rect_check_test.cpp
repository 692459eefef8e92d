// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_rect_check (docs/blocks/rectifier.md 2) against mcadsw::rect_check: random
// configurations laid out like a frame's (valid), each then broken in one way (a step,
// a raw size or stride, a mesh size, a misaligned base, two regions overlapping by a
// byte or touching, a region ending at or past 2^32), and random regions anywhere. The
// block's result after done_o must equal the reference's, and every check must be seen
// both passing and failing.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <sstream>
#include <string>

#include "Vrect_check.h"
#include "mcadsw/params.hpp"
#include "mcadsw/rectify.hpp"
#include "rtl_bench.hpp"
#include "vbits.hpp"

namespace mcadsw {
namespace {

// One check on the block: the configuration applied, a start, the result at done_o.
struct CheckRun {
  int err = -1;
  long cycles = 0;
  int done_pulses = 0;
};

CheckRun run(Vrect_check& t, const RectCheck& c) {
  t.step_log2_i = uint32_t(c.step_log2);
  t.width_i = uint32_t(c.width);
  t.height_i = uint32_t(c.height);
  t.raw_w_i = uint32_t(c.raw_width);
  t.raw_h_i = uint32_t(c.raw_height);
  t.raw_stride_i = c.raw_stride;
  t.tiled_i = c.tiled;
  t.planes_i = uint32_t(c.planes);
  for (int p = 0; p < 6; ++p) {
    sim::set_bits(t.raw_base_i, 32 * p, 32, c.raw_base[p]);
    sim::set_bits(t.rect_base_i, 32 * p, 32, c.rect_base[p]);
  }
  t.rect_size_i = c.rect_size;
  for (int v = 0; v < 2; ++v) {
    sim::set_bits(t.mesh_base_i, 32 * v, 32, c.mesh_base[v]);
    sim::set_bits(t.valid_base_i, 32 * v, 32, c.valid_base[v]);
  }
  t.mesh_nx_i = uint32_t(c.mesh_nx);
  t.mesh_ny_i = uint32_t(c.mesh_ny);
  for (int k = 0; k < 4; ++k) {
    sim::set_bits(t.out_base_i, 32 * k, 32, c.out_base[k]);
    sim::set_bits(t.out_size_i, 44 * k, 44, c.out_size[k]);
  }
  t.outs_i = uint32_t(c.outs);
  t.start_i = 1;
  CheckRun r;
  for (; r.cycles < 2000; ++r.cycles) {
    t.clk_i = 0;
    t.eval();
    if (t.done_o) {
      ++r.done_pulses;
      r.err = int(t.err_o);
    }
    t.clk_i = 1;
    t.eval();
    t.start_i = 0;
    if (r.done_pulses && !t.busy_o) break;
  }
  return r;
}

std::string describe(const RectCheck& c) {
  std::ostringstream o;
  o << "s " << c.step_log2 << ", " << c.width << "x" << c.height << " from " << c.raw_width << "x"
    << c.raw_height << " stride " << c.raw_stride << (c.tiled ? " tiled" : " raster") << ", planes " << c.planes
    << ", nodes " << c.mesh_nx << "x" << c.mesh_ny << ", outs " << c.outs << std::hex << "; raw";
  for (uint32_t b : c.raw_base) o << " " << b;
  o << "; rect";
  for (uint32_t b : c.rect_base) o << " " << b;
  o << " size " << c.rect_size << "; mesh " << c.mesh_base[0] << " " << c.mesh_base[1] << "; valid "
    << c.valid_base[0] << " " << c.valid_base[1] << "; out";
  for (int k = 0; k < 4; ++k) o << " " << c.out_base[k] << "+" << c.out_size[k];
  return o.str();
}

// A configuration as a frame would have it: every region in its own place, in a random
// order, 4-byte aligned, a random gap (0 or more bytes) between two.
RectCheck valid_config(std::mt19937& rng) {
  RectCheck c;
  auto pick = [&](int lo, int hi) { return lo + int(rng() % uint32_t(hi - lo + 1)); };
  c.step_log2 = pick(3, 5);
  c.width = pick(1, 400);
  c.height = pick(1, 300);
  c.raw_width = pick(1, 500);
  c.raw_height = pick(1, 400);
  c.tiled = rng() % 3 == 0;
  c.raw_stride = uint32_t(c.tiled ? 4 * c.raw_height : c.raw_width);
  c.raw_stride = (c.raw_stride + 3) & ~3u;
  c.raw_stride += 4 * uint32_t(pick(0, 3));
  static const int plane_sets[] = {0x0f, 0x39, 0x3f, 0x01, 0x08, 0x07, 0x38};
  c.planes = plane_sets[rng() % 7];
  c.mesh_nx = ((c.width - 1) >> c.step_log2) + 2;
  c.mesh_ny = ((c.height - 1) >> c.step_log2) + 2;
  c.rect_size = uint64_t((c.width + 3) & ~3) * uint64_t(c.height);
  c.outs = int(rng() % 16);
  for (int k = 0; k < 4; ++k) c.out_size[k] = uint64_t(pick(1, 200000));
  const uint64_t raw_size = uint64_t(c.raw_stride) * uint64_t(c.tiled ? (c.raw_width + 3) / 4 : c.raw_height);
  const uint64_t mesh_size = 8ull * uint64_t(c.mesh_nx) * uint64_t(c.mesh_ny);
  const uint64_t bm_size = 4ull * uint64_t((c.width + 3) / 4) * uint64_t((c.height + 7) / 8);
  // Lay the 20 regions out in a random order from a random start.
  std::vector<std::pair<uint32_t*, uint64_t>> regions;
  for (int p = 0; p < 6; ++p) regions.push_back({&c.raw_base[p], raw_size});
  for (int v = 0; v < 2; ++v) regions.push_back({&c.mesh_base[v], mesh_size});
  for (int p = 0; p < 6; ++p) regions.push_back({&c.rect_base[p], c.rect_size});
  for (int v = 0; v < 2; ++v) regions.push_back({&c.valid_base[v], bm_size});
  for (int k = 0; k < 4; ++k) regions.push_back({&c.out_base[k], c.out_size[k]});
  std::shuffle(regions.begin(), regions.end(), rng);
  uint64_t at = 4ull * (rng() % (1u << 28));
  for (auto& [base, size] : regions) {
    at += rng() % 2 ? 0 : 4ull * (rng() % 64);
    *base = uint32_t(at);
    at = (at + size + 3) & ~3ull;
  }
  if (at > (1ull << 32)) return valid_config(rng);  // the layout wrapped: draw again
  return c;
}

// Breaks one thing of a valid configuration.
void break_one(RectCheck& c, std::mt19937& rng) {
  uint32_t* bases[] = {&c.raw_base[0], &c.raw_base[1], &c.raw_base[2], &c.raw_base[3], &c.raw_base[4],
                       &c.raw_base[5], &c.mesh_base[0], &c.mesh_base[1], &c.valid_base[0], &c.valid_base[1],
                       &c.rect_base[0], &c.rect_base[3], &c.out_base[0], &c.out_base[2]};
  const int nb = int(sizeof(bases) / sizeof(bases[0]));
  switch (rng() % 12) {
    case 0: c.step_log2 = int(rng() % 2) ? int(rng() % 3) : 6 + int(rng() % 2); break;
    case 1: c.raw_width = rng() % 2 ? 0 : kMaxWidth + 1 + int(rng() % 100); break;
    case 2: c.raw_height = rng() % 2 ? 0 : kMaxHeight + 1 + int(rng() % 100); break;
    case 3: c.raw_stride = c.tiled ? 4u * uint32_t(c.raw_height) - 4 : uint32_t(c.raw_width) - 1; break;
    case 4: c.raw_stride += 1 + rng() % 3; break;
    case 5: (rng() % 2 ? c.mesh_nx : c.mesh_ny) += rng() % 2 ? 1 : -1; break;
    case 6: *bases[rng() % uint32_t(nb)] += 1 + rng() % 3; break;
    case 7:
    case 8: {  // one region moved onto another: overlapping by a byte, or just touching
      uint32_t* a = bases[rng() % uint32_t(nb)];
      uint32_t* b = bases[rng() % uint32_t(nb)];
      *a = *b + (rng() % 2 ? 0u : 4u * (rng() % 8));
      break;
    }
    case 9: *bases[rng() % uint32_t(nb)] = 0xFFFFFFFCu - 4u * (rng() % 64); break;  // near the top
    case 10: c.rect_size = uint64_t(c.rect_size) * (1 + rng() % 64); break;        // the engine's planes grow
    default: c.out_size[rng() % 4] *= 1 + rng() % 4096; break;
  }
}

struct RandomInitialValues {
  RandomInitialValues() { sim::random_initial_values(7); }
};

// A model after reset; its flip-flops without a reset start at random values.
class RectCheckTest : public ::testing::Test, private RandomInitialValues {  // before the model
 protected:
  void SetUp() override {
    t.rst_ni = 0;
    t.start_i = 0;
    sim::tick(t);
    t.rst_ni = 1;
  }
  Vrect_check t;
};

TEST_F(RectCheckTest, ResultsMatchTheReference) {
  std::mt19937 rng(3301);
  int seen[7][2] = {};  // per check (0: none failed), [reference result == k]
  long runs = 0, cycles = 0;
  for (int n = 0; n < 3000; ++n) {
    RectCheck c = valid_config(rng);
    if (n % 4 != 0) break_one(c, rng);
    if (n % 4 == 1) break_one(c, rng);  // some with two faults: the first in the order wins
    const int want = rect_check(c);
    const CheckRun r = run(t, c);
    ASSERT_EQ(r.done_pulses, 1) << "case " << n << ": " << describe(c);
    ASSERT_EQ(r.err, want) << "case " << n << ": " << describe(c);
    seen[want][1] = 1;
    ++runs;
    cycles += r.cycles;
  }
  std::printf("%ld configurations, %.0f cycles a check; results:", runs, double(cycles) / double(runs));
  for (int k = 0; k <= 6; ++k) {
    std::printf(" %d%s", k, seen[k][1] ? "" : "(never)");
    EXPECT_TRUE(seen[k][1]) << "no configuration gave result " << k;
  }
  std::printf("\n");
}

// By hand: the sizes the block multiplies out (a raw plane raster and tiled, the mesh,
// the bitmap) decide an overlap to the byte, and a region that ends exactly at 2^32
// is inside the space.
TEST_F(RectCheckTest, SizesToTheByte) {
  RectCheck c;
  c.step_log2 = 4;
  c.width = 100;
  c.height = 50;
  c.raw_width = 120;
  c.raw_height = 70;
  c.raw_stride = 128;
  c.planes = 0x01;  // LY only: raw plane 0, mesh 0, rectified plane 0, bitmap 0
  c.mesh_nx = 8;    // (99 >> 4) + 2
  c.mesh_ny = 5;    // (49 >> 4) + 2
  c.rect_size = 100 * 50;
  c.raw_base[0] = 0x10000;               // 128 x 70 = 8960 bytes: ends at 0x12300
  c.mesh_base[0] = 0x12300;              // 8 x 8 x 5 = 320 bytes: ends at 0x12440
  c.valid_base[0] = 0x12440;             // 4 x 25 x 7 = 700 bytes: ends at 0x126FC
  c.rect_base[0] = 0x126FC;
  EXPECT_EQ(rect_check(c), 0);
  EXPECT_EQ(run(t, c).err, 0);
  // A word into the region below: the mesh into the raw plane (two reads: harmless), the
  // bitmap into the mesh (a read), the rectified plane into the bitmap.
  const std::pair<uint32_t*, int> moves[] = {{&c.mesh_base[0], 0}, {&c.valid_base[0], 5}, {&c.rect_base[0], 5}};
  for (const auto& [b, want] : moves) {
    *b -= 4;
    EXPECT_EQ(rect_check(c), want);
    EXPECT_EQ(run(t, c).err, want);
    *b += 4;
  }
  c.tiled = true;                        // tiled: 128 x ceil(120 / 4) = 3840 bytes, stride >= 4 x 70
  c.raw_stride = 280;                    // 280 x 30 = 8400 bytes
  EXPECT_EQ(rect_check(c), 0);
  EXPECT_EQ(run(t, c).err, 0);
  c.raw_stride = 276;
  EXPECT_EQ(rect_check(c), 2);
  EXPECT_EQ(run(t, c).err, 2);
  c.raw_stride = 280;
  c.raw_base[0] = uint32_t((1ull << 32) - 8400);  // ends exactly at 2^32
  EXPECT_EQ(rect_check(c), 0);
  EXPECT_EQ(run(t, c).err, 0);
  c.raw_base[0] += 4;
  EXPECT_EQ(rect_check(c), 6);
  EXPECT_EQ(run(t, c).err, 6);
}

}  // namespace
}  // namespace mcadsw

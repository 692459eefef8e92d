// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The whole-frame fast path (sw_ref/src/fast.cpp) against the block-by-block
// path, pixel for pixel: random and structured images, sizes around the
// window and the SIMD widths, every kind of disparity range, random legal weight
// tables, several thread counts; both the SIMD and the portable kernel.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "mcadsw/image_io.hpp"
#include "mcadsw/ref.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

// Empty when equal, else the first differing pixel and both values.
std::string first_difference(const Plane& got, const Plane& want) {
  if (got.width != want.width || got.height != want.height)
    return "size " + std::to_string(got.width) + "x" + std::to_string(got.height) + " vs " +
           std::to_string(want.width) + "x" + std::to_string(want.height);
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x)
      if (got.at(x, y) != want.at(x, y))
        return "first difference at (" + std::to_string(x) + "," + std::to_string(y) +
               "): fast " + std::to_string(got.at(x, y)) + ", blocks " +
               std::to_string(want.at(x, y));
  return "";
}

// A random legal table (as in ref_weights_test): non-increasing powers of two,
// possibly skipping levels, possibly starting below 64.
WeightTable random_table(std::mt19937& rng) {
  WeightTable t(kWeightTableSize);
  int code = int(rng() % 8);
  const int step = 5 + int(rng() % 120);  // how fast it decays
  for (auto& w : t) {
    if (code > 0 && rng() % step == 0) code -= 1 + int(rng() % code);
    w = uint8_t(weight_from_code(code));
  }
  return t;
}

enum class Pattern { kNoise, kFlat, kStripes, kGradient, kBlocks };

Plane pattern_plane(Pattern p, int w, int h, std::mt19937& rng) {
  Plane out(w, h);
  const int period = 2 + int(rng() % 9), phase = int(rng() % 256);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int v = 0;
      switch (p) {
        case Pattern::kNoise: v = int(rng() % 256); break;
        case Pattern::kFlat: v = phase; break;
        case Pattern::kStripes: v = (x / period) % 2 ? 200 : 40; break;
        case Pattern::kGradient: v = phase + 3 * x + 2 * y; break;
        case Pattern::kBlocks: v = ((x / period + y / period) % 3) * 90 + int(rng() % 8); break;
      }
      out.at(x, y) = uint8_t(v & 255);
    }
  return out;
}

YuvImage pattern_yuv(Pattern p, int w, int h, std::mt19937& rng) {
  return {pattern_plane(p, w, h, rng), pattern_plane(p, w, h, rng), pattern_plane(p, w, h, rng)};
}

// The right view: the left shifted by a random disparity plus noise, or unrelated.
YuvImage right_view(const YuvImage& left, Pattern p, std::mt19937& rng) {
  if (rng() % 3 == 0) return pattern_yuv(p, left.width(), left.height(), rng);
  YuvImage r = left;
  const int shift = int(rng() % 20);
  for (int y = 0; y < left.height(); ++y)
    for (int x = 0; x < left.width(); ++x)
      r.y.at(x, y) = uint8_t(std::clamp(
          int(left.y.clamped(x + shift, y)) + int(rng() % 7) - 3, 0, 255));
  return r;
}

void expect_same(const YuvImage& l, const YuvImage& r, Config cfg, const std::string& what) {
  cfg.threads = 1;
  const Plane want = disparity_map_blocks(l, r, cfg);
  for (bool portable : {false, true})
    for (int threads : {1, 2, 3, 7}) {
      if (portable && threads > 2) continue;  // the portable kernel is slow; threading is shared
      cfg.threads = threads;
      const Plane got = disparity_map_fast(l, r, cfg, portable);
      const std::string diff = first_difference(got, want);
      ASSERT_EQ(diff, "") << what << ", D=" << cfg.disparities << ", " << threads << " threads"
                          << (portable ? ", portable kernel" : ", SIMD kernel");
    }
}

struct Size {
  int w, h;
};

TEST(FastPath, MatchesBlocksOnSmallAndOddSizes) {
  std::mt19937 rng(21);
  const Size sizes[] = {{1, 1},  {1, 9},  {9, 1},  {1, 40}, {40, 1}, {2, 3},   {5, 5},
                        {17, 13}, {30, 30}, {31, 31}, {33, 2}, {45, 37}, {63, 20}, {70, 47}};
  const int ds[] = {1, 2, 15, 16, 17, 31, 32, 33, 48, 63, 64};
  int n = 0;
  for (const Size& s : sizes)
    for (Pattern p : {Pattern::kNoise, Pattern::kFlat, Pattern::kStripes, Pattern::kGradient,
                      Pattern::kBlocks}) {
      const YuvImage l = pattern_yuv(p, s.w, s.h, rng);
      const YuvImage r = right_view(l, p, rng);
      Config cfg;
      cfg.disparities = ds[n++ % std::size(ds)];
      if (rng() % 2) cfg.table = random_table(rng);
      expect_same(l, r, cfg,
                  std::to_string(s.w) + "x" + std::to_string(s.h) + " pattern " +
                      std::to_string(int(p)));
    }
}

TEST(FastPath, MatchesBlocksForEveryDisparityRange) {
  std::mt19937 rng(22);
  const YuvImage l = pattern_yuv(Pattern::kBlocks, 37, 29, rng);
  const YuvImage r = right_view(l, Pattern::kBlocks, rng);
  Config cfg;
  for (int d = 1; d <= kDmax; ++d) {
    cfg.disparities = d;
    cfg.table = d % 2 ? make_weight_table(kDefaultGamma) : random_table(rng);
    expect_same(l, r, cfg, "37x29 blocks");
  }
}

TEST(FastPath, MatchesBlocksOnLargerImagesAndExtremeTables) {
  std::mt19937 rng(23);
  struct Case {
    Size s;
    int d;
    Pattern p;
  };
  const Case cases[] = {{{500, 40}, 64, Pattern::kNoise},    {{257, 70}, 17, Pattern::kGradient},
                        {{130, 90}, 63, Pattern::kBlocks},   {{97, 50}, 2, Pattern::kStripes},
                        {{480, 35}, 48, Pattern::kBlocks}};
  for (const Case& c : cases) {
    const YuvImage l = pattern_yuv(c.p, c.s.w, c.s.h, rng);
    const YuvImage r = right_view(l, c.p, rng);
    Config cfg;
    cfg.disparities = c.d;
    const std::string what = std::to_string(c.s.w) + "x" + std::to_string(c.s.h);
    expect_same(l, r, cfg, what + " default table");
    cfg.table = WeightTable(kWeightTableSize, uint8_t(kWeightMax));  // every weight 64
    expect_same(l, r, cfg, what + " all-64 table");
    cfg.table = WeightTable(kWeightTableSize, 0);  // every weight 0: every cost ties
    expect_same(l, r, cfg, what + " all-0 table");
  }
}

// Largest costs everywhere (inverted census, all weights 64) reach kFinalCostMax.
TEST(FastPath, MatchesBlocksAtTheCostBound) {
  const int W = 40, H = 36;
  YuvImage l = test::flat_yuv(W, H), r = test::flat_yuv(W, H);
  // Checkerboard luma with a unit step: the census of l and of r (its
  // complement) differ in every bit where the colour is flat enough for weight 64.
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      l.y.at(x, y) = uint8_t(100 + ((x + y) % 2));
      r.y.at(x, y) = uint8_t(100 + ((x + y + 1) % 2));
    }
  Config cfg;
  cfg.table = WeightTable(kWeightTableSize, uint8_t(kWeightMax));
  for (int d : {1, 16, 64}) {
    cfg.disparities = d;
    expect_same(l, r, cfg, "cost bound");
  }
}

// The four Middlebury pairs at their usual D.
TEST(FastPath, MatchesBlocksOnMiddleburyPairs) {
  const std::filesystem::path data = MCADSW_DATA_DIR;
  const std::pair<const char*, int> pairs[] = {{"tsukuba", 16}, {"venus", 20}, {"teddy", 60}, {"cones", 60}};
  for (const auto& [name, d] : pairs) {
    const auto dir = data / "middlebury" / name;
    const YuvImage l = load_yuv((dir / "left.png").string());
    const YuvImage r = load_yuv((dir / "right.png").string());
    Config cfg;
    cfg.disparities = d;
    cfg.threads = 0;
    const Plane want = disparity_map_blocks(l, r, cfg);
    EXPECT_EQ(first_difference(disparity_map(l, r, cfg), want), "") << name;
    cfg.threads = 3;
    EXPECT_EQ(first_difference(disparity_map_fast(l, r, cfg), want), "") << name << ", 3 threads";
  }
}

}  // namespace
}  // namespace mcadsw

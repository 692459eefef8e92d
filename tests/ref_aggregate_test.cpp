// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Cost aggregation (Eqs. 3-4): worked cases, width bounds, and the fast loops
// against a direct transcription of the equations.
#include <gtest/gtest.h>

#include "mcadsw/ref.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

struct Aggregated {
  std::vector<uint16_t> ev;
  std::vector<uint32_t> e;
};

Aggregated aggregate(const std::vector<uint8_t>& cost, const Weights& w) {
  Aggregated a;
  vertical_aggregate(cost, w, a.ev);
  horizontal_aggregate(a.ev, w, a.e);
  return a;
}

// Flat image, constant cost c: every weight is 64, so
// Ev = 31*c*64 and E = 31*Ev*64 (worked by hand for c = 1: 1984 and 3936256).
TEST(Aggregate, FlatImageConstantCost) {
  const Weights w = generate_weights(test::flat_yuv(40, 35), make_weight_table(kDefaultGamma));
  const Aggregated a = aggregate(std::vector<uint8_t>(40 * 35, 1), w);
  for (uint16_t v : a.ev) ASSERT_EQ(v, 1984);
  for (uint32_t v : a.e) ASSERT_EQ(v, 3936256u);
}

// Upper bound: cost 6 everywhere, weight 64 everywhere reaches kFinalCostMax
// exactly; the declared widths hold it without overflow.
TEST(Aggregate, MaximumCostFitsDeclaredWidths) {
  const Weights w = generate_weights(test::flat_yuv(33, 31), make_weight_table(kDefaultGamma));
  const Aggregated a = aggregate(std::vector<uint8_t>(33 * 31, 6), w);
  for (uint16_t v : a.ev) ASSERT_EQ(v, kVertCostMax);
  for (uint32_t v : a.e) ASSERT_EQ(v, uint32_t(kFinalCostMax));
  EXPECT_LT(kVertCostMax, 1LL << kVertCostBits);
  EXPECT_LT(kFinalCostMax, 1LL << kFinalCostBits);
  EXPECT_GE(kFinalCostMax, 1LL << (kFinalCostBits - 1));
}

// One unit of cost at the top-left pixel of a flat 40x40 image. Pixel (0,0):
// rows y+k, k = -15..0, all clamp to row 0 -> Ev(0,0) = 16*64 = 1024; columns
// x+j, j = -15..0, clamp to column 0 -> E(0,0) = 16*1024*64 = 1048576.
// Pixel (15,15) sees it once: 64*64. Pixel (16,0) does not see it.
TEST(Aggregate, ClampedCornerWorkedByHand) {
  const Weights w = generate_weights(test::flat_yuv(40, 40), make_weight_table(kDefaultGamma));
  std::vector<uint8_t> cost(40 * 40, 0);
  cost[0] = 1;
  const Aggregated a = aggregate(cost, w);
  EXPECT_EQ(a.ev[0], 1024);
  EXPECT_EQ(a.e[0], 1048576u);
  EXPECT_EQ(a.e[15 * 40 + 15], 4096u);
  EXPECT_EQ(a.e[0 * 40 + 16], 0u);
  EXPECT_EQ(a.e[16 * 40 + 0], 0u);
  // Same at the opposite corner (bottom-right clamp).
  std::vector<uint8_t> cost2(40 * 40, 0);
  cost2[40 * 40 - 1] = 1;
  EXPECT_EQ(aggregate(cost2, w).e[40 * 40 - 1], 1048576u);
}

// Table with 64 at dC = 0 only, on an image where every pixel differs from the
// others in its row and column: only the centre taps count, so E = cost*64*64
// for pixels at least kRadius from the border (nearer, clamped taps replicate
// the centre pixel, distance 0).
TEST(Aggregate, OnlyCentreWeightLeavesTheCentreCost) {
  WeightTable t(kWeightTableSize, 0);
  t[0] = 64;
  const int N = 2 * kRadius + 10;
  YuvImage img = test::flat_yuv(N, N);
  for (int y = 0; y < N; ++y)
    for (int x = 0; x < N; ++x) img.y.at(x, y) = uint8_t(x * 20 + y);
  const Weights w = generate_weights(img, t);
  std::mt19937 rng(7);
  std::vector<uint8_t> cost(N * N);
  for (auto& c : cost) c = uint8_t(rng() % 7);
  const Aggregated a = aggregate(cost, w);
  for (int y = kRadius; y < N - kRadius; ++y)
    for (int x = kRadius; x < N - kRadius; ++x)
      ASSERT_EQ(a.e[y * N + x], cost[y * N + x] * 4096u) << "(" << x << "," << y << ")";
}

TEST(Aggregate, AllZeroWeightsGiveZeroCost) {
  const Weights w = generate_weights(test::flat_yuv(18, 18), WeightTable(kWeightTableSize, 0));
  const Aggregated a = aggregate(std::vector<uint8_t>(18 * 18, 6), w);
  for (uint32_t v : a.e) ASSERT_EQ(v, 0u);
}

// The fast loops against Eqs. 3-4 written directly, on random images of
// awkward sizes (smaller than the window, not multiples of 18).
TEST(Aggregate, MatchesDirectEquations) {
  std::mt19937 rng(8);
  for (auto [W, H] : {std::pair{1, 1}, {7, 3}, {31, 31}, {37, 20}, {50, 45}}) {
    const YuvImage img = test::random_yuv(W, H, rng);
    const WeightTable t = make_weight_table(double(5 + rng() % 40));
    const Weights w = generate_weights(img, t);
    std::vector<uint8_t> cost(size_t(W) * H);
    for (auto& c : cost) c = uint8_t(rng() % 7);
    const Aggregated a = aggregate(cost, w);
    const auto cl = [](int v, int n) { return std::clamp(v, 0, n - 1); };
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        uint64_t e = 0;
        for (int j = -kRadius; j <= kRadius; ++j) {
          const int xc = cl(x + j, W);
          uint64_t ev = 0;  // Ev(xc, y): column centred on (xc, y)
          for (int k = -kRadius; k <= kRadius; ++k)
            ev += cost[size_t(cl(y + k, H)) * W + xc] * t[color_distance(img, xc, y + k, xc, y)];
          if (j == 0) {
            ASSERT_EQ(a.ev[size_t(y) * W + x], ev) << W << "x" << H << " (" << x << "," << y << ")";
          }
          e += ev * t[color_distance(img, xc, y, x, y)];
        }
        ASSERT_EQ(a.e[size_t(y) * W + x], e) << W << "x" << H << " (" << x << "," << y << ")";
      }
  }
}

}  // namespace
}  // namespace mcadsw

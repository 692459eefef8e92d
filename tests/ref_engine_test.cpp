// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// WTA tie rule, configuration checks and whole-engine properties.
#include <gtest/gtest.h>

#include <stdexcept>

#include "mcadsw/ref.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

TEST(Wta, StrictlySmallerWinsAndTiesKeepSmallestD) {
  Wta wta(4);
  wta.update({10, 10, 10, 10}, 0);
  wta.update({9, 10, 11, 10}, 1);
  wta.update({9, 3, 11, 10}, 2);
  wta.update({8, 3, 11, 10}, 3);
  EXPECT_EQ(wta.best_d, (std::vector<uint8_t>{3, 2, 0, 0}));
  EXPECT_EQ(wta.best_cost, (std::vector<uint32_t>{8, 3, 10, 10}));
}

TEST(Wta, MaximumCostAtEveryDisparityGivesZero) {
  Wta wta(1);
  for (int d = 0; d < kDmax; ++d) wta.update({uint32_t(kFinalCostMax)}, d);
  EXPECT_EQ(wta.best_d[0], 0);
}

TEST(Config, RejectsOutOfRangeValues) {
  Config c;
  EXPECT_NO_THROW(check_config(c, 352, 288));
  EXPECT_THROW(check_config(c, 0, 288), std::invalid_argument);
  EXPECT_THROW(check_config(c, kMaxWidth + 1, 288), std::invalid_argument);
  EXPECT_THROW(check_config(c, 352, 0), std::invalid_argument);
  EXPECT_THROW(check_config(c, 352, kMaxHeight + 1), std::invalid_argument);
  c.disparities = 0;
  EXPECT_THROW(check_config(c, 352, 288), std::invalid_argument);
  c.disparities = kDmax + 1;
  EXPECT_THROW(check_config(c, 352, 288), std::invalid_argument);
  c.disparities = kDmax;
  EXPECT_NO_THROW(check_config(c, 352, 288));
  c.table[3] = 5;
  EXPECT_THROW(check_config(c, 352, 288), std::invalid_argument);
}

TEST(Engine, RejectsMismatchedViews) {
  std::mt19937 rng(9);
  EXPECT_THROW(disparity_map(test::random_yuv(10, 10, rng), test::random_yuv(11, 10, rng), Config{}),
               std::invalid_argument);
}

// A random texture shifted by a known disparity is recovered exactly away from
// the left border (where x - d leaves the image). A large gamma keeps most
// weights non-zero, so the whole window votes (with random colours and gamma 22
// nearly every weight is 0 and the 6-bit centre census alone would decide).
TEST(Engine, RecoversAKnownShift) {
  std::mt19937 rng(10);
  const int W = 80, H = 40, shift = 7;
  const YuvImage right = test::random_yuv(W, H, rng);
  YuvImage left = right;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int xs = std::max(x - shift, 0);  // left(x) = right(x - shift)
      left.y.at(x, y) = right.y.at(xs, y);
      left.u.at(x, y) = right.u.at(xs, y);
      left.v.at(x, y) = right.v.at(xs, y);
    }
  Config cfg;
  cfg.disparities = 16;
  cfg.table = make_weight_table(1000.0);
  const Plane disp = disparity_map(left, right, cfg);
  for (int y = 0; y < H; ++y)
    for (int x = shift + kCensusRadius + kRadius; x < W; ++x)
      ASSERT_EQ(disp.at(x, y), shift) << "(" << x << "," << y << ")";
}

// Disparity 0 only, and D = DMAX on a flat pair (every cost ties): all zeros.
TEST(Engine, EdgeDisparityRanges) {
  std::mt19937 rng(11);
  const YuvImage a = test::random_yuv(30, 20, rng), b = test::random_yuv(30, 20, rng);
  Config cfg;
  cfg.disparities = 1;
  for (uint8_t v : disparity_map(a, b, cfg).px) ASSERT_EQ(v, 0);
  cfg.disparities = kDmax;
  const YuvImage flat = test::flat_yuv(30, 20);
  for (uint8_t v : disparity_map(flat, flat, cfg).px) ASSERT_EQ(v, 0);
}

// The disparity is the argmin of the kept final costs, smallest d on ties, and
// the result is independent of the number of worker threads.
TEST(Engine, OutputIsArgminOfFinalCostsForAnyThreadCount) {
  std::mt19937 rng(12);
  const YuvImage l = test::random_yuv(45, 37, rng), r = test::random_yuv(45, 37, rng);
  Config cfg;
  cfg.disparities = 13;
  cfg.threads = 1;
  Intermediates keep;
  const Plane d1 = disparity_map(l, r, cfg, &keep);
  ASSERT_EQ(keep.final_cost.size(), 13u);
  for (size_t i = 0; i < d1.px.size(); ++i) {
    int best = 0;
    for (int d = 1; d < 13; ++d)
      if (keep.final_cost[d][i] < keep.final_cost[best][i]) best = d;
    ASSERT_EQ(d1.px[i], best) << "pixel " << i;
  }
  for (int threads : {2, 3, 13}) {
    cfg.threads = threads;
    EXPECT_EQ(disparity_map(l, r, cfg).px, d1.px) << threads << " threads";
  }
}

}  // namespace
}  // namespace mcadsw

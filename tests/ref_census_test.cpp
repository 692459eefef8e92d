// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Mini-census transformer: hand-checked codes, Hamming cost, border clamping.
#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include "mcadsw/image_io.hpp"
#include "mcadsw/ref.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

TEST(Census, HandCheckedFiveByFivePatch) {
  // Centre 100; the six template neighbours, in bit order 5..0:
  //   (0,-2)=150 > 100 -> 0   (-2,-1)=100 == -> 1   (+2,-1)=50 -> 1
  //   (-2,+1)=101 -> 0        (+2,+1)=99 -> 1       (0,+2)=255 -> 0
  // Code 0b011010 = 26. Every other pixel is random and must not matter.
  std::mt19937 rng(1);
  for (int trial = 0; trial < 20; ++trial) {
    Plane p = test::random_plane(5, 5, rng);
    p.at(2, 2) = 100;
    p.at(2, 0) = 150;
    p.at(0, 1) = 100;
    p.at(4, 1) = 50;
    p.at(0, 3) = 101;
    p.at(4, 3) = 99;
    p.at(2, 4) = 255;
    EXPECT_EQ(census_code(p, 2, 2), 0b011010);
  }
}

TEST(Census, FlatImageIsAllOnes) {
  const Plane p(7, 6, 42);
  const Plane c = census_transform(p);
  for (uint8_t v : c.px) EXPECT_EQ(v, 0x3F);
}

TEST(Census, SinglePixelImageClampsEveryNeighbourToItself) {
  EXPECT_EQ(census_code(Plane(1, 1, 200), 0, 0), 0x3F);
}

// Clamping at all four borders equals an independent construction: OpenCV's
// replicate padding, then the census of the interior of the padded image.
TEST(Census, ClampingMatchesReplicatePadding) {
  std::mt19937 rng(2);
  for (auto [w, h] : {std::pair{9, 7}, {1, 5}, {5, 1}, {3, 3}, {2, 2}}) {
    const Plane p = test::random_plane(w, h, rng);
    cv::Mat padded;
    cv::copyMakeBorder(to_mat(p), padded, kCensusRadius, kCensusRadius, kCensusRadius,
                       kCensusRadius, cv::BORDER_REPLICATE);
    const Plane pp = from_mat(padded);
    const Plane c = census_transform(p);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const int cx = x + kCensusRadius, cy = y + kCensusRadius;
        uint8_t ref = 0;
        for (const Offset& o : kCensusTaps)
          ref = uint8_t(ref << 1) | (pp.at(cx + o.dx, cy + o.dy) <= pp.at(cx, cy));
        ASSERT_EQ(c.at(x, y), ref) << "at (" << x << "," << y << ") of " << w << "x" << h;
      }
    }
  }
}

TEST(Census, TemplateIsFitsTheFiveByFiveWindow) {
  for (const Offset& o : kCensusTaps) {
    EXPECT_LE(std::abs(o.dx), kCensusRadius);
    EXPECT_LE(std::abs(o.dy), kCensusRadius);
    EXPECT_FALSE(o.dx == 0 && o.dy == 0);
  }
}

TEST(CensusCost, HammingDistance) {
  EXPECT_EQ(census_cost(0b111000, 0b111011), 2);  // the example of the paper's Fig. 2
  EXPECT_EQ(census_cost(0, 0x3F), 6);
  for (int a = 0; a < 64; ++a) {
    EXPECT_EQ(census_cost(uint8_t(a), uint8_t(a)), 0);
    for (int b = 0; b < 64; ++b)
      ASSERT_EQ(census_cost(uint8_t(a), uint8_t(b)), __builtin_popcount(unsigned(a ^ b)));
  }
}

TEST(CensusCost, SliceClampsRightCoordinateAtLeftBorder) {
  std::mt19937 rng(3);
  const Plane l = test::random_plane(10, 3, rng, 0, 63);
  const Plane r = test::random_plane(10, 3, rng, 0, 63);
  for (int d : {0, 1, 4, 9, 10, 15}) {
    std::vector<uint8_t> cost;
    census_cost_slice(l, r, d, cost);
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 10; ++x)
        ASSERT_EQ(cost[y * 10 + x], census_cost(l.at(x, y), r.at(std::max(x - d, 0), y)))
            << "d=" << d << " (" << x << "," << y << ")";
  }
}

// Census is a relative measure: a brightness offset that does not saturate
// leaves every code, hence every census cost, unchanged.
TEST(CensusProperty, CostUnchangedByBrightnessOffset) {
  std::mt19937 rng(4);
  const Plane l = test::random_plane(40, 30, rng, 0, 200);
  const Plane r = test::random_plane(40, 30, rng, 0, 200);
  for (int offset : {1, 17, 55}) {
    Plane l2 = l, r2 = r;
    for (auto& v : l2.px) v = uint8_t(v + offset);
    for (auto& v : r2.px) v = uint8_t(v + offset);
    std::vector<uint8_t> c1, c2;
    for (int d : {0, 3, 12}) {
      census_cost_slice(census_transform(l), census_transform(r), d, c1);
      census_cost_slice(census_transform(l2), census_transform(r2), d, c2);
      ASSERT_EQ(c1, c2) << "offset " << offset << " d " << d;
    }
  }
}

}  // namespace
}  // namespace mcadsw

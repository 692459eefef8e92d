// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Weight generator: table definition, colour distance, clamped weight planes.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "mcadsw/ref.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

TEST(WeightTable, EndpointsAndHandCheckedStepsForDefaultGamma) {
  const WeightTable t = make_weight_table(kDefaultGamma);
  ASSERT_EQ(t.size(), size_t(kWeightTableSize));
  EXPECT_EQ(t.front(), 64);
  EXPECT_EQ(t.back(), 0);
  // gamma 22: one halving every 22*ln2 = 15.249 colour levels.
  ASSERT_EQ(kDefaultGamma, 22);
  EXPECT_EQ(t[1], 32);
  EXPECT_EQ(t[15], 32);
  EXPECT_EQ(t[16], 16);
  EXPECT_EQ(t[91], 1);
  EXPECT_EQ(t[92], 0);
}

TEST(WeightTable, MonotoneOneHotAndTheMsbOfTheExponential) {
  for (double gamma : {1.0, 5.0, 13.0, 22.0, 40.0, 300.0}) {
    const WeightTable t = make_weight_table(gamma);
    EXPECT_NO_THROW(check_weight_table(t));
    for (int dc = 0; dc < kWeightTableSize; ++dc) {
      if (dc > 0) {
        ASSERT_LE(t[dc], t[dc - 1]) << "gamma " << gamma << " dC " << dc;
      }
      const double exact = kWeightMax * std::exp(-dc / gamma);
      if (t[dc] == 0) {
        ASSERT_LT(exact, 1.0) << "gamma " << gamma << " dC " << dc;
      } else {
        ASSERT_LE(t[dc], exact + 1e-9) << "gamma " << gamma << " dC " << dc;
        ASSERT_GT(2.0 * t[dc], exact) << "gamma " << gamma << " dC " << dc;
      }
    }
  }
}

TEST(WeightTable, RejectsBadTablesAndGamma) {
  WeightTable t = make_weight_table(kDefaultGamma);
  t[7] = 3;
  EXPECT_THROW(check_weight_table(t), std::invalid_argument);
  t[7] = 128;
  EXPECT_THROW(check_weight_table(t), std::invalid_argument);
  EXPECT_THROW(check_weight_table(WeightTable(10, 1)), std::invalid_argument);
  t = make_weight_table(kDefaultGamma);
  t[200] = 64;  // rises again: not representable as thresholds
  EXPECT_THROW(check_weight_table(t), std::invalid_argument);
  EXPECT_THROW(make_weight_table(0.0), std::invalid_argument);
  EXPECT_THROW(make_weight_table(-3.0), std::invalid_argument);
}

TEST(WeightTable, ThresholdsHandChecked) {
  // gamma 22: codes drop at dC = 1, 16, 31, 46, 61, 77, 92 (one every 15.25).
  const WeightThresholds t = weight_thresholds(make_weight_table(kDefaultGamma));
  EXPECT_EQ(t, (WeightThresholds{1, 16, 31, 46, 61, 77, 92}));
  EXPECT_EQ(weight_thresholds(WeightTable(kWeightTableSize, 64)),
            (WeightThresholds{766, 766, 766, 766, 766, 766, 766}));
  EXPECT_EQ(weight_thresholds(WeightTable(kWeightTableSize, 0)),
            (WeightThresholds{0, 0, 0, 0, 0, 0, 0}));
}

TEST(WeightTable, ThresholdsRoundTripForRandomLegalTables) {
  std::mt19937 rng(13);
  for (int trial = 0; trial < 200; ++trial) {
    WeightTable t(kWeightTableSize);
    int code = int(rng() % 8);
    for (auto& w : t) {
      if (code > 0 && rng() % 60 == 0) code -= 1 + int(rng() % code);  // may skip levels
      w = uint8_t(weight_from_code(code));
    }
    ASSERT_EQ(weight_table_from_thresholds(weight_thresholds(t)), t) << "trial " << trial;
  }
  for (double g : {1.0, 7.5, 22.0, 100.0, 1000.0})
    EXPECT_EQ(weight_table_from_thresholds(weight_thresholds(make_weight_table(g))),
              make_weight_table(g));
}

TEST(ColorDistance, ManhattanOverYuvWithClamping) {
  YuvImage img = test::flat_yuv(3, 2, 10, 20, 30);
  img.y.at(2, 1) = 255;
  img.u.at(2, 1) = 0;
  img.v.at(2, 1) = 35;
  EXPECT_EQ(color_distance(img, 0, 0, 2, 1), 245 + 20 + 5);
  EXPECT_EQ(color_distance(img, 2, 1, 0, 0), 270);
  EXPECT_EQ(color_distance(img, 9, 9, 2, 1), 0);  // (9,9) clamps to (2,1)
  const YuvImage extreme{Plane(2, 1, 0), Plane(2, 1, 0), Plane(2, 1, 0)};
  YuvImage e2 = extreme;
  e2.y.at(1, 0) = e2.u.at(1, 0) = e2.v.at(1, 0) = 255;
  EXPECT_EQ(color_distance(e2, 0, 0, 1, 0), kColorDistMax);
}

TEST(Weights, CentreTapIsAlwaysTableZero) {
  std::mt19937 rng(5);
  const YuvImage img = test::random_yuv(12, 9, rng);
  const Weights w = generate_weights(img, make_weight_table(kDefaultGamma));
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 12; ++x) {
      EXPECT_EQ(w.v(kRadius, x, y), 64);
      EXPECT_EQ(w.h(kRadius, x, y), 64);
    }
}

TEST(Weights, FlatImageGivesAllSixtyFour) {
  const Weights w = generate_weights(test::flat_yuv(5, 4), make_weight_table(kDefaultGamma));
  for (uint8_t v : w.vert) ASSERT_EQ(v, 64);
  for (uint8_t v : w.horz) ASSERT_EQ(v, 64);
}

TEST(Weights, PlanesFollowTheDefinitionWithClampedCoordinates) {
  std::mt19937 rng(6);
  const YuvImage img = test::random_yuv(20, 17, rng);
  const WeightTable t = make_weight_table(9.0);
  const Weights w = generate_weights(img, t);
  for (int i = 0; i < kWindow; ++i)
    for (int y = 0; y < 17; ++y)
      for (int x = 0; x < 20; ++x) {
        const int off = i - kRadius;
        const int yy = std::clamp(y + off, 0, 16), xx = std::clamp(x + off, 0, 19);
        const auto dist = [&](int x0, int y0, int x1, int y1) {
          return std::abs(img.y.at(x0, y0) - img.y.at(x1, y1)) +
                 std::abs(img.u.at(x0, y0) - img.u.at(x1, y1)) +
                 std::abs(img.v.at(x0, y0) - img.v.at(x1, y1));
        };
        ASSERT_EQ(w.v(i, x, y), t[dist(x, yy, x, y)]) << "vert k=" << off << " (" << x << "," << y << ")";
        ASSERT_EQ(w.h(i, x, y), t[dist(xx, y, x, y)]) << "horz j=" << off << " (" << x << "," << y << ")";
      }
}

}  // namespace
}  // namespace mcadsw

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Post-processing beyond the paper (docs/algorithm.md section 12): the
// right-reference pass against a direct evaluation of its formula, the
// sub-pixel values of the fast path against the block path's final costs, and
// the left-right check, fill and median on hand-made and library-checked cases.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "mcadsw/image_io.hpp"
#include "mcadsw/ref.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

// dR by the formula of 12.1, pixel by pixel: the right view's census and
// weights, left pixel clamp(x + d), Eqs. 3 and 4, ties to the smallest d.
Plane right_map_direct(const YuvImage& left, const YuvImage& right, const Config& cfg) {
  const int W = left.width(), H = left.height();
  const Plane cl = census_transform(left.y), cr = census_transform(right.y);
  const Weights w = generate_weights(right, cfg.table);
  Plane out(W, H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      uint64_t best = UINT64_MAX;
      for (int d = 0; d < cfg.disparities; ++d) {
        uint64_t e = 0;
        for (int j = 0; j < kWindow; ++j) {
          const int xj = clamp_coord(x + j - kRadius, W);
          uint64_t ev = 0;
          for (int k = 0; k < kWindow; ++k) {
            const int yk = clamp_coord(y + k - kRadius, H);
            ev += uint64_t(census_cost(cr.at(xj, yk), cl.at(clamp_coord(xj + d, W), yk))) * w.v(k, xj, y);
          }
          e += ev * w.h(j, x, y);
        }
        if (e < best) {
          best = e;
          out.at(x, y) = uint8_t(d);
        }
      }
    }
  return out;
}

TEST(Post, RightPassEqualsItsFormula) {
  std::mt19937 rng(1);
  for (auto [w, h, d] : {std::tuple{23, 17, 8}, std::tuple{9, 30, 12}, std::tuple{40, 6, 5}}) {
    YuvImage l = test::random_yuv(w, h, rng), r = test::random_yuv(w, h, rng);
    for (Plane* p : {&l.u, &l.v, &r.u, &r.v})
      for (auto& v : p->px) v = uint8_t(120 + v / 16);  // spread the weights
    Config cfg;
    cfg.disparities = d;
    const Plane got = disparity_map_right(l, r, cfg), want = right_map_direct(l, r, cfg);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        ASSERT_EQ(got.at(x, y), want.at(x, y)) << w << "x" << h << " D=" << d << " at (" << x << "," << y << ")";
  }
}

TEST(Post, RightPassNeedsTheRightColourPlanes) {
  std::mt19937 rng(2);
  const YuvImage l = test::random_yuv(10, 10, rng);
  YuvImage r = l;
  r.u = Plane();
  Config cfg;
  EXPECT_THROW(disparity_map_right(l, r, cfg), std::invalid_argument);
  DepthOptions opt;
  opt.lr = true;
  EXPECT_THROW(depth_map(l, r, cfg, opt), std::invalid_argument);
  opt.lr = false;
  opt.subpixel = true;
  EXPECT_NO_THROW(depth_map(l, r, cfg, opt)) << "sub-pixel alone reads the right view's Y only";
}

TEST(Post, SubpixelValueRules) {
  EXPECT_EQ(subpixel_value(0, 16, 0, 5, 100), 0) << "d = 0: no left neighbour";
  EXPECT_EQ(subpixel_value(15, 16, 100, 5, 0), 16 * 15) << "d = D-1: no right neighbour";
  EXPECT_EQ(subpixel_value(7, 16, 50, 10, 50), 16 * 7) << "symmetric: the vertex is at d";
  // num = -20, den = 40: 16 * 20 / 80 = 4 exactly, towards d - 1.
  EXPECT_EQ(subpixel_value(7, 16, 10, 0, 30), 16 * 7 - 4);
  // num = 6, den = 32: 8 * 6 / 32 = 1.5, rounded half away from zero, both signs.
  EXPECT_EQ(subpixel_value(7, 16, 19, 0, 13), 16 * 7 + 2);
  EXPECT_EQ(subpixel_value(7, 16, 13, 0, 19), 16 * 7 - 2);
  // num = 5, den = 21: 40 / 21 = 1.9 -> 2.
  EXPECT_EQ(subpixel_value(3, 16, 13, 0, 8), 16 * 3 + 2);
  EXPECT_EQ(subpixel_value(3, 16, 8, 0, 13), 16 * 3 - 2);
  EXPECT_EQ(subpixel_value(3, 16, 1, 0, 1000), 16 * 3 - 8) << "the offset is at most half a pixel";
  EXPECT_EQ(subpixel_value(3, 16, 7, 7, 7), 16 * 3) << "flat: den = 0";
}

TEST(Post, SubpixelOffsetsStayWithinHalfAPixel) {
  std::mt19937 rng(3);
  for (int i = 0; i < 100000; ++i) {
    const uint32_t c0 = rng() % 1000000;
    const uint32_t cm = c0 + 1 + rng() % 1000000, cp = c0 + rng() % 1000000;  // WTA: Cm > C0 <= Cp
    const int v = subpixel_value(5, 10, cm, c0, cp) - 16 * 5;
    ASSERT_LE(std::abs(v), kSubpixelOffsetMax) << cm << " " << c0 << " " << cp;
    const double exact = 8.0 * (double(cm) - cp) / (double(cm) + cp - 2.0 * c0);
    ASSERT_LE(std::abs(v - exact), 0.5 + 1e-9) << "not the rounded vertex";
  }
}

// The fast path's sub-pixel values equal 12.6 applied to the block path's final costs.
TEST(Post, SubpixelFastPathEqualsBlockPath) {
  std::mt19937 rng(4);
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/cif/teddy/";
  const YuvImage tl = crop(load_yuv(dir + "left.png"), 150, 100, 61, 37);
  const YuvImage tr = crop(load_yuv(dir + "right.png"), 150, 100, 61, 37);
  struct C {
    YuvImage l, r;
    int d;
  };
  std::vector<C> cases = {{tl, tr, 20}, {tl, tr, 64}, {test::random_yuv(33, 21, rng), test::random_yuv(33, 21, rng), 13}};
  for (const C& c : cases) {
    Config cfg;
    cfg.disparities = c.d;
    Intermediates keep;
    const Plane disp = disparity_map_blocks(c.l, c.r, cfg, &keep);
    const Plane16 want = subpixel_from_costs(keep, disp, c.d);
    for (bool portable : {true, false}) {
      Plane16 got;
      const Plane fast = disparity_map_fast(c.l, c.r, cfg, portable, &got);
      ASSERT_EQ(fast.px, disp.px);
      for (size_t i = 0; i < want.px.size(); ++i)
        ASSERT_EQ(got.px[i], want.px[i]) << "D=" << c.d << " pixel " << i << (portable ? " portable" : " simd");
    }
    int fractional = 0;
    for (uint16_t v : want.px) fractional += v % kSubpixelScale != 0;
    EXPECT_GT(fractional, int(want.px.size()) / 4) << "most pixels should get an offset";
  }
}

TEST(Post, LeftRightCheck) {
  Plane dl(6, 1), dr(6, 1);
  // x:    0  1  2  3  4  5
  // dL:   1  0  2  3  1  2
  // dR:   1  0  0  2  5  7
  const int l[] = {1, 0, 2, 3, 1, 2}, r[] = {1, 0, 0, 2, 5, 7};
  for (int x = 0; x < 6; ++x) {
    dl.at(x, 0) = uint8_t(l[x]);
    dr.at(x, 0) = uint8_t(r[x]);
  }
  const Plane v1 = lr_check(dl, dr, 1);
  // x=0: x-d<0 invalid; x=1: dR(1)=0 ok; x=2: dR(0)=1, |2-1|=1 ok; x=3: dR(0)=1, 2 > 1;
  // x=4: dR(3)=2, 1 ok; x=5: dR(3)=2, 0 ok.
  const int want1[] = {0, 255, 255, 0, 255, 255};
  for (int x = 0; x < 6; ++x) EXPECT_EQ(v1.at(x, 0), want1[x]) << "T=1 x=" << x;
  const Plane v0 = lr_check(dl, dr, 0);
  const int want0[] = {0, 255, 0, 0, 0, 255};
  for (int x = 0; x < 6; ++x) EXPECT_EQ(v0.at(x, 0), want0[x]) << "T=0 x=" << x;
  EXPECT_THROW(lr_check(dl, dr, -1), std::invalid_argument);
  EXPECT_THROW(lr_check(dl, dr, kLrToleranceMax + 1), std::invalid_argument);
  EXPECT_NO_THROW(lr_check(dl, dr, kLrToleranceMax));
  EXPECT_THROW(lr_check(dl, Plane(5, 1), 1), std::invalid_argument);
}

// 13.4: the rectification's validity in the check. Same maps as above (T = 1): a left
// pixel invalid after rectification fails; so does one whose match lands on an invalid
// right pixel; the code 255 for dR gives the same (the equivalence the spec states).
TEST(Post, LeftRightCheckWithRectificationValidity) {
  Plane dl(6, 1), dr(6, 1), lv(6, 1, 1), rv(6, 1, 1);
  const int l[] = {1, 0, 2, 3, 1, 2}, r[] = {1, 0, 0, 2, 5, 7};
  for (int x = 0; x < 6; ++x) {
    dl.at(x, 0) = uint8_t(l[x]);
    dr.at(x, 0) = uint8_t(r[x]);
  }
  lv.at(1, 0) = 0;  // x = 1 passes without it
  rv.at(3, 0) = 0;  // x = 4 and x = 5 match right pixel 3
  const Plane v = lr_check(dl, dr, 1, &lv, &rv);
  const int want[] = {0, 0, 255, 0, 0, 0};
  for (int x = 0; x < 6; ++x) EXPECT_EQ(v.at(x, 0), want[x]) << "x=" << x;
  Plane coded = dr;
  coded.at(3, 0) = uint8_t(kRectInvalidDisp8);
  const Plane c = lr_check(dl, coded, kLrToleranceMax, &lv, nullptr);
  EXPECT_EQ(c.at(4, 0), 0);
  EXPECT_EQ(c.at(5, 0), 0);
  const Plane narrow(5, 1, 1);
  EXPECT_THROW(lr_check(dl, dr, 1, &lv, &narrow), std::invalid_argument);
}

// 13.4 end to end: invalid left pixels get the code after fill and median, in every
// mode; the rest equals the steps of 12.2-12.4 with the validity in the check, the
// invalid pixels filled like any other (so their neighbours' medians see filled values).
TEST(Post, RectificationInvalidPixelsGetTheCodeInEveryMode) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/cif/cones/";
  const YuvImage l = crop(load_yuv(dir + "left.png"), 100, 80, 90, 50);
  const YuvImage r = crop(load_yuv(dir + "right.png"), 100, 80, 90, 50);
  Config cfg;
  cfg.disparities = 32;
  Plane lv(90, 50, 1), rv(90, 50, 1);
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 90; ++x) {
      if (x < 7 || (y > 30 && x > 70)) lv.at(x, y) = 0;  // a strip and a corner
      if (x > 80) rv.at(x, y) = 0;
    }
  for (const bool lr : {false, true})
    for (const bool sub : {false, true}) {
      DepthOptions opt;
      opt.lr = lr;
      opt.subpixel = sub;
      const DepthResult plain = depth_map(l, r, cfg, opt);
      opt.left_valid = lv;
      opt.right_valid = rv;
      const DepthResult got = depth_map(l, r, cfg, opt);
      Plane16 want = plain.disp16;
      if (lr) {
        const Plane valid = lr_check(got.raw, got.right, opt.tolerance, &lv, &rv);
        ASSERT_EQ(got.valid.px, valid.px);
        DepthOptions no_lr;
        no_lr.subpixel = sub;
        const Plane16 base = depth_map(l, r, cfg, no_lr).disp16;
        want = median3x3(fill_invalid(base, valid));
      }
      const Plane got8 = got.disp8();
      int coded = 0;
      for (size_t i = 0; i < want.px.size(); ++i) {
        if (!lv.px[i]) {
          ASSERT_EQ(got.disp16.px[i], kRectInvalidDisp16) << "pixel " << i;
          ASSERT_EQ(got8.px[i], kRectInvalidDisp8) << "pixel " << i;
          if (lr) {
            ASSERT_EQ(got.valid.px[i], 0) << "pixel " << i;
          }
          ++coded;
        } else {
          ASSERT_EQ(got.disp16.px[i], want.px[i]) << "lr " << lr << " sub " << sub << " pixel " << i;
        }
      }
      EXPECT_EQ(coded, 7 * 50 + 19 * 19);
      if (!lr) {
        EXPECT_EQ(got.raw.px, plain.raw.px) << "the raw map itself carries no code";
      }
    }
}

TEST(Post, FillTakesTheSmallerNearestValidValue) {
  Plane16 d(8, 3);
  Plane v(8, 3);
  // Row 0: invalid at the start, in the middle and at the end.
  const int vals[] = {90, 40, 99, 99, 70, 99, 50, 99};
  const int ok[] = {0, 1, 0, 0, 1, 0, 1, 0};
  for (int x = 0; x < 8; ++x) {
    d.at(x, 0) = uint16_t(vals[x]);
    v.at(x, 0) = ok[x] ? 255 : 0;
    d.at(x, 1) = 33;  // row 1: nothing valid -> 0
    d.at(x, 2) = uint16_t(x);
    v.at(x, 2) = 255;  // row 2: all valid, unchanged
  }
  const Plane16 f = fill_invalid(d, v);
  const int want[] = {40, 40, 40, 40, 70, 50, 50, 50};
  for (int x = 0; x < 8; ++x) {
    EXPECT_EQ(f.at(x, 0), want[x]) << "x=" << x;
    EXPECT_EQ(f.at(x, 1), 0) << "a row without a valid pixel";
    EXPECT_EQ(f.at(x, 2), x);
  }
}

TEST(Post, MedianEqualsOpenCvWithReplicatedEdges) {
  std::mt19937 rng(5);
  for (auto [w, h] : {std::pair{1, 1}, std::pair{2, 3}, std::pair{17, 11}, std::pair{64, 40}}) {
    Plane16 p(w, h);
    for (auto& v : p.px) v = uint16_t(rng() % 1024);
    const Plane16 got = median3x3(p);
    cv::Mat src = to_mat(p), dst;
    cv::Mat padded;
    cv::copyMakeBorder(src, padded, 1, 1, 1, 1, cv::BORDER_REPLICATE);
    cv::medianBlur(padded, dst, 3);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        ASSERT_EQ(got.at(x, y), dst.at<uint16_t>(y + 1, x + 1)) << w << "x" << h << " (" << x << "," << y << ")";
  }
}

TEST(Post, LrModeWithoutSubpixelIsSixteenTimesTheEightBitMap) {
  std::mt19937 rng(6);
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/cif/cones/";
  const YuvImage l = crop(load_yuv(dir + "left.png"), 100, 80, 90, 50);
  const YuvImage r = crop(load_yuv(dir + "right.png"), 100, 80, 90, 50);
  Config cfg;
  cfg.disparities = 32;
  DepthOptions opt;
  opt.lr = true;
  const DepthResult a = depth_map(l, r, cfg, opt);
  int filled = 0;
  for (size_t i = 0; i < a.disp16.px.size(); ++i) {
    ASSERT_EQ(a.disp16.px[i] % kSubpixelScale, 0);
    filled += a.valid.px[i] == 0;
  }
  EXPECT_GT(filled, 0) << "the crop has occlusions the check should find";
  // The same steps by hand on the 8-bit maps.
  const Plane raw = disparity_map(l, r, cfg);
  const Plane valid = lr_check(raw, disparity_map_right(l, r, cfg), 1);
  Plane16 raw16(raw.width, raw.height);
  for (size_t i = 0; i < raw.px.size(); ++i) raw16.px[i] = raw.px[i];
  const Plane16 want = median3x3(fill_invalid(raw16, valid));
  const Plane got8 = a.disp8();
  for (size_t i = 0; i < want.px.size(); ++i) ASSERT_EQ(got8.px[i], want.px[i]) << "pixel " << i;
  EXPECT_EQ(a.valid.px, valid.px);
  // Sub-pixel with LR: the same validity, values within half a pixel of the
  // integer pipeline's except where a median picks another neighbour.
  opt.subpixel = true;
  const DepthResult b = depth_map(l, r, cfg, opt);
  EXPECT_EQ(b.valid.px, a.valid.px);
}

}  // namespace
}  // namespace mcadsw

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// End to end on the bundled Middlebury pairs: a regression guard on the "all"
// error, and the committed CIF crops against their generator.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "mcadsw/eval.hpp"
#include "mcadsw/image_io.hpp"
#include "mcadsw/ref.hpp"

namespace mcadsw {
namespace {

const std::filesystem::path kData = MCADSW_DATA_DIR;

struct PairCase {
  const char* name;
  int disparities;
  double scale;
  double max_all;  // percent; measured with `scripts/eval_pairs.sh` (docs/algorithm.md)
};

// gtest prints the parameter by name rather than as bytes.
void PrintTo(const PairCase& c, std::ostream* os) { *os << c.name << " D=" << c.disparities; }

// Guards set from measurement at the default gamma (22), rounded up to 0.01:
// 3.6341 / 0.8684 / 15.1127 / 11.4535. The error may only improve.
class Middlebury : public ::testing::TestWithParam<PairCase> {};

TEST_P(Middlebury, AllErrorStaysAtMeasuredLevel) {
  const PairCase& c = GetParam();
  const auto dir = kData / "middlebury" / c.name;
  Config cfg;
  cfg.disparities = c.disparities;
  const Plane disp = disparity_map(load_yuv((dir / "left.png").string()),
                                   load_yuv((dir / "right.png").string()), cfg);
  const auto read = [&](const char* f) {
    return cv::imread((dir / f).string(), cv::IMREAD_UNCHANGED);
  };
  const ErrorRates e = evaluate(to_mat(disp), read("gt.png"), c.scale, read("nonocc.png"),
                                read("all.png"), read("disc.png"));
  std::printf("%s D=%d: nonocc %.4f all %.4f disc %.4f\n", c.name, c.disparities, e.nonocc, e.all,
              e.disc);
  EXPECT_LE(e.all, c.max_all);
  EXPECT_LE(e.nonocc, e.all + 1e-9);  // nonocc is a subset of all and excludes occlusions
}

INSTANTIATE_TEST_SUITE_P(Pairs, Middlebury,
                         ::testing::Values(PairCase{"tsukuba", 16, 16, 3.64},
                                           PairCase{"venus", 20, 8, 0.87},
                                           PairCase{"teddy", 60, 4, 15.12},
                                           PairCase{"cones", 60, 4, 11.46}),
                         [](const auto& info) { return std::string(info.param.name); });

// Post-processing (docs/algorithm.md section 12), guards from measurement
// (`mcadsw match --lr` / `--subpixel`, then `mcadsw eval`), rounded up to 0.01: LR
// "all" 3.44 / 0.41 / 12.36 / 9.00 (average 6.30; issue bar 6.5), sub-pixel
// "nonocc" at threshold 0.5 9.66 / 1.85 / 12.68 / 8.04 (Venus, Teddy, Cones
// average 7.52; bar 8.5).
struct PostCase {
  const char* name;
  int disparities;
  double scale;
  double max_lr_all, max_sub_nonocc;
};
void PrintTo(const PostCase& c, std::ostream* os) { *os << c.name << " D=" << c.disparities; }
class MiddleburyPost : public ::testing::TestWithParam<PostCase> {};

TEST_P(MiddleburyPost, LrAndSubpixelErrorsStayAtMeasuredLevel) {
  const PostCase& c = GetParam();
  const auto dir = kData / "middlebury" / c.name;
  Config cfg;
  cfg.disparities = c.disparities;
  const YuvImage l = load_yuv((dir / "left.png").string()), r = load_yuv((dir / "right.png").string());
  const auto read = [&](const char* f) { return cv::imread((dir / f).string(), cv::IMREAD_UNCHANGED); };
  DepthOptions lr;
  lr.lr = true;
  const ErrorRates e = evaluate(to_mat(depth_map(l, r, cfg, lr).disp8()), read("gt.png"), c.scale,
                                read("nonocc.png"), read("all.png"), read("disc.png"));
  DepthOptions sub;
  sub.subpixel = true;
  EvalOptions half;
  half.disp_scale = kSubpixelScale;
  half.threshold = 0.5;
  const ErrorRates s = evaluate(to_mat(depth_map(l, r, cfg, sub).disp16), read("gt.png"), c.scale,
                                read("nonocc.png"), read("all.png"), read("disc.png"), half);
  std::printf("%s D=%d: lr all %.4f, subpixel nonocc@0.5 %.4f\n", c.name, c.disparities, e.all, s.nonocc);
  EXPECT_LE(e.all, c.max_lr_all);
  EXPECT_LE(s.nonocc, c.max_sub_nonocc);
}

INSTANTIATE_TEST_SUITE_P(Pairs, MiddleburyPost,
                         ::testing::Values(PostCase{"tsukuba", 16, 16, 3.45, 9.67},
                                           PostCase{"venus", 20, 8, 0.42, 1.86},
                                           PostCase{"teddy", 60, 4, 12.37, 12.69},
                                           PostCase{"cones", 60, 4, 9.01, 8.05}),
                         [](const auto& info) { return std::string(info.param.name); });

// Regenerates a committed crop set (make_cif_crops SRC TMP [flag]) and compares
// every image of `names` in data/<set> with it, pixel for pixel.
void expect_crops_regenerate(const char* set, const std::string& flag,
                             std::initializer_list<const char*> names, int w = 352, int h = 288) {
  const auto tmp = std::filesystem::temp_directory_path() / (std::string("mcadsw_check_") + set);
  std::filesystem::remove_all(tmp);
  const std::string cmd = std::string(MCADSW_CIF_TOOL) + " " + (kData / "middlebury").string() +
                          " " + tmp.string() + flag + " > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  for (const char* name : names)
    for (const char* f : {"left.png", "right.png", "gt.png", "nonocc.png", "all.png", "disc.png"}) {
      const cv::Mat a = cv::imread((kData / set / name / f).string(), cv::IMREAD_UNCHANGED);
      const cv::Mat b = cv::imread((tmp / name / f).string(), cv::IMREAD_UNCHANGED);
      ASSERT_FALSE(a.empty()) << set << "/" << name << "/" << f;
      ASSERT_EQ(a.cols, w);
      ASSERT_EQ(a.rows, h);
      ASSERT_EQ(a.type(), b.type());
      EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0) << set << "/" << name << "/" << f;
    }
  std::filesystem::remove_all(tmp);
}

// data/cif is committed; regenerating it from data/middlebury must give the same pixels.
TEST(CifCrops, CommittedCropsMatchTheirGenerator) {
  expect_crops_regenerate("cif", "", {"tsukuba", "venus", "teddy", "cones"});
}

// data/cif_x2 and data/vga_x2 (2x upscaled Teddy and Cones, disparities above
// 64; CIF and VGA windows) likewise; the ground truth keeps its values (scale 2
// for the doubled disparities).
TEST(CifCrops, CommittedUpscaledCropsMatchTheirGenerator) {
  expect_crops_regenerate("cif_x2", " --x2", {"teddy", "cones"});
  expect_crops_regenerate("vga_x2", " --x2 --vga", {"teddy", "cones"}, 640, 480);
  for (const char* set : {"cif_x2", "vga_x2"})
    for (const char* name : {"teddy", "cones"}) {
      // Disparities well above 64 are there (the crop holds the most of them).
      double hi = 0;
      cv::minMaxLoc(cv::imread((kData / set / name / "gt.png").string(), cv::IMREAD_UNCHANGED),
                    nullptr, &hi);
      EXPECT_GT(hi / 2, 90) << set << "/" << name;
    }
}

}  // namespace
}  // namespace mcadsw

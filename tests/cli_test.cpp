// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The mcadsw CLI: results and bad input (one message, non-zero exit, no output left behind).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "cli_util.hpp"
#include "mcadsw/params.hpp"
#include "mcadsw/regs.hpp"

namespace {

const std::string kDRange = "out of range 1.." + std::to_string(mcadsw::kDmax);

namespace fs = std::filesystem;
using mcadsw::test::CliRun;
const fs::path kData = MCADSW_DATA_DIR;

CliRun run(const std::string& args) { return mcadsw::test::run_command(MCADSW_CLI, args); }

class Cli : public mcadsw::test::CliFixture {
 protected:
  std::string pair(const char* name = "tsukuba") const {
    const auto d = kData / "middlebury" / name;
    return (d / "left.png").string() + " " + (d / "right.png").string();
  }
};

TEST_F(Cli, HelpExitsZero) {
  const CliRun r = run("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.output.find("mcadsw match"), std::string::npos);
  EXPECT_NE(r.output.find("mcadsw eval"), std::string::npos);
}

TEST_F(Cli, VersionNamesTheReleaseAndTheRegisterMap) {
  const CliRun r = run("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.output, std::string("mcadsw ") + MCADSW_VERSION + " (register map " +
                          std::to_string(mcadsw::regs::kVersionMajor) + "." +
                          std::to_string(mcadsw::regs::kVersionMinor) + ")\n");
}

TEST_F(Cli, MatchThenEvalReproducesTheLibraryResult) {
  const CliRun m = run("match " + pair() + " -d 16 -o " + out_);
  ASSERT_EQ(m.status, 0) << m.output;
  const cv::Mat raw = cv::imread(out_, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(raw.type(), CV_8UC1);
  EXPECT_EQ(raw.cols, 384);
  double lo, hi;
  cv::minMaxLoc(raw, &lo, &hi);
  EXPECT_LE(hi, 15.0);
  const cv::Mat color = cv::imread((dir_ / "out_color.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_EQ(color.type(), CV_8UC3);
  const auto d = kData / "middlebury" / "tsukuba";
  const CliRun e = run("eval " + out_ + " " + (d / "gt.png").string() + " --scale 16 --masks " + d.string());
  ASSERT_EQ(e.status, 0) << e.output;
  EXPECT_NE(e.output.find("all 3.63"), std::string::npos) << e.output;  // docs/algorithm.md table
}

TEST_F(Cli, MissingFile) {
  expect_failure(run("match nonexistent.png " + (kData / "middlebury/tsukuba/right.png").string() +
                     " -d 16 -o " + out_),
                 "no such file");
}

TEST_F(Cli, CorruptImage) {
  const auto bad = dir_ / "corrupt.png";
  std::ofstream(bad) << "\x89PNG\r\n\x1a\n this is not a png";
  expect_failure(run("match " + bad.string() + " " + bad.string() + " -d 16 -o " + out_),
                 "not an image");
}

TEST_F(Cli, GrayscaleImage) {
  const auto gray = dir_ / "gray.png";
  cv::imwrite(gray.string(), cv::imread((kData / "middlebury/tsukuba/left.png").string(),
                                        cv::IMREAD_GRAYSCALE));
  expect_failure(run("match " + gray.string() + " " + gray.string() + " -d 16 -o " + out_),
                 "grayscale");
}

TEST_F(Cli, SizeMismatch) {
  expect_failure(run("match " + (kData / "middlebury/tsukuba/left.png").string() + " " +
                     (kData / "middlebury/venus/right.png").string() + " -d 16 -o " + out_),
                 "same size");
}

TEST_F(Cli, DisparityRangeOutOfRange) {
  expect_failure(run("match " + pair() + " -d 0 -o " + out_), kDRange);
  expect_failure(run("match " + pair() + " -d " + std::to_string(mcadsw::kDmax + 1) + " -o " + out_), kDRange);
  expect_failure(run("match " + pair() + " -d abc -o " + out_), "must be an integer");
}

// docs/algorithm.md section 12: --lr (8-bit map and validity mask), --subpixel
// (16-bit map of 16 x disparity), both together, and eval of a 16-bit map.
TEST_F(Cli, LeftRightCheckAndSubpixelOutputs) {
  const auto d = kData / "middlebury" / "tsukuba";
  const std::string eval_args = " " + (d / "gt.png").string() + " --scale 16 --masks " + d.string();
  const std::string mask = (dir_ / "valid.png").string();
  CliRun m = run("match " + pair() + " -d 16 --lr --valid " + mask + " -o " + out_);
  ASSERT_EQ(m.status, 0) << m.output;
  const cv::Mat lr = cv::imread(out_, cv::IMREAD_UNCHANGED), v = cv::imread(mask, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(lr.type(), CV_8UC1);
  ASSERT_EQ(v.type(), CV_8UC1);
  EXPECT_EQ(cv::countNonZero(v == 0) + cv::countNonZero(v == 255), v.rows * v.cols) << "mask is 0 or 255";
  EXPECT_GT(cv::countNonZero(v == 0), 0);
  CliRun e = run("eval " + out_ + eval_args);
  EXPECT_NE(e.output.find("all 3.44"), std::string::npos) << e.output;

  m = run("match " + pair() + " -d 16 --subpixel -o " + out_);
  ASSERT_EQ(m.status, 0) << m.output;
  const cv::Mat sub = cv::imread(out_, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(sub.type(), CV_16UC1);
  double lo, hi;
  cv::minMaxLoc(sub, &lo, &hi);
  EXPECT_LE(hi, 16.0 * 15);
  e = run("eval " + out_ + eval_args + " --disp-scale 16 --threshold 0.5");
  ASSERT_EQ(e.status, 0) << e.output;
  EXPECT_NE(e.output.find("nonocc 9.66"), std::string::npos) << e.output;
  e = run("eval " + out_ + eval_args);  // read as whole disparities: nearly every pixel bad
  EXPECT_EQ(e.status, 0);
  EXPECT_EQ(e.output.find("all 3."), std::string::npos) << e.output;

  m = run("match " + pair() + " -d 16 --lr --subpixel -T 2 -o " + out_);
  ASSERT_EQ(m.status, 0) << m.output;
  EXPECT_EQ(cv::imread(out_, cv::IMREAD_UNCHANGED).type(), CV_16UC1);
}

TEST_F(Cli, BadLeftRightAndEvalOptions) {
  expect_failure(run("match " + pair() + " -d 16 --lr -T 64 -o " + out_), "out of range 0..63");
  expect_failure(run("match " + pair() + " -d 16 --lr -T -1 -o " + out_), "out of range 0..63");
  expect_failure(run("match " + pair() + " -d 16 -T 2 -o " + out_), "need --lr");
  expect_failure(run("match " + pair() + " -d 16 --valid " + out_ + " -o " + out_), "need --lr");
  const auto d = kData / "middlebury" / "tsukuba";
  const std::string eval_args = " " + (d / "gt.png").string() + " --scale 16 --masks " + d.string();
  expect_failure(run("eval " + (d / "gt.png").string() + eval_args + " --disp-scale 0"), "positive");
  expect_failure(run("eval " + (d / "gt.png").string() + eval_args + " --threshold -1"), "positive");
}

TEST_F(Cli, MissingArgumentsAndUnknownOptions) {
  expect_failure(run("match " + pair() + " -o " + out_), "needs -d");
  expect_failure(run("match " + pair() + " -d 16"), "needs -o");
  expect_failure(run("match " + pair() + " -d 16 --bogus 1 -o " + out_), "unknown option");
  expect_failure(run("frobnicate"), "unknown command");
}

TEST_F(Cli, OutputDirectoryMissing) {
  const CliRun r = run("match " + pair() + " -d 16 -o " + (dir_ / "no/such/dir/out.png").string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
}

TEST_F(Cli, EvalSizeMismatchAndMissingMasks) {
  const auto t = kData / "middlebury" / "tsukuba";
  const auto v = kData / "middlebury" / "venus";
  CliRun r = run("eval " + (t / "gt.png").string() + " " + (v / "gt.png").string() + " --scale 16 --masks " +
              t.string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("size mismatch"), std::string::npos) << r.output;
  r = run("eval " + (t / "gt.png").string() + " " + (t / "gt.png").string() + " --scale 16 --masks " +
          dir_.string());
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("nonocc.png"), std::string::npos) << r.output;
}

}  // namespace

// mcadsw mesh / rectify (docs/algorithm.md 13): an OpenCV calibration file in, the
// mesh memory image of the size the frame needs and the rectified pair out; a bad
// calibration or step is one message and no output.
class CliRectify : public Cli {
 protected:
  std::string calib(bool drop_k2 = false) const {
    const std::string p = (dir_ / (drop_k2 ? "bad.yml" : "calib.yml")).string();
    cv::FileStorage f(p, cv::FileStorage::WRITE);
    f << "image_width" << 352 << "image_height" << 288;
    f << "K1" << cv::Mat(cv::Matx33d(300, 0, 170, 0, 305, 140, 0, 0, 1));
    f << "D1" << cv::Mat(cv::Matx<double, 1, 5>(-0.12, 0.03, 0.001, -0.0008, 0));
    if (!drop_k2) f << "K2" << cv::Mat(cv::Matx33d(310, 0, 180, 0, 312, 146, 0, 0, 1));
    f << "D2" << cv::Mat(cv::Matx<double, 1, 5>(-0.08, 0.01, -0.0005, 0.0007, 0));
    f << "R" << cv::Mat(cv::Matx33d::eye()) << "T" << cv::Mat(cv::Vec3d(-60, 0, 0));
    return p;
  }
  std::string cif_pair() const {
    const auto d = kData / "cif" / "teddy";
    return (d / "left.png").string() + " " + (d / "right.png").string();
  }
};

TEST_F(CliRectify, MeshAndRectifiedPair) {
  const std::string mesh = (dir_ / "mesh.bin").string();
  const CliRun m = run("mesh " + calib() + " --step 16 -o " + mesh);
  ASSERT_EQ(m.status, 0) << m.output;
  EXPECT_EQ(fs::file_size(mesh), 2u * 23 * 19 * 8) << "two views of 23 x 19 nodes, 8 bytes a node";
  const CliRun r = run("rectify " + calib() + " " + cif_pair() + " --step 8 -o " + (dir_ / "rect").string());
  ASSERT_EQ(r.status, 0) << r.output;
  for (const char* f : {"left.png", "right.png", "left_valid.png", "right_valid.png"}) {
    const cv::Mat img = cv::imread((dir_ / "rect" / f).string(), cv::IMREAD_UNCHANGED);
    ASSERT_FALSE(img.empty()) << f;
    EXPECT_EQ(img.cols, 352) << f;
  }
  const cv::Mat valid = cv::imread((dir_ / "rect" / "left_valid.png").string(), cv::IMREAD_UNCHANGED);
  EXPECT_GT(cv::countNonZero(valid), 352 * 288 / 2);
}

// match --calib (docs/algorithm.md 13.4): the raw pair of camera C (off-centre: invalid
// strips) rectified, then matched; every left pixel invalid after rectification (as
// `mcadsw rectify` reports it) carries the invalid code and mask 0, in the LR mode
// and with --subpixel.
TEST_F(CliRectify, MatchWithCalibrationMarksInvalidPixels) {
  const auto raw = kData / "raw" / "C" / "cif" / "teddy";
  const std::string cal = (raw / "calib.yml").string(),
                    views = (raw / "left.png").string() + " " + (raw / "right.png").string();
  const CliRun r = run("rectify " + cal + " " + views + " -o " + (dir_ / "rect").string());
  ASSERT_EQ(r.status, 0) << r.output;
  const cv::Mat lvalid = cv::imread((dir_ / "rect" / "left_valid.png").string(), cv::IMREAD_UNCHANGED);
  ASSERT_FALSE(lvalid.empty());
  const int invalid = int(lvalid.total()) - cv::countNonZero(lvalid);
  EXPECT_GT(invalid, 5000) << "camera C leaves an invalid strip";
  const std::string d8 = (dir_ / "d8.png").string(), mask = (dir_ / "mask.png").string(),
                    d16 = (dir_ / "d16.png").string();
  const CliRun m = run("match " + views + " -d 64 --lr --calib " + cal + " --valid " + mask + " -o " + d8);
  ASSERT_EQ(m.status, 0) << m.output;
  EXPECT_NE(m.output.find(std::to_string(invalid) + " left"), std::string::npos) << m.output;
  const CliRun s = run("match " + views + " -d 64 --subpixel --calib " + cal + " --step 8 -o " + d16);
  ASSERT_EQ(s.status, 0) << s.output;
  const cv::Mat a = cv::imread(d8, cv::IMREAD_UNCHANGED), v = cv::imread(mask, cv::IMREAD_UNCHANGED),
                b = cv::imread(d16, cv::IMREAD_UNCHANGED);
  ASSERT_EQ(a.type(), CV_8UC1);
  ASSERT_EQ(b.type(), CV_16UC1);
  int coded = 0;
  for (int y = 0; y < a.rows; ++y)
    for (int x = 0; x < a.cols; ++x) {
      if (lvalid.at<uint8_t>(y, x)) {
        ASSERT_LT(a.at<uint8_t>(y, x), 64) << x << "," << y;
        continue;
      }
      ++coded;
      ASSERT_EQ(a.at<uint8_t>(y, x), 255) << x << "," << y;
      ASSERT_EQ(v.at<uint8_t>(y, x), 0) << x << "," << y;
    }
  EXPECT_EQ(coded, invalid);
  EXPECT_GT(cv::countNonZero(b == 0xFFFF), invalid / 2) << "step 8 gives nearly the same strip";
}

TEST_F(CliRectify, BadCalibrationAndStep) {
  const CliRun k = run("mesh " + calib(true) + " -o " + (dir_ / "m.bin").string());
  EXPECT_EQ(k.status, 1);
  EXPECT_NE(k.output.find("no key K2"), std::string::npos) << k.output;
  EXPECT_FALSE(fs::exists(dir_ / "m.bin"));
  const CliRun s = run("mesh " + calib() + " --step 12 -o " + (dir_ / "m.bin").string());
  EXPECT_EQ(s.status, 2);
  EXPECT_NE(s.output.find("--step must be 8, 16 or 32"), std::string::npos) << s.output;
  const CliRun w = run("rectify " + calib() + " " + pair() + " -o " + (dir_ / "r").string());
  EXPECT_EQ(w.status, 1);
  EXPECT_NE(w.output.find("the calibration's images 352x288"), std::string::npos) << w.output;
  EXPECT_FALSE(fs::exists(dir_ / "r"));
  const CliRun ns = run("match " + pair() + " -d 16 --step 16 -o " + (dir_ / "x.png").string());
  EXPECT_EQ(ns.status, 2);
  EXPECT_NE(ns.output.find("--step needs --calib"), std::string::npos) << ns.output;
  const CliRun mw = run("match " + pair() + " -d 16 --calib " + calib() + " -o " + (dir_ / "x.png").string());
  EXPECT_EQ(mw.status, 1);
  EXPECT_NE(mw.output.find("the calibration's images 352x288"), std::string::npos) << mw.output;
  const CliRun mk = run("match " + cif_pair() + " -d 16 --calib " + calib(true) + " -o " + (dir_ / "x.png").string());
  EXPECT_EQ(mk.status, 1);
  EXPECT_NE(mk.output.find("no key K2"), std::string::npos) << mk.output;
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

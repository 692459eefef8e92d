// The mcadsw CLI: results and bad input (one message, non-zero exit, no output left behind).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "cli_util.hpp"
#include "mcadsw/params.hpp"

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

// The mcadsw CLI: results and bad input (one message, non-zero exit, no output left behind).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "cli_util.hpp"

namespace {

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
  expect_failure(run("match " + pair() + " -d 0 -o " + out_), "out of range 1..64");
  expect_failure(run("match " + pair() + " -d 65 -o " + out_), "out of range 1..64");
  expect_failure(run("match " + pair() + " -d abc -o " + out_), "must be an integer");
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

// The mcadsw CLI: results and bad input (one message, non-zero exit, no output left behind).
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <string>

namespace {

namespace fs = std::filesystem;
const fs::path kData = MCADSW_DATA_DIR;

struct CliRun {
  int status;
  std::string output;  // stdout and stderr
};

CliRun run(const std::string& args) {
  const std::string cmd = std::string(MCADSW_CLI) + " " + args + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buf;
  while (fgets(buf.data(), int(buf.size()), pipe.get())) out += buf.data();
  const int status = pclose(pipe.release());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("mcadsw_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    out_ = (dir_ / "out.png").string();
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string pair(const char* name = "tsukuba") const {
    const auto d = kData / "middlebury" / name;
    return (d / "left.png").string() + " " + (d / "right.png").string();
  }
  void expect_failure(const CliRun& r, const std::string& message) {
    EXPECT_NE(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out_));
    EXPECT_FALSE(fs::exists(dir_ / "out_color.png"));
  }
  fs::path dir_;
  std::string out_;
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

// The simulation harness `mcadsw_sim` on bad input: one clear message, a
// non-zero exit, no output left behind, and the engine is never started.
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

CliRun run(const std::string& args) { return mcadsw::test::run_command(MCADSW_SIM, args); }

class SimCli : public mcadsw::test::CliFixture {
 protected:
  static std::string view(const char* name, const char* side) {
    return (kData / "middlebury" / name / side).string();
  }
  // A small crop keeps the one successful run short.
  std::string pair() const { return view("tsukuba", "left.png") + " " + view("tsukuba", "right.png"); }
  std::string outputs() const { return " --out " + out_ + " --json " + (dir_ / "r.json").string(); }
  void expect_failure(const CliRun& r, const std::string& message) {
    CliFixture::expect_failure(r, message);
    EXPECT_FALSE(fs::exists(dir_ / "r.json"));
    EXPECT_EQ(r.output.find("cycles"), std::string::npos) << "the engine ran:\n" << r.output;
  }
};

TEST_F(SimCli, SmallCropRunsBitExact) {
  const CliRun r = run(pair() + " -d 8 --crop 100,100,30,20" + outputs());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("MATCH"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out_));
  EXPECT_TRUE(fs::exists(dir_ / "r.json"));
}

TEST_F(SimCli, WavesWritesAnFstFile) {
  const fs::path fst = dir_ / "w.fst";
  const CliRun r = run(pair() + " -d 4 --crop 100,100,20,10 --waves " + fst.string());
  EXPECT_EQ(r.status, 0) << r.output;
  ASSERT_TRUE(fs::exists(fst)) << r.output;
  EXPECT_GT(fs::file_size(fst), 1000u);
}

TEST_F(SimCli, MissingFile) {
  expect_failure(run("nonexistent.png " + view("tsukuba", "right.png") + " -d 16" + outputs()),
                 "no such file");
}

TEST_F(SimCli, CorruptImage) {
  const auto bad = dir_ / "corrupt.png";
  std::ofstream(bad) << "\x89PNG\r\n\x1a\n this is not a png";
  expect_failure(run(bad.string() + " " + bad.string() + " -d 16" + outputs()), "not an image");
}

TEST_F(SimCli, GrayscaleImage) {
  const auto gray = dir_ / "gray.png";
  cv::imwrite(gray.string(), cv::imread(view("tsukuba", "left.png"), cv::IMREAD_GRAYSCALE));
  expect_failure(run(gray.string() + " " + gray.string() + " -d 16" + outputs()), "grayscale");
}

TEST_F(SimCli, SizeMismatch) {
  expect_failure(run(view("tsukuba", "left.png") + " " + view("venus", "right.png") + " -d 16" + outputs()),
                 "same size");
}

TEST_F(SimCli, DisparityRangeOutOfRange) {
  expect_failure(run(pair() + " -d 0" + outputs()), "out of range 1..64");
  expect_failure(run(pair() + " -d 65" + outputs()), "out of range 1..64");
  expect_failure(run(pair() + " -d -3" + outputs()), "out of range 1..64");
  expect_failure(run(pair() + " -d abc" + outputs()), "must be an integer");
}

TEST_F(SimCli, BadArguments) {
  expect_failure(run(pair() + outputs()), "need -d D");
  expect_failure(run(view("tsukuba", "left.png") + " -d 16" + outputs()), "need LEFT and RIGHT");
  expect_failure(run(pair() + " -d 16 --bogus 1" + outputs()), "unknown option");
  expect_failure(run(pair() + " -d 16 --crop 1,2,3" + outputs()), "--crop takes X,Y,W,H");
  expect_failure(run(pair() + " -d 16 --crop 300,200,200,200" + outputs()), "not inside");
  expect_failure(run(pair() + " -d 16 --latency -1" + outputs()), "latency must not be negative");
  expect_failure(run(pair() + " -d 16 --gt x.png" + outputs()), "--gt needs");
  expect_failure(run(pair() + " -d 16 --out " + (dir_ / "no/such/dir/o.png").string()),
                 "does not exist");
}

}  // namespace

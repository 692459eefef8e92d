// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The simulation harness `mcadsw_sim` on bad input: one clear message, a
// non-zero exit, no output left behind, and the engine is never started.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/core/persistence.hpp>
#include <opencv2/imgcodecs.hpp>
#include <cmath>
#include <iterator>
#include <sstream>
#include <string>

#include "cli_util.hpp"
#include "mcadsw/params.hpp"

namespace {

const std::string kDRange = "out of range 1.." + std::to_string(mcadsw::kDmax);

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

// The verdict word of a result row, surrounded by spaces ("BIT-EXACT" or "FAILED").
bool has_word(const std::string& out, const std::string& word) {
  return out.find("  " + word + "  ") != std::string::npos;
}

TEST_F(SimCli, SmallCropRunsBitExact) {
  const CliRun r = run(pair() + " -d 8 --crop 100,100,30,20" + outputs());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has_word(r.output, "BIT-EXACT")) << r.output;
  EXPECT_FALSE(has_word(r.output, "FAILED")) << r.output;
  EXPECT_TRUE(fs::exists(out_));
  EXPECT_TRUE(fs::exists(dir_ / "r.json"));
}

// Rows 1000 bytes apart in memory: still exact, nothing read or written in the padding.
TEST_F(SimCli, LargeStrideRunsBitExact) {
  const CliRun r = run(pair() + " -d 8 --crop 100,100,30,20 --stride 1000" + outputs());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has_word(r.output, "BIT-EXACT")) << r.output;
  std::ifstream j(dir_ / "r.json");
  const std::string json((std::istreambuf_iterator<char>(j)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"stride\": 1000"), std::string::npos) << json;
  EXPECT_NE(json.find("\"bus_violations\": 0"), std::string::npos) << json;
}

TEST_F(SimCli, BadStride) {
  expect_failure(run(pair() + " -d 8 --stride 1002" + outputs()), "must be a multiple of 4");
  expect_failure(run(pair() + " -d 8 --stride 0" + outputs()), "must be a multiple of 4");
  expect_failure(run(pair() + " -d 8 --stride x" + outputs()), "must be a 32-bit unsigned integer");
  expect_failure(run(pair() + " -d 8 --stride 0x100000000" + outputs()), "must be a 32-bit unsigned integer");
  expect_failure(run(pair() + " -d 8 --crop 100,100,30,20 --stride 28" + outputs()),
                 "stride 28 is below the width 30");
}

// The frame's placement (--origin, --stride): an origin off a 4 KiB boundary, or
// planes that do not fit below 2^32, are refused with a message, nothing run.
TEST_F(SimCli, BadPlacement) {
  expect_failure(run(pair() + " -d 8 --crop 100,100,30,20 --origin 0x1004" + outputs()),
                 "origin 4100 must be a multiple of 4096");
  expect_failure(run(pair() + " -d 8 --crop 100,100,30,20 --origin -4096" + outputs()),
                 "must be a 32-bit unsigned integer");
  expect_failure(run(pair() + " -d 8 --crop 100,100,30,20 --origin 0xfffff000" + outputs()),
                 "do not fit in the 32-bit address space");
  expect_failure(run(pair() + " -d 8 --crop 100,100,30,20 --stride 0x10000000" + outputs()),
                 "do not fit in the 32-bit address space");
}

// The clock period of constraints/mcadsw.sdc, in ps.
long sdc_period_ps() {
  std::ifstream sdc(fs::path(MCADSW_SOURCE_DIR) / "constraints" / "mcadsw.sdc");
  std::string line;
  while (std::getline(sdc, line))
    if (line.rfind("set period ", 0) == 0) return std::lround(std::stod(line.substr(11)) * 1000);
  return 0;
}

// Waves in real time: a picosecond timescale, value changes only on the half
// periods of the sdc clock, and the last one about cycles x period after the start.
TEST_F(SimCli, WavesUseTheRealClockPeriod) {
  const fs::path fst = dir_ / "w.fst";
  const CliRun r = run(pair() + " -d 4 --crop 100,100,20,10 --waves " + fst.string() +
                       " --json " + (dir_ / "r.json").string());
  EXPECT_EQ(r.status, 0) << r.output;
  ASSERT_TRUE(fs::exists(fst)) << r.output;
  const long period = sdc_period_ps();
  ASSERT_GT(period, 0) << "no `set period` in constraints/mcadsw.sdc";
  std::ifstream j(dir_ / "r.json");
  const std::string json((std::istreambuf_iterator<char>(j)), std::istreambuf_iterator<char>());
  const long cycles = std::stol(json.substr(json.find("\"cycles\": ") + 10));
  const CliRun vcd = mcadsw::test::run_command("fst2vcd", fst.string());
  ASSERT_EQ(vcd.status, 0) << "fst2vcd (gtkwave) failed";
  std::istringstream in(vcd.output);
  std::string line, timescale;
  long last = -1, odd = 0;
  bool in_timescale = false;
  while (std::getline(in, line)) {
    if (line.find("$timescale") != std::string::npos) in_timescale = true;
    else if (in_timescale) {
      timescale = line.substr(line.find_first_not_of(" \t"));
      in_timescale = false;
    }
    if (line.size() > 1 && line[0] == '#') {
      last = std::stol(line.substr(1));
      if (last % (period / 2) != 0) ++odd;
    }
  }
  EXPECT_EQ(timescale, "1ps");
  EXPECT_EQ(odd, 0) << "time stamps off the half periods of " << period << " ps";
  // Reset (4 cycles), the register writes that program and start the engine and
  // the status reads after the frame (AXI4-Lite with random stalls: 26 writes
  // and 6 reads, a few hundred cycles) come on top of the counted cycles.
  EXPECT_GE(last, cycles * period);
  EXPECT_LE(last, (cycles + 600) * period);
}

// mcadsw_sim's model is not traced; --waves runs mcadsw_sim_waves beside it (above). Without
// that executable: a message naming the target to build, exit 2, no wave file.
TEST_F(SimCli, WavesWithoutTheTracedModelNameWhatToBuild) {
  const fs::path alone = dir_ / "alone" / "mcadsw_sim";
  fs::create_directories(alone.parent_path());
  fs::copy_file(MCADSW_SIM, alone);
  const fs::path fst = dir_ / "w.fst";
  const CliRun r = mcadsw::test::run_command(alone.string(), pair() + " -d 4 --crop 100,100,20,10 --waves " +
                                                                 fst.string() + outputs());
  expect_failure(r, "--target mcadsw_sim_waves");
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(fs::exists(fst));
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
  expect_failure(run(pair() + " -d 0" + outputs()), kDRange);
  expect_failure(run(pair() + " -d " + std::to_string(mcadsw::kDmax + 1) + outputs()), kDRange);
  expect_failure(run(pair() + " -d -3" + outputs()), kDRange);
  expect_failure(run(pair() + " -d abc" + outputs()), "must be an integer");
}

// The LR mode: output, mask and both scratch maps compared; -T as `mcadsw match`.
TEST_F(SimCli, LrCropRunsBitExact) {
  const CliRun r = run(pair() + " -d 12 --crop 100,100,30,20 --lr -T 2 --subpixel" + outputs());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has_word(r.output, "BIT-EXACT")) << r.output;
  std::ifstream j(dir_ / "r.json");
  const std::string json((std::istreambuf_iterator<char>(j)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"lr\": true"), std::string::npos) << json;
}

TEST_F(SimCli, BadLrOptions) {
  expect_failure(run(pair() + " -d 16 --lr --right" + outputs()), "--lr and --right do not combine");
  expect_failure(run(pair() + " -d 16 --lr -T 64" + outputs()), "out of range 0..63");
  expect_failure(run(pair() + " -d 16 --lr -T -1" + outputs()), "out of range 0..63");
  // Wider than the post stage's rows (1024).
  cv::Mat wide(8, 1030, CV_8UC3, cv::Scalar(40, 80, 120));
  const std::string l = (dir_ / "wl.png").string(), rr = (dir_ / "wr.png").string();
  ASSERT_TRUE(cv::imwrite(l, wide) && cv::imwrite(rr, wide));
  expect_failure(run(l + " " + rr + " -d 16 --lr" + outputs()), "the LR mode takes widths up to 1024");
}

// Rectification: raw camera views and their calibration; a region of the
// rectified frame on whole mesh cells; the rectified planes and bitmaps compared too.
std::string raw_view(const char* camera, const char* side) {
  return (kData / "raw" / camera / "cif" / "teddy" / side).string();
}
std::string raw_pair(const char* camera) { return raw_view(camera, "left.png") + " " + raw_view(camera, "right.png"); }

TEST_F(SimCli, RectifiedCropRunsBitExact) {
  const CliRun r = run(raw_pair("C") + " -d 8 --calib " + raw_view("C", "calib.yml") +
                       " --step 8 --crop 16,8,32,16 --lr" + outputs());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(has_word(r.output, "BIT-EXACT")) << r.output;
  EXPECT_NE(r.output.find("rect S=8"), std::string::npos) << r.output;
  std::ifstream j(dir_ / "r.json");
  const std::string json((std::istreambuf_iterator<char>(j)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("\"rect\": true"), std::string::npos) << json;
}

// Bad rectification input: a clear message, the engine never started.
TEST_F(SimCli, BadRectificationInput) {
  const std::string calib = raw_view("B", "calib.yml");
  expect_failure(run(raw_pair("B") + " -d 16 --calib " + calib + " --step 7" + outputs()), "--step must be 8, 16 or 32");
  expect_failure(run(raw_pair("B") + " -d 16 --step 8" + outputs()), "--step needs --calib or --mesh");
  expect_failure(run(raw_pair("B") + " -d 16 --calib " + calib + " --mesh m.bin" + outputs()),
                 "--calib and --mesh do not combine");
  expect_failure(run(raw_pair("B") + " -d 16 --calib " + calib + " --crop 4,0,32,16" + outputs()),
                 "multiples of the mesh step");
  expect_failure(run(raw_pair("B") + " -d 16 --calib " + (dir_ / "none.yml").string() + outputs()), "calibration");
  // A calibration without P2.
  const fs::path partial = dir_ / "partial.yml";
  {
    cv::FileStorage in(calib, cv::FileStorage::READ), out(partial.string(), cv::FileStorage::WRITE);
    for (const char* k : {"image_width", "image_height"}) out << k << int(in[k]);
    for (const char* k : {"K1", "D1", "R1", "P1", "K2", "D2", "R2"}) out << k << in[k].mat();
  }
  expect_failure(run(raw_pair("B") + " -d 16 --calib " + partial.string() + outputs()), "no key");
  // The calibration's image size is not the raw views'.
  expect_failure(run(view("tsukuba", "left.png") + " " + view("tsukuba", "right.png") + " -d 16 --calib " + calib +
                     outputs()),
                 "the calibration's images");
  // A mesh image of the wrong size (a few bytes).
  const fs::path mesh = dir_ / "short.bin";
  std::ofstream(mesh, std::ios::binary) << "0123456789";
  expect_failure(run(raw_pair("B") + " -d 16 --mesh " + mesh.string() + outputs()), "bytes");
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

// The whole engine (mcadsw_top) in the modelled memory, against the reference:
// every pixel of the disparity plane, nothing written outside it. Small pairs
// so that the suite stays fast; `make sim` runs the full-size regression.
#include <gtest/gtest.h>

#include <random>

#include "engine_bench.hpp"
#include "mcadsw/image_io.hpp"
#include "mcadsw/ref.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

using sim::EngineOptions;
using sim::EngineResult;

void expect_exact(const EngineResult& r) {
  EXPECT_FALSE(r.timed_out) << "engine did not finish";
  EXPECT_FALSE(r.error) << "configuration rejected, code " << r.error_code;
  EXPECT_EQ(r.mismatches, 0) << r.report;
  EXPECT_EQ(r.bad_writes, 0) << r.report;
  std::printf("%dx%d D=%d: %ld cycles, %ld words read, %ld written, %ld stall cycles\n", r.width,
              r.height, r.disparities, r.cycles, r.words_read, r.words_written, r.stall_cycles);
}

YuvImage crop(const YuvImage& img, int x0, int y0, int w, int h) {
  YuvImage c{Plane(w, h), Plane(w, h), Plane(w, h)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      c.y.at(x, y) = img.y.at(x0 + x, y0 + y);
      c.u.at(x, y) = img.u.at(x0 + x, y0 + y);
      c.v.at(x, y) = img.v.at(x0 + x, y0 + y);
    }
  return c;
}

TEST(Engine, RandomPairSmallerThanOneBlock) {
  std::mt19937 rng(1);
  Config cfg;
  cfg.disparities = 8;
  expect_exact(sim::run_engine(test::random_yuv(13, 9, rng), test::random_yuv(13, 9, rng), cfg, {}));
}

TEST(Engine, RandomPairWithPartialBlocks) {
  std::mt19937 rng(2);
  Config cfg;
  cfg.disparities = 12;
  cfg.table = make_weight_table(60.0);
  expect_exact(sim::run_engine(test::random_yuv(41, 23, rng), test::random_yuv(41, 23, rng), cfg, {}));
}

TEST(Engine, TeddyCropAtDmaxWithRandomLatency) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/cif/teddy/";
  const YuvImage l = crop(load_yuv(dir + "left.png"), 100, 100, 74, 38);
  const YuvImage r = crop(load_yuv(dir + "right.png"), 100, 100, 74, 38);
  Config cfg;
  cfg.disparities = kDmax;
  EngineOptions opt;
  opt.latency.random = true;
  opt.latency.seed = 7;
  expect_exact(sim::run_engine(l, r, cfg, opt));
}

TEST(Engine, FixedLatencyAndSingleDisparity) {
  std::mt19937 rng(3);
  Config cfg;
  cfg.disparities = 1;
  EngineOptions opt;
  opt.latency.fixed = 3;
  expect_exact(sim::run_engine(test::random_yuv(37, 20, rng), test::random_yuv(37, 20, rng), cfg, opt));
}

// Invalid configurations: the engine reports the error code of docs/memory_map.md,
// finishes at once and writes nothing.
TEST(Engine, RejectsInvalidConfigurationsAndWritesNothing) {
  const sim::RawConfig good{0x1000, 0x2000, 0x3000, 0x4000, 0x5000, 64, 60, 40, 16};
  struct Bad {
    const char* what;
    sim::RawConfig cfg;
    int code;
  };
  std::vector<Bad> bad;
  auto with = [&](const char* what, int code, auto change) {
    sim::RawConfig c = good;
    change(c);
    bad.push_back({what, c, code});
  };
  with("width 0", 1, [](auto& c) { c.width = 0; });
  with("width above the maximum", 1, [](auto& c) { c.width = kMaxWidth + 1; });
  with("height 0", 2, [](auto& c) { c.height = 0; });
  with("D = 0", 3, [](auto& c) { c.disparities = 0; });
  with("D above DMAX", 3, [](auto& c) { c.disparities = kDmax + 1; });
  with("stride below width", 4, [](auto& c) { c.stride = 56; });
  with("stride not a multiple of 4", 4, [](auto& c) { c.stride = 66; });
  with("misaligned base", 5, [](auto& c) { c.base_lu = 0x2002; });
  with("output overlaps the right view", 6, [](auto& c) { c.base_out = 0x4000 + 64; });
  for (const Bad& b : bad) {
    const sim::EngineResult r = sim::run_raw(b.cfg, {}, 1000);
    EXPECT_FALSE(r.timed_out) << b.what;
    EXPECT_TRUE(r.error) << b.what;
    EXPECT_EQ(r.error_code, b.code) << b.what;
    EXPECT_EQ(r.bad_writes, 0) << b.what << ": the engine wrote to memory";
  }
}

}  // namespace
}  // namespace mcadsw

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The whole engine (mcadsw_engine) in the modelled memory, against the reference:
// every pixel of the disparity plane, nothing written outside it. Small pairs
// so that the suite stays fast; `make sim` runs the full-size regression.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "Vmcadsw_top.h"
#include "engine_bench.hpp"
#include "engine_expect.hpp"
#include "mcadsw/image_io.hpp"
#include "mcadsw/rectify.hpp"
#include "mcadsw/ref.hpp"
#include "mcadsw/regs.hpp"
#include "random_mesh.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

using sim::EngineOptions;
using sim::EngineResult;

using test::expect_exact;

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
  opt.memory.latency.random = true;
  opt.memory.latency.seed = 7;
  expect_exact(sim::run_engine(l, r, cfg, opt));
}

TEST(Engine, FixedLatencyAndSingleDisparity) {
  std::mt19937 rng(3);
  Config cfg;
  cfg.disparities = 1;
  EngineOptions opt;
  opt.memory.latency.fixed = 3;
  expect_exact(sim::run_engine(test::random_yuv(37, 20, rng), test::random_yuv(37, 20, rng), cfg, opt));
}

// Frames back to back through one engine, no reset between them: sizes, D and
// weight tables change from frame to frame, and each frame is exact.
TEST(Engine, BackToBackFramesWithoutReset) {
  std::mt19937 rng(4);
  std::vector<sim::Frame> frames;
  auto add = [&](int w, int h, int d, double gamma) {
    Config cfg;
    cfg.disparities = d;
    cfg.table = make_weight_table(gamma);
    frames.push_back({test::random_yuv(w, h, rng), test::random_yuv(w, h, rng), cfg});
  };
  add(41, 23, 12, 22.0);
  add(13, 9, 8, 60.0);
  add(37, 20, 1, 10.0);
  EngineOptions opt;
  opt.memory.latency.random = true;
  opt.memory.latency.seed = 11;
  for (const EngineResult& r : sim::run_frames(frames, opt)) expect_exact(r);
}

// Reset in the middle of a frame (engine and memory system), then the same
// frame from the start and another one: both exact, nothing written elsewhere.
TEST(Engine, ResetInMidFrameThenCleanFrames) {
  std::mt19937 rng(5);
  Config cfg;
  cfg.disparities = 12;
  std::vector<sim::Frame> frames;
  frames.push_back({test::random_yuv(41, 23, rng), test::random_yuv(41, 23, rng), cfg});
  frames.push_back({test::random_yuv(20, 30, rng), test::random_yuv(20, 30, rng), cfg});
  // Early, in the middle and late in the first frame, whatever its length.
  const long frame0 = sim::run_frames({frames[0]}, {}).at(0).cycles;
  for (long at : {50L, frame0 * 2 / 5, frame0 * 9 / 10}) {
    SCOPED_TRACE("reset after " + std::to_string(at) + " cycles");
    for (const EngineResult& r :
         sim::run_frames(frames, {}, {sim::Fault::kResetMidFrame, at}))
      expect_exact(r);
  }
}

// start_i while busy is ignored, whatever the configuration ports then hold:
// the frame is exact, takes as many cycles as without the second start, and
// its status shows no error. Cycle 1 is the cycle after the accepted start
// (busy_o already high, the scheduler not yet started).
TEST(Engine, StartWhileBusyIsIgnored) {
  std::mt19937 rng(6);
  Config cfg;
  cfg.disparities = 12;
  const std::vector<sim::Frame> frames{
      {test::random_yuv(41, 23, rng), test::random_yuv(41, 23, rng), cfg}};
  const EngineResult clean = sim::run_frames(frames, {}).at(0);
  expect_exact(clean);
  // The frame's planes are at 0x1000..0x5000 (sim::run_frames, origin 0); the
  // other valid configuration names the same planes with another size and D.
  const sim::RawConfig valid{0x1000, 0x2000, 0x3000, 0x4000, 0x5000, 24, 24, 20, 10, 5};
  sim::RawConfig invalid = valid;
  invalid.width = 0;
  for (const auto& [what, other] : {std::pair{"a valid other", valid}, std::pair{"an invalid", invalid}})
    for (long at : {1L, 2L, 7000L}) {
      SCOPED_TRACE(std::string(what) + " configuration, second start " + std::to_string(at) +
                   " cycles after the first");
      const EngineResult r =
          sim::run_frames(frames, {}, {sim::Fault::kStartWhileBusy, at, other}).at(0);
      expect_exact(r);
      EXPECT_EQ(r.error_code, 0);
      EXPECT_EQ(r.cycles, clean.cycles) << "a start while busy changed the frame";
      EXPECT_EQ(r.words_read, clean.words_read);
      EXPECT_EQ(r.words_written, clean.words_written);
    }
}

// Rows far apart in memory (stride much larger than the width) and random
// memory timing: exact, and the memory model sees no read or write outside the
// planes' pixels (the padding between width and stride is neither read nor
// written).
TEST(Engine, LargeStrideWithRandomLatency) {
  std::mt19937 rng(8);
  Config cfg;
  cfg.disparities = 20;
  EngineOptions opt;
  opt.frame.stride = 1000;
  opt.memory.latency.random = true;
  opt.memory.latency.seed = 3;
  expect_exact(sim::run_engine(test::random_yuv(43, 22, rng), test::random_yuv(43, 22, rng), cfg, opt));
}

// Costs near the top of the accumulators: no other test reaches the upper bits
// of the 25-bit final cost (`make mutate` showed mutants there surviving; those
// turned out equivalent, but the carries into the top bits were untested). The
// weight table gives every colour distance the largest weight (64), the left view
// is a texture (Y = 128 +- 2), the right view its negative (census codes inverted
// wherever no neighbour ties with the centre), so the final costs come close to
// 2^25. Raw and sub-pixel output (the offset depends on the cost differences).
TEST(Engine, CostsNearTheAccumulatorsTopBits) {
  std::mt19937 rng(12);
  const int w = 44, h = 36;
  YuvImage l = test::flat_yuv(w, h, 128), r = test::flat_yuv(w, h, 128);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      l.y.at(x, y) = uint8_t(126 + int(rng() % 5));
      r.y.at(x, y) = uint8_t(255 - l.y.at(x, y));
    }
  Config cfg;
  cfg.disparities = 9;
  for (auto& v : cfg.table) v = uint8_t(weight_from_code(7));
  Intermediates keep;
  disparity_map_blocks(l, r, cfg, &keep);
  uint32_t top = 0;
  for (const auto& fc : keep.final_cost) top = std::max(top, *std::max_element(fc.begin(), fc.end()));
  EXPECT_GE(top, 1u << 24) << "the stimulus no longer reaches the final cost's top bit";
  for (const bool sub : {false, true}) {
    SCOPED_TRACE(sub ? "sub-pixel" : "raw");
    EngineOptions opt;
    opt.frame.subpixel = sub;
    expect_exact(sim::run_engine(l, r, cfg, opt));
  }
}

// The right edge under the largest weights: window columns right of the image
// must take the edge column's cost (the ping-pong buffer's edge rule), and with
// every weight 64 and a faint texture (Y = 126 .. 130, where census bits flip on
// differences of 1) in both views, a wrong cost there moves disparities of the
// last 15 columns. Four widths, so that the last in-image column of the last two
// blocks takes every value mod 4. (Written while analysing a `make mutate`
// survivor in the census transformer's right bound, which this edge rule makes
// equivalent: tests/mutate/survivors.txt.)
TEST(Engine, FaintTextureAtTheRightEdge) {
  std::mt19937 rng(17);
  Config cfg;
  cfg.disparities = 6;
  for (auto& v : cfg.table) v = uint8_t(weight_from_code(7));
  for (const int w : {40, 41, 42, 43}) {
    SCOPED_TRACE("width " + std::to_string(w));
    YuvImage l = test::flat_yuv(w, 8, 128), r = test::flat_yuv(w, 8, 128);
    for (Plane* p : {&l.y, &r.y})
      for (auto& v : p->px) v = uint8_t(126 + int(rng() % 5));
    expect_exact(sim::run_engine(l, r, cfg, {}));
  }
}

// Colour distances at weight thresholds above 255 (found by `make mutate`: a
// threshold compare with bit 1 of a threshold of 256 or more toggled survived; the
// default table's thresholds lie below 256). The table halves the weight every 4
// levels from 258 to 282 (every threshold has bits 8 and 1 set) and noise pairs
// put many of a window's colour distances (sum of three absolute differences,
// centred near 255) within 2 of a threshold; raw and sub-pixel output.
TEST(Engine, ColourDistancesAtThresholdsAbove255) {
  std::mt19937 rng(16);
  const auto table_from = [](int first) {
    WeightTable t(kWeightTableSize);
    for (int dc = 0; dc < kWeightTableSize; ++dc) {
      const int halvings = dc < first ? 0 : 1 + (dc - first) / 4;
      t[dc] = halvings > kWeightShiftMax ? 0 : uint8_t(kWeightMax >> halvings);
    }
    return t;
  };
  Config cfg;
  cfg.disparities = 11;
  cfg.table = table_from(258);
  check_weight_table(cfg.table);
  const YuvImage l = test::random_yuv(40, 26, rng), r = test::random_yuv(40, 26, rng);
  // The stimulus reaches the thresholds: every threshold 2 lower changes many pixels.
  Config lower = cfg;
  lower.table = table_from(256);
  const Plane a = disparity_map_blocks(l, r, cfg), b = disparity_map_blocks(l, r, lower);
  long changed = 0;
  for (size_t i = 0; i < a.px.size(); ++i) changed += a.px[i] != b.px[i];
  EXPECT_GT(changed, 20) << "thresholds 2 lower change too few pixels: the test is weak";
  for (const bool sub : {false, true}) {
    SCOPED_TRACE(sub ? "sub-pixel" : "raw");
    EngineOptions opt;
    opt.frame.subpixel = sub;
    expect_exact(sim::run_engine(l, r, cfg, opt));
  }
}

// The widest frame (kMaxWidth columns): column and address bits above 1023 (found by
// `make mutate`: the random cases this wide were flat, striped or a real crop
// replicated beyond its border, so a column read 1024 too far left gave the same
// pixels). Noise in both views; left and right view as base, raster and tiled;
// the LR mode at its widest.
TEST(Engine, WidestFrameOfNoise) {
  std::mt19937 rng(13);
  const YuvImage l = test::random_yuv(kMaxWidth, 3, rng), r = test::random_yuv(kMaxWidth, 3, rng);
  Config cfg;
  cfg.disparities = 5;
  for (const bool right : {false, true})
    for (const bool tiled : {false, true}) {
      SCOPED_TRACE(std::string(right ? "right" : "left") + " view as base, " + (tiled ? "tiled" : "raster"));
      EngineOptions opt;
      opt.frame.right = right;
      opt.frame.tiled = tiled;
      expect_exact(sim::run_engine(l, r, cfg, opt));
    }
  // The LR mode at the post stage's widest (kPostMaxWidth): its column bits,
  // raw and sub-pixel (twice the dL words a row).
  for (const bool sub : {false, true}) {
    SCOPED_TRACE(std::string("LR mode") + (sub ? ", sub-pixel" : ""));
    EngineOptions lr;
    lr.frame.lr = true;
    lr.frame.subpixel = sub;
    expect_exact(sim::run_engine(crop(l, 0, 0, kPostMaxWidth, 3), crop(r, 0, 0, kPostMaxWidth, 3), cfg, lr));
  }
}

// The planes in the reverse order in memory (written planes below the ones
// read): every overlap comparison of the configuration check (error 6) is then
// decided the other way (found by `make mutate`: with the harness's one order, a
// mutant of a comparison between the mask and the right view's V plane passed).
// From the origin 0 and from 1 MiB: there the planes read have address bit 20
// set and the planes written end less than 1 MiB below them, so a compare that
// loses that bit of a base (found by `make mutate`: below()'s base_by bit 20
// forced to 0) rejects this valid frame as an overlap.
TEST(Engine, PlanesInReverseOrder) {
  std::mt19937 rng(14);
  const YuvImage l = test::random_yuv(30, 19, rng), r = test::random_yuv(30, 19, rng);
  Config cfg;
  cfg.disparities = 7;
  for (const uint32_t origin : {0u, 0x100000u}) {
    for (const int mode : {0, 1, 2}) {
      SCOPED_TRACE(std::string(mode == 0 ? "left view as base" : mode == 1 ? "right view as base" : "LR mode") +
                   ", origin " + std::to_string(origin));
      EngineOptions opt;
      opt.frame.reversed_planes = true;
      opt.frame.origin = origin;
      opt.frame.right = mode == 1;
      opt.frame.lr = mode == 2;
      expect_exact(sim::run_engine(l, r, cfg, opt));
    }
  }
}

// Sub-pixel mode (docs/algorithm.md 12.6): every 16-bit value equal to the
// reference's, under random memory timing, with an output stride of its own
// far beyond the row (the memory model checks that no padding byte is
// written); D = 1 and D = 2 reach the d = 0 and d = D - 1 rules at every pixel.
TEST(Engine, SubpixelOutputMatchesReference) {
  std::mt19937 rng(9);
  for (const int d : {1, 2, 23}) {
    SCOPED_TRACE("D = " + std::to_string(d));
    Config cfg;
    cfg.disparities = d;
    EngineOptions opt;
    opt.frame.subpixel = true;
    opt.frame.stride = 48;
    opt.frame.out_stride = 300;
    opt.memory.latency.random = true;
    opt.memory.latency.seed = uint32_t(d);
    const EngineResult r =
        sim::run_engine(test::random_yuv(41, 21, rng), test::random_yuv(41, 21, rng), cfg, opt);
    expect_exact(r);
    ASSERT_EQ(r.disparity16.width, 41);
    bool offset_seen = false;
    for (uint16_t v : r.disparity16.px) offset_seen |= v % kSubpixelScale != 0;
    if (d > 2) {
      EXPECT_TRUE(offset_seen) << "no pixel has a sub-pixel offset: the test is weak";
    }
  }
}

// The right view as base (docs/algorithm.md 12.1): the pass runs mirrored about
// the width rounded up to 4, so every width modulo 4 shifts the image inside
// the pass differently (W = 40..43); raw and sub-pixel output, random memory
// timing, strides beyond the rows. The memory model checks that only the
// right view's Y, U, V and the left view's Y are read.
TEST(Engine, RightViewAsBaseMatchesReference) {
  std::mt19937 rng(10);
  for (const int w : {40, 41, 42, 43})
    for (const bool sub : {false, true}) {
      SCOPED_TRACE("W = " + std::to_string(w) + (sub ? ", sub-pixel" : ", raw"));
      Config cfg;
      cfg.disparities = 17;
      EngineOptions opt;
      opt.frame.right = true;
      opt.frame.subpixel = sub;
      opt.frame.stride = 64;
      opt.frame.out_stride = sub ? 100 : 48;
      opt.memory.latency.random = true;
      opt.memory.latency.seed = uint32_t(w);
      expect_exact(sim::run_engine(test::random_yuv(w, 20, rng), test::random_yuv(w, 20, rng), cfg, opt));
    }
}

// The LR mode (docs/algorithm.md 12.2-12.5): left map, right map, post stage. Teddy
// crops of every width modulo 4 (the right pass runs mirrored about the width
// rounded up to 4), 8-bit and sub-pixel, T = 0, 1 and 7, random memory timing,
// strides beyond the rows. The scoreboard compares the output, the mask and both
// scratch maps; the memory model checks that each of the four written planes is
// written once a byte and that only the inputs and the scratch planes are read.
TEST(Engine, LrModeMatchesReference) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/cif/teddy/";
  const YuvImage left = load_yuv(dir + "left.png"), right = load_yuv(dir + "right.png");
  int k = 0;
  for (const int w : {40, 41, 42, 43})
    for (const bool sub : {false, true}) {
      const int tol = (k % 3 == 0) ? 0 : (k % 3 == 1) ? 1 : 7;
      SCOPED_TRACE("W = " + std::to_string(w) + (sub ? ", sub-pixel" : ", 8-bit") + ", T = " +
                   std::to_string(tol));
      Config cfg;
      cfg.disparities = 23;
      EngineOptions opt;
      opt.frame.lr = true;
      opt.frame.lr_tolerance = tol;
      opt.frame.subpixel = sub;
      opt.frame.stride = 64;
      opt.frame.out_stride = sub ? 100 : 48;
      opt.memory.latency.random = k % 2 == 0;
      opt.memory.latency.seed = uint32_t(w);
      const EngineResult r = sim::run_engine(crop(left, 120 + 7 * k, 110, w, 21),
                                             crop(right, 120 + 7 * k, 110, w, 21), cfg, opt);
      expect_exact(r);
      // Both outcomes of the check occur, or the case tests little.
      long valid = 0;
      for (uint8_t v : r.mask.px) valid += v != 0;
      EXPECT_GT(valid, 0);
      EXPECT_LT(valid, long(r.mask.px.size()));
      ++k;
    }
}

// The LR mode's three passes under the faults of the raw mode: frames back to
// back without a reset, a reset in each pass (the post stage included) followed
// by clean frames, and a start while the post stage runs (ignored).
TEST(Engine, LrModeFaultsAndBackToBackFrames) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/cif/teddy/";
  const YuvImage left = load_yuv(dir + "left.png"), right = load_yuv(dir + "right.png");
  Config c1, c2;
  c1.disparities = 13;
  c2.disparities = 20;
  const std::vector<sim::Frame> frames{{crop(left, 150, 90, 37, 19), crop(right, 150, 90, 37, 19), c1},
                                       {crop(left, 60, 140, 22, 25), crop(right, 60, 140, 22, 25), c2}};
  EngineOptions opt;
  opt.frame.lr = true;
  opt.frame.subpixel = true;
  opt.frame.lr_tolerance = 2;
  const std::vector<EngineResult> clean = sim::run_frames(frames, opt);
  for (const EngineResult& r : clean) expect_exact(r);
  const long frame0 = clean.at(0).cycles;
  // Left pass, right pass, post stage (the last few per cent of the frame).
  for (long at : {frame0 / 5, frame0 * 3 / 5, frame0 * 97 / 100}) {
    SCOPED_TRACE("reset after " + std::to_string(at) + " of " + std::to_string(frame0) + " cycles");
    for (const EngineResult& r : sim::run_frames(frames, opt, {sim::Fault::kResetMidFrame, at}))
      expect_exact(r);
  }
  // A second start (with the same, valid, configuration on the ports) in the post stage.
  const sim::RawConfig other{0x1000, 0x2000, 0x3000, 0x4000, 0x5000, 24, 24, 20, 10, 5};
  const EngineResult r =
      sim::run_frames({frames[0]}, opt, {sim::Fault::kStartWhileBusy, frame0 * 97 / 100, other}).at(0);
  expect_exact(r);
  EXPECT_EQ(r.cycles, frame0) << "a start while busy changed the frame";
  EXPECT_EQ(r.words_written, clean.at(0).words_written);
}

// A rejected start: finished at once with DONE and ERROR and the code, STATUS steady
// over later reads, nothing read or written.
void expect_rejected(const EngineResult& r, int code, const std::string& what) {
  EXPECT_FALSE(r.timed_out) << what;
  EXPECT_TRUE(r.error) << what;
  EXPECT_TRUE(r.done) << what << ": STATUS.DONE not set by the rejected start";
  EXPECT_EQ(r.error_code, code) << what << ": " << regs::error_text(r.error_code);
  EXPECT_EQ(r.status_changes, 0) << what << ": STATUS changed between reads";
  EXPECT_EQ(r.bus.bad_writes, 0) << what << ": the engine wrote to memory";
  EXPECT_EQ(r.bus.bad_reads, 0) << what << ": the engine read memory";
}

// Variants of a good configuration, each with the code the engine must reject it with
// (0: accepted).
struct BadConfigs {
  struct Bad {
    const char* what;
    sim::RawConfig cfg;
    int code;
  };
  sim::RawConfig good;
  std::vector<Bad> list;
  template <class Change>
  void add(const char* what, int code, Change change) {
    sim::RawConfig c = good;
    change(c);
    list.push_back({what, c, code});
  }
};

// ---- Rectification (docs/blocks/rectifier.md) -----------------------------------
// A raw pair: crops of camera B's raw Teddy views (real texture), of raw_w x raw_h.
std::pair<YuvImage, YuvImage> raw_crops(int raw_w, int raw_h, std::mt19937& rng) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/raw/B/cif/teddy/";
  const YuvImage l = load_yuv(dir + "left.png"), r = load_yuv(dir + "right.png");
  const int x = std::uniform_int_distribution<int>(0, l.width() - raw_w)(rng);
  const int y = std::uniform_int_distribution<int>(0, l.height() - raw_h)(rng);
  return {crop(l, x, y, raw_w, raw_h), crop(r, x, y, raw_w, raw_h)};
}

// One rectified frame at D disparities (at most DMAX): every output pixel, the rectified
// planes and both validity bitmaps equal the reference's.
void expect_rectified(const YuvImage& raw_l, const YuvImage& raw_r, const EngineOptions& opt, int d) {
  Config cfg;
  cfg.disparities = std::min(d, kDmax);
  const EngineResult r = sim::run_engine(raw_l, raw_r, cfg, opt);
  expect_exact(r);
  EXPECT_EQ(r.rect_mismatches, 0);
}

// The engine rectifies random raw pairs through random smooth meshes (some reaching
// outside the raw views: invalid pixels), then matches: the rectified planes, both
// validity bitmaps and every output pixel (the invalid code at invalid base pixels)
// equal the reference's, in the raw, sub-pixel, right-view and LR modes, raster and
// tiled, at S = 8, 16, 32, with random memory timing.
TEST(Engine, RectifiedFramesMatchReference) {
  if (!kRect) GTEST_SKIP() << "a build without the rectifier (MCADSW_RECT=OFF)";
  std::mt19937 rng(32);
  for (int k = 0; k < 9; ++k) {
    std::uniform_int_distribution<int> wd(12, 90), hd(6, 50);
    const int w = wd(rng), h = hd(rng), s = 3 + k % 3;
    const int rw = std::max(8, int(w * std::uniform_real_distribution<double>(0.7, 1.4)(rng)));
    const int rh = std::max(4, int(h * std::uniform_real_distribution<double>(0.7, 1.4)(rng)));
    const auto [raw_l, raw_r] = raw_crops(rw, rh, rng);
    EngineOptions opt;
    opt.frame.rect = sim::Rectification{sim::random_fitting_mesh(w, h, s, rw, rh, rng),
                                  sim::random_fitting_mesh(w, h, s, rw, rh, rng)};
    opt.frame.subpixel = k % 2 == 1;
    opt.frame.lr = k >= 6;  // dR 255 and dL flagged at invalid pixels before the post stage
    opt.frame.right = !opt.frame.lr && k % 3 == 2;
    opt.frame.tiled = k >= 3 && k != 6;
    // The last: a tile stride of 128 KiB, so the writer's strip step has bit 17 set (`make
    // mutate` found its high bits unchecked).
    if (k == 8) opt.frame.tile_stride = 0x20000;
    opt.memory.latency.random = k % 2 == 0;
    opt.memory.latency.seed = uint32_t(40 + k);
    Config cfg;
    cfg.disparities = std::uniform_int_distribution<int>(2, std::min(24, kDmax))(rng);
    SCOPED_TRACE("frame " + std::to_string(k) + ": " + std::to_string(w) + "x" + std::to_string(h) + " from " +
                 std::to_string(rw) + "x" + std::to_string(rh) + ", S = " + std::to_string(1 << s) +
                 (opt.frame.subpixel ? ", sub-pixel" : "") + (opt.frame.right ? ", right view as base" : "") +
                 (opt.frame.lr ? ", LR" : "") +
                 (opt.frame.tiled ? ", tiled" : "") + (opt.frame.tile_stride ? ", tile stride 128 KiB" : ""));
    const EngineResult r = sim::run_engine(raw_l, raw_r, cfg, opt);
    expect_exact(r);
    EXPECT_EQ(r.rect_mismatches, 0);
  }
}

// Rectified frames at S = 16 with a vertical scale of about 1.2 (the v row step R_v has bit 13
// set), a width of 32k + 3 (a 3-pixel last strip in each tile row), 64 rows
// and random memory latency (the writer stalls mid-strip): `make mutate` found the row step's
// low bit unchecked, where an extra unit a row adds up down a strip and moves a sample only
// when its v sum lies that close below a rounding half. Four jittered meshes a view (with
// `make mutate`'s mutant, frames 0 and 3 differ; 3 frames of 35 x 24 showed nothing).
TEST(Engine, RectifiedFramesAtAVerticalScaleAbove1) {
  if (!kRect) GTEST_SKIP() << "a build without the rectifier (MCADSW_RECT=OFF)";
  std::mt19937 rng(37);
  const int w = 35, h = 64, rw = 48, rh = 104;
  const auto scaled = [&](double sv) {
    Mesh m = make_mesh(w, h, 4);
    std::normal_distribution<double> jit(0, 0.6);
    for (int j = 0; j < m.ny; ++j)
      for (int i = 0; i < m.nx; ++i) {
        const double u = 4 + i * m.step() * 1.02 + jit(rng), v = 3 + j * m.step() * sv + jit(rng);
        m.u[size_t(j * m.nx + i)] = int32_t(std::lround(u * 32));
        m.v[size_t(j * m.nx + i)] = int32_t(std::lround(v * 32));
      }
    check_mesh(m);
    check_rect_footprints(m, rw, rh);
    return m;
  };
  for (int k = 0; k < 4; ++k) {
    SCOPED_TRACE("frame " + std::to_string(k));
    const auto [raw_l, raw_r] = raw_crops(rw, rh, rng);
    EngineOptions opt;
    opt.frame.rect = sim::Rectification{scaled(1.15 + 0.05 * (k % 3)), scaled(1.2 + 0.05 * (k % 3))};
    opt.memory.latency.random = true;
    opt.memory.latency.seed = uint32_t(60 + k);
    expect_rectified(raw_l, raw_r, opt, 6);
  }
}

// A rectified frame at S = 32 (a tile holds the upper or lower half of a cell row) whose upper
// tile's source is exactly 32 raw rows, the most the tile buffer holds: rows 4 .. 35, the
// bottom edge from the node column's midpoint, the two nodes' v summed in 1/64 pixel, 64 k - 2
// (128 + 2110 = 2238, k = 35), rounded up to 1/32 pixel (1119, row 34) plus one row. One unit
// more (64 k - 1) would make it 33 rows, and the check rejects the frame (code 23): `make
// mutate` found the midpoint's bit 0 unchecked where bit 4 is set. The raw view is 60 rows
// high, so the lower tile's rows (34 .. 66, clamped to 59) fit, its bottom pixels invalid.
TEST(Engine, RectifiedFrameAtStep32WithA32RowTileSource) {
  if (!kRect) GTEST_SKIP() << "a build without the rectifier (MCADSW_RECT=OFF)";
  std::mt19937 rng(38);
  const int w = 32, h = 32, rw = 48, rh = 60;
  Mesh m = make_mesh(w, h, 5);
  for (int j = 0; j < m.ny; ++j)
    for (int i = 0; i < m.nx; ++i) {
      m.u[size_t(j * m.nx + i)] = (4 + 32 * i) << kMeshFracBits;
      m.v[size_t(j * m.nx + i)] = j == 0 ? 128 : 2110;
    }
  check_mesh(m);
  // The premise, from the reference: the upper tile's box ends at 1119 / 32 and spans 32 rows.
  const TileSource top = tile_source(m, 0, 0, rw, rh);
  ASSERT_EQ(top.vmax, 1119);
  ASSERT_EQ(top.rows, 32);
  ASSERT_TRUE(top.fits());
  check_rect_footprints(m, rw, rh);
  const auto [raw_l, raw_r] = raw_crops(rw, rh, rng);
  EngineOptions opt;
  opt.frame.rect = sim::Rectification{m, m};
  expect_rectified(raw_l, raw_r, opt, 8);
}

// A rectified raster frame of three tile bands (16 rows each) with a row stride of 4 MiB: the
// band offsets the rectifier writes at are 16 b STRIDE, 64 MiB (bit 26) for band 1 (`make
// mutate` found that bit of the band offset unchecked: the suite's other strides are small).
TEST(Engine, RectifiedFrameAtA4MiBStride) {
  if (!kRect) GTEST_SKIP() << "a build without the rectifier (MCADSW_RECT=OFF)";
  std::mt19937 rng(36);
  const int w = 40, h = 40, rw = 44, rh = 44;
  const auto [raw_l, raw_r] = raw_crops(rw, rh, rng);
  EngineOptions opt;
  opt.frame.rect = sim::Rectification{sim::random_fitting_mesh(w, h, 4, rw, rh, rng),
                                      sim::random_fitting_mesh(w, h, 4, rw, rh, rng)};
  opt.frame.stride = 1u << 22;
  expect_rectified(raw_l, raw_r, opt, 8);
}

// LR and sub-pixel with disparities of 32 and more: the right view is the left shifted by 40
// pixels, so the scratch values the post stage reads back (16 d + offset) reach bit 9
// (`make mutate` found that bit of the post stage's row buffer unchecked: the other LR
// sub-pixel frames of the suite stay below d = 32).
TEST(Engine, LrSubpixelAtLargeDisparities) {
  if (kDmax < 48) GTEST_SKIP() << "DMAX " << kDmax << " is below the shift";
  std::mt19937 rng(34);
  const int w = 96, h = 20, shift = 40;
  const YuvImage left = test::random_yuv(w, h, rng);
  YuvImage right = left;
  for (const auto& [pl, pr] : {std::pair{&left.y, &right.y}, {&left.u, &right.u}, {&left.v, &right.v}})
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) pr->at(x, y) = pl->at(std::min(w - 1, x + shift), y);
  EngineOptions opt;
  opt.frame.lr = true;
  opt.frame.subpixel = true;
  Config cfg;
  cfg.disparities = std::min(64, kDmax);
  const EngineResult r = sim::run_engine(left, right, cfg, opt);
  expect_exact(r);
}

// Meshes whose nodes lie left of and above the raw views (negative u and v: the sign bit of
// an 18-bit node, every node of the first tiles' left and top; `make mutate` found the sign
// of a node inside a tile unchecked): the identity shifted by 40 pixels left and 12 up at
// step 8, so the pixels that map outside come out invalid.
TEST(Engine, RectifiedFrameFromNodesLeftOfTheRawView) {
  if (!kRect) GTEST_SKIP() << "a build without the rectifier (MCADSW_RECT=OFF)";
  std::mt19937 rng(33);
  const int w = 64, h = 24, rw = 80, rh = 40;
  const auto [raw_l, raw_r] = raw_crops(rw, rh, rng);
  const auto shifted = [&](int dx, int dy) {
    Mesh m = make_mesh(w, h, 3);
    for (int j = 0; j < m.ny; ++j)
      for (int i = 0; i < m.nx; ++i) {
        m.u[size_t(j * m.nx + i)] = (i * m.step() - dx) * 32;
        m.v[size_t(j * m.nx + i)] = (j * m.step() - dy) * 32;
      }
    return m;
  };
  EngineOptions opt;
  opt.frame.rect = sim::Rectification{shifted(40, 12), shifted(36, 12)};
  Config cfg;
  cfg.disparities = std::min(16, kDmax);
  const EngineResult r = sim::run_engine(raw_l, raw_r, cfg, opt);
  expect_exact(r);
  EXPECT_EQ(r.rect_mismatches, 0);
}

// Faults in the rectify pass: a reset and a CTRL.ABORT while it runs, then clean
// frames (the rectifier's state starts again; nothing of the aborted frame leaks).
TEST(Engine, RectifyPassFaults) {
  if (!kRect) GTEST_SKIP() << "a build without the rectifier (MCADSW_RECT=OFF)";
  std::mt19937 rng(33);
  std::vector<sim::Frame> frames;
  EngineOptions opt;
  const int w = 40, h = 24, rw = 44, rh = 28;
  const auto [l0, r0] = raw_crops(rw, rh, rng);
  const auto [l1, r1] = raw_crops(rw, rh, rng);
  opt.frame.rect = sim::Rectification{sim::random_fitting_mesh(w, h, 4, rw, rh, rng, 0.3),
                                sim::random_fitting_mesh(w, h, 4, rw, rh, rng, 0.3)};
  Config cfg;
  cfg.disparities = 9;
  frames.push_back({l0, r0, cfg});
  frames.push_back({l1, r1, cfg});
  const std::vector<EngineResult> clean = sim::run_frames(frames, opt);
  for (const EngineResult& r : clean) expect_exact(r);
  // The rectify pass comes first: 4 planes of 40 x 24 pixels, about 4 000 cycles.
  for (long at : {300L, 2500L}) {
    SCOPED_TRACE("fault after " + std::to_string(at) + " cycles");
    for (const EngineResult& r : sim::run_frames(frames, opt, {sim::Fault::kResetMidFrame, at})) expect_exact(r);
    const auto res = sim::run_frames(frames, opt, {sim::Fault::kAbort, at});
    EXPECT_TRUE(res[0].error);
    EXPECT_EQ(res[0].error_code, regs::kErrAborted);
    expect_exact(res[1]);
  }
}

// A valid rectified frame: 64 x 40 from raw views of 80 x 50 at S = 16 (5 x 4 nodes a view).
sim::RawConfig rectified_config() {
  sim::RawConfig c{0x1000, 0x2000, 0x3000, 0x4000, 0x5000, 64, 64, 64, 40, 16};
  c.rect = true;
  c.rect_step = 4;
  c.raw_width = 80;
  c.raw_height = 50;
  c.raw_stride = 80;
  c.raw_base = {0x10000, 0x11000, 0x12000, 0x13000, 0x14000, 0x15000};
  c.mesh_base = {0x20000, 0x21000};
  c.valid_base = {0x22000, 0x23000};
  c.mesh_nx = 5;
  c.mesh_ny = 4;
  return c;
}

// The rectification's configuration errors (register map 1.2, codes 16 .. 23): each
// rejected with its code, DONE and ERROR set, and nothing written; 16 .. 21
// before anything is read, 22 and 23 after the check phase read the meshes.
TEST(Engine, RejectsBadRectificationAndWritesNothing) {
  if (!kRect) GTEST_SKIP() << "a build without the rectifier (MCADSW_RECT=OFF)";
  const sim::RawConfig good = rectified_config();
  BadConfigs bad{good, {}};
  const auto with = [&](const char* what, int code, auto change) { bad.add(what, code, change); };
  with("step 2", 16, [](auto& c) { c.rect_step = 2; });
  with("step 6", 16, [](auto& c) { c.rect_step = 6; });
  with("raw width 0", 17, [](auto& c) { c.raw_width = 0; });
  with("raw height above 2048", 17, [](auto& c) { c.raw_height = 2049; });
  with("raw stride below the raw width", 17, [](auto& c) { c.raw_stride = 76; });
  with("raw stride not a multiple of 4", 17, [](auto& c) { c.raw_stride = 82; });
  with("mesh a node short in x", 18, [](auto& c) { c.mesh_nx = 4; });
  with("mesh for another step", 18, [](auto& c) { c.mesh_ny = 7; });
  with("misaligned raw RY", 19, [](auto& c) { c.raw_base[3] = 0x13002; });
  with("misaligned mesh R", 19, [](auto& c) { c.mesh_base[1] = 0x21001; });
  with("misaligned bitmap L", 19, [](auto& c) { c.valid_base[0] = 0x22002; });
  with("raw LY overlaps the output", 20, [](auto& c) { c.raw_base[0] = 0x5000 + 64; });
  with("mesh L overlaps the rectified LU", 20, [](auto& c) { c.mesh_base[0] = 0x2000 + 100; });
  with("bitmap R overlaps raw RY", 20, [](auto& c) { c.valid_base[1] = 0x13000 + 40; });
  with("bitmap L overlaps bitmap R", 20, [](auto& c) { c.valid_base[0] = 0x23000 - 8; });
  with("raw LV beyond 4 GiB", 21, [](auto& c) { c.raw_base[2] = 0xfffff800u; });  // 80 x 50 bytes
  // A raw plane of exactly 2^37 bytes (RAW_STRIDE 2^31, 64 rows) reaches over every other
  // region: the check's sizes are exact (44 bits; `make mutate` found bit 37 of its
  // multiplier unchecked).
  with("raw planes of 2^37 bytes", 20, [](auto& c) {
    c.raw_stride = 0x80000000u;
    c.raw_height = 64;
  });
  // Raw planes of 2^38 bytes (128 rows) above every other region: they overlap only each
  // other (reads: allowed), so only their exact ends, bit 38, put them beyond 4 GiB (`make
  // mutate` found that bit unchecked: the overlap compares of the other order cover it
  // wherever a written region lies above a raw plane).
  with("raw planes of 2^38 bytes above the other regions", 21, [](auto& c) {
    c.raw_stride = 0x80000000u;
    c.raw_height = 128;
    c.raw_base = {0x100000, 0x101000, 0x102000, 0x103000, 0x104000, 0x105000};
  });
  // The engine's own codes come first.
  with("width 0 and step 2", 1, [](auto& c) {
    c.width = 0;
    c.rect_step = 2;
  });
  for (const BadConfigs::Bad& b : bad.list) {
    SCOPED_TRACE(b.what);
    expect_rejected(sim::run_raw(b.cfg, {}, 3000), b.code, b.what);
  }
  // Control: a raw stride of 256 MiB (only bit 28 set) and one raw row, the raw planes (of
  // stride x height bytes each) above every other region, is accepted: the frame starts and
  // is still running after 3000 cycles (`make mutate` found bit 28 of the registered
  // RAW_STRIDE unchecked: held at 0, the stride falls below the raw width and the start is
  // rejected with code 17).
  {
    sim::RawConfig c = good;
    c.raw_stride = 0x10000000u;
    c.raw_height = 1;
    c.raw_base = {0x30000, 0x31000, 0x32000, 0x33000, 0x34000, 0x35000};
    const sim::EngineResult r = sim::run_raw(c, {}, 3000);
    EXPECT_FALSE(r.error) << "raw stride 256 MiB: rejected with code " << r.error_code << " ("
                          << regs::error_text(r.error_code) << ")";
    EXPECT_TRUE(r.timed_out) << "raw stride 256 MiB: finished within 3000 cycles";
  }
  // Codes 22 and 23: meshes in memory (each node u then v, 32-bit little-endian), all
  // nodes in range and small tiles but one: a node beyond 4096 pixels, or a tile whose
  // source is 3 times too wide. The check phase reads nodes, then ends the frame.
  const auto mesh_bytes = [](const Mesh& m) {
    std::vector<uint8_t> b;
    for (size_t i = 0; i < m.u.size(); ++i)
      for (const int32_t v : {m.u[i], m.v[i]})
        for (int k = 0; k < 4; ++k) b.push_back(uint8_t(uint32_t(v) >> (8 * k)));
    return b;
  };
  Mesh ident = make_mesh(64, 40, 4);
  for (int j = 0; j < ident.ny; ++j)
    for (int i = 0; i < ident.nx; ++i) {
      ident.u[size_t(j * ident.nx + i)] = std::min(i * 16, 79) * 32;
      ident.v[size_t(j * ident.nx + i)] = std::min(j * 16, 49) * 32;
    }
  for (int v = 0; v < 2; ++v)
    for (const int code : {22, 23}) {
      SCOPED_TRACE(std::string(code == 22 ? "a node out of range" : "a tile too wide") + " in the " +
                   (v ? "right" : "left") + " mesh");
      Mesh bad_mesh = ident;
      if (code == 22) bad_mesh.u[7] = 4096 * 32 + 5;
      else bad_mesh.u[7] = bad_mesh.u[6] + 3 * 32 * 32;
      const Mesh& ml = v ? ident : bad_mesh;
      const Mesh& mr = v ? bad_mesh : ident;
      const sim::EngineResult r =
          sim::run_raw(good, {}, 20000, {{good.mesh_base[0], mesh_bytes(ml)}, {good.mesh_base[1], mesh_bytes(mr)}});
      EXPECT_FALSE(r.timed_out);
      EXPECT_TRUE(r.error);
      EXPECT_TRUE(r.done);
      EXPECT_EQ(r.error_code, code) << regs::error_text(r.error_code);
      EXPECT_EQ(r.bus.bad_writes, 0) << "the engine wrote to memory";
      EXPECT_EQ(r.bus.bad_reads, 0) << r.bus.describe();
    }
}

// A build without the rectifier (MCADSW_RECT=OFF, package RECT = 0): RECT_CTRL.ENABLE
// is rejected with code 24 and nothing read or written; the engine's codes 1 .. 12 come
// first; a frame without rectification runs.
TEST(Engine, RectificationRejectedWithoutTheRectifier) {
  if (kRect) GTEST_SKIP() << "a build with the rectifier (code 24 needs MCADSW_RECT=OFF)";
  const sim::RawConfig cfg = rectified_config();
  expect_rejected(sim::run_raw(cfg, {}, 3000), 24, "rectification without the rectifier");
  sim::RawConfig first = cfg;
  first.width = 0;
  expect_rejected(sim::run_raw(first, {}, 3000), 1, "width 0 and rectification");
  std::mt19937 rng(34);
  Config plain;
  plain.disparities = 5;
  expect_exact(sim::run_engine(test::random_yuv(30, 20, rng), test::random_yuv(30, 20, rng), plain, {}));
}

// Invalid configurations: the engine reports the error code of docs/memory_map.md,
// finishes at once (STATUS.DONE with ERROR, the code steady over reads a cycle
// apart and two apart: `make mutate` found a code that alternated from cycle to
// cycle, and DONE left clear, both passing a single read) and writes nothing.
TEST(Engine, RejectsInvalidConfigurationsAndWritesNothing) {
  const sim::RawConfig good{0x1000, 0x2000, 0x3000, 0x4000, 0x5000, 64, 64, 60, 40, 16};
  BadConfigs bad{good, {}};
  const auto with = [&](const char* what, int code, auto change) { bad.add(what, code, change); };
  with("width 0", 1, [](auto& c) { c.width = 0; });
  with("width above the maximum", 1, [](auto& c) { c.width = kMaxWidth + 1; });
  with("height 0", 2, [](auto& c) { c.height = 0; });
  with("D = 0", 3, [](auto& c) { c.disparities = 0; });
  with("D above DMAX", 3, [](auto& c) { c.disparities = kDmax + 1; });
  with("stride below width", 4, [](auto& c) { c.stride = 56; });
  with("stride not a multiple of 4", 4, [](auto& c) { c.stride = 66; });
  with("misaligned base", 5, [](auto& c) { c.base_lu = 0x2002; });
  with("output overlaps the right view", 6, [](auto& c) { c.base_out = 0x4000 + 64; });
  // The output plane spans out_stride x height bytes (2 bytes a pixel in sub-pixel mode).
  with("sub-pixel output plane reaches the right view", 6, [](auto& c) {
    c.mode = 1;
    c.out_stride = 128;
    c.base_ry = 0x6000;
  });
  with("wide output stride reaches the right view", 6, [](auto& c) {
    c.out_stride = 1024;
    c.base_ry = 0x6000;
  });
  with("output stride below the width", 7, [](auto& c) { c.out_stride = 56; });
  with("output stride not a multiple of 4", 7, [](auto& c) { c.out_stride = 66; });
  with("sub-pixel output stride below 2 x width", 7, [](auto& c) {
    c.mode = 1;
    c.out_stride = 64;
  });
  // The LR mode reads the right U and V too and writes dL, dR, the output and the mask.
  const auto lr = [&](const char* what, int code, auto change) {
    with(what, code, [=](auto& c) {
      c.mode = 2;
      c.base_ru = 0x6000;
      c.base_rv = 0x7000;
      c.base_dl = 0x8000;
      c.base_dr = 0x9000;
      c.base_mask = 0xa000;
      c.lr_t = 1;
      change(c);
    });
  };
  lr("LR mode with the right view as base", 8, [](auto& c) { c.mode = 6; });
  lr("LR mode, misaligned dL", 5, [](auto& c) { c.base_dl = 0x8001; });
  lr("LR mode, misaligned mask", 5, [](auto& c) { c.base_mask = 0xa002; });
  // Every plane the mode reads or writes, one byte and two bytes off a word (a
  // mutant forcing bit 1 of one write base to 0 in the check survived a sample
  // of an earlier design, when only some planes had a misaligned case).
  for (const uint32_t off : {1u, 2u}) {
    const auto moved = [off](uint32_t sim::RawConfig::*base) {
      return [off, base](auto& c) { c.*base += off; };
    };
    using R = sim::RawConfig;
    with("misaligned left Y", 5, moved(&R::base_ly));
    with("misaligned left U", 5, moved(&R::base_lu));
    with("misaligned left V", 5, moved(&R::base_lv));
    with("misaligned right Y", 5, moved(&R::base_ry));
    with("misaligned output", 5, moved(&R::base_out));
    lr("LR mode, misaligned right U", 5, moved(&R::base_ru));
    lr("LR mode, misaligned right V", 5, moved(&R::base_rv));
    lr("LR mode, misaligned output", 5, moved(&R::base_out));
    lr("LR mode, misaligned dL", 5, moved(&R::base_dl));
    lr("LR mode, misaligned dR", 5, moved(&R::base_dr));
    lr("LR mode, misaligned mask", 5, moved(&R::base_mask));
  }
  lr("LR mode, dL overlaps the output", 6, [](auto& c) { c.base_dl = 0x5000 + 64; });
  lr("LR mode, dR overlaps the mask", 6, [](auto& c) { c.base_dr = 0xa000 - 64; });
  lr("LR mode, mask overlaps the right U", 6, [](auto& c) { c.base_mask = 0x6000 + 128; });
  lr("LR mode, output overlaps the right V", 6, [](auto& c) { c.base_out = 0x7000 - 64; });
  // The base view's V plane (the left V at 0x3000, 2 560 bytes) against the mask (`make
  // mutate` found that pair's compare unchecked).
  lr("LR mode, mask overlaps the left V", 6, [](auto& c) { c.base_mask = 0x3000 + 128; });
  lr("LR mode, sub-pixel dL reaches dR", 6, [](auto& c) {
    c.mode = 3;
    c.out_stride = 128;  // 40 rows of 128 bytes from 0x8000 reach 0x9000
    c.base_out = 0xb000;
  });
  lr("LR mode, mask beyond 4 GiB", 9, [](auto& c) { c.base_mask = 0xfffffc00u; });
  lr("LR mode, T = 64", 10, [](auto& c) { c.lr_t = 64; });
  lr("LR mode, T = 255", 10, [](auto& c) { c.lr_t = 255; });
  lr("LR mode, width above the post stage's rows", 11, [](auto& c) {
    c.width = kPostMaxWidth + 1;
    c.stride = c.out_stride = kPostMaxWidth + 4;
    c.height = 1;
  });
  lr("LR mode, right U and V left at 0", 12, [](auto& c) { c.base_ru = c.base_rv = 0; });
  lr("LR mode, right U the left U", 12, [](auto& c) { c.base_ru = 0x2000; });
  lr("LR mode, right V the right Y", 12, [](auto& c) { c.base_rv = 0x4000; });
  // Controls: the configurations the cases above change are accepted (the engine
  // starts; the run is cut short).
  lr("control: valid LR configuration", 0, [](auto&) {});
  lr("control: valid LR sub-pixel configuration", 0, [](auto& c) {
    c.mode = 3;
    c.out_stride = 120;  // 2 x 60 bytes a row,
    c.height = 30;       // 3600 bytes a plane
  });
  with("control: valid raw configuration", 0, [](auto&) {});
  // With the right view as base, its U and V planes are read and checked too.
  const auto right_base = [&](const char* what, int code, uint32_t ru, uint32_t rv) {
    with(what, code, [=](auto& c) {
      c.mode = 4;
      c.base_ru = ru;
      c.base_rv = rv;
    });
  };
  right_base("right view as base, misaligned right U", 5, 0x7002, 0x8000);
  right_base("right view as base, output overlaps the right V", 6, 0x7000, 0x5000 + 128);
  right_base("right view as base, right U beyond 4 GiB", 9, 0xfffffc00u, 0x8000);
  // With the right view as base the left Y is the match view: a left Y at 16 MiB (bit 24 set)
  // holding the output is found (`make mutate` found bit 24 of that base unchecked in this
  // mode: seen at 0, the plane misses the output and the frame would run).
  with("right view as base, output inside the left Y at 16 MiB", 6, [](auto& c) {
    c.mode = 4;
    c.base_ru = 0x7000;
    c.base_rv = 0x8000;
    c.base_ly = 0x01000000u;
    c.base_out = 0x01000000u + 64;
  });
  with("output plane beyond 4 GiB", 9, [](auto& c) { c.base_out = 0xfffffc00u; });
  // Column-tiled input planes (TILE_STRIDE != 0): 15 columns of 4 pixels, each
  // of TILE_STRIDE >= 4 x 40 bytes; STRIDE is then checked only in the LR mode
  // (dR and the mask).
  with("tile stride below 4 x height", 4, [](auto& c) { c.tile_stride = 156; });
  with("tile stride not a multiple of 4", 4, [](auto& c) { c.tile_stride = 162; });
  with("tiled right Y reaches the output", 6, [](auto& c) { c.tile_stride = 400; });
  // A tiled plane of exactly 256 MiB (16 columns of 4 pixels, 16 MiB each): its size has only
  // bit 28 set (a mutant forcing that bit of the product to 0 survived a sample).
  with("tiled planes of 256 MiB reach the output", 6, [](auto& c) {
    c.width = 64;
    c.tile_stride = 1u << 24;
  });
  with("tiled left V beyond 4 GiB (raster, 2560 bytes, would end at 4 GiB)", 9, [](auto& c) {
    c.tile_stride = 184;  // 15 x 184 = 2760 bytes; raster 64 x 40 = 2560
    c.base_lv = 0xfffff600u;
  });
  with("control: valid tiled configuration, stride 0", 0, [](auto& c) {
    c.tile_stride = 160;
    c.stride = 0;
  });
  lr("LR mode, tiled, stride below width", 4, [](auto& c) {
    c.tile_stride = 160;
    c.stride = 56;
  });
  lr("control: valid tiled LR configuration", 0, [](auto& c) { c.tile_stride = 160; });
  // dR and the mask span stride x height bytes: 4 MiB x 64 rows, exactly 256 MiB (only bit 28
  // of the product set; a mutant forcing that bit to 0 survived a sample). The mask starts
  // 4 KiB before dR's end.
  const auto lr_big = [&](const char* what, int code, uint32_t mask) {
    lr(what, code, [=](auto& c) {
      c.tile_stride = 256;
      c.height = 64;
      c.stride = 1u << 22;
      c.base_dr = 0x10000000u;
      c.base_mask = mask;
    });
  };
  lr_big("LR mode, 256 MiB dR reaches the mask", 6, 0x1ffff000u);
  lr_big("control: LR mode, 256 MiB dR and mask apart", 0, 0x20000000u);
  with("input plane beyond 4 GiB", 9, [](auto& c) { c.base_lv = 0xfffff800u; });
  for (const BadConfigs::Bad& b : bad.list) {
    const sim::EngineResult r = sim::run_raw(b.cfg, {}, 1000);
    if (b.code == 0) {
      EXPECT_FALSE(r.error) << b.what << ": rejected with code " << r.error_code;
      EXPECT_TRUE(r.timed_out) << b.what << ": finished within 1000 cycles";
      continue;
    }
    expect_rejected(r, b.code, b.what);
  }
}

// The RTL's assertions (docs/verification.md section 3) are compiled in (Verilator
// --assert) and stop the simulation: an AXI4 R beat with no read outstanding
// violates the AXI4 master's invariant and, passed on, the memory controller's
// and a reader's; they fire on the same edge, and which one Verilator reports
// first is its scheduling order, so any of the messages counts.
TEST(EngineDeathTest, AssertionStopsTheSimulation) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const auto spurious_read_data = [] {
    dup2(2, 1);  // Verilator reports on stdout; the death test reads stderr
    VerilatedContext ctx;
    Vmcadsw_top top{&ctx};
    const auto cycle = [&] {
      top.clk_i = 0;
      top.eval();
      top.clk_i = 1;
      top.eval();
    };
    top.rst_ni = 0;
    cycle();
    top.rst_ni = 1;
    cycle();
    top.m_rvalid_i = 1;  // nothing was requested (a one-beat burst's only beat)
    top.m_rlast_i = 1;
    for (int i = 0; i < 4; ++i) cycle();
    top.final();
  };
  EXPECT_DEATH(spurious_read_data(),
               "(u_axi_master: ReadBeatInFlight|u_mem_ctrl: ReadDataOnlyWhenOutstanding|"
               ".*: ReadDataOnlyWhenInFlight)");
}

// ---- The longest tests last ------------------------------------------------------------
// GoogleTest runs a file's tests in their order here, and `make mutate` stops a mutant's
// kill suite at its first failing test: these two take more than half of the suite's
// time (on the mutant model, minutes in CI), so they come after the tests that kill most
// mutants sooner (the rectifier's, the configuration errors').

// The tallest frames, kMaxHeight - 1 and kMaxHeight rows: row bits above 1023
// (found by `make mutate`: no other test has a frame that tall, so the
// scheduler's last-block-row compare could ignore the height's bit 10), and
// in the LR mode.
TEST(Engine, TallestFrames) {
  std::mt19937 rng(15);
  Config cfg;
  cfg.disparities = 2;
  for (const int h : {kMaxHeight - 1, kMaxHeight})
    for (const bool lr : {false, true}) {  // the LR mode: its post stage's row bits
      SCOPED_TRACE("H = " + std::to_string(h) + (lr ? ", LR mode" : ""));
      EngineOptions opt;
      opt.frame.lr = lr;
      expect_exact(sim::run_engine(test::random_yuv(4, h, rng), test::random_yuv(4, h, rng), cfg, opt));
    }
}

// Frames anywhere in the 32-bit address space (the address, base
// and stride bits above the first MiB, which no frame laid out from address 0
// reaches): at the top of the space (the planes end less than 8 KiB below
// 2^32), planes packed at 4-byte alignment (base bits 2..11), and strides of up
// to 3 GiB a row (sim::MemoryModel stores the space sparsely). Each placement
// in every mode whose planes fit (the LR mode has two more planes of the input
// stride and one more of the output stride): exact, no access outside the
// planes' pixels.
TEST(Engine, FramesAnywhereInTheAddressSpace) {
  std::mt19937 rng(16);
  struct Placement {
    const char* what;
    int w, h;
    uint32_t stride, out_stride, tile_stride;  // 0: the harness's default
    bool tiled, packed, top;
  };
  const Placement placements[] = {
      {"at the top, packed", 37, 21, 0, 0, 0, false, true, true},
      {"at the top, 4 KiB aligned, tiled", 37, 21, 0, 0, 0, true, false, true},
      {"input stride 2^29 + 4, one row", 23, 1, 0x20000004u, 0, 0, false, true, false},
      {"input stride 2^27 + 2^26 + 36, two rows, at the top", 23, 2, 0x0c000024u, 0, 0, false, true, true},
      {"output stride 3 GiB, one row", 23, 1, 0, 0xc0000000u, 0, false, false, false},
      {"output stride 2^27 - 4, 3 rows, at the top", 23, 3, 0, 0x07fffffcu, 0, false, true, true},
      {"tile stride 2^29 - 4, one column of tiles", 4, 5, 0, 0, 0x1ffffffcu, true, true, false},
      {"tile stride 2^26 + 2^25 + 4, two columns, at the top", 7, 4, 0, 0, 0x06000004u, true, true, true},
      // Alternating bit patterns: the row and column offsets (stride x row, tile
      // stride x column) set every other bit up to bit 28.
      {"input stride 0x15545554, two rows", 23, 2, 0x15545554u, 0, 0, false, true, false},
      {"input stride 0x0aaaaaa8, two rows", 23, 2, 0x0aaaaaa8u, 0, 0, false, true, false},
      {"tile stride 0x15545554, two columns", 5, 3, 0, 0, 0x15545554u, true, true, false},
      {"tile stride 0x0aaaaaa8, two columns", 5, 3, 0, 0, 0x0aaaaaa8u, true, true, false},
      {"input stride 0x05555554, two rows", 23, 2, 0x05555554u, 0, 0, false, true, false},
      // A window's first row far down a tall frame: its row offset (row x stride).
      {"input stride 0x000aaaa8, 600 rows", 4, 600, 0x000aaaa8u, 0, 0, false, true, false},
      // The LR mode's widest strides (its dL, dR, output and mask planes must fit too).
      {"input stride 0x1ffff000, one row", 23, 1, 0x1ffff000u, 0, 0, false, true, false},
      {"output stride 0x7fff0000, one row", 23, 1, 0, 0x7fff0000u, 0, false, true, false},
  };
  Config cfg;
  cfg.disparities = 5;
  int runs = 0;
  for (const Placement& pl : placements) {
    const YuvImage l = test::random_yuv(pl.w, pl.h, rng), r = test::random_yuv(pl.w, pl.h, rng);
    for (const int mode : {0, 1, 2}) {
      EngineOptions opt;
      opt.frame.stride = pl.stride;
      opt.frame.out_stride = pl.out_stride;
      opt.frame.tiled = pl.tiled;
      opt.frame.tile_stride = pl.tile_stride;
      opt.frame.packed = pl.packed;
      opt.frame.right = mode == 1;
      opt.frame.lr = mode == 2;
      opt.frame.subpixel = mode == 2;
      uint64_t bytes = 0;
      try {
        bytes = sim::frame_bytes(pl.w, pl.h, opt);
      } catch (const std::invalid_argument&) {
        continue;  // the LR mode's two more planes of this stride do not fit
      }
      if (pl.top) opt.frame.origin = uint32_t(((uint64_t(1) << 32) - bytes) / 4096 * 4096);
      SCOPED_TRACE(std::string(pl.what) + (mode == 0 ? ", left view as base" : mode == 1 ? ", right view as base" : ", LR sub-pixel") +
                   ", origin " + std::to_string(opt.frame.origin));
      expect_exact(sim::run_engine(l, r, cfg, opt));
      ++runs;
    }
  }
  EXPECT_EQ(runs, 45) << "placements that no longer fit";
}

}  // namespace
}  // namespace mcadsw

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The C header (driver/include/mcadsw/mcadsw_regs.h) at work: the C99 firmware of
// firmware.c identifies the SoC (mcadsw_top, Verilated), programs and starts each
// frame and reads its outcome, on the register bus the C++ driver uses
// (sim::RunControl::firmware); the bench scores every output pixel against the
// reference as for the driver's frames. One Teddy crop a mode: raw, sub-pixel,
// right view as base, LR, and rectified; then starts the engine rejects, whose
// codes and texts the firmware reads.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>

#include "engine_bench.hpp"
#include "rtl/engine_expect.hpp"
#include "firmware.h"
#include "mcadsw/driver.hpp"
#include "mcadsw/image_io.hpp"
#include "mcadsw/params.hpp"
#include "mcadsw/regs.hpp"
#include "random_mesh.hpp"

namespace mcadsw {
namespace {

// firmware.c behind the bench's firmware seam.
class CFirmware : public sim::Firmware {
 public:
  void configure(driver::RegisterBus& bus, const driver::FrameConfig& c) override {
    const mcadsw_bus b = wrap(bus);
    identified = mcadsw_identify(&b, &identity) == 0;
    mcadsw_frame f;
    std::memset(&f, 0, sizeof f);
    f.base_ly = c.base_ly, f.base_lu = c.base_lu, f.base_lv = c.base_lv;
    f.base_ry = c.base_ry, f.base_ru = c.base_ru, f.base_rv = c.base_rv;
    f.base_out = c.base_out, f.base_dl = c.base_dl, f.base_dr = c.base_dr, f.base_mask = c.base_mask;
    f.stride = c.stride, f.out_stride = c.out_stride, f.tile_stride = c.tile_stride;
    f.width = uint32_t(c.width), f.height = uint32_t(c.height), f.disparities = uint32_t(c.disparities);
    f.subpixel = c.subpixel, f.lr = c.lr, f.right = c.right;
    f.lr_tolerance = uint32_t(c.lr_tolerance);
    for (int i = 0; i < MCADSW_WEIGHT_THRESHOLDS; ++i) f.thresholds[i] = c.thresholds[size_t(i)];
    f.rect = c.rect;
    f.rect_step_log2 = uint32_t(c.rect_step_log2);
    f.raw_width = uint32_t(c.raw_width), f.raw_height = uint32_t(c.raw_height), f.raw_stride = c.raw_stride;
    for (int p = 0; p < MCADSW_RAW_PLANES; ++p) f.raw_base[p] = c.raw_base[size_t(p)];
    for (int v = 0; v < 2; ++v) f.mesh_base[v] = c.mesh_base[size_t(v)], f.valid_base[v] = c.valid_base[size_t(v)];
    f.mesh_nx = uint32_t(c.mesh_nx), f.mesh_ny = uint32_t(c.mesh_ny);
    mcadsw_configure(&b, &f);
  }
  void start(driver::RegisterBus& bus) override {
    const mcadsw_bus b = wrap(bus);
    mcadsw_start(&b);
    ++starts;
  }
  void frame_over(driver::RegisterBus& bus) override {
    const mcadsw_bus b = wrap(bus);
    mcadsw_finish(&b, &outcome);
    ++finished;
  }

  bool identified = false;
  mcadsw_identity identity{};
  mcadsw_outcome outcome{};
  int starts = 0, finished = 0;

 private:
  static mcadsw_bus wrap(driver::RegisterBus& bus) {
    mcadsw_bus b;
    b.read = [](void* ctx, uint32_t offset) { return static_cast<driver::RegisterBus*>(ctx)->read(offset); };
    b.write = [](void* ctx, uint32_t offset, uint32_t value) {
      static_cast<driver::RegisterBus*>(ctx)->write(offset, value);
    };
    b.ctx = &bus;
    return b;
  }
};

YuvImage teddy(const char* view, int x, int y, int w, int h) {
  return crop(load_yuv(std::string(MCADSW_DATA_DIR) + "/cif/teddy/" + view + ".png"), x, y, w, h);
}

// What the C firmware read after the frame equals what the bench read with the
// C++ driver, and the interrupt it acknowledged is gone.
void expect_outcome(const CFirmware& fw, const sim::EngineResult& r) {
  EXPECT_TRUE(fw.identified) << "ID / VERSION do not answer the C header's register map";
  EXPECT_EQ(fw.identity.dmax, uint32_t(kDmax));
  EXPECT_EQ(fw.identity.par, uint32_t(kPar));
  EXPECT_EQ(fw.identity.rect, kRect);
  EXPECT_EQ(fw.starts, 1);
  EXPECT_EQ(fw.finished, 1);
  const mcadsw_outcome& o = fw.outcome;
  EXPECT_TRUE(o.done);
  EXPECT_FALSE(o.busy);
  EXPECT_EQ(o.error, r.error);
  EXPECT_EQ(o.error_code, uint32_t(r.error_code));
  EXPECT_STREQ(o.error_text, regs::error_text(r.error_code));
  EXPECT_EQ(o.irq_done, 1);
  EXPECT_EQ(o.irq_error, int(r.error));
  EXPECT_EQ(o.irq_after_ack, 0u);
  EXPECT_EQ(long(o.cycles), r.cycles);
  EXPECT_EQ(long(o.words_read), r.words_read);
  EXPECT_EQ(long(o.words_written), r.words_written);
  EXPECT_EQ(long(o.stalls), r.stall_cycles);
}

struct Mode {
  const char* name;
  bool subpixel, right, lr;
};

TEST(CFirmware, FramesInEveryOutputModeMatchReference) {
  const YuvImage l = teddy("left", 120, 90, 44, 26), r = teddy("right", 120, 90, 44, 26);
  for (const Mode m : {Mode{"raw", false, false, false}, Mode{"sub-pixel", true, false, false},
                       Mode{"right view as base", false, true, false}, Mode{"LR", false, false, true}}) {
    SCOPED_TRACE(m.name);
    CFirmware fw;
    sim::EngineOptions opt;
    opt.run.firmware = &fw;
    opt.frame.subpixel = m.subpixel;
    opt.frame.right = m.right;
    opt.frame.lr = m.lr;
    opt.memory.latency.random = true;  // random memory timing and back-pressure
    opt.memory.latency.seed = 11;
    Config cfg;
    cfg.disparities = std::min(kDmax, 20);
    const sim::EngineResult res = sim::run_engine(l, r, cfg, opt);
    test::expect_exact(res);
    expect_outcome(fw, res);
  }
}

TEST(CFirmware, RectifiedFrameMatchesReference) {
  if (!kRect) GTEST_SKIP() << "a build without the rectifier (MCADSW_RECT=OFF)";
  std::mt19937 rng(5);
  const int w = 40, h = 24, raw_w = 46, raw_h = 28;
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/raw/B/cif/teddy/";
  const YuvImage l = crop(load_yuv(dir + "left.png"), 150, 100, raw_w, raw_h);
  const YuvImage r = crop(load_yuv(dir + "right.png"), 150, 100, raw_w, raw_h);
  CFirmware fw;
  sim::EngineOptions opt;
  opt.run.firmware = &fw;
  opt.frame.rect = sim::Rectification{sim::random_fitting_mesh(w, h, 3, raw_w, raw_h, rng),
                                sim::random_fitting_mesh(w, h, 3, raw_w, raw_h, rng)};
  Config cfg;
  cfg.disparities = std::min(kDmax, 12);
  const sim::EngineResult res = sim::run_engine(l, r, cfg, opt);
  test::expect_exact(res);
  EXPECT_EQ(res.rect_mismatches, 0);
  expect_outcome(fw, res);
}

// Starts the configuration check rejects: the firmware reads the code and its text.
TEST(CFirmware, RejectedStartsReportTheirCodes) {
  const sim::RawConfig good{0x1000, 0x2000, 0x3000, 0x4000, 0x5000, 64, 64, 60, 40, 16};
  struct Bad {
    const char* what;
    int code;
    sim::RawConfig cfg;
  };
  sim::RawConfig no_width = good, no_d = good, odd_base = good;
  no_width.width = 0;
  no_d.disparities = 0;
  odd_base.base_out = 0x5002;
  for (const Bad& b : {Bad{"width 0", MCADSW_ERR_WIDTH, no_width}, Bad{"D = 0", MCADSW_ERR_DISP, no_d},
                       Bad{"unaligned output base", MCADSW_ERR_ALIGN, odd_base}}) {
    SCOPED_TRACE(b.what);
    CFirmware fw;
    sim::EngineOptions opt;
    opt.run.firmware = &fw;
    const sim::EngineResult res = sim::run_raw(b.cfg, opt, 3000);
    EXPECT_EQ(res.bus.total(), 0) << res.bus.describe();
    EXPECT_TRUE(res.error);
    EXPECT_EQ(res.error_code, b.code);
    expect_outcome(fw, res);
  }
}

}  // namespace
}  // namespace mcadsw

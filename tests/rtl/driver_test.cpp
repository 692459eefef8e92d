// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The driver (driver/include/mcadsw/driver.hpp) against the AXI4-Lite register
// block (rtl/mcadsw_regs.sv), through sim::AxilDriver (random VALID delays and
// READY back-pressure, protocol monitor): every FrameConfig field lands on the
// engine's configuration ports, start() pulses START once with the mode kept,
// abort() ABORT, status() and counters() decode what the engine reports, and
// the error texts come from the one list of codes.
#include <gtest/gtest.h>

#include <functional>
#include <random>
#include <stdexcept>
#include <string>

#include "Vmcadsw_regs.h"
#include "axil_driver.hpp"
#include "cfg_bundle.hpp"
#include "mcadsw/driver.hpp"
#include "mcadsw/params.hpp"
#include "mcadsw/regs.hpp"
#include "vbits.hpp"

namespace mcadsw {
namespace {

class Bench : public driver::RegisterBus {
 public:
  Bench(uint32_t seed, double stall)
      : axi(t, [this](const std::function<void()>& at_sample) { cycle(at_sample); }, seed, stall) {
    t.rst_ni = 0;
    t.clk_i = 0;
    t.busy_i = t.done_i = t.error_i = 0;
    t.error_code_i = 0;
    t.cnt_cycles_i = t.cnt_words_read_i = t.cnt_words_written_i = t.cnt_stall_i = 0;
    t.eval();
    t.clk_i = 1;
    t.eval();
    t.rst_ni = 1;
    axi.idle(2);
  }
  // The driver's two functions, on the AXI4-Lite port; every access must answer OKAY.
  uint32_t read(uint32_t offset) override {
    int resp = 0;
    const uint32_t v = axi.read(offset, &resp);
    if (resp != 0) throw std::runtime_error("read of " + std::to_string(offset) + " not OKAY");
    return v;
  }
  void write(uint32_t offset, uint32_t value) override {
    if (axi.write(offset, value) != 0)
      throw std::runtime_error("write to " + std::to_string(offset) + " not OKAY");
  }
  void cycle(const std::function<void()>& at_sample) {
    t.clk_i = 0;
    t.eval();
    at_sample();
    starts += t.start_o;
    aborts += t.abort_o;
    t.clk_i = 1;
    t.eval();
  }

  Vmcadsw_regs t;
  sim::AxilDriver<Vmcadsw_regs> axi;
  int starts = 0, aborts = 0;
};

driver::FrameConfig random_config(std::mt19937& rng) {
  const auto word = [&] { return uint32_t(rng()) & ~3u; };
  driver::FrameConfig c;
  c.base_ly = word(), c.base_lu = word(), c.base_lv = word();
  c.base_ry = word(), c.base_ru = word(), c.base_rv = word();
  c.base_out = word(), c.base_dl = word(), c.base_dr = word(), c.base_mask = word();
  c.stride = word(), c.out_stride = word(), c.tile_stride = word();
  c.width = 1 + int(rng() % kMaxWidth);
  c.height = 1 + int(rng() % kMaxHeight);
  c.disparities = 1 + int(rng() % kDmax);
  c.subpixel = rng() & 1;
  c.lr = rng() & 1;
  c.right = !c.lr && (rng() & 1);
  c.lr_tolerance = int(rng() % (kLrToleranceMax + 1));
  for (auto& t : c.thresholds) t = uint32_t(rng() % 766);
  return c;
}

TEST(Driver, ConfigureReachesEveryEnginePort) {
  std::mt19937 rng(31);
  for (int n = 0; n < 20; ++n) {
    Bench b(uint32_t(n), n % 2 ? 0.3 : 0.0);
    driver::Engine e(b);
    const driver::FrameConfig c = random_config(rng);
    e.configure(c);
    auto& t = b.t;
    using regs::Cfg;
    const auto cfg = [&t](Cfg f) { return sim::get_cfg(t.cfg_o, f); };
    EXPECT_EQ(cfg(Cfg::kBaseLy), c.base_ly);
    EXPECT_EQ(cfg(Cfg::kBaseLu), c.base_lu);
    EXPECT_EQ(cfg(Cfg::kBaseLv), c.base_lv);
    EXPECT_EQ(cfg(Cfg::kBaseRy), c.base_ry);
    EXPECT_EQ(cfg(Cfg::kBaseRu), c.base_ru);
    EXPECT_EQ(cfg(Cfg::kBaseRv), c.base_rv);
    EXPECT_EQ(cfg(Cfg::kBaseOut), c.base_out);
    EXPECT_EQ(cfg(Cfg::kBaseDl), c.base_dl);
    EXPECT_EQ(cfg(Cfg::kBaseDr), c.base_dr);
    EXPECT_EQ(cfg(Cfg::kBaseMask), c.base_mask);
    EXPECT_EQ(cfg(Cfg::kStride), c.stride);
    EXPECT_EQ(cfg(Cfg::kOutStride), c.out_stride);
    EXPECT_EQ(cfg(Cfg::kTileStride), c.tile_stride);
    EXPECT_EQ(int(cfg(Cfg::kWidth)), c.width % 4096);
    EXPECT_EQ(int(cfg(Cfg::kHeight)), c.height % 4096);
    EXPECT_EQ(int(cfg(Cfg::kDisp)), c.disparities);
    EXPECT_EQ(int(cfg(Cfg::kLrT)), c.lr_tolerance);
    EXPECT_EQ(int(cfg(Cfg::kMode)), int(c.subpixel) | int(c.lr) << 1 | int(c.right) << 2);
    for (int i = 0; i < kWeightThresholds; ++i)
      EXPECT_EQ(uint32_t(sim::get_cfg(t.cfg_o, Cfg::kThr, i, regs::kThrBits)),
                c.thresholds[size_t(i)]) << "threshold " << i;
    EXPECT_EQ(b.starts, 0) << "configure() must not start a frame";
  }
}

TEST(Driver, StartAbortStatusCountersIdentity) {
  Bench b(7, 0.25);
  driver::Engine e(b);
  std::mt19937 rng(5);
  driver::FrameConfig c = random_config(rng);
  c.lr = true;
  c.right = false;
  c.subpixel = true;
  e.configure(c);
  e.start();
  b.axi.idle(2);
  EXPECT_EQ(b.starts, 1);
  EXPECT_EQ(int(sim::get_cfg(b.t.cfg_o, regs::Cfg::kMode)), 3) << "start() keeps the mode";
  e.abort();
  b.axi.idle(2);
  EXPECT_EQ(b.aborts, 1);
  EXPECT_EQ(b.starts, 1);
  EXPECT_EQ(int(sim::get_cfg(b.t.cfg_o, regs::Cfg::kMode)), 3) << "abort() keeps the mode";

  // The engine's status and counters as the driver decodes them.
  b.t.busy_i = 1;
  EXPECT_TRUE(e.status().busy);
  EXPECT_FALSE(e.status().done);
  b.t.busy_i = 0;
  b.t.done_i = 1;
  b.t.error_i = 1;
  b.t.error_code_i = regs::kErrAborted;
  b.axi.idle(2);
  driver::Status st = e.wait(10);
  EXPECT_TRUE(st.done);
  EXPECT_TRUE(st.error);
  EXPECT_EQ(st.error_code, regs::kErrAborted);
  EXPECT_STREQ(driver::error_text(st.error_code), "the frame ended: CTRL.ABORT was written while busy");
  e.enable_interrupts(true, false);
  EXPECT_TRUE(e.interrupt_pending());
  b.t.done_i = 0;
  b.t.error_i = 0;
  e.clear();
  st = e.status();
  EXPECT_FALSE(st.done) << "clear() acknowledges DONE";
  EXPECT_FALSE(st.error);
  EXPECT_FALSE(e.interrupt_pending());

  b.t.cnt_cycles_i = 2226986;
  b.t.cnt_words_read_i = 361332;
  b.t.cnt_words_written_i = 28224;
  b.t.cnt_stall_i = 0xdeadbeef;
  const driver::Counters n = e.counters();
  EXPECT_EQ(n.cycles, 2226986u);
  EXPECT_EQ(n.words_read, 361332u);
  EXPECT_EQ(n.words_written, 28224u);
  EXPECT_EQ(n.stalls, 0xdeadbeefu);

  const driver::Identity id = e.identify();
  EXPECT_TRUE(id.compatible());
  EXPECT_EQ(id.dmax, kDmax);
  EXPECT_EQ(id.par, kPar);
}

TEST(Driver, WaitGivesUpAfterItsPolls) {
  Bench b(3, 0.0);
  driver::Engine e(b);
  b.t.busy_i = 1;
  long idles = 0;
  const driver::Status st = e.wait(5, [&] { ++idles; });
  EXPECT_FALSE(st.done);
  EXPECT_TRUE(st.busy);
  EXPECT_EQ(idles, 4);
}

TEST(Driver, EveryErrorCodeHasItsText) {
  for (int code = 0; code < regs::kErrCount; ++code) {
    const std::string text = driver::error_text(code);
    EXPECT_NE(text, "unknown error code") << code;
    EXPECT_FALSE(text.empty()) << code;
  }
  EXPECT_STREQ(driver::error_text(regs::kErrCount), "unknown error code");
  EXPECT_STREQ(driver::error_text(1 << regs::kErrCodeBits), "unknown error code");
  EXPECT_STREQ(driver::error_text(regs::kErrReadResponse),
               "the frame ended: an AXI4 read was answered SLVERR or DECERR");
}

}  // namespace
}  // namespace mcadsw

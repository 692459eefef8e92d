// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_regs: the AXI4-Lite register block against the register
// map of sw_ref/include/mcadsw/regs.hpp, through sim::AxilDriver (random VALID
// delays and READY back-pressure, protocol monitor of the slave's side). Every
// read-write register with random data and byte strobes (read back and on the
// engine ports), read-only and unmapped offsets, CTRL.START and MODE, the sticky
// STATUS bits with write-1-to-clear, the interrupt and its enables, D above DMAX.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "Vmcadsw_regs.h"
#include "axil_driver.hpp"
#include "cfg_bundle.hpp"
#include "mcadsw/regs.hpp"
#include "regs_expect.hpp"
#include "vbits.hpp"

namespace mcadsw {
namespace {

using namespace regs;
constexpr int kOkay = 0, kSlverr = 2;

using test::writable_bits;

class Bench {
 public:
  Bench(uint32_t seed, double stall)
      : axi(t, [this](const std::function<void()>& at_sample) { cycle(at_sample); }, seed, stall) {
    t.rst_ni = 0;
    t.clk_i = 0;
    t.busy_i = 0;
    t.done_i = 0;
    t.error_i = 0;
    t.error_code_i = 0;
    t.cnt_cycles_i = 0;
    t.cnt_words_read_i = 0;
    t.cnt_words_written_i = 0;
    t.cnt_stall_i = 0;
    t.eval();
    t.clk_i = 1;
    t.eval();
    t.rst_ni = 1;
    axi.idle(2);
  }

  // A field of the configuration bundle (cfg_o).
  uint32_t cfg(regs::Cfg f) const { return uint32_t(sim::get_cfg(t.cfg_o, f)); }

  // The engine-side value of a read-write register, rebuilt from the configuration bundle.
  uint32_t port_value(uint32_t off) {
    switch (off) {
      case kStride: return cfg(regs::Cfg::kStride);
      case kOutStride: return cfg(regs::Cfg::kOutStride);
      case kTileStride: return cfg(regs::Cfg::kTileStride);
      case kSize: return (cfg(regs::Cfg::kWidth) << kSizeWidthLsb) | (cfg(regs::Cfg::kHeight) << kSizeHeightLsb);
      case kDisp: return cfg(regs::Cfg::kDisp);  // D <= DMAX here
      case kLrT: return cfg(regs::Cfg::kLrT);
      case kCtrl: return cfg(regs::Cfg::kMode) << kCtrlModeLsb;
      case kIrqEnable: return ~0u;      // no port: not compared
      default:
        if (off >= kBaseLy && off <= kBaseMask)  // BASE_LY .. BASE_MASK: Cfg kBaseLy .. kBaseMask
          return cfg(regs::Cfg(int(regs::Cfg::kBaseLy) + int(off - kBaseLy) / 4));
        if (off >= kThr0 && off < kThr0 + 4 * kWeightThresholds)
          return uint32_t(sim::get_cfg(t.cfg_o, regs::Cfg::kThr, int(off - kThr0) / 4, kThrBits));
        return ~0u;
    }
  }

  Vmcadsw_regs t;
  sim::AxilDriver<Vmcadsw_regs> axi;
  std::function<void()> on_sample;  // a test's hook, at the sample point of every cycle
  int starts = 0;             // cycles with start_o
  int aborts = 0;             // cycles with abort_o
  int mode_at_start = -1;     // the bundle's MODE in the last of them

 private:
  void cycle(const std::function<void()>& at_sample) {
    t.clk_i = 0;
    t.eval();
    at_sample();
    if (on_sample) on_sample();
    aborts += t.abort_o;
    if (t.start_o) {
      ++starts;
      mode_at_start = int(cfg(regs::Cfg::kMode));
    }
    t.clk_i = 1;
    t.eval();
  }
};

class Regs : public ::testing::TestWithParam<double> {};  // parameter: stall probability

TEST_P(Regs, IdentificationAndResetValues) {
  Bench b(1, GetParam());
  int resp = -1;
  EXPECT_EQ(b.axi.read(kId, &resp), kIdValue);
  EXPECT_EQ(resp, kOkay);
  EXPECT_EQ(b.axi.read(kVersion), kVersionMajor << kVersionMajorLsb | kVersionMinor << kVersionMinorLsb);
  EXPECT_EQ(b.axi.read(kHwConfig), uint32_t(kDmax) << kHwConfigDmaxLsb | uint32_t(kPar) << kHwConfigParLsb |
                                       uint32_t(!kRect) << kHwConfigNoRectLsb);
  for (const auto& [off, bits] : writable_bits()) EXPECT_EQ(b.axi.read(off), 0u) << "offset " << off;
  EXPECT_EQ(b.axi.read(kStatus), 0u);
  EXPECT_EQ(b.axi.read(kIrqStatus), 0u);
  EXPECT_FALSE(b.t.irq_o);
}

TEST_P(Regs, EveryReadWriteRegisterWithRandomDataAndStrobes) {
  Bench b(2, GetParam());
  std::mt19937 rng(22);
  const auto bits = writable_bits();
  std::map<uint32_t, uint32_t> model;
  for (const auto& [off, m] : bits) model[off] = 0;
  std::vector<uint32_t> offs;
  for (const auto& [off, m] : bits) offs.push_back(off);
  for (int i = 0; i < 600; ++i) {
    const uint32_t off = offs[rng() % offs.size()];
    uint32_t data = rng();
    if (off == kCtrl) data &= ~(1u << kCtrlStartLsb);  // no start here
    if (off == kDisp) data = (data & ~0xFFu) | (rng() % (kDmax + 1));  // D <= DMAX on the port
    const uint32_t strb = rng() & 0xF;
    ASSERT_EQ(b.axi.write(off, data, strb), kOkay) << "offset " << off;
    uint32_t bytes = 0;
    for (int k = 0; k < 4; ++k)
      if (strb >> k & 1) bytes |= 0xFFu << (8 * k);
    model[off] = ((model[off] & ~bytes) | (data & bytes)) & bits.at(off);
    // Read back a random register and check every engine port.
    const uint32_t roff = offs[rng() % offs.size()];
    ASSERT_EQ(b.axi.read(roff), model[roff]) << "offset " << roff << " after writing " << off;
    for (const auto& [o, v] : model) {
      const uint32_t p = b.port_value(o);
      if (p != ~0u && (o != kDisp || v <= uint32_t(kDmax))) {
        ASSERT_EQ(p, v) << "port of offset " << o;
      }
    }
  }
  EXPECT_EQ(b.starts, 0);
}

TEST_P(Regs, ReadOnlyWritesAreDroppedUnmappedOffsetsAnswerSlverr) {
  Bench b(3, GetParam());
  b.t.cnt_cycles_i = 0x12345678;
  b.t.cnt_words_read_i = 111;
  b.t.cnt_words_written_i = 222;
  b.t.cnt_stall_i = 333;
  ASSERT_EQ(b.axi.write(kStride, 0xCAFEF00D), kOkay);
  for (uint32_t off : {kId, kVersion, kHwConfig, kIrqStatus, kCycles, kWordsRead, kWordsWritten, kStalls})
    EXPECT_EQ(b.axi.write(off, 0xFFFFFFFF), kOkay) << "read-only offset " << off;
  EXPECT_EQ(b.axi.read(kId), kIdValue);
  EXPECT_EQ(b.axi.read(kCycles), 0x12345678u);
  EXPECT_EQ(b.axi.read(kWordsRead), 111u);
  EXPECT_EQ(b.axi.read(kWordsWritten), 222u);
  EXPECT_EQ(b.axi.read(kStalls), 333u);
  EXPECT_EQ(b.axi.read(kIrqStatus), 0u);
  // Every word slot not in the map, and misaligned offsets of mapped ones.
  int unmapped = 0;
  for (const uint32_t off : test::unmapped_offsets()) {
    int resp = -1;
    EXPECT_EQ(b.axi.read(off, &resp), 0u) << "offset " << off;
    EXPECT_EQ(resp, kSlverr) << "read of offset " << off;
    EXPECT_EQ(b.axi.write(off, 0xFFFFFFFF), kSlverr) << "write to offset " << off;
    ++unmapped;
  }
  EXPECT_GT(unmapped, 30);
  // Nothing changed, and nothing started.
  EXPECT_EQ(b.axi.read(kStride), 0xCAFEF00Du);
  for (uint32_t off : {kBaseLy, kCtrl, kSize, kDisp, kIrqEnable}) EXPECT_EQ(b.axi.read(off), 0u) << off;
  EXPECT_EQ(b.starts, 0);
  EXPECT_FALSE(b.t.irq_o);
}

TEST_P(Regs, StartPulsesOnceWithTheModeOfTheSameWrite) {
  Bench b(4, GetParam());
  for (uint32_t mode : {5u, 2u, 0u, 7u}) {
    const int before = b.starts;
    ASSERT_EQ(b.axi.write(kCtrl, (mode << kCtrlModeLsb) | 1u), kOkay);
    b.axi.idle(3);
    EXPECT_EQ(b.starts, before + 1) << "one start cycle per write of START";
    EXPECT_EQ(uint32_t(b.mode_at_start), mode) << "the start sees the mode written with it";
    EXPECT_EQ(b.axi.read(kCtrl), mode << kCtrlModeLsb) << "START reads 0";
  }
  // START with its byte strobe off: no start, the mode byte still written.
  const int before = b.starts;
  ASSERT_EQ(b.axi.write(kCtrl, (3u << kCtrlModeLsb) | 1u, 0x2), kOkay);
  b.axi.idle(3);
  EXPECT_EQ(b.starts, before);
  EXPECT_EQ(b.axi.read(kCtrl), 3u << kCtrlModeLsb);
}

// CTRL.ABORT: one abort_o cycle per write of the bit, no start with it, reads 0,
// the mode kept; with its byte strobe off nothing.
TEST_P(Regs, AbortPulsesOnceAndKeepsTheMode) {
  Bench b(8, GetParam());
  ASSERT_EQ(b.axi.write(kCtrl, 6u << kCtrlModeLsb), kOkay);
  for (int i = 0; i < 3; ++i) {
    const int before = b.aborts;
    ASSERT_EQ(b.axi.write(kCtrl, (6u << kCtrlModeLsb) | 1u << kCtrlAbortLsb), kOkay);
    b.axi.idle(3);
    EXPECT_EQ(b.aborts, before + 1) << "one abort cycle per write of ABORT";
    EXPECT_EQ(b.axi.read(kCtrl), 6u << kCtrlModeLsb) << "ABORT reads 0";
  }
  EXPECT_EQ(b.starts, 0);
  const int before = b.aborts;
  ASSERT_EQ(b.axi.write(kCtrl, 1u << kCtrlAbortLsb, 0x2), kOkay);
  b.axi.idle(3);
  EXPECT_EQ(b.aborts, before);
}

TEST_P(Regs, StickyDoneAndErrorClearedByWritingOneAndTheInterrupt) {
  Bench b(5, GetParam());
  auto& t = b.t;
  const uint32_t done = 1u << kStatusDoneLsb, error = 1u << kStatusErrorLsb;
  // A frame: busy, then done rises (a level until the next start).
  t.busy_i = 1;
  b.axi.idle(3);
  EXPECT_EQ(b.axi.read(kStatus) & 1u, 1u) << "BUSY";
  t.busy_i = 0;
  t.done_i = 1;
  b.axi.idle(2);
  EXPECT_EQ(b.axi.read(kStatus), done);
  EXPECT_FALSE(t.irq_o) << "interrupt not enabled";
  ASSERT_EQ(b.axi.write(kIrqEnable, 1u << kIrqDoneLsb), kOkay);
  b.axi.idle(1);
  EXPECT_TRUE(t.irq_o);
  EXPECT_EQ(b.axi.read(kIrqStatus), 1u << kIrqDoneLsb);
  // Writing 0, or 1 without the byte strobe, clears nothing.
  ASSERT_EQ(b.axi.write(kStatus, 0), kOkay);
  ASSERT_EQ(b.axi.write(kStatus, done, 0xE), kOkay);
  EXPECT_EQ(b.axi.read(kStatus), done);
  ASSERT_EQ(b.axi.write(kStatus, done), kOkay);
  b.axi.idle(1);
  EXPECT_EQ(b.axi.read(kStatus), 0u) << "W1C";
  EXPECT_FALSE(t.irq_o);
  // The done level staying high does not set the bit again: only a rising edge does.
  b.axi.idle(5);
  EXPECT_EQ(b.axi.read(kStatus), 0u);
  // A rejected start: done and error rise together, with a code.
  t.done_i = 0;
  b.axi.idle(2);
  t.done_i = 1;
  t.error_i = 1;
  t.error_code_i = 9;
  b.axi.idle(2);
  EXPECT_EQ(b.axi.read(kStatus), done | error | (9u << kStatusCodeLsb));
  EXPECT_TRUE(t.irq_o);
  ASSERT_EQ(b.axi.write(kIrqEnable, 1u << kIrqErrorLsb), kOkay);
  ASSERT_EQ(b.axi.write(kStatus, error), kOkay);
  b.axi.idle(1);
  EXPECT_FALSE(t.irq_o) << "done pending but not enabled, error cleared";
  EXPECT_EQ(b.axi.read(kIrqStatus), 0u);
  EXPECT_EQ(b.axi.read(kStatus), done | (9u << kStatusCodeLsb));
}

// The engine's done rises in the very cycle a write of 1 to STATUS.DONE takes
// effect: the event wins, the bit stays set (a frame's end is never lost).
TEST(RegsRace, DoneRisingInTheCycleOfItsClearWins) {
  Bench b(7, 0.0);  // no stalls: AW and W in the same cycle, the write one cycle later
  auto& t = b.t;
  t.done_i = 1;
  b.axi.idle(2);
  ASSERT_EQ(b.axi.read(kStatus), 1u << kStatusDoneLsb);
  t.done_i = 0;
  b.axi.idle(2);
  // Arm: the cycle after AW and W to STATUS are accepted, raise done.
  int armed = 0;
  b.on_sample = [&] {
    if (armed == 1) {
      t.done_i = 1;  // seen at this cycle's rising edge, with the write
      armed = 2;
    }
    if (armed == 0 && t.s_awvalid_i && t.s_awready_o && t.s_awaddr_i == kStatus) armed = 1;
  };
  ASSERT_EQ(b.axi.write(kStatus, 1u << kStatusDoneLsb), kOkay);
  b.on_sample = nullptr;
  ASSERT_EQ(armed, 2);
  EXPECT_EQ(b.axi.read(kStatus), 1u << kStatusDoneLsb) << "the rising done must win over the clear";
  // Without the race the same write clears.
  ASSERT_EQ(b.axi.write(kStatus, 1u << kStatusDoneLsb), kOkay);
  EXPECT_EQ(b.axi.read(kStatus), 0u);
}

TEST_P(Regs, DisparitiesAboveDmaxReachTheEngineAsZero) {
  Bench b(6, GetParam());
  ASSERT_EQ(b.axi.write(kDisp, uint32_t(kDmax)), kOkay);
  EXPECT_EQ(int(b.cfg(regs::Cfg::kDisp)), kDmax);
  ASSERT_EQ(b.axi.write(kDisp, uint32_t(kDmax) + 1), kOkay);
  EXPECT_EQ(int(b.cfg(regs::Cfg::kDisp)), 0) << "the engine then rejects the start with code 3";
  EXPECT_EQ(b.axi.read(kDisp), uint32_t(kDmax) + 1) << "the register keeps what was written";
  ASSERT_EQ(b.axi.write(kDisp, 255), kOkay);
  EXPECT_EQ(int(b.cfg(regs::Cfg::kDisp)), 0);
}

INSTANTIATE_TEST_SUITE_P(BackPressure, Regs, ::testing::Values(0.0, 0.5, 0.85),
                         [](const auto& info) { return "stall" + std::to_string(int(info.param * 100)); });

}  // namespace
}  // namespace mcadsw

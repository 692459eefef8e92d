// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The engine's AXI4 master (rtl/mcadsw_axi_master.sv) in the whole engine,
// against the AXI4 memory model (sim/axi_memory.hpp), whose protocol checks
// count in every result's bus violations: write bursts, response errors
// (SLVERR / DECERR on reads and writes) and CTRL.ABORT, each followed by a clean
// frame on the same engine without a reset.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "engine_bench.hpp"
#include "engine_expect.hpp"
#include "frame_layout.hpp"
#include "mcadsw/driver.hpp"
#include "mcadsw/ref.hpp"
#include "mcadsw/regs.hpp"
#include "regs_expect.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

using sim::EngineOptions;
using sim::EngineResult;

using test::expect_exact;

// A frame ended early: not hung, DONE with ERROR and the code, and the bus
// rules kept while it drained (reads and writes stay inside the planes).
void expect_ended(const EngineResult& r, int code) {
  EXPECT_FALSE(r.timed_out) << "the frame did not end";
  EXPECT_TRUE(r.error);
  EXPECT_EQ(r.error_code, code);
  EXPECT_EQ(r.bus.protocol, 0) << r.bus.describe();
  EXPECT_EQ(r.bus.bad_reads + r.bus.bad_writes + r.bus.double_writes, 0) << r.bus.describe();
}

std::vector<sim::Frame> two_frames(uint32_t seed) {
  std::mt19937 rng(seed);
  Config cfg;
  cfg.disparities = 12;
  std::vector<sim::Frame> f;
  f.push_back({test::random_yuv(41, 23, rng), test::random_yuv(41, 23, rng), cfg});
  f.push_back({test::random_yuv(20, 30, rng), test::random_yuv(20, 30, rng), cfg});
  return f;
}

// Depth rows leave as write bursts: every block row (18 pixels, 18 or 36 bytes)
// is one burst of up to 10 contiguous words, whatever the back-pressure, also
// mirrored (the right view as base: the depth FIFO writes such a row from its
// last pass column down, so that addresses ascend); every read is one beat.
TEST(Axi, DepthRowsAreWriteBursts) {
  std::mt19937 rng(21);
  Config cfg;
  cfg.disparities = 16;
  const int w = 64, h = 48;  // w a multiple of 4: the mirrored pass has w columns too
  const long block_rows = long(h) * ((w + kBlock - 1) / kBlock);
  const YuvImage l = test::random_yuv(w, h, rng), r = test::random_yuv(w, h, rng);
  for (bool right : {false, true})
    for (bool sub : {false, true})
      for (bool random : {false, true}) {
        SCOPED_TRACE(std::string(right ? "right view as base, " : "") + (sub ? "sub-pixel" : "raw") +
                     (random ? ", random back-pressure" : ""));
        EngineOptions opt;
        opt.frame.subpixel = sub;
        opt.frame.right = right;
        opt.memory.latency.random = random;
        opt.memory.latency.seed = 9;
        const EngineResult res = sim::run_engine(l, r, cfg, opt);
        expect_exact(res);
        EXPECT_EQ(res.write_bursts, block_rows);
        // Each block row writes the words its pixels' bytes touch; mirrored, pass
        // columns x0 .. x1 - 1 are image columns w - x1 .. w - x0 - 1.
        const int bpp = sub ? 2 : 1;
        long words = 0;
        for (int x0 = 0; x0 < w; x0 += kBlock) {
          const int x1 = std::min(w, x0 + kBlock);
          const int lo = right ? w - x1 : x0, hi = right ? w - x0 : x1;
          words += (hi * bpp - 1) / 4 - lo * bpp / 4 + 1;
        }
        EXPECT_EQ(res.words_written, words * h);
        EXPECT_EQ(res.read_bursts, res.words_read);
      }
}

// SLVERR and DECERR on a read burst early and late in frame 0, and on a write
// burst: the frame ends with code 13 (read) or 14 (write); the next frame, on the
// same engine, is exact.
TEST(Axi, ResponseErrorsEndTheFrameThenACleanFrame) {
  const auto frames = two_frames(22);
  EngineOptions clean_opt;
  const EngineResult clean = sim::run_frames({frames[0]}, clean_opt).at(0);
  expect_exact(clean);
  ASSERT_GT(clean.write_bursts, 8);
  clean_opt.frame.tiled = true;
  const EngineResult clean_tiled = sim::run_frames({frames[0]}, clean_opt).at(0);
  expect_exact(clean_tiled);
  ASSERT_LT(clean_tiled.read_bursts, clean.read_bursts);
  ASSERT_EQ(clean_tiled.write_bursts, clean.write_bursts);
  struct Case {
    const char* what;
    long read_burst, write_burst;
    int code;
  };
  const Case cases[] = {
      {"first read", 1, 0, regs::kErrReadResponse},
      {"a read late in the frame", clean.read_bursts * 9 / 10, 0, regs::kErrReadResponse},
      {"first write", 0, 1, regs::kErrWriteResponse},
      {"last write", 0, clean.write_bursts, regs::kErrWriteResponse},
  };
  for (const Case& c : cases)
    for (int resp : {2, 3})
      for (bool random : {false, true}) {
        // Column-tiled input (read bursts of several beats), with SLVERR and back-pressure.
        const bool tiled = resp == 2 && random;
        SCOPED_TRACE(std::string(c.what) + (resp == 2 ? " SLVERR" : " DECERR") +
                     (random ? ", random back-pressure" : "") + (tiled ? ", tiled input" : ""));
        EngineOptions opt;
        // A late read: 9/10 of the frame's read bursts (in its layout).
        const long read_burst =
            c.read_burst > 1 ? (tiled ? clean_tiled : clean).read_bursts * 9 / 10 : c.read_burst;
        opt.memory.axi_fault = {read_burst, c.write_burst, resp};
        opt.memory.latency.random = random;
        opt.frame.tiled = tiled;
        opt.memory.latency.seed = 5;
        const auto res = sim::run_frames(frames, opt);
        expect_ended(res[0], c.code);
        expect_exact(res[1]);
      }
}

// CTRL.ABORT early, in the middle and late in frame 0 ends it with code 15; the
// next frame is exact. Written while idle (before the start) it is ignored.
TEST(Axi, AbortEndsTheFrameThenACleanFrame) {
  const auto frames = two_frames(23);
  const EngineResult clean = sim::run_frames({frames[0]}, {}).at(0);
  for (long at : {5L, clean.cycles / 2, clean.cycles * 19 / 20})
    for (bool random : {false, true}) {
      SCOPED_TRACE("abort after " + std::to_string(at) + " cycles" +
                   (random ? ", random back-pressure, tiled input" : ""));
      EngineOptions opt;
      opt.memory.latency.random = random;
      opt.frame.tiled = random;  // read bursts of several beats in flight
      opt.memory.latency.seed = 6;
      const auto res = sim::run_frames(frames, opt, {sim::Fault::kAbort, at});
      expect_ended(res[0], regs::kErrAborted);
      expect_exact(res[1]);
    }
  const auto idle = sim::run_frames(frames, {}, {sim::Fault::kAbort, 0});
  expect_exact(idle[0]);
  EXPECT_EQ(idle[0].cycles, clean.cycles);
  expect_exact(idle[1]);
}

// Writes answered (and landing) 3000 cycles late: the LR post stage, which
// reads dL and dR back, waits for every write of the passes, and DONE waits for
// the last write response; both frames exact.
TEST(Axi, SlowWriteResponsesAreWaitedFor) {
  std::mt19937 rng(25);
  Config cfg;
  cfg.disparities = 12;
  const YuvImage l = test::random_yuv(30, 20, rng), r = test::random_yuv(30, 20, rng);
  for (bool lr : {false, true}) {
    SCOPED_TRACE(lr ? "LR mode" : "raw mode");
    EngineOptions opt;
    opt.frame.lr = lr;
    opt.memory.axi_write_latency = 3000;
    expect_exact(sim::run_engine(l, r, cfg, opt));
  }
}

// Column-tiled input planes (docs/memory_map.md): the same words are read as
// from raster planes, but a strip plane's rows inside the image are read in
// bursts of up to 8 beats (never across 4 KiB: the memory model counts that as
// a protocol violation, and the tile strides here put 4 KiB boundaries inside
// columns), with and without back-pressure, also mirrored and in the LR mode.
TEST(Axi, TiledInputIsReadInBursts) {
  std::mt19937 rng(26);
  Config cfg;
  cfg.disparities = 16;
  const int w = 64, h = 48;
  const YuvImage l = test::random_yuv(w, h, rng), r = test::random_yuv(w, h, rng);
  for (int mode = 0; mode < 3; ++mode)
    for (uint32_t tile : {0u, 4u * h + 308})  // 500: 4 KiB at row 24 of column 8
      for (bool random : {false, true}) {
        SCOPED_TRACE(std::string(mode == 1 ? "right view as base" : mode == 2 ? "LR" : "left") +
                     ", tile stride " + std::to_string(tile) + (random ? ", random back-pressure" : ""));
        EngineOptions opt;
        opt.frame.right = mode == 1;
        opt.frame.lr = mode == 2;
        opt.memory.latency.random = random;
        opt.memory.latency.seed = 10;
        const EngineResult raster = sim::run_engine(l, r, cfg, opt);
        opt.frame.tiled = true;
        opt.frame.tile_stride = tile;
        const EngineResult tiled = sim::run_engine(l, r, cfg, opt);
        expect_exact(raster);
        expect_exact(tiled);
        EXPECT_EQ(tiled.words_read, raster.words_read);
        EXPECT_EQ(raster.read_bursts, raster.words_read);
        // Bursts of at most 8 beats; on this image more than 4 on average (the
        // LR post stage's reads of dL and dR stay single words).
        EXPECT_GE(8 * tiled.read_bursts, tiled.words_read);
        if (mode != 2) EXPECT_LT(4 * tiled.read_bursts, tiled.words_read);
        else EXPECT_LT(tiled.read_bursts, raster.read_bursts / 2);
      }
}

// A long read latency (30 cycles before each R beat, the DDR-like case of
// docs/blocks/soc_top.md 3): exact, no protocol violation. And 40 cycles in the
// LR mode on rows of 40 words: the post stage asks for a row's dR words
// without a credit limit, so the AXI4 master's 32 read beats in flight fill.
TEST(Axi, LongReadLatency) {
  std::mt19937 rng(24);
  Config cfg;
  cfg.disparities = 20;
  EngineOptions opt;
  opt.memory.latency.fixed = 30;
  expect_exact(sim::run_engine(test::random_yuv(50, 33, rng), test::random_yuv(50, 33, rng), cfg, opt));
  opt.memory.latency.fixed = 40;
  opt.frame.lr = true;
  expect_exact(sim::run_engine(test::random_yuv(160, 12, rng), test::random_yuv(160, 12, rng), cfg, opt));
}

// The register window through the whole SoC (the block's decode as
// mcadsw_top wires it, not only the block alone, rtl_regs_test): every
// unmapped word offset and a sample of misaligned ones answer SLVERR and read
// 0; writes to the read-only registers answer OKAY and change nothing; every
// read-write register keeps exactly its bits of all-ones, all-zeros
// and alternating patterns; a start with every configuration bit set is
// rejected (width 4095: code 1), and one with every bit clear too (width 0),
// neither touching memory.
TEST(Axi, RegisterWindowThroughTheSoc) {
  using namespace regs;
  constexpr int kOkay = 0, kSlverr = 2;
  const auto bits = test::writable_bits();
  const auto status = [&](sim::RegisterPort& p) {
    int resp = -1;
    const uint32_t st = p.read(kStatus, &resp);
    EXPECT_EQ(resp, kOkay);
    return st;
  };
  const sim::MemoryModel::Violations v = sim::with_registers([&](sim::RegisterPort& p) {
    int unmapped = 0;
    for (const uint32_t off : test::unmapped_offsets()) {
      int resp = -1;
      EXPECT_EQ(p.read(off, &resp), 0u) << "offset " << off;
      EXPECT_EQ(resp, kSlverr) << "read of offset " << off;
      EXPECT_EQ(p.write(off, ~0u), kSlverr) << "write to offset " << off;
      ++unmapped;
    }
    EXPECT_GT(unmapped, 30);
    // Read-only registers: writes answer OKAY and change nothing.
    const uint32_t id = p.read(kId, nullptr), version = p.read(kVersion, nullptr),
                   hw = p.read(kHwConfig, nullptr);
    for (uint32_t off : {kId, kVersion, kHwConfig, kIrqStatus, kCycles, kWordsRead, kWordsWritten, kStalls})
      EXPECT_EQ(p.write(off, ~0u), kOkay) << "read-only offset " << off;
    EXPECT_EQ(id, kIdValue);
    EXPECT_EQ(p.read(kVersion, nullptr), version);
    EXPECT_EQ(p.read(kHwConfig, nullptr), hw);
    for (uint32_t off : {kIrqStatus, kCycles, kWordsRead, kWordsWritten, kStalls})
      EXPECT_EQ(p.read(off, nullptr), 0u) << "read-only offset " << off << " after reset";
    for (const uint32_t pattern : {~0u, 0u, 0x5a5a5a5au, 0xa5a5a5a5u, ~0u})
      for (const auto& [off, keep] : bits) {
        if (off == kCtrl || off == kIrqEnable) continue;  // started below; the interrupt
        EXPECT_EQ(p.write(off, pattern), kOkay) << "offset " << off;
        int resp = -1;
        EXPECT_EQ(p.read(off, &resp), pattern & keep) << "offset " << off << ", written " << pattern;
        EXPECT_EQ(resp, kOkay);
      }
    for (const bool ones : {true, false}) {
      if (!ones)
        for (const auto& [off, keep] : bits)
          if (off != kCtrl && off != kIrqEnable) p.write(off, 0);
      EXPECT_EQ(p.write(kCtrl, 1u << kCtrlStartLsb | (ones ? 7u : 0u) << kCtrlModeLsb), kOkay);
      p.cycles(10);
      const uint32_t st = status(p);
      EXPECT_TRUE(st >> kStatusErrorLsb & 1) << "STATUS " << st;
      EXPECT_EQ(st >> kStatusCodeLsb & 15, 1u) << "STATUS " << st;
      EXPECT_FALSE(st >> kStatusBusyLsb & 1);
      p.write(kStatus, 1u << kStatusDoneLsb | 1u << kStatusErrorLsb);
    }
  });
  EXPECT_EQ(v.bad_reads + v.bad_writes, 0) << v.describe();
}

// STATUS and IRQ_STATUS of a frame, through the SoC: while it runs BUSY 1 and DONE 0 (a
// driver polls DONE, driver::Engine::wait, so a DONE that read 1 during the frame would end
// its wait at once); at its end DONE 1, ERROR 0 and, with both interrupts enabled, only the
// done interrupt pending, until cleared (the other benches wait on the interrupt line or the
// core's done and never read these during or after a frame). The frame reads a memory
// that holds no image: its output is not checked here.
TEST(Axi, StatusAndInterruptsOfAFrameThroughTheSoc) {
  using namespace regs;
  struct Bus : driver::RegisterBus {
    sim::RegisterPort& p;
    explicit Bus(sim::RegisterPort& port) : p(port) {}
    uint32_t read(uint32_t offset) override { return p.read(offset, nullptr); }
    void write(uint32_t offset, uint32_t value) override { p.write(offset, value); }
  };
  sim::with_registers([&](sim::RegisterPort& p) {
    Bus bus(p);
    driver::Engine e(bus);
    const sim::RawConfig c{0x10000, 0x20000, 0x30000, 0x40000, 0x50000, 64, 64, 64, 40, 16};
    e.configure(sim::bench::frame_config(c, make_weight_table(kDefaultGamma)));
    e.enable_interrupts(true, true);
    e.start();
    for (int i = 0; i < 4; ++i) {
      p.cycles(25);
      const driver::Status st = e.status();
      EXPECT_TRUE(st.busy) << "read " << i;
      EXPECT_FALSE(st.done) << "read " << i;
      EXPECT_FALSE(st.error) << "read " << i;
      EXPECT_EQ(p.read(kIrqStatus, nullptr), 0u) << "read " << i;
    }
    const driver::Status st = e.wait(2000, [&] { p.cycles(100); });
    EXPECT_FALSE(st.busy);
    EXPECT_TRUE(st.done);
    EXPECT_FALSE(st.error);
    EXPECT_EQ(p.read(kIrqStatus, nullptr), 1u << kIrqDoneLsb) << "only the done interrupt pending";
    e.clear();
    EXPECT_EQ(p.read(kIrqStatus, nullptr), 0u);
  });
}

// Byte strobes through the SoC: a write with WSTRB k changes exactly the bytes
// k selects and keeps the others, in every read-write register and for every
// strobe from 1 to 15, over random old values. rtl_regs_test checks the block
// alone; every other SoC-level write has all four strobes, so this is the one
// check of WSTRB as mcadsw_top wires it (written while analysing a `make
// mutate` survivor of the old-value path, which turned out equivalent).
TEST(Axi, ByteStrobesThroughTheSoc) {
  using namespace regs;
  constexpr int kOkay = 0;
  const auto bits = test::writable_bits();
  const sim::MemoryModel::Violations v = sim::with_registers([&](sim::RegisterPort& p) {
    std::mt19937 rng(31);
    for (uint32_t strb = 1; strb <= 15; ++strb) {
      uint32_t mask = 0;
      for (int k = 0; k < 4; ++k)
        if (strb >> k & 1) mask |= 0xFFu << (8 * k);
      // All old values first, then all strobed writes: a register's old value
      // is seen while the others hold other random data.
      std::map<uint32_t, uint32_t> old;
      for (const auto& [off, keep] : bits) {
        if (off == kCtrl || off == kIrqEnable) continue;  // CTRL starts; see above
        old[off] = uint32_t(rng());
        ASSERT_EQ(p.write(off, old[off]), kOkay) << "offset " << off;
      }
      for (const auto& [off, before] : old) {
        const uint32_t data = uint32_t(rng());
        ASSERT_EQ(p.write_strobed(off, data, strb), kOkay) << "offset " << off;
        int resp = -1;
        EXPECT_EQ(p.read(off, &resp), ((before & ~mask) | (data & mask)) & bits.at(off))
            << "offset " << off << ", WSTRB " << strb << ", old " << before << ", written " << data;
        EXPECT_EQ(resp, kOkay);
      }
    }
  });
  EXPECT_EQ(v.bad_reads + v.bad_writes, 0) << v.describe();
}

// Writes back to back through the SoC's AXI4-Lite port, as a master with several
// writes in flight sends them: the next AW and W come before the previous B (held
// off by BREADY low), so the register block must hold them off (AWREADY / WREADY
// low while its one-entry write buffers are full) rather than overwrite the
// buffered write (found by `make mutate`: WREADY forced to 1 survived, since the
// driver waits for each B). Every write, an unmapped one among them, answers in
// order and lands with its own data.
TEST(Axi, WritesBeforeTheirPredecessorsResponse) {
  using namespace regs;
  constexpr int kOkay = 0, kSlverr = 2;
  const sim::MemoryModel::Violations v = sim::with_registers([&](sim::RegisterPort& p) {
    for (const long hold_b : {0L, 3L, 40L}) {
      SCOPED_TRACE("BREADY low for " + std::to_string(hold_b) + " cycles");
      const uint32_t salt = uint32_t(hold_b) * 0x01010101u;
      std::vector<std::pair<uint32_t, uint32_t>> w;
      for (uint32_t off = kBaseLy; off <= kBaseMask; off += 4) w.emplace_back(off, 0x1000u * off + salt);
      w.emplace_back(kStride, 0x11223344u ^ salt);
      const size_t unmapped = w.size();
      w.emplace_back(test::unmapped_offsets().front(), ~0u);
      w.emplace_back(kOutStride, 0x55667788u ^ salt);
      w.emplace_back(kTileStride, 0x99aabbccu ^ salt);
      const std::vector<int> bresp = p.write_pipelined(w, hold_b);
      ASSERT_EQ(bresp.size(), w.size());
      for (size_t i = 0; i < w.size(); ++i) {
        EXPECT_EQ(bresp[i], i == unmapped ? kSlverr : kOkay) << "write " << i << " to offset " << w[i].first;
        if (i == unmapped) continue;
        int resp = -1;
        EXPECT_EQ(p.read(w[i].first, &resp), w[i].second) << "offset " << w[i].first;
        EXPECT_EQ(resp, kOkay);
      }
    }
  });
  EXPECT_EQ(v.bad_reads + v.bad_writes, 0) << v.describe();
}

}  // namespace
}  // namespace mcadsw

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The memory model's checks of the engine's port (sim/memory_model.hpp), on a
// scripted port: each check flags what it must and nothing else. Without these
// the engine tests could not see a stalled request that changes, a read
// outside the configured planes, a write into row padding or a second write.
#include <gtest/gtest.h>

#include <vector>

#include "axi_memory.hpp"
#include "memory_model.hpp"

namespace mcadsw::sim {
namespace {

// The port signals of the Verilated model that MemoryModel touches.
struct Port {
  bool mem_req_o = false, mem_we_o = false;
  unsigned mem_be_o = 0;
  uint32_t mem_addr_o = 0, mem_wdata_o = 0;
  unsigned mem_len_o = 0;
  bool mem_gnt_i = false, mem_rvalid_i = false;
  uint32_t mem_rdata_i = 0;
  void eval() {}
};

struct Req {
  bool req, we;
  unsigned be;
  uint32_t addr, wdata;
};

// Planes of 10 x 3 pixels, stride 16: inputs at 0x100 and 0x200, output at 0x300.
MemoryModel::Regions regions() { return {{0x100, 0x200}, 0x300, 16, 10, 3, 0, 1, false, {}}; }

// Presents the requests one per cycle, each granted at once (fixed latency).
MemoryModel::Violations drive(const std::vector<Req>& reqs) {
  MemoryModel::Latency lat;
  MemoryModel mem(0x400, lat);
  mem.set_regions(regions());
  Port p;
  for (size_t i = 0; i < reqs.size(); ++i) {
    mem.drive_response(p);
    p.mem_req_o = reqs[i].req;
    p.mem_we_o = reqs[i].we;
    p.mem_be_o = reqs[i].be;
    p.mem_addr_o = reqs[i].addr;
    p.mem_wdata_o = reqs[i].wdata;
    mem.serve(p);
    mem.end_cycle();
  }
  return mem.violations();
}

TEST(MemoryModel, AcceptsPixelReadsAndSingleWritesOfOutputPixels) {
  const auto v = drive({{true, false, 0xf, 0x100, 0},          // left plane, row 0
                        {true, false, 0xf, 0x208, 0},          // second plane, row 0, x 8..11
                        {true, false, 0xf, 0x120, 0},          // row 2
                        {true, true, 0x3, 0x300, 0x0101},      // output x 0, 1
                        {true, true, 0xc, 0x300, 0x01010000},  // output x 2, 3: same word, other bytes
                        {true, true, 0x3, 0x328, 0x0202}});     // row 2, x 8, 9
  EXPECT_EQ(v.total(), 0) << v.describe();
}

TEST(MemoryModel, FlagsReadsOutsideTheInputPixels) {
  const auto v = drive({{true, false, 0xf, 0x10c, 0},   // row 0 padding (x 12..15)
                        {true, false, 0xf, 0x130, 0},   // row 3: below the plane
                        {true, false, 0xf, 0x300, 0},   // the output plane is no input
                        {true, false, 0xf, 0x000, 0}});  // guard
  EXPECT_EQ(v.bad_reads, 4) << v.describe();
  EXPECT_EQ(v.total(), 4);
  EXPECT_NE(v.first_bad_read.find("0x0000010c"), std::string::npos) << v.first_bad_read;
}

// The modelled range may lie anywhere in the 32-bit space, up to its top, and
// span gigabytes (stored sparsely): bytes at both ends are kept, words just
// outside the range (or misaligned) are harness errors, and a range beyond
// 2^32 is refused.
TEST(MemoryModel, RangeAnywhereInTheAddressSpace) {
  MemoryModel mem(0x40000000u, uint64_t(1) << 32, {});
  mem.set_regions({});
  mem.byte(0xffffffffu) = 0xab;
  mem.byte(0x40000000u) = 0xcd;
  mem.byte(0x9abcdef0u) = 0x12;
  EXPECT_EQ(mem.byte(0xffffffffu), 0xab);
  EXPECT_EQ(mem.byte(0x40000000u), 0xcd);
  EXPECT_EQ(mem.byte(0x9abcdef0u), 0x12);
  EXPECT_EQ(mem.byte(0x9abcdef1u), 0) << "untouched bytes read 0";
  EXPECT_EQ(mem.read_word(0xfffffffcu), 0xab000000u);
  EXPECT_THROW(mem.byte(0x3fffffffu), std::runtime_error);
  EXPECT_THROW(mem.read_word(0x3ffffffcu), std::runtime_error);
  EXPECT_THROW(mem.read_word(0x40000002u), std::runtime_error);
  EXPECT_THROW(MemoryModel(0x1000, (uint64_t(1) << 32) + 4, {}), std::invalid_argument);
}

// A read burst (mem_len_o + 1 words) on the request/grant port: its words at
// consecutive addresses, one a cycle from the cycle after the grant; a burst
// across a 4 KiB boundary is a protocol violation. Column-tiled input planes
// (Regions::tile): a column of 4 pixels, all rows, is tile bytes.
TEST(MemoryModel, ReadBurstsAndTiledPlanes) {
  MemoryModel mem(0x2000, {});
  MemoryModel::Regions r = regions();
  r.inputs = {0x100};
  r.tile = 12;  // 3 rows x 4 bytes; 10 pixels: columns 0..2 (the last holds x 8, 9)
  mem.set_regions(r);
  for (uint32_t a = 0; a < 0x2000; ++a) mem.byte(a) = uint8_t(a / 4);
  Port p;
  std::vector<uint32_t> got;
  const auto cycle = [&](bool req, uint32_t addr, unsigned len) {
    mem.drive_response(p);
    if (p.mem_rvalid_i) got.push_back(p.mem_rdata_i);
    p.mem_req_o = req;
    p.mem_addr_o = addr;
    p.mem_len_o = len;
    mem.serve(p);
    mem.end_cycle();
  };
  cycle(true, 0x100, 2);  // column 0, rows 0..2
  cycle(true, 0x118, 2);  // column 2, rows 0..2
  for (int i = 0; i < 8; ++i) cycle(false, 0, 0);
  ASSERT_EQ(got.size(), 6u);
  for (uint32_t i = 0; i < 3; ++i) {
    EXPECT_EQ(got[i] & 0xff, (0x100 + 4 * i) / 4);
    EXPECT_EQ(got[3 + i] & 0xff, (0x118 + 4 * i) / 4);
  }
  EXPECT_EQ(mem.violations().total(), 0) << mem.violations().describe();
  cycle(true, 0x124, 0);  // column 3: x 12 .. 15, outside the width
  EXPECT_EQ(mem.violations().bad_reads, 1);
  r.inputs = {0xff8};
  r.tile = 0x100;
  mem.set_regions(r);
  cycle(true, 0xff8, 2);  // column 0, rows 0..2 at 0xff8 .. 0x1003: across 4 KiB
  EXPECT_EQ(mem.violations().protocol, 1) << mem.violations().describe();
  EXPECT_EQ(mem.violations().bad_reads, 0) << mem.violations().describe();
}

TEST(MemoryModel, FlagsWritesOutsideTheOutputPixelsAndWithoutBytes) {
  const auto v = drive({{true, true, 0x4, 0x308, 0},   // x 10: row padding
                        {true, true, 0x1, 0x330, 0},   // row 3
                        {true, true, 0x1, 0x100, 0},   // an input plane
                        {true, true, 0x0, 0x300, 0}});  // no byte enabled
  EXPECT_EQ(v.bad_writes, 4) << v.describe();
  EXPECT_EQ(v.total(), 4);
}

TEST(MemoryModel, FlagsASecondWriteOfAPixel) {
  const auto v = drive({{true, true, 0xf, 0x314, 0}, {true, true, 0x2, 0x314, 0}});
  EXPECT_EQ(v.double_writes, 1) << v.describe();
  EXPECT_NE(v.first_double_write.find("(5,1)"), std::string::npos) << v.first_double_write;
}

// Random mode with grant probability 0: every request stalls, so the request
// of the next cycle must equal it.
MemoryModel::Violations stall_then(const Req& first, const Req& next) {
  MemoryModel::Latency lat;
  lat.random = true;
  lat.gnt_prob = 0.0;
  MemoryModel mem(0x400, lat);
  mem.set_regions(regions());
  Port p;
  for (const Req& r : {first, next}) {
    mem.drive_response(p);
    p.mem_req_o = r.req;
    p.mem_we_o = r.we;
    p.mem_be_o = r.be;
    p.mem_addr_o = r.addr;
    p.mem_wdata_o = r.wdata;
    mem.serve(p);
    EXPECT_FALSE(p.mem_gnt_i);
    mem.end_cycle();
  }
  return mem.violations();
}

TEST(MemoryModel, StalledRequestMustStayTheSame) {
  const Req rd{true, false, 0xf, 0x100, 0}, wr{true, true, 0x3, 0x300, 0x1234};
  EXPECT_EQ(stall_then(rd, rd).total(), 0);
  EXPECT_EQ(stall_then(wr, wr).total(), 0);
  auto changed = [&](Req a, auto change) {
    Req b = a;
    change(b);
    return stall_then(a, b).unstable_requests;
  };
  EXPECT_EQ(changed(rd, [](Req& r) { r.addr = 0x104; }), 1) << "address";
  EXPECT_EQ(changed(rd, [](Req& r) { r.req = false; }), 1) << "withdrawn";
  EXPECT_EQ(changed(rd, [](Req& r) { r = {true, true, 0x1, 0x300, 7}; }), 1) << "a write instead";
  EXPECT_EQ(changed(wr, [](Req& r) { r.be = 0xf; }), 1) << "byte enables";
  EXPECT_EQ(changed(wr, [](Req& r) { r.wdata = 0x4321; }), 1) << "write data";
  const auto v = stall_then(rd, {true, false, 0xf, 0x200, 0});
  EXPECT_NE(v.first_unstable.find("became read addr 0x00000200"), std::string::npos) << v.first_unstable;
}

}  // namespace
// ---- The AXI4 model (sim/axi_memory.hpp) -------------------------------------------------

// The AXI4 master signals of the Verilated model that AxiMemory touches.
struct AxiPort {
  bool m_arvalid_o = false, m_awvalid_o = false, m_wvalid_o = false, m_wlast_o = false;
  uint32_t m_araddr_o = 0, m_awaddr_o = 0, m_wdata_o = 0;
  unsigned m_arlen_o = 0, m_arsize_o = 2, m_arburst_o = 1, m_awlen_o = 0, m_awsize_o = 2,
           m_awburst_o = 1, m_wstrb_o = 0xf;
  bool m_rready_o = true, m_bready_o = true;
  bool m_arready_i = false, m_awready_i = false, m_wready_i = false, m_rvalid_i = false,
       m_rlast_i = false, m_bvalid_i = false;
  uint32_t m_rdata_i = 0;
  unsigned m_rresp_i = 0, m_bresp_i = 0;
};

// One cycle of the master: `set` changes its outputs after the model drove its inputs.
struct AxiBench {
  MemoryModel mem{0x400, {}};
  AxiMemory axi;
  AxiPort p;
  std::vector<uint32_t> rdata;
  std::vector<unsigned> rresp, bresp;
  explicit AxiBench(MemoryModel::Latency lat = {}, AxiMemory::Fault f = {})
      : mem(0x400, lat), axi(mem, lat, f) {
    mem.set_regions(regions());
    for (uint32_t a = 0x100; a < 0x400; ++a) mem.byte(a) = uint8_t(a);
  }
  template <typename F>
  void cycle(F set) {
    axi.drive(p);
    set(p);
    if (p.m_rvalid_i) {
      rdata.push_back(p.m_rdata_i);
      rresp.push_back(p.m_rresp_i);
    }
    if (p.m_bvalid_i) bresp.push_back(p.m_bresp_i);
    axi.sample(p);
    mem.end_cycle();
  }
  void idle(int n) {
    for (int i = 0; i < n; ++i) cycle([](AxiPort& q) { q.m_arvalid_o = q.m_awvalid_o = q.m_wvalid_o = false; });
  }
  // Holds AR until ready, then drops it.
  void read(uint32_t addr, unsigned len) {
    bool done = false;
    while (!done)
      cycle([&](AxiPort& q) {
        q.m_arvalid_o = true;
        q.m_araddr_o = addr;
        q.m_arlen_o = len;
        done = q.m_arready_i;
      });
    idle(1);
  }
  // AW then the beats (WLAST on beat `last_at`), each held until ready.
  void write(uint32_t addr, const std::vector<uint32_t>& data, size_t last_at) {
    bool done = false;
    while (!done)
      cycle([&](AxiPort& q) {
        q.m_awvalid_o = true;
        q.m_awaddr_o = addr;
        q.m_awlen_o = unsigned(data.size() - 1);
        done = q.m_awready_i;
      });
    for (size_t i = 0; i < data.size(); ++i) {
      done = false;
      while (!done)
        cycle([&](AxiPort& q) {
          q.m_awvalid_o = false;
          q.m_wvalid_o = true;
          q.m_wdata_o = data[i];
          q.m_wlast_o = i == last_at;
          done = q.m_wready_i;
        });
    }
    idle(1);
  }
};

TEST(AxiMemory, ServesReadAndWriteBurstsInOrderUnderBackPressure) {
  MemoryModel::Latency lat;
  lat.random = true;
  lat.gnt_prob = 0.4;
  lat.seed = 3;
  AxiBench b(lat);
  b.read(0x100, 3);  // row 0 of the first input plane: 16 bytes, 4 beats (x 10..15 padding)
  b.read(0x204, 1);
  b.write(0x300, {0x04030201, 0x08070605}, 1);  // output row 0, x 0..7
  b.idle(40);
  EXPECT_EQ(b.mem.violations().protocol, 0) << b.mem.violations().describe();
  ASSERT_EQ(b.rdata.size(), 6u);
  EXPECT_EQ(b.rdata[0], 0x03020100u);
  EXPECT_EQ(b.rdata[4], 0x07060504u);
  EXPECT_EQ(b.bresp, std::vector<unsigned>{0});
  EXPECT_EQ(b.mem.byte(0x307), 8);
}

TEST(AxiMemory, AWriteLandsAtItsResponse) {
  AxiBench b;
  b.mem.set_regions({{0x100}, 0x300, 16, 10, 3, 0, 1, true, {}});  // the output read back
  AxiMemory slow(b.mem, {}, {}, 50);
  b.p = {};
  // Through a model whose B comes 50 cycles late: before it the old bytes.
  bool done = false;
  auto cyc = [&](auto set) {
    slow.drive(b.p);
    set(b.p);
    slow.sample(b.p);
    b.mem.end_cycle();
  };
  while (!done)
    cyc([&](AxiPort& q) { q.m_awvalid_o = true; q.m_awaddr_o = 0x300; q.m_awlen_o = 0;
                          q.m_wvalid_o = true; q.m_wdata_o = 0xaabbccdd; q.m_wlast_o = true;
                          done = q.m_awready_i && q.m_wready_i; });
  cyc([](AxiPort& q) { q.m_awvalid_o = q.m_wvalid_o = false; });
  EXPECT_EQ(b.mem.byte(0x300), 0x00) << "landed before its B";
  for (int i = 0; i < 60; ++i) cyc([](AxiPort&) {});
  EXPECT_EQ(b.mem.byte(0x300), 0xdd);
  EXPECT_EQ(b.mem.violations().total(), 0) << b.mem.violations().describe();
}

TEST(AxiMemory, FlagsEachBrokenRule) {
  struct Case {
    const char* what;
    void (*run)(AxiBench&);
  };
  const Case cases[] = {
      {"AR VALID dropped before READY", [](AxiBench& b) {
         b.cycle([](AxiPort& q) { q.m_arvalid_o = true; q.m_araddr_o = 0x100; q.m_arready_i = false; });
         b.cycle([](AxiPort& q) { q.m_arvalid_o = false; });
       }},
      {"AW address changed before READY", [](AxiBench& b) {
         b.cycle([](AxiPort& q) { q.m_awvalid_o = true; q.m_awaddr_o = 0x300; q.m_awready_i = false; });
         b.cycle([](AxiPort& q) { q.m_awaddr_o = 0x304; });
       }},
      {"W data changed before READY", [](AxiBench& b) {
         b.cycle([](AxiPort& q) { q.m_wvalid_o = true; q.m_wlast_o = true; q.m_wdata_o = 1; q.m_wready_i = false; });
         b.cycle([](AxiPort& q) { q.m_wdata_o = 2; });
       }},
      {"read burst across 4 KiB", [](AxiBench& b) { b.read(0x0ff8, 3); }},
      {"read burst of 2-byte beats", [](AxiBench& b) {
         b.cycle([](AxiPort& q) { q.m_arvalid_o = true; q.m_araddr_o = 0x100; q.m_arsize_o = 1; q.m_arready_i = true; });
       }},
      {"WLAST early", [](AxiBench& b) { b.write(0x300, {1, 2}, 0); }},
      {"WLAST missing", [](AxiBench& b) { b.write(0x300, {1, 2}, 5); }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.what);
    AxiBench b;
    c.run(b);
    b.idle(10);
    EXPECT_GE(b.mem.violations().protocol, 1);
  }
}

// An AR accepted at most every ar_interval cycles: ARVALID held high throughout,
// ARREADY on every fourth cycle.
TEST(AxiMemory, AcceptsAnArEveryIntervalCycles) {
  MemoryModel mem(0x400, {});
  mem.set_regions(regions());
  AxiMemory axi(mem, {}, {}, 0, 4);
  AxiPort p;
  std::vector<int> accepted;
  for (int c = 0; c < 12; ++c) {
    axi.drive(p);
    p.m_arvalid_o = true;
    p.m_araddr_o = 0x100;
    if (p.m_arready_i) accepted.push_back(c);
    axi.sample(p);
    mem.end_cycle();
  }
  EXPECT_EQ(accepted, (std::vector<int>{0, 4, 8}));
  EXPECT_EQ(mem.violations().total(), 0) << mem.violations().describe();
}

TEST(AxiMemory, InjectsResponseErrors) {
  AxiBench b({}, {2, 1, 3});  // the second read burst and the first write burst: DECERR
  b.read(0x100, 1);
  b.read(0x104, 1);
  b.write(0x300, {7}, 0);
  b.idle(10);
  EXPECT_EQ(b.rresp, (std::vector<unsigned>{0, 0, 3, 3}));
  EXPECT_EQ(b.bresp, std::vector<unsigned>{3});
  EXPECT_EQ(b.mem.byte(0x300), 0x00) << "a failed write burst landed";
}

}  // namespace mcadsw::sim

// The memory model's checks of the engine's port (sim/memory_model.hpp), on a
// scripted port: each check flags what it must and nothing else. Without these
// the engine tests could not see a stalled request that changes, a read
// outside the configured planes, a write into row padding or a second write.
#include <gtest/gtest.h>

#include <vector>

#include "memory_model.hpp"

namespace mcadsw::sim {
namespace {

// The port signals of the Verilated model that MemoryModel touches.
struct Port {
  bool mem_req_o = false, mem_we_o = false;
  unsigned mem_be_o = 0;
  uint32_t mem_addr_o = 0, mem_wdata_o = 0;
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
}  // namespace mcadsw::sim

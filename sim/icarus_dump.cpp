// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "icarus_dump.hpp"

#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "mcadsw/driver.hpp"
#include "mcadsw/regs.hpp"

namespace mcadsw::sim::bench {

namespace {

class RecordingBus : public driver::RegisterBus {
 public:
  uint32_t read(uint32_t offset) override {
    const auto it = last_.find(offset);
    const uint32_t v = it == last_.end() ? 0 : it->second;
    return offset == regs::kCtrl ? v & ~(1u << regs::kCtrlStartLsb | 1u << regs::kCtrlAbortLsb) : v;
  }
  void write(uint32_t offset, uint32_t value) override {
    last_[offset] = value;
    writes_.emplace_back(offset, value);
  }
  const std::vector<std::pair<uint32_t, uint32_t>>& writes() const { return writes_; }

 private:
  std::map<uint32_t, uint32_t> last_;
  std::vector<std::pair<uint32_t, uint32_t>> writes_;
};

}  // namespace

void dump_before(const std::string& dir, MemoryModel& mem, const RawConfig& c, const WeightTable& table) {
  // The Verilog bench's memory starts at address 0 (tests/icarus/tb_mcadsw_engine.sv).
  if (mem.lo() != 0) throw std::invalid_argument("--dump needs the frame at origin 0");
  std::ofstream m(dir + "/mem.hex");
  for (uint64_t a = 0; a + 4 <= mem.hi(); a += 4) {
    uint32_t w = 0;
    for (int b = 0; b < 4; ++b) w |= uint32_t(mem.byte(a + b)) << (8 * b);
    char buf[16];
    std::snprintf(buf, sizeof buf, "%08x\n", w);
    m << buf;
  }
  RecordingBus bus;
  driver::Engine drv(bus);
  drv.configure(frame_config(c, table));
  drv.enable_interrupts(true, true);
  drv.start();
  std::ofstream r(dir + "/regs.txt");
  for (const auto& [offset, value] : bus.writes()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%02x %08x\n", offset, value);
    r << buf;
  }
  std::ofstream f(dir + "/config.txt");
  f << "+WORDS=" << mem.hi() / 4 << "\n";
  if (!m || !r || !f) throw std::runtime_error("cannot write the dump files in " + dir);
}

void dump_after(const std::string& dir, MemoryModel& mem, const Layout& lay, const EngineResult& r) {
  std::ofstream m(dir + "/verilator_out.hex");
  const auto words = [&](uint64_t base, uint64_t bytes) {
    for (uint64_t a = base; a < base + bytes; a += 4) {
      uint32_t w = 0;
      for (int b = 0; b < 4; ++b) w |= uint32_t(mem.byte(a + b)) << (8 * b);
      char buf[16];
      std::snprintf(buf, sizeof buf, "%08x\n", w);
      m << buf;
    }
  };
  std::ofstream g(dir + "/verilator_regions.txt");
  const auto plane = [&](uint64_t base, uint64_t bytes) {
    words(base, bytes);
    char buf[48];
    std::snprintf(buf, sizeof buf, "%08llx %llu\n", static_cast<unsigned long long>(base),
                  static_cast<unsigned long long>(bytes));
    g << buf;
  };
  plane(lay.out, uint64_t(lay.out_stride) * uint32_t(lay.height));
  if (lay.lr) plane(lay.mask, uint64_t(lay.stride) * uint32_t(lay.height));  // and the mask plane
  std::ofstream c(dir + "/verilator_counters.txt");
  c << "cycles " << r.cycles << " words_read " << r.words_read << " words_written "
    << r.words_written << "\n";
  if (!m || !g || !c) throw std::runtime_error("cannot write the dump files in " + dir);
}

}  // namespace mcadsw::sim::bench

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The harness's model of a build without the register block: mcadsw_engine (the
// gate-level netlist of make gls; sim/bench_dut.hpp). Its 32-bit port faces the
// memory model directly (a write completes at its grant); the register bus maps
// the driver's register writes onto the configuration ports (docs/registers.md
// gives the same fields) and STATUS and the counters onto the status ports.
#include <verilated.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>

#include "Vmcadsw_engine.h"
#include "bench_dut.hpp"
#include "cfg_bundle.hpp"
#include "mcadsw/regs.hpp"
#include "vbits.hpp"

namespace mcadsw::sim {
namespace {

using Model = Vmcadsw_engine;

// Field value of a register word (the widths of sw_ref/include/mcadsw/regs.hpp).
constexpr uint32_t field(uint32_t v, int lsb, int width) { return v >> lsb & ((1u << width) - 1); }

class PortBus : public driver::RegisterBus {
 public:
  PortBus(Model& t, BenchDut::Cycle cycle) : t_(t), cycle_(std::move(cycle)) {}

  uint32_t read(uint32_t offset) override {
    switch (offset) {
      case regs::kStatus:
        return uint32_t(t_.busy_o) << regs::kStatusBusyLsb | uint32_t(t_.done_o) << regs::kStatusDoneLsb |
               uint32_t(t_.error_o) << regs::kStatusErrorLsb | uint32_t(t_.error_code_o) << regs::kStatusCodeLsb;
      case regs::kCycles: return t_.cnt_cycles_o;
      case regs::kWordsRead: return t_.cnt_words_read_o;
      case regs::kWordsWritten: return t_.cnt_words_written_o;
      case regs::kStalls: return t_.cnt_stall_o;
      case regs::kCtrl: return uint32_t(get_cfg(t_.cfg_i, regs::Cfg::kMode)) << regs::kCtrlModeLsb;  // the pulse bits read 0
      default: {
        const auto it = written_.find(offset);
        return it == written_.end() ? 0 : it->second;
      }
    }
  }

  void write(uint32_t offset, uint32_t v) override {
    using regs::Cfg;
    written_[offset] = v;
    auto& t = t_;
    if (offset >= regs::kThr0 && offset < regs::kThr0 + 4 * kWeightThresholds && offset % 4 == 0) {
      set_cfg(t.cfg_i, Cfg::kThr, int(offset - regs::kThr0) / 4, regs::kThrBits, v);
      return;
    }
    if (offset >= regs::kBaseLy && offset <= regs::kBaseMask && offset % 4 == 0) {  // BASE_LY .. BASE_MASK
      set_cfg(t.cfg_i, Cfg(int(Cfg::kBaseLy) + int(offset - regs::kBaseLy) / 4), v);
      return;
    }
    if (offset >= regs::kRawLy && offset < regs::kRawLy + 24 && offset % 4 == 0) {  // RAW_LY .. RAW_RV
      set_cfg(t.cfg_i, Cfg::kRaw, int(offset - regs::kRawLy) / 4, 32, v);
      return;
    }
    switch (offset) {
      case regs::kStride: set_cfg(t.cfg_i, Cfg::kStride, v); break;
      case regs::kOutStride: set_cfg(t.cfg_i, Cfg::kOutStride, v); break;
      case regs::kTileStride: set_cfg(t.cfg_i, Cfg::kTileStride, v); break;
      case regs::kSize:
        set_cfg(t.cfg_i, Cfg::kWidth, field(v, regs::kSizeWidthLsb, regs::kSizeBits));
        set_cfg(t.cfg_i, Cfg::kHeight, field(v, regs::kSizeHeightLsb, regs::kSizeBits));
        break;
      // DISP.D as the register block hands it on: 0 above DMAX (the engine rejects it, code 3)
      case regs::kDisp: {
        const uint32_t d = field(v, 0, regs::kDispBitsReg);
        set_cfg(t.cfg_i, Cfg::kDisp, d > uint32_t(kDmax) ? 0 : d);
        break;
      }
      case regs::kLrT: set_cfg(t.cfg_i, Cfg::kLrT, field(v, 0, regs::kLrTBits)); break;
      // Rectification (register map 1.2)
      case regs::kRectCtrl:
        set_cfg(t.cfg_i, Cfg::kRectEn, field(v, regs::kRectEnableLsb, 1));
        set_cfg(t.cfg_i, Cfg::kRectStep, field(v, regs::kRectStepLsb, regs::kRectStepWidth));
        break;
      case regs::kRawSize:
        set_cfg(t.cfg_i, Cfg::kRawWidth, field(v, regs::kSizeWidthLsb, regs::kSizeBits));
        set_cfg(t.cfg_i, Cfg::kRawHeight, field(v, regs::kSizeHeightLsb, regs::kSizeBits));
        break;
      case regs::kRawStride: set_cfg(t.cfg_i, Cfg::kRawStride, v); break;
      case regs::kMeshL: set_cfg(t.cfg_i, Cfg::kMesh, 0, 32, v); break;
      case regs::kMeshR: set_cfg(t.cfg_i, Cfg::kMesh, 1, 32, v); break;
      case regs::kMeshNodes:
        set_cfg(t.cfg_i, Cfg::kMeshNx, field(v, regs::kMeshNxLsb, regs::kSizeBits));
        set_cfg(t.cfg_i, Cfg::kMeshNy, field(v, regs::kMeshNyLsb, regs::kSizeBits));
        break;
      case regs::kValidL: set_cfg(t.cfg_i, Cfg::kValid, 0, 32, v); break;
      case regs::kValidR: set_cfg(t.cfg_i, Cfg::kValid, 1, 32, v); break;
      case regs::kCtrl:
        set_cfg(t.cfg_i, Cfg::kMode, field(v, regs::kCtrlModeLsb, regs::kCtrlModeWidth));
        if (v >> regs::kCtrlAbortLsb & 1)
          throw std::runtime_error("abort: the engine core has no register block (no CTRL.ABORT)");
        if (v >> regs::kCtrlStartLsb & 1) {  // a start pulse of one cycle
          t.start_i = 1;
          cycle_({});
          t.start_i = 0;
        }
        break;
      case regs::kStatus:     // write 1 to clear: the core's done / error last until its next start
      case regs::kIrqEnable:  // no interrupt line: the bench watches done
        break;
      default:
        throw std::runtime_error("register offset " + std::to_string(offset) +
                                 " has no port in the engine core");
    }
  }

 private:
  Model& t_;
  BenchDut::Cycle cycle_;
  std::map<uint32_t, uint32_t> written_;
};

// The ports of one clock cycle as a text line (--record-ports, `make power`):
// each port in hex, as the rising edge finds it; the header names them. The
// activity simulator (sim/activity/netlist_activity.cpp) replays the inputs on
// the netlist and compares the outputs.
class PortRecorder {
 public:
  explicit PortRecorder(const std::string& path) : f_(path) {
    if (!f_) throw std::runtime_error("--record-ports: cannot write " + path);
  }
  template <typename T>
  void scalar(const char* name, int width, bool input, T v) {
    if (named(name, width, input)) return;
    char buf[24];
    std::snprintf(buf, sizeof buf, "%llx ", static_cast<unsigned long long>(v));
    line_ += buf;
  }
  template <std::size_t N>
  void wide(const char* name, int width, bool input, const VlWide<N>& v) {
    if (named(name, width, input)) return;
    for (int w = (width + 31) / 32 - 1; w >= 0; --w) {
      char buf[12];
      std::snprintf(buf, sizeof buf, "%08x", static_cast<unsigned>(v[w]));
      line_ += buf;
    }
    line_ += ' ';
  }
  template <typename Model>
  void record(const Model& t) {
    scalar("rst_ni", 1, true, t.rst_ni);
    scalar("start_i", 1, true, t.start_i);
    wide("cfg_i", regs::kCfgBits, true, t.cfg_i);
    scalar("mem_gnt_i", 1, true, t.mem_gnt_i);
    scalar("mem_rvalid_i", 1, true, t.mem_rvalid_i);
    scalar("mem_rdata_i", 32, true, t.mem_rdata_i);
    scalar("mem_wr_idle_i", 1, true, t.mem_wr_idle_i);
    scalar("busy_o", 1, false, t.busy_o);
    scalar("done_o", 1, false, t.done_o);
    scalar("error_o", 1, false, t.error_o);
    scalar("error_code_o", regs::kStatusCodeWidth, false, t.error_code_o);
    scalar("cnt_cycles_o", 32, false, t.cnt_cycles_o);
    scalar("cnt_words_read_o", 32, false, t.cnt_words_read_o);
    scalar("cnt_words_written_o", 32, false, t.cnt_words_written_o);
    scalar("cnt_stall_o", 32, false, t.cnt_stall_o);
    scalar("mem_req_o", 1, false, t.mem_req_o);
    scalar("mem_we_o", 1, false, t.mem_we_o);
    scalar("mem_be_o", 4, false, t.mem_be_o);
    scalar("mem_addr_o", 32, false, t.mem_addr_o);
    scalar("mem_len_o", 4, false, t.mem_len_o);
    scalar("mem_wdata_o", 32, false, t.mem_wdata_o);
    if (header_) {
      f_ << "ports" << names_ << "\n";
      header_ = false;
      record(t);
      return;
    }
    line_.back() = '\n';
    f_ << line_;
    line_.clear();
    if (!f_) throw std::runtime_error("--record-ports: write failed");
  }

 private:
  // The first record writes the header: the port's name, width and direction.
  bool named(const char* name, int width, bool input) {
    if (header_) names_ += std::string(" ") + name + ":" + std::to_string(width) + (input ? ":in" : ":out");
    return header_;
  }

  std::ofstream f_;
  bool header_ = true;
  std::string names_, line_;
};

class CoreDut : public BenchDut {
 public:
  CoreDut(VerilatedContext& ctx, MemoryModel& mem, Cycle cycle, const std::string& record_ports)
      : mem_(mem), top_(&ctx), bus_(top_, std::move(cycle)) {
    if (!record_ports.empty()) recorder_ = std::make_unique<PortRecorder>(record_ports);
    top_.clk_i = 0;
    top_.start_i = 0;
    top_.mem_gnt_i = 0;
    top_.mem_rvalid_i = 0;
    top_.mem_wr_idle_i = 1;  // the port completes a write at its grant
  }

  void set_reset(bool active) override {
    top_.rst_ni = !active;
    if (active) top_.start_i = 0;
  }
  void reset_memory() override {}
  void clock_low() override {
    mem_.drive_response(top_);
    top_.clk_i = 0;
    top_.eval();
    mem_.serve(top_);
  }
  void clock_high() override {
    if (recorder_) {
      top_.eval();  // the inputs the memory set after the fall, settled
      recorder_->record(top_);
    }
    top_.clk_i = 1;
    top_.eval();
  }
  void eval() override { top_.eval(); }
  void trace(VerilatedFstC&) override {
    throw std::runtime_error("this model was built without FST tracing: no waves");
  }
  void final() override { top_.final(); }

  driver::RegisterBus& registers() override { return bus_; }
  bool frame_over() override { return top_.done_o; }
  long read_bursts() const override { return 0; }   // no AXI4: not counted
  long write_bursts() const override { return 0; }
  RegisterPort raw_registers(const std::function<void(long)>&) override {
    throw std::runtime_error("with_registers: the engine core (gate-level model) has no register block");
  }
  bool can_abort() const override { return false; }

 private:
  MemoryModel& mem_;
  Model top_;
  PortBus bus_;
  std::unique_ptr<PortRecorder> recorder_;
};

}  // namespace

std::unique_ptr<BenchDut> make_bench_dut(VerilatedContext& ctx, MemoryModel& mem, const EngineOptions& opt,
                                         BenchDut::Cycle cycle) {
  return std::make_unique<CoreDut>(ctx, mem, std::move(cycle), opt.run.record_ports);
}

}  // namespace mcadsw::sim

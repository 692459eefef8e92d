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
      case regs::kCtrl: return uint32_t(t_.cfg_mode_i) << regs::kCtrlModeLsb;  // the pulse bits read 0
      default: {
        const auto it = written_.find(offset);
        return it == written_.end() ? 0 : it->second;
      }
    }
  }

  void write(uint32_t offset, uint32_t v) override {
    written_[offset] = v;
    auto& t = t_;
    if (offset >= regs::kThr0 && offset < regs::kThr0 + 4 * kWeightThresholds && offset % 4 == 0) {
      set_bits(t.cfg_thr_i, int(offset - regs::kThr0) / 4 * kColorDistBits, kColorDistBits, v);
      return;
    }
    switch (offset) {
      case regs::kBaseLy: t.cfg_base_ly_i = v; break;
      case regs::kBaseLu: t.cfg_base_lu_i = v; break;
      case regs::kBaseLv: t.cfg_base_lv_i = v; break;
      case regs::kBaseRy: t.cfg_base_ry_i = v; break;
      case regs::kBaseRu: t.cfg_base_ru_i = v; break;
      case regs::kBaseRv: t.cfg_base_rv_i = v; break;
      case regs::kBaseOut: t.cfg_base_out_i = v; break;
      case regs::kBaseDl: t.cfg_base_dl_i = v; break;
      case regs::kBaseDr: t.cfg_base_dr_i = v; break;
      case regs::kBaseMask: t.cfg_base_mask_i = v; break;
      case regs::kStride: t.cfg_stride_i = v; break;
      case regs::kOutStride: t.cfg_out_stride_i = v; break;
      case regs::kTileStride: t.cfg_tile_stride_i = v; break;
      case regs::kSize:
        t.cfg_width_i = field(v, regs::kSizeWidthLsb, regs::kSizeBits);
        t.cfg_height_i = field(v, regs::kSizeHeightLsb, regs::kSizeBits);
        break;
      case regs::kDisp: t.cfg_disp_i = v & ((2u << kDispBits) - 1); break;  // NB = DISP_BITS + 1 bits
      case regs::kLrT: t.cfg_lr_t_i = field(v, 0, regs::kLrTBits); break;
      // Rectification (register map 1.2)
      case regs::kRectCtrl:
        t.cfg_rect_en_i = field(v, regs::kRectEnableLsb, 1);
        t.cfg_rect_step_i = field(v, regs::kRectStepLsb, regs::kRectStepWidth);
        break;
      case regs::kRawSize:
        t.cfg_raw_width_i = field(v, regs::kSizeWidthLsb, regs::kSizeBits);
        t.cfg_raw_height_i = field(v, regs::kSizeHeightLsb, regs::kSizeBits);
        break;
      case regs::kRawStride: t.cfg_raw_stride_i = v; break;
      case regs::kRawLy + 0: t.cfg_raw_ly_i = v; break;
      case regs::kRawLy + 4: t.cfg_raw_lu_i = v; break;
      case regs::kRawLy + 8: t.cfg_raw_lv_i = v; break;
      case regs::kRawLy + 12: t.cfg_raw_ry_i = v; break;
      case regs::kRawLy + 16: t.cfg_raw_ru_i = v; break;
      case regs::kRawLy + 20: t.cfg_raw_rv_i = v; break;
      case regs::kMeshL: t.cfg_mesh_l_i = v; break;
      case regs::kMeshR: t.cfg_mesh_r_i = v; break;
      case regs::kMeshNodes:
        t.cfg_mesh_nx_i = field(v, regs::kMeshNxLsb, regs::kSizeBits);
        t.cfg_mesh_ny_i = field(v, regs::kMeshNyLsb, regs::kSizeBits);
        break;
      case regs::kValidL: t.cfg_valid_l_i = v; break;
      case regs::kValidR: t.cfg_valid_r_i = v; break;
      case regs::kCtrl:
        t.cfg_mode_i = field(v, regs::kCtrlModeLsb, regs::kCtrlModeWidth);
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
    scalar("cfg_base_ly_i", 32, true, t.cfg_base_ly_i);
    scalar("cfg_base_lu_i", 32, true, t.cfg_base_lu_i);
    scalar("cfg_base_lv_i", 32, true, t.cfg_base_lv_i);
    scalar("cfg_base_ry_i", 32, true, t.cfg_base_ry_i);
    scalar("cfg_base_ru_i", 32, true, t.cfg_base_ru_i);
    scalar("cfg_base_rv_i", 32, true, t.cfg_base_rv_i);
    scalar("cfg_base_out_i", 32, true, t.cfg_base_out_i);
    scalar("cfg_base_dl_i", 32, true, t.cfg_base_dl_i);
    scalar("cfg_base_dr_i", 32, true, t.cfg_base_dr_i);
    scalar("cfg_base_mask_i", 32, true, t.cfg_base_mask_i);
    scalar("cfg_stride_i", 32, true, t.cfg_stride_i);
    scalar("cfg_out_stride_i", 32, true, t.cfg_out_stride_i);
    scalar("cfg_tile_stride_i", 32, true, t.cfg_tile_stride_i);
    scalar("cfg_mode_i", 3, true, t.cfg_mode_i);
    scalar("cfg_lr_t_i", regs::kLrTBits, true, t.cfg_lr_t_i);
    scalar("cfg_width_i", regs::kSizeBits, true, t.cfg_width_i);
    scalar("cfg_height_i", regs::kSizeBits, true, t.cfg_height_i);
    scalar("cfg_disp_i", kDispBits + 1, true, t.cfg_disp_i);
    wide("cfg_thr_i", kWeightThresholds * kColorDistBits, true, t.cfg_thr_i);
    scalar("cfg_rect_en_i", 1, true, t.cfg_rect_en_i);
    scalar("cfg_rect_step_i", regs::kRectStepWidth, true, t.cfg_rect_step_i);
    scalar("cfg_raw_width_i", regs::kSizeBits, true, t.cfg_raw_width_i);
    scalar("cfg_raw_height_i", regs::kSizeBits, true, t.cfg_raw_height_i);
    scalar("cfg_raw_stride_i", 32, true, t.cfg_raw_stride_i);
    scalar("cfg_raw_ly_i", 32, true, t.cfg_raw_ly_i);
    scalar("cfg_raw_lu_i", 32, true, t.cfg_raw_lu_i);
    scalar("cfg_raw_lv_i", 32, true, t.cfg_raw_lv_i);
    scalar("cfg_raw_ry_i", 32, true, t.cfg_raw_ry_i);
    scalar("cfg_raw_ru_i", 32, true, t.cfg_raw_ru_i);
    scalar("cfg_raw_rv_i", 32, true, t.cfg_raw_rv_i);
    scalar("cfg_mesh_l_i", 32, true, t.cfg_mesh_l_i);
    scalar("cfg_mesh_r_i", 32, true, t.cfg_mesh_r_i);
    scalar("cfg_mesh_nx_i", regs::kSizeBits, true, t.cfg_mesh_nx_i);
    scalar("cfg_mesh_ny_i", regs::kSizeBits, true, t.cfg_mesh_ny_i);
    scalar("cfg_valid_l_i", 32, true, t.cfg_valid_l_i);
    scalar("cfg_valid_r_i", 32, true, t.cfg_valid_r_i);
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
    top_.rst_ni = 0;
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

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The harness's model of a build with the register block: mcadsw_top, the SoC
// wrapper (sim/bench_dut.hpp). The register bus is the AXI4-Lite bus functional
// model; every write must answer OKAY.
#include <verilated.h>
#if VM_TRACE_FST
#include <verilated_fst_c.h>
#endif

#include <stdexcept>
#include <string>

#include "Vmcadsw_top.h"
#include "axi_memory.hpp"
#include "axil_driver.hpp"
#include "bench_dut.hpp"

namespace mcadsw::sim {
namespace {

using Model = Vmcadsw_top;

class AxilBus : public driver::RegisterBus {
 public:
  explicit AxilBus(AxilDriver<Model>& axi) : axi_(axi) {}
  uint32_t read(uint32_t offset) override { return axi_.read(offset); }
  void write(uint32_t offset, uint32_t value) override {
    if (axi_.write(offset, value) != 0)
      throw std::runtime_error("register write to offset " + std::to_string(offset) + " not OKAY");
  }

 private:
  AxilDriver<Model>& axi_;
};

class SocDut : public BenchDut {
 public:
  SocDut(VerilatedContext& ctx, MemoryModel& mem, const EngineOptions& opt, Cycle cycle)
      : axi_mem_(mem, opt.memory.latency, opt.memory.axi_fault, opt.memory.axi_write_latency, opt.memory.axi_ar_interval),
        top_(&ctx),
        // READY and VALID of the register bus held back 30 % of the cycles.
        axi_(top_, std::move(cycle), opt.memory.latency.seed + 77, 0.3),
        bus_(axi_) {
    top_.clk_i = 0;
  }

  void set_reset(bool active) override { top_.rst_ni = !active; }
  void reset_memory() override { axi_mem_.reset(); }
  void clock_low() override {
    axi_mem_.drive(top_);
    top_.clk_i = 0;
    top_.eval();
    axi_mem_.sample(top_);
  }
  void clock_high() override {
    top_.clk_i = 1;
    top_.eval();
  }
  void eval() override { top_.eval(); }
  void trace(VerilatedFstC& fst) override {
#if VM_TRACE_FST
    top_.trace(&fst, 99);
#else
    (void)fst;
    throw std::runtime_error("this model was built without FST tracing: no waves");
#endif
  }
  void final() override { top_.final(); }

  driver::RegisterBus& registers() override { return bus_; }
  bool frame_over() override { return top_.irq_o; }
  long read_bursts() const override { return axi_mem_.read_bursts(); }
  long write_bursts() const override { return axi_mem_.write_bursts_done(); }
  RegisterPort raw_registers(const std::function<void(long)>& cycles) override {
    RegisterPort port;
    port.write = [this](uint32_t off, uint32_t v) { return axi_.write(off, v); };
    port.write_strobed = [this](uint32_t off, uint32_t v, uint32_t strb) { return axi_.write(off, v, strb); };
    port.read = [this](uint32_t off, int* resp) { return axi_.read(off, resp); };
    port.write_pipelined = [this](const std::vector<std::pair<uint32_t, uint32_t>>& w, long hold_b) {
      return axi_.write_pipelined(w, hold_b);
    };
    port.cycles = cycles;
    return port;
  }
  bool can_abort() const override { return true; }

 private:
  AxiMemory axi_mem_;  // the AXI4 slave in front of the memory model
  Model top_;
  AxilDriver<Model> axi_;
  AxilBus bus_;
};

}  // namespace

std::unique_ptr<BenchDut> make_bench_dut(VerilatedContext& ctx, MemoryModel& mem, const EngineOptions& opt,
                                         BenchDut::Cycle cycle) {
  if (!opt.run.record_ports.empty())
    throw std::runtime_error("--record-ports: the SoC build has no engine-core ports; use mcadsw_sim_core");
  return std::make_unique<SocDut>(ctx, mem, opt, std::move(cycle));
}

}  // namespace mcadsw::sim

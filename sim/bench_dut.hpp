// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The verilated model as the harness (engine_bench.cpp) drives it: one interface,
// one implementation a build, chosen by CMake (sim/CMakeLists.txt):
//   dut_soc.cpp   mcadsw_top, the SoC wrapper: its AXI4 master faces the AXI4
//                 memory model (axi_memory.hpp), its AXI4-Lite registers the bus
//                 functional model (axil_driver.hpp); the register bus is that model.
//   dut_core.cpp  mcadsw_engine (the gate-level netlist of make gls): its 32-bit
//                 port faces the memory model directly; the register bus maps the
//                 register writes of the driver onto the configuration ports.
// Either way the harness programs the engine with the driver a user's firmware
// uses (driver/include/mcadsw/driver.hpp) over registers().
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "engine_bench.hpp"
#include "mcadsw/driver.hpp"

class VerilatedContext;
class VerilatedFstC;

namespace mcadsw::sim {

class BenchDut {
 public:
  // Runs one clock cycle of the bench (the callback runs once the cycle's outputs
  // have settled); the register bus uses it to wait.
  using Cycle = std::function<void(const std::function<void()>& at_sample)>;

  virtual ~BenchDut() = default;

  // rst_ni low (and the start input quiet) or high. The bench releases it before
  // the model's first evaluation, so that asserting the reset is a falling edge: an asynchronous reset
  // (`always_ff @(posedge clk_i or negedge rst_ni)`) acts in an event-driven
  // model only on that edge or on a clock edge, and a block behind a clock gate
  // that is closed during reset sees no clock edge (in silicon the level resets it).
  virtual void set_reset(bool active) = 0;
  // The memory side's state back to its reset (with the engine's reset).
  virtual void reset_memory() = 0;
  // The two halves of a clock cycle: the memory drives its inputs, the clock
  // falls, the model settles and the memory samples its outputs; then the clock rises.
  virtual void clock_low() = 0;
  virtual void clock_high() = 0;
  virtual void eval() = 0;
  virtual void trace(VerilatedFstC& fst) = 0;  // throws if the model has no FST tracing
  virtual void final() = 0;

  // The register bus the driver runs on (each access takes cycles through Cycle).
  virtual driver::RegisterBus& registers() = 0;
  // The frame is over: the interrupt line (SoC), or done (engine core).
  virtual bool frame_over() = 0;
  // AXI4 bursts seen by the memory so far (the engine core: one a word).
  virtual long read_bursts() const = 0;
  virtual long write_bursts() const = 0;
  // Raw register access with the AXI4-Lite response (with_registers); the engine
  // core has no register block and throws.
  virtual RegisterPort raw_registers(const std::function<void(long)>& cycles) = 0;
  // CTRL.ABORT exists (not in the engine core, which has no register block).
  virtual bool can_abort() const = 0;
};

// The build's model around `mem` (the implementation CMake linked).
std::unique_ptr<BenchDut> make_bench_dut(VerilatedContext& ctx, MemoryModel& mem, const EngineOptions& opt,
                                         BenchDut::Cycle cycle);

}  // namespace mcadsw::sim

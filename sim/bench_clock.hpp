// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The bench's clock: the verilated model (sim/bench_dut.hpp) with its reset, its
// waves and coverage, and a frame run through the driver (or a user's firmware) from
// start to its end or a cycle limit. Compiled with each model (VM_TRACE_FST, VM_COVERAGE).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include <verilated.h>
#if VM_TRACE_FST
#include <verilated_fst_c.h>
#endif

#include "bench_dut.hpp"
#include "engine_bench.hpp"
#include "memory_model.hpp"
#include "mcadsw/driver.hpp"
#include "mcadsw/ref.hpp"

namespace mcadsw::sim::bench {

class Engine {
 public:
  Engine(MemoryModel& mem, const EngineOptions& opt);
  // Asynchronous reset for 4 cycles, with the memory system.
  void reset();
  ~Engine();
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  BenchDut& dut() { return *dut_; }
  driver::Engine& driver() { return *driver_; }
  Firmware* firmware() { return firmware_; }

  // One clock cycle; `at_sample` runs once the cycle's outputs have settled.
  void cycle(const std::function<void()>& at_sample = {});

 private:
  MemoryModel& mem_;
  std::unique_ptr<VerilatedContext> ctx_ = std::make_unique<VerilatedContext>();
  std::unique_ptr<BenchDut> dut_;
  std::unique_ptr<driver::Engine> driver_;
  Firmware* firmware_ = nullptr;
#if VM_TRACE_FST
  std::unique_ptr<VerilatedFstC> trace_;
#endif
  uint64_t time_ = 0;
};

// The configuration through the driver (or RunControl::firmware), both
// interrupts on; the frame starts with start().
void program(Engine& e, const RawConfig& c, const WeightTable& table);
void start(Engine& e);
void abort_frame(Engine& e);

// Status and counters, read as a driver reads them.
void read_status(Engine& e, EngineResult& r);

// Runs from start until the frame is over (done, or the interrupt) or the cycle
// limit; `again` > 0 programs `other` and starts again that many cycles after
// the start (the configuration keeps `other` until the frame ends), or, with
// `abort`, writes CTRL.ABORT then (at 0: just before the start).
struct StartAgain {
  long at = 0;
  RawConfig other{};
  const WeightTable* table = nullptr;
  bool abort = false;
};
void run_frame(Engine& e, EngineResult& r, long limit, bool progress, const StartAgain& again = {});

// Generous: four times the memory-bound estimate of 8000 cycles per block; with
// rectification, 16 cycles a rectified pixel of each of up to 6 planes more (about
// 1.05 at zero latency, docs/blocks/rectifier.md 7), the mark step included.
long frame_limit(int W, int H, const EngineOptions& opt);

}  // namespace mcadsw::sim::bench

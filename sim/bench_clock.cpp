// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "bench_clock.hpp"

#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>

#if VM_COVERAGE
#include <unistd.h>
#include <verilated_cov.h>

#include <atomic>
#endif

#include "frame_layout.hpp"

namespace mcadsw::sim::bench {

Engine::Engine(MemoryModel& mem, const EngineOptions& opt) : mem_(mem) {
  // Waves in real time: one cycle is kClockPeriodPs; the model is verilated
  // with --timescale 1ns/1ps (sim/CMakeLists.txt), so trace times are in ps.
  ctx_->traceEverOn(!opt.run.waves.empty());
  // `make mutate` (flow/mutate.py): a model built with every mutant of the
  // list reads the plusarg +mcadsw_mutant=K, passed on from the environment
  // variable MCADSW_MUTANT (0 or unset: none, the design as written); other
  // models ignore it.
  const char* k = std::getenv("MCADSW_MUTANT");
  const std::string mutant = std::string("+mcadsw_mutant=") + (k ? k : "0");
  const char* mutant_arg[] = {mutant.c_str()};
  ctx_->commandArgsAdd(1, mutant_arg);
  dut_ = make_bench_dut(*ctx_, mem, opt,
                        [this](const std::function<void()>& at_sample) { cycle(at_sample); });
  driver_ = std::make_unique<driver::Engine>(dut_->registers());
  firmware_ = opt.run.firmware;
  if (!opt.run.waves.empty()) {
#if VM_TRACE_FST
    trace_ = std::make_unique<VerilatedFstC>();
    dut_->trace(*trace_);
    trace_->open(opt.run.waves.c_str());
#else
    throw std::runtime_error("this model was built without FST tracing: no waves");
#endif
  }
  // Released first, so that asserting the reset is a falling edge (bench_dut.hpp).
  dut_->set_reset(false);
  dut_->eval();
  reset();
}

// Asynchronous reset for 4 cycles, with the memory system.
void Engine::reset() {
  dut_->set_reset(true);
  dut_->eval();
  mem_.reset();
  dut_->reset_memory();
  for (int i = 0; i < 4; ++i) cycle();
  dut_->set_reset(false);
}

Engine::~Engine() {
#if VM_TRACE_FST
  if (trace_) trace_->close();
#endif
  dut_->final();
#if VM_COVERAGE
  // `make coverage` (flow/coverage.py): one coverage file per engine instance.
  if (const char* dir = std::getenv("MCADSW_COVERAGE_DIR")) {
    static std::atomic<int> serial{0};
    const std::string path = std::string(dir) + "/" + std::to_string(getpid()) + "_" +
                             std::to_string(serial++) + ".dat";
    ctx_->coveragep()->write(path.c_str());
  }
#endif
}

void Engine::cycle(const std::function<void()>& at_sample) {
  dut_->clock_low();
  if (at_sample) at_sample();
#if VM_TRACE_FST
  // Inputs change at the start of the low phase; the rising edge is half a
  // period later.
  if (trace_) trace_->dump(time_ * kClockPeriodPs);
#endif
  dut_->clock_high();
#if VM_TRACE_FST
  if (trace_) trace_->dump(time_ * kClockPeriodPs + kClockPeriodPs / 2);
#endif
  mem_.end_cycle();
  ++time_;
}

void program(Engine& e, const RawConfig& c, const WeightTable& table) {
  if (e.firmware()) return e.firmware()->configure(e.dut().registers(), frame_config(c, table));
  e.driver().configure(frame_config(c, table));
  e.driver().enable_interrupts(true, true);
}

void start(Engine& e) {
  if (e.firmware()) return e.firmware()->start(e.dut().registers());
  e.driver().start();
}

void abort_frame(Engine& e) {
  if (!e.dut().can_abort())
    throw std::runtime_error("abort: the gate-level model has no register block (no CTRL.ABORT)");
  e.driver().abort();
}

void read_status(Engine& e, EngineResult& r) {
  const driver::Status st = e.driver().status();
  r.error = st.error;
  r.error_code = st.error_code;
  r.done = st.done;
  const driver::Counters n = e.driver().counters();
  r.cycles = long(n.cycles);
  r.words_read = long(n.words_read);
  r.words_written = long(n.words_written);
  r.stall_cycles = long(n.stalls);
  r.read_bursts = e.dut().read_bursts();
  r.write_bursts = e.dut().write_bursts();
}

void run_frame(Engine& e, EngineResult& r, long limit, bool progress, const StartAgain& again) {
  if (again.abort && again.at == 0) abort_frame(e);
  EngineResult before;
  before.read_bursts = e.dut().read_bursts();
  before.write_bursts = e.dut().write_bursts();
  start(e);
  const auto t0 = std::chrono::steady_clock::now();
  long n = 0;
  while (!e.dut().frame_over()) {
    if (++n > limit) {
      r.timed_out = true;
      break;
    }
    if (n == again.at && again.abort) {
      abort_frame(e);
    } else if (n == again.at) {
      program(e, again.other, *again.table);
      start(e);
    } else {
      e.cycle();
    }
    if (progress && n % 2000000 == 0)
      std::fprintf(stderr, "  ... %ld Mcycles simulated\n", n / 1000000);
  }
  r.sim_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  read_status(e, r);
  if (e.firmware()) e.firmware()->frame_over(e.dut().registers());
  r.read_bursts -= before.read_bursts;
  r.write_bursts -= before.write_bursts;
}

long frame_limit(int W, int H, const EngineOptions& opt) {
  const long blocks = long((W + kBlock - 1) / kBlock) * ((H + kBlock - 1) / kBlock);
  const long rect = opt.frame.rect ? 16L * 6 * W * H + 100000 : 0;
  return opt.run.max_cycles > 0 ? opt.run.max_cycles : (opt.frame.lr ? 3 : 1) * (40000 * blocks + 100000) + rect;
}

}  // namespace mcadsw::sim::bench

namespace mcadsw::sim {

#if VM_TRACE_FST
bool model_writes_waves() { return true; }
#else
bool model_writes_waves() { return false; }
#endif

}  // namespace mcadsw::sim

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// AXI4-Lite master for a Verilated model with the s_aw*/s_w*/s_b*/s_ar*/s_r*
// slave ports of rtl/mcadsw_regs.sv, as a driver would use it, with random
// VALID delays and READY back-pressure, and a protocol monitor of the slave's
// side (AMBA AXI4-Lite):
//   - BVALID / RVALID held until BREADY / RREADY, with a stable payload;
//   - no B response without an accepted AW and W, no R response without an accepted AR;
//   - a response arrives within a bound (no hang).
// The master's own side follows the same rules: VALID held with a stable
// payload until READY, AW and W raised independently after random delays (either
// may come first), one transaction at a time (write_pipelined: writes back to
// back, the next AW and W before the previous B).
//
// The bench supplies `cycle`: one clock cycle of the model and everything around
// it (its memory, the waves), which calls `at_sample` once the outputs of the
// cycle have settled, before the rising edge. The driver sets its inputs before
// the cycle and samples handshakes in `at_sample`.
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mcadsw::sim {

template <typename V>
class AxilDriver {
 public:
  // `stall` in [0, 1): the probability that a VALID or READY the driver controls is
  // held back in a cycle.
  using Cycle = std::function<void(const std::function<void()>& at_sample)>;
  AxilDriver(V& t, Cycle cycle, uint32_t seed, double stall)
      : t_(t), cycle_(std::move(cycle)), rng_(seed), stall_(stall) {
    t_.s_awvalid_i = 0;
    t_.s_wvalid_i = 0;
    t_.s_bready_i = 0;
    t_.s_arvalid_i = 0;
    t_.s_rready_i = 0;
  }

  // Returns BRESP (0 OKAY, 2 SLVERR).
  int write(uint32_t addr, uint32_t data, uint32_t strb = 0xF) {
    bool aw_done = false, w_done = false;
    long aw_wait = delay(), w_wait = delay();
    for (long n = 0;; ++n) {
      if (n > kLimit) fail("write to 0x" + hex(addr) + ": no B response");
      // Raise VALID after its delay; once up it stays up with the same payload.
      if (!aw_done && aw_wait-- <= 0) {
        t_.s_awvalid_i = 1;
        t_.s_awaddr_i = addr;
      }
      if (!w_done && w_wait-- <= 0) {
        t_.s_wvalid_i = 1;
        t_.s_wdata_i = data;
        t_.s_wstrb_i = strb;
      }
      if (aw_done && w_done) t_.s_bready_i = coin() ? 0 : 1;
      const WriteHandshakes hs = write_cycle();
      if (hs.aw) {
        aw_done = true;
        t_.s_awvalid_i = 0;
      }
      if (hs.w) {
        w_done = true;
        t_.s_wvalid_i = 0;
      }
      if (hs.b) {
        t_.s_bready_i = 0;
        return hs.bresp;
      }
    }
  }

  // Several writes back to back, as a master with more than one write in flight
  // would send them: each AW and each W is offered as soon as the previous one on
  // its channel was accepted (not after its B), and BREADY stays low for the first
  // `hold_b` cycles, so the slave sees the next AW and W while a B waits (it may
  // hold them off with AWREADY / WREADY). Returns the BRESPs in order.
  std::vector<int> write_pipelined(const std::vector<std::pair<uint32_t, uint32_t>>& writes, long hold_b) {
    size_t aw_next = 0, w_next = 0;
    std::vector<int> bresp;
    long aw_wait = delay(), w_wait = delay();
    for (long n = 0; bresp.size() < writes.size(); ++n) {
      if (n > kLimit) fail("pipelined writes: " + std::to_string(bresp.size()) + " of " +
                           std::to_string(writes.size()) + " B responses");
      if (aw_next < writes.size() && !t_.s_awvalid_i && aw_wait-- <= 0) {
        t_.s_awvalid_i = 1;
        t_.s_awaddr_i = writes[aw_next].first;
      }
      if (w_next < writes.size() && !t_.s_wvalid_i && w_wait-- <= 0) {
        t_.s_wvalid_i = 1;
        t_.s_wdata_i = writes[w_next].second;
        t_.s_wstrb_i = 0xF;
      }
      t_.s_bready_i = n >= hold_b && !coin();
      const WriteHandshakes hs = write_cycle();
      if (hs.aw) {
        t_.s_awvalid_i = 0;
        ++aw_next;
        aw_wait = delay();
      }
      if (hs.w) {
        t_.s_wvalid_i = 0;
        ++w_next;
        w_wait = delay();
      }
      if (hs.b) bresp.push_back(hs.bresp);
    }
    t_.s_bready_i = 0;
    return bresp;
  }

  // Returns RDATA; *resp gets RRESP.
  uint32_t read(uint32_t addr, int* resp = nullptr) {
    bool ar_done = false;
    long ar_wait = delay();
    for (long n = 0;; ++n) {
      if (n > kLimit) fail("read of 0x" + hex(addr) + ": no R response");
      if (!ar_done && ar_wait-- <= 0) {
        t_.s_arvalid_i = 1;
        t_.s_araddr_i = addr;
      }
      if (ar_done) t_.s_rready_i = coin() ? 0 : 1;
      bool ar_hs = false, r_hs = false;
      uint32_t data = 0;
      int rresp = 0;
      tick([&] {
        ar_hs = t_.s_arvalid_i && t_.s_arready_o;
        r_hs = t_.s_rvalid_o && t_.s_rready_i;
        data = t_.s_rdata_o;
        rresp = t_.s_rresp_o;
        ar_accepted_ += ar_hs;
      });
      if (ar_hs) {
        ar_done = true;
        t_.s_arvalid_i = 0;
      }
      if (r_hs) {
        t_.s_rready_i = 0;
        if (resp) *resp = rresp;
        return data;
      }
    }
  }

  // Cycles without a transaction (the monitor still runs).
  void idle(long cycles) {
    for (long i = 0; i < cycles; ++i) tick([] {});
  }

  long cycles() const { return cycles_; }

 private:
  static constexpr long kLimit = 10000;

  bool coin() { return std::bernoulli_distribution(stall_)(rng_); }
  long delay() {
    long d = 0;
    while (coin()) ++d;
    return d;
  }
  static std::string hex(uint32_t v) {
    std::ostringstream o;
    o << std::hex << v;
    return o.str();
  }
  [[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("AXI4-Lite: " + what + " (cycle " + std::to_string(cycles_) + ")");
  }

  // One cycle of a write: the AW, W and B handshakes at its sample point (the
  // accepted AWs and Ws counted for the monitor).
  struct WriteHandshakes {
    bool aw = false, w = false, b = false;
    int bresp = 0;
  };
  WriteHandshakes write_cycle() {
    WriteHandshakes hs;
    tick([&] {
      hs.aw = t_.s_awvalid_i && t_.s_awready_o;
      hs.w = t_.s_wvalid_i && t_.s_wready_o;
      hs.b = t_.s_bvalid_o && t_.s_bready_i;
      hs.bresp = t_.s_bresp_o;
      aw_accepted_ += hs.aw;
      w_accepted_ += hs.w;
    });
    return hs;
  }

  // One cycle; at its sample point the monitor checks the slave's outputs (before
  // it records this cycle's handshakes), then `sample` runs.
  template <typename F>
  void tick(F sample) {
    cycle_([&] {
      monitor();
      sample();
    });
    ++cycles_;
  }

  void monitor() {
    // Responses held with a stable payload until taken.
    if (b_pending_ && !t_.s_bvalid_o) fail("BVALID dropped before BREADY");
    if (b_pending_ && t_.s_bresp_o != bresp_) fail("BRESP changed while BVALID waited");
    if (r_pending_ && !t_.s_rvalid_o) fail("RVALID dropped before RREADY");
    if (r_pending_ && (t_.s_rdata_o != rdata_ || t_.s_rresp_o != rresp_))
      fail("RDATA/RRESP changed while RVALID waited");
    // No response without a request.
    if (t_.s_bvalid_o && !b_pending_) {
      if (aw_accepted_ <= b_count_ || w_accepted_ <= b_count_) fail("B response without AW and W");
    }
    if (t_.s_rvalid_o && !r_pending_) {
      if (ar_accepted_ <= r_count_) fail("R response without AR");
    }
    // This cycle's state for the next check.
    const bool b_taken = t_.s_bvalid_o && t_.s_bready_i;
    const bool r_taken = t_.s_rvalid_o && t_.s_rready_i;
    if (t_.s_bvalid_o) bresp_ = t_.s_bresp_o;
    if (t_.s_rvalid_o) {
      rdata_ = t_.s_rdata_o;
      rresp_ = t_.s_rresp_o;
    }
    b_pending_ = t_.s_bvalid_o && !b_taken;
    r_pending_ = t_.s_rvalid_o && !r_taken;
    b_count_ += b_taken;
    r_count_ += r_taken;
  }

  V& t_;
  Cycle cycle_;
  std::mt19937 rng_;
  double stall_;
  long cycles_ = 0;
  long aw_accepted_ = 0, w_accepted_ = 0, ar_accepted_ = 0, b_count_ = 0, r_count_ = 0;
  bool b_pending_ = false, r_pending_ = false;
  int bresp_ = 0, rresp_ = 0;
  uint32_t rdata_ = 0;
};

}  // namespace mcadsw::sim

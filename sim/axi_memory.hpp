// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// AXI4 slave model of the frame memory, in front of MemoryModel
// (its bytes and its address checks): the harness's memory for mcadsw_top.
//
// Serves one ID, in order: AR and AW bursts (INCR, 4-byte beats), R beats a
// read latency after the AR handshake, B once a burst's AW and all its W beats
// are in. Reads sample the memory at the AR handshake and writes land at their
// B, so a master that reads back what it wrote before the B sees stale data.
// Latency and back-pressure (MemoryModel::Latency): `fixed` extra cycles before
// each burst's first R beat and before each B (write_latency more before a B); `random` adds 0..max_random
// cycles a burst and drives ARREADY, AWREADY and WREADY high with probability
// gnt_prob a cycle (otherwise they are always high).
// Faults: the n-th read burst answers every beat with `resp` (SLVERR 2 or
// DECERR 3), the n-th write burst its B (the burst is not written).
//
// Checks, counted as MemoryModel protocol violations (the first described):
//   - AR, AW and W VALID, once high, stay high with the same payload until READY;
//   - ARSIZE / AWSIZE 4 bytes, INCR bursts, aligned addresses, no burst across a
//     4 KiB boundary, at most 256 beats;
//   - WLAST on the last beat of each burst and on no other;
//   - RREADY / BREADY: a response is held until taken (the model), and a master
//     that leaves a response untaken forever shows as a timeout.
// Every beat's address goes through MemoryModel's read and write checks.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "memory_model.hpp"

namespace mcadsw::sim {

class AxiMemory {
 public:
  struct Fault {
    long read_burst = 0;   // 1-based: the read burst answered with `resp`; 0: none
    long write_burst = 0;  // 1-based: the write burst answered with `resp`; 0: none
    int resp = 2;          // SLVERR 2, DECERR 3
  };

  // write_latency: further cycles before each B (and before the burst lands).
  // ar_interval: an AR is accepted at most every ar_interval cycles (a memory
  // controller's command rate).
  AxiMemory(MemoryModel& mem, MemoryModel::Latency lat, Fault fault, long write_latency = 0,
            int ar_interval = 1)
      : mem_(mem), lat_(lat), fault_(fault), write_latency_(write_latency),
        ar_interval_(ar_interval), rng_(lat.seed ^ 0x5a5a5a5au) {}

  // Inputs of the coming cycle: READYs, and the head R beat and B response.
  // Call before evaluating the cycle's low phase.
  template <typename V>
  void drive(V& t) {
    const auto ready = [this] {
      return !lat_.random || std::bernoulli_distribution(lat_.gnt_prob)(rng_);
    };
    t.m_arready_i = ready() && now() - last_ar_ >= ar_interval_;
    t.m_awready_i = ready();
    t.m_wready_i = ready();
    r_on_ = !rq_.empty() && rq_.front().due <= now();
    t.m_rvalid_i = r_on_;
    t.m_rdata_i = r_on_ ? rq_.front().data : 0;
    t.m_rresp_i = r_on_ ? rq_.front().resp : 0;
    t.m_rlast_i = r_on_ && rq_.front().last;
    b_on_ = !bq_.empty() && bq_.front().due <= now();
    t.m_bvalid_i = b_on_;
    t.m_bresp_i = b_on_ ? bq_.front().resp : 0;
  }

  // The cycle's handshakes, with its outputs settled (clock low, evaluated):
  // checks them and performs them.
  template <typename V>
  void sample(V& t) {
    const Addr ar{bool(t.m_arvalid_o), uint32_t(t.m_araddr_o), unsigned(t.m_arlen_o),
                  unsigned(t.m_arsize_o), unsigned(t.m_arburst_o)};
    const Addr aw{bool(t.m_awvalid_o), uint32_t(t.m_awaddr_o), unsigned(t.m_awlen_o),
                  unsigned(t.m_awsize_o), unsigned(t.m_awburst_o)};
    const Beat w{bool(t.m_wvalid_o), uint32_t(t.m_wdata_o), unsigned(t.m_wstrb_o),
                 bool(t.m_wlast_o)};
    stable(ar_wait_, ar_held_, ar, "AR");
    stable(aw_wait_, aw_held_, aw, "AW");
    if (w_wait_ && !(w.valid && w.data == w_held_.data && w.strb == w_held_.strb &&
                     w.last == w_held_.last))
      mem_.protocol_violation("W VALID dropped or its payload changed before WREADY");
    const bool ar_go = ar.valid && t.m_arready_i, aw_go = aw.valid && t.m_awready_i,
               w_go = w.valid && t.m_wready_i;
    ar_wait_ = ar.valid && !ar_go;
    aw_wait_ = aw.valid && !aw_go;
    w_wait_ = w.valid && !w_go;
    ar_held_ = ar;
    aw_held_ = aw;
    w_held_ = w;
    if (r_on_ && t.m_rready_o) rq_.pop_front();
    if (b_on_ && t.m_bready_o) {
      for (const PendingWrite& p : bq_.front().writes) mem_.write_word(p.addr, p.strb, p.data);
      bq_.pop_front();
    }
    if (ar_go) {
      last_ar_ = now();
      read_burst(ar);
    }
    if (aw_go) {
      check_burst(aw, "AW");
      awq_.push_back(aw);
    }
    if (w_go) wq_.push_back(w);
    write_bursts();
  }

  // Reset with the master: everything in flight is forgotten.
  void reset() {
    rq_.clear();
    bq_.clear();
    awq_.clear();
    wq_.clear();
    ar_wait_ = aw_wait_ = w_wait_ = false;
  }
  long read_bursts() const { return n_reads_; }
  long write_bursts_done() const { return n_writes_; }

 private:
  struct Addr {
    bool valid = false;
    uint32_t addr = 0;
    unsigned len = 0, size = 0, burst = 0;
    bool operator==(const Addr& o) const {
      return valid == o.valid && addr == o.addr && len == o.len && size == o.size &&
             burst == o.burst;
    }
  };
  struct Beat {
    bool valid = false;
    uint32_t data = 0;
    unsigned strb = 0;
    bool last = false;
  };
  struct RBeat {
    long due;
    uint32_t data;
    unsigned resp;
    bool last;
  };
  struct PendingWrite {
    uint32_t addr;
    unsigned strb;
    uint32_t data;
  };
  struct BResp {
    long due;
    unsigned resp;
    std::vector<PendingWrite> writes;  // land in memory at the B handshake
  };

  long now() const { return mem_.cycle(); }
  static std::string hex(uint32_t v) { return MemoryModel::hex(v); }

  void stable(bool waiting, const Addr& held, const Addr& cur, const char* ch) {
    if (waiting && !(cur == held))
      mem_.protocol_violation(std::string(ch) + " VALID dropped or its payload changed before READY (addr 0x" +
                              hex(held.addr) + ")");
  }

  bool check_burst(const Addr& a, const char* ch) {
    std::string bad;
    if (a.size != 2) bad = "size " + std::to_string(a.size) + " (not 4 bytes)";
    else if (a.burst != 1) bad = "burst type " + std::to_string(a.burst) + " (not INCR)";
    else if (a.addr % 4 != 0) bad = "misaligned";
    else if (a.addr % 4096 + 4 * (a.len + 1) > 4096) bad = "crosses a 4 KiB boundary";
    if (bad.empty()) return true;
    mem_.protocol_violation(std::string(ch) + " burst at 0x" + hex(a.addr) + ", " +
                            std::to_string(a.len + 1) + " beats: " + bad);
    return false;
  }

  long extra() {
    return lat_.fixed + (lat_.random ? std::uniform_int_distribution<int>(0, lat_.max_random)(rng_) : 0);
  }

  void read_burst(const Addr& a) {
    const bool ok = check_burst(a, "AR");
    const unsigned resp = ++n_reads_ == fault_.read_burst ? unsigned(fault_.resp) : 0u;
    long due = now() + 1 + extra();
    if (!rq_.empty()) due = std::max(due, rq_.back().due + 1);
    for (unsigned i = 0; i <= a.len; ++i, ++due) {
      const uint32_t data = ok && resp == 0 ? mem_.read_word(a.addr + 4 * i) : 0xdeadbeef;
      rq_.push_back({due, data, resp, i == a.len});
    }
  }

  // Bursts whose AW and W beats are all in: checked, written, answered.
  void write_bursts() {
    while (!awq_.empty() && wq_.size() > awq_.front().len) {
      const Addr a = awq_.front();
      awq_.pop_front();
      const unsigned resp = ++n_writes_ == fault_.write_burst ? unsigned(fault_.resp) : 0u;
      bool ok = true;
      std::vector<PendingWrite> writes;
      for (unsigned i = 0; i <= a.len; ++i) {
        const Beat b = wq_.front();
        wq_.pop_front();
        if (b.last != (i == a.len)) {
          mem_.protocol_violation("WLAST " + std::string(b.last ? "on beat " : "missing on beat ") +
                                  std::to_string(i + 1) + " of a burst of " +
                                  std::to_string(a.len + 1) + " at 0x" + hex(a.addr));
          ok = false;
        }
        if (resp == 0 && ok && a.size == 2 && a.addr % 4 == 0)
          writes.push_back({a.addr + 4 * i, b.strb, b.data});
      }
      long due = now() + 1 + write_latency_ + extra();
      if (!bq_.empty()) due = std::max(due, bq_.back().due + 1);
      bq_.push_back({due, resp, std::move(writes)});
    }
  }

  MemoryModel& mem_;
  MemoryModel::Latency lat_;
  Fault fault_;
  long write_latency_;
  int ar_interval_;
  long last_ar_ = -1000000;
  std::mt19937 rng_;
  std::deque<RBeat> rq_;
  std::deque<BResp> bq_;
  std::deque<Addr> awq_;
  std::deque<Beat> wq_;
  bool r_on_ = false, b_on_ = false;
  bool ar_wait_ = false, aw_wait_ = false, w_wait_ = false;
  Addr ar_held_, aw_held_;
  Beat w_held_;
  long n_reads_ = 0, n_writes_ = 0;
};

}  // namespace mcadsw::sim

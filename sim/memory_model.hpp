// Model of the engine's 32-bit external memory port (docs/memory_map.md):
// req/gnt handshake, writes with byte enables, reads answered in order with
// rvalid. Latency counts wait cycles beyond the minimum of one (data the cycle
// after the grant, as a synchronous RAM): 0, a fixed N, or random (seeded),
// with random grant stalls in the random mode. Counts traffic, and records
// writes outside the region the engine may write.
#pragma once

#include <cstdint>
#include <deque>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace mcadsw::sim {

class MemoryModel {
 public:
  struct Latency {
    int fixed = 0;          // extra wait cycles of every read
    bool random = false;    // random extra wait 0..max_random and random grant stalls
    int max_random = 8;
    double gnt_prob = 0.7;  // probability of a grant per requesting cycle (random mode)
    uint32_t seed = 1;
  };

  MemoryModel(size_t bytes, Latency lat) : mem_(bytes, 0), lat_(lat), rng_(lat.seed) {}

  uint8_t* data() { return mem_.data(); }
  size_t size() const { return mem_.size(); }
  void allow_writes(uint32_t lo, uint32_t hi) { wlo_ = lo; whi_ = hi; }

  // Drives rvalid/rdata for this cycle; call before evaluating the cycle.
  template <typename V>
  void drive_response(V& t) {
    t.mem_rvalid_i = 0;
    if (!pending_.empty() && pending_.front().due <= cycle_) {
      t.mem_rvalid_i = 1;
      t.mem_rdata_i = pending_.front().data;
      pending_.pop_front();
    }
  }

  // Decides the grant for this cycle's request and performs it.
  template <typename V>
  void serve(V& t) {
    t.mem_gnt_i = 0;
    if (t.mem_req_o) {
      const bool gnt = !lat_.random || std::bernoulli_distribution(lat_.gnt_prob)(rng_);
      if (!gnt) ++stalls_;
      t.mem_gnt_i = gnt;
      t.eval();
      if (gnt) access(t.mem_we_o, t.mem_be_o, t.mem_addr_o, t.mem_wdata_o);
    }
  }

  void end_cycle() { ++cycle_; }
  // The memory system is reset with the engine: responses still in flight are
  // dropped (docs/memory_map.md).
  void reset() { pending_.clear(); }

  long reads() const { return reads_; }
  long writes() const { return writes_; }
  long bad_writes() const { return bad_writes_; }
  std::string first_bad_write() const { return first_bad_; }

 private:
  struct Pending {
    long due;
    uint32_t data;
  };

  void access(bool we, unsigned be, uint32_t addr, uint32_t wdata) {
    if (addr % 4 != 0 || size_t(addr) + 4 > mem_.size())
      throw std::runtime_error("memory access out of range or misaligned: 0x" + hex(addr));
    if (we) {
      ++writes_;
      for (int b = 0; b < 4; ++b) {
        if (!((be >> b) & 1)) continue;
        if (addr + b < wlo_ || addr + b >= whi_) {
          if (bad_writes_++ == 0) first_bad_ = "byte write to 0x" + hex(addr + b);
        }
        mem_[addr + b] = uint8_t(wdata >> (8 * b));
      }
      return;
    }
    ++reads_;
    uint32_t v = 0;
    for (int b = 0; b < 4; ++b) v |= uint32_t(mem_[addr + b]) << (8 * b);
    int extra = lat_.fixed;
    if (lat_.random) extra += std::uniform_int_distribution<int>(0, lat_.max_random)(rng_);
    // In order, at most one response a cycle.
    long due = cycle_ + 1 + extra;
    if (!pending_.empty()) due = std::max(due, pending_.back().due + 1);
    pending_.push_back({due, v});
  }

  static std::string hex(uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%08x", v);
    return buf;
  }

  std::vector<uint8_t> mem_;
  Latency lat_;
  std::mt19937 rng_;
  std::deque<Pending> pending_;
  long cycle_ = 0, reads_ = 0, writes_ = 0, stalls_ = 0, bad_writes_ = 0;
  uint32_t wlo_ = 0, whi_ = 0;
  std::string first_bad_;
};

}  // namespace mcadsw::sim

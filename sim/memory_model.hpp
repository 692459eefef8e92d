// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Model of the engine's 32-bit external memory port (docs/memory_map.md):
// req/gnt handshake, writes with byte enables, reads answered in order with
// rvalid. Latency counts wait cycles beyond the minimum of one (data the cycle
// after the grant, as a synchronous RAM): 0, a fixed N, or random (seeded),
// with random grant stalls in the random mode.
//
// Besides serving the port it checks it (docs/memory_map.md, "Harness checks"):
//   - a request that is not granted stays the same (req, we, be, addr, wdata)
//     until its grant, checked on every stalled cycle;
//   - a read touches a pixel of one of the frame's input planes (not the
//     padding between width and stride, not another plane, not a guard);
//   - a write enables at least one byte, every enabled byte belongs to a pixel
//     of the disparity plane (x < width, y < height; 1 or 2 bytes a pixel), and
//     no byte is written twice in a frame;
//   - the LR mode writes three more planes (dR, the output, the mask) and reads
//     back the two scratch planes: `more_outs`, each written at most once a
//     byte, read only where marked readable.
//   - rectification adds areas of their own geometry (`areas`): raw
//     planes and meshes read only, rectified planes and validity bitmaps written
//     at most once a byte and read back only where already written (a read
//     overtaking the write of what it reads); the output pixels of invalid base
//     pixels may be written twice (`out_rewrite`: the pass, then the mark step).
// Violations are counted, the first of each kind described; a word address
// outside the modelled range or misaligned is a harness error (exception).
//
// The modelled range [lo, hi) may be anywhere in the 32-bit address space and
// up to 4 GiB long: it is stored sparsely, in 4 KiB pages allocated (zeroed) on
// first touch, so a frame may sit at the top of the space or have strides of
// hundreds of MiB (the address bits above the first MiB).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>
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

  // The planes a frame may touch: reads inside the pixels of `inputs`, writes
  // inside the pixels of `out`. Input pixel (x, y) is the byte at
  // base + y * stride + x (raster), or with tile != 0 (column-tiled) at
  // base + (x / 4) * tile + 4 * y + x % 4; output pixel (x, y) the out_bpp bytes at
  // out + y * out_stride + out_bpp * x. Width 0: nothing may be read or written.
  struct OutPlane {
    uint32_t base = 0, stride = 0;
    int bpp = 1;
    bool readable = false;    // read back by the frame (the LR mode's scratch planes)
    // Per pixel (y * width + x): nonzero where it may be written twice (the LR mode's
    // planes with rectification: the pass or post stage, then the mark step); empty: once.
    std::vector<uint8_t> rewrite{};
  };
  // A plane or byte range of its own size and layout (the rectifier's):
  // pixel (x, y) of width x height at base + y * stride + x (raster), or with
  // tile != 0 at base + (x / 4) * tile + 4 * y + x % 4; a byte range of n bytes is
  // a plane of n x 1, stride n.
  struct Area {
    std::string name;         // for the messages: "raw plane LY", "mesh L", ...
    uint32_t base = 0;
    int width = 0, height = 0;
    uint32_t stride = 0, tile = 0;
    bool writable = false;    // written by the frame, each byte at most once
    bool readable = true;
    bool written_first = false;  // readable only where the frame wrote it before
  };
  struct Regions {
    std::vector<uint32_t> inputs;
    uint32_t out = 0, stride = 0;
    int width = 0, height = 0;
    uint32_t out_stride = 0;  // 0: stride
    int out_bpp = 1;
    bool out_readable = false;
    std::vector<OutPlane> more_outs;
    uint32_t tile = 0;        // input planes column-tiled: bytes per 4-pixel column
    std::vector<Area> areas{};  // further planes (rectification)
    // Per output pixel (y * width + x): nonzero where it may be written twice (the
    // rectifier's mark step after the pass); empty: once everywhere.
    std::vector<uint8_t> out_rewrite{};
  };

  // What the checks found (counts since the last set_regions()).
  struct Violations {
    long bad_reads = 0;          // reads that touch no input pixel
    long bad_writes = 0;         // bytes written outside the output pixels (or writes with no byte)
    long double_writes = 0;      // output bytes written a second time
    long unstable_requests = 0;  // stalled requests changed or withdrawn before their grant
    long protocol = 0;           // AXI4 rules broken (sim/axi_memory.hpp)
    long early_reads = 0;        // reads of a byte the frame writes, before its write landed
    std::string first_bad_read, first_bad_write, first_double_write, first_unstable, first_protocol;
    std::string first_early_read;
    long total() const {
      return bad_reads + bad_writes + double_writes + unstable_requests + protocol + early_reads;
    }
    std::string describe() const;
  };

  // The addresses [lo, hi); hi at most 2^32.
  MemoryModel(uint64_t lo, uint64_t hi, Latency lat) : lo_(lo), hi_(hi), lat_(lat), rng_(lat.seed) {
    if (lo > hi || hi > (uint64_t(1) << 32))
      throw std::invalid_argument("memory range 0x" + hex64(lo) + "..0x" + hex64(hi) +
                                  " is not inside the 32-bit address space");
  }
  // The addresses [0, bytes).
  MemoryModel(uint64_t bytes, Latency lat) : MemoryModel(0, bytes, lat) {}

  // The byte at address a (inside the range, else an exception).
  uint8_t& byte(uint64_t a) {
    if (a < lo_ || a >= hi_)
      throw std::runtime_error("memory byte 0x" + hex64(a) + " outside the modelled range 0x" +
                               hex64(lo_) + "..0x" + hex64(hi_));
    const uint32_t page = uint32_t(a >> kPageBits);
    if (page != last_page_ || !last_) {
      auto& p = pages_[page];
      if (!p) p = std::make_unique<uint8_t[]>(size_t(1) << kPageBits);  // zeroed
      last_page_ = page;
      last_ = p.get();
    }
    return last_[a & ((uint64_t(1) << kPageBits) - 1)];
  }
  uint64_t lo() const { return lo_; }
  uint64_t hi() const { return hi_; }
  // Starts a frame's checks: new regions, no byte written yet, counts cleared.
  void set_regions(const Regions& r) {
    regions_ = r;
    if (regions_.out_stride == 0) regions_.out_stride = regions_.stride;
    outs_ = {{regions_.out, regions_.out_stride, r.out_bpp, r.out_readable}};
    outs_.insert(outs_.end(), r.more_outs.begin(), r.more_outs.end());
    written_.assign(outs_.size() + r.areas.size(), {});
    for (size_t k = 0; k < outs_.size(); ++k)
      written_[k].assign(size_t(r.width) * size_t(outs_[k].bpp) * size_t(r.height), 0);
    for (size_t k = 0; k < r.areas.size(); ++k)
      if (r.areas[k].writable)
        written_[outs_.size() + k].assign(size_t(r.areas[k].width) * size_t(r.areas[k].height), 0);
    v_ = Violations{};
  }
  const Violations& violations() const { return v_; }
  // Times byte `a` was written since set_regions(), or -1 when it belongs to no
  // plane the frame writes (the scoreboard's "never written" with rectification,
  // where the output's "never written" fill is a legal value).
  int times_written(uint32_t a) const {
    int x, y;
    for (size_t k = 0; k < outs_.size(); ++k)
      if (pixel_of(outs_[k].base, outs_[k].stride, uint32_t(regions_.width * outs_[k].bpp), a, x, y))
        return written_[k][size_t(y) * size_t(regions_.width * outs_[k].bpp) + size_t(x)];
    for (size_t k = 0; k < regions_.areas.size(); ++k)
      if (regions_.areas[k].writable && area_pixel(regions_.areas[k], a, x, y))
        return written_[outs_.size() + k][size_t(y) * size_t(regions_.areas[k].width) + size_t(x)];
    return -1;
  }

  // Drives rvalid/rdata for this cycle, and gnt low until serve() decides it;
  // call before evaluating the cycle.
  template <typename V>
  void drive_response(V& t) {
    t.mem_gnt_i = 0;
    t.mem_rvalid_i = 0;
    if (!pending_.empty() && pending_.front().due <= cycle_) {
      // A read burst's beats are queued one a cycle (access()); one leaves a cycle.
      t.mem_rvalid_i = 1;
      t.mem_rdata_i = pending_.front().data;
      pending_.pop_front();
    }
  }

  // Decides the grant for this cycle's request and performs it. Call with the
  // request of this cycle settled (clock low, gnt low, evaluated).
  template <typename V>
  void serve(V& t) {
    const auto sample = [&t] {
      return Request{bool(t.mem_req_o), bool(t.mem_we_o), unsigned(t.mem_be_o),
                     uint32_t(t.mem_addr_o), uint32_t(t.mem_wdata_o), unsigned(t.mem_len_o)};
    };
    const Request now = sample();
    if (stalled_ && !(now == held_))
      unstable("stalled " + held_.str() + " became " +
               (now.req ? now.str() : std::string("no request")));
    stalled_ = false;
    if (now.req) {
      const bool gnt = !lat_.random || std::bernoulli_distribution(lat_.gnt_prob)(rng_);
      t.mem_gnt_i = gnt;
      t.eval();
      if (gnt && !(sample() == now))  // a request must not depend on its grant
        unstable(now.str() + " became " + sample().str() + " when granted");
      if (gnt) {
        access(now);
      } else {
        stalled_ = true;
        held_ = now;
      }
    }
  }

  void end_cycle() { ++cycle_; }
  long cycle() const { return cycle_; }

  // One word access, with the address checks above; what the port's grant and
  // the AXI4 model (sim/axi_memory.hpp) perform. A word outside the modelled
  // memory or misaligned throws.
  uint32_t read_word(uint32_t addr) {
    check_range(addr);
    note_read(addr);
    uint32_t v = 0;
    for (int b = 0; b < 4; ++b) v |= uint32_t(byte(uint64_t(addr) + b)) << (8 * b);
    return v;
  }
  void write_word(uint32_t addr, unsigned be, uint32_t wdata);
  // A broken bus rule, counted with the other violations.
  void protocol_violation(const std::string& what) {
    if (v_.protocol++ == 0) v_.first_protocol = "cycle " + std::to_string(cycle_) + ": " + what;
  }
  // The memory system is reset with the engine: responses still in flight are
  // dropped (docs/memory_map.md), and a stalled request is forgotten.
  void reset() {
    pending_.clear();
    stalled_ = false;
  }

  // 8 hex digits, for the violation messages.
  static std::string hex(uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%08x", v);
    return buf;
  }
  static std::string hex64(uint64_t v) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "%09llx", static_cast<unsigned long long>(v));
    return buf;
  }

 private:
  struct Pending {
    long due;
    uint32_t data;
  };
  struct Request {
    bool req = false, we = false;
    unsigned be = 0;
    uint32_t addr = 0, wdata = 0;
    unsigned len = 0;  // read: beats - 1
    bool operator==(const Request& o) const {
      return req == o.req && we == o.we && be == o.be && addr == o.addr && wdata == o.wdata &&
             (we || len == o.len);
    }
    std::string str() const {
      return std::string(we ? "write" : "read") + " addr 0x" + hex(addr) + " be " +
             std::to_string(be) + " wdata 0x" + hex(wdata) +
             (we ? "" : " len " + std::to_string(len));
    }
  };

  void unstable(const std::string& what) {
    if (v_.unstable_requests++ == 0) v_.first_unstable = "cycle " + std::to_string(cycle_) + ": " + what;
  }

  // Byte `a` of a plane at `base` with `stride` bytes a row and rows of `row`
  // bytes: its byte column x and row y, or false.
  bool pixel_of(uint32_t base, uint32_t stride, uint32_t row, uint32_t a, int& x, int& y) const {
    const Regions& r = regions_;
    if (r.width <= 0 || a < base || stride == 0) return false;
    const uint32_t off = a - base;
    if (off / stride >= uint32_t(r.height) || off % stride >= row) return false;
    x = int(off % stride);
    y = int(off / stride);
    return true;
  }
  // Byte `a` of an input plane: raster, or column-tiled (Regions::tile).
  bool pixel_of(uint32_t base, uint32_t a, int& x, int& y) const {
    const Regions& r = regions_;
    if (r.tile == 0) return pixel_of(base, r.stride, uint32_t(r.width), a, x, y);
    if (r.width <= 0 || a < base) return false;
    const uint32_t off = a - base, col = off / r.tile, in = off % r.tile;
    x = int(4 * col + in % 4);
    y = int(in / 4);
    return x < r.width && y < r.height;
  }

  // Byte `a` of an area: its pixel (x, y), or false.
  static bool area_pixel(const Area& r, uint32_t a, int& x, int& y) {
    if (r.width <= 0 || r.height <= 0 || a < r.base) return false;
    const uint32_t off = a - r.base;
    if (r.tile == 0) {
      if (r.stride == 0 || off / r.stride >= uint32_t(r.height) || off % r.stride >= uint32_t(r.width))
        return false;
      x = int(off % r.stride);
      y = int(off / r.stride);
      return true;
    }
    const uint32_t col = off / r.tile, in = off % r.tile;
    if (uint64_t(col) * 4 >= uint64_t(r.width)) return false;
    x = int(4 * col + in % 4);
    y = int(in / 4);
    return x < r.width && y < r.height;
  }

  void access(const Request& q) {
    if (q.we) {
      write_word(q.addr, q.be, q.wdata);
      return;
    }
    int extra = lat_.fixed;
    if (lat_.random) extra += std::uniform_int_distribution<int>(0, lat_.max_random)(rng_);
    // In order, at most one response a cycle; a burst's words at consecutive
    // addresses, not across a 4 KiB boundary.
    if (q.addr % 4096 + 4 * (q.len + 1) > 4096)
      protocol_violation("read burst at 0x" + hex(q.addr) + " of " + std::to_string(q.len + 1) +
                         " words crosses a 4 KiB boundary");
    long due = cycle_ + 1 + extra;
    for (unsigned i = 0; i <= q.len; ++i, ++due) {
      if (!pending_.empty()) due = std::max(due, pending_.back().due + 1);
      pending_.push_back({due, read_word(q.addr + 4 * i)});
    }
  }

  void check_range(uint32_t addr) const {
    if (addr % 4 != 0 || addr < lo_ || uint64_t(addr) + 4 > hi_)
      throw std::runtime_error("memory access out of range or misaligned: 0x" + hex(addr));
  }

  // A read must touch a pixel of an input plane (or of a readable output plane).
  void note_read(uint32_t addr) {
    bool inside = false;
    for (uint32_t base : regions_.inputs)
      for (int b = 0; b < 4 && !inside; ++b) {
        int x, y;
        inside = pixel_of(base, addr + b, x, y);
      }
    for (const OutPlane& o : outs_)
      for (int b = 0; b < 4 && !inside && o.readable; ++b) {
        int x, y;
        inside = pixel_of(o.base, o.stride, uint32_t(regions_.width * o.bpp), addr + b, x, y);
      }
    // The rectification's areas: a byte the frame writes must have been written
    // before it is read (each byte of the word that is a pixel of such an area).
    for (size_t k = 0; k < regions_.areas.size(); ++k) {
      const Area& ar = regions_.areas[k];
      if (!ar.readable) continue;
      for (int b = 0; b < 4; ++b) {
        int x, y;
        if (!area_pixel(ar, addr + b, x, y)) continue;
        inside = true;
        if (ar.written_first && ar.writable &&
            written_[outs_.size() + k][size_t(y) * size_t(ar.width) + size_t(x)] == 0 && v_.early_reads++ == 0)
          v_.first_early_read = "cycle " + std::to_string(cycle_) + ": read of 0x" + hex(addr) + ", " + ar.name +
                                " (" + std::to_string(x) + "," + std::to_string(y) + ") not written yet";
      }
    }
    if (!inside && v_.bad_reads++ == 0)
      v_.first_bad_read = "read of 0x" + hex(addr) + ", no pixel of an input plane";
  }

  static constexpr int kPageBits = 12;
  uint64_t lo_, hi_;
  std::unordered_map<uint32_t, std::unique_ptr<uint8_t[]>> pages_;
  uint32_t last_page_ = 0;      // the page last touched, a shortcut for byte()
  uint8_t* last_ = nullptr;
  Latency lat_;
  std::mt19937 rng_;
  std::deque<Pending> pending_;
  long cycle_ = 0;
  Regions regions_;
  std::vector<OutPlane> outs_;                // regions_.out, then regions_.more_outs
  std::vector<std::vector<uint8_t>> written_;  // per output plane, per byte of its pixels
  Violations v_;
  bool stalled_ = false;
  Request held_;
};

inline void MemoryModel::write_word(uint32_t addr, unsigned be, uint32_t wdata) {
  check_range(addr);
  if (be == 0 && v_.bad_writes++ == 0)
    v_.first_bad_write = "write with no byte enabled at 0x" + hex(addr);
  for (int b = 0; b < 4; ++b) {
    if (!((be >> b) & 1)) continue;
    int x = 0, y = 0;
    size_t k = 0;
    while (k < outs_.size() &&
           !pixel_of(outs_[k].base, outs_[k].stride, uint32_t(regions_.width * outs_[k].bpp),
                     addr + b, x, y))
      ++k;
    if (k == outs_.size()) {
      // The rectification's areas (none without it): a writable one, once a byte.
      size_t a = 0;
      while (a < regions_.areas.size() && !area_pixel(regions_.areas[a], addr + b, x, y)) ++a;
      if (a == regions_.areas.size() || !regions_.areas[a].writable) {
        if (v_.bad_writes++ == 0)
          v_.first_bad_write = "byte write to 0x" + hex(addr + b) +
                               (a == regions_.areas.size() ? "" : " (" + regions_.areas[a].name + ", read only)");
      } else if (written_[outs_.size() + a][size_t(y) * size_t(regions_.areas[a].width) + size_t(x)]++ &&
                 v_.double_writes++ == 0) {
        v_.first_double_write = regions_.areas[a].name + " byte (" + std::to_string(x) + "," + std::to_string(y) +
                                ") written again (word 0x" + hex(addr) + ", be " + std::to_string(be) + ")";
      }
    } else {
      // The output pixels the mark step rewrites (out_rewrite) may be written twice.
      const size_t i = size_t(y) * size_t(regions_.width * outs_[k].bpp) + size_t(x);
      const size_t px = size_t(y) * size_t(regions_.width) + size_t(x / outs_[k].bpp);
      const std::vector<uint8_t>& rw = k == 0 ? regions_.out_rewrite : outs_[k].rewrite;
      const int allowed = 1 + (px < rw.size() && rw[px] != 0);
      if (written_[k][i]++ >= allowed && v_.double_writes++ == 0)
        v_.first_double_write = "pixel (" + std::to_string(x / outs_[k].bpp) + "," +
                                std::to_string(y) + ") of output plane " + std::to_string(k) +
                                " written again (word 0x" + hex(addr) + ", be " + std::to_string(be) +
                                ")";
    }
    byte(uint64_t(addr) + b) = uint8_t(wdata >> (8 * b));
  }
}

inline std::string MemoryModel::Violations::describe() const {
  std::string s;
  auto line = [&](long n, const char* what, const std::string& first) {
    if (n) s += "  " + std::to_string(n) + " " + what + ", first: " + first + "\n";
  };
  line(bad_reads, "reads outside the input (or scratch) planes' pixels", first_bad_read);
  line(bad_writes, "bytes written outside the output pixels", first_bad_write);
  line(double_writes, "output bytes written twice", first_double_write);
  line(unstable_requests, "stalled requests changed before their grant", first_unstable);
  line(protocol, "AXI4 protocol violations", first_protocol);
  line(early_reads, "reads of bytes the frame writes before their write landed", first_early_read);
  return s;
}

}  // namespace mcadsw::sim

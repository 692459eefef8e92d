// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_post (the LR mode's post-processing stage, docs/algorithm.md 12.2-12.5)
// against the reference: lr_check, fill_invalid and median3x3 on random left and
// right maps in a modelled memory, 8-bit and sub-pixel (packed scratch format,
// docs/blocks/post.md). Every output pixel and mask byte is
// compared; bytes outside the output and mask pixels must stay untouched.
// Built with MAXW = 64 (tests/rtl/CMakeLists.txt) to keep the model small.
#include <gtest/gtest.h>

#include <deque>
#include <memory>
#include <random>
#include <sstream>

#include "Vmcadsw_post.h"
#include "mcadsw/ref.hpp"

namespace mcadsw {
namespace {

constexpr int kMaxW = 64;

struct Case {
  int w = 0, h = 0, d = 16, tol = 1;
  bool wide = false;
  double gnt_prob = 1.0;     // grant probability of a requesting cycle
  int latency = 0;           // extra cycles before read data
  uint32_t seed = 1;
};

struct Maps {
  Plane dl, dr;              // integer disparities
  Plane16 value;             // d, or 16 d + offset
};

// dR made from dL so that most pixels pass the check, with occluded runs and noise.
Maps random_maps(const Case& c, std::mt19937& rng) {
  Maps m{Plane(c.w, c.h), Plane(c.w, c.h), Plane16(c.w, c.h)};
  std::uniform_int_distribution<int> dd(0, c.d - 1), off(-8, 8), pct(0, 99);
  for (int y = 0; y < c.h; ++y) {
    int d = dd(rng);
    for (int x = 0; x < c.w; ++x) {
      if (pct(rng) < 15) d = dd(rng);
      m.dl.at(x, y) = uint8_t(d);
    }
    for (int x = 0; x < c.w; ++x) m.dr.at(x, y) = uint8_t(dd(rng));
    // Most left pixels find their own disparity at x - d, some off by up to 2.
    for (int x = 0; x < c.w; ++x) {
      const int d = m.dl.at(x, y);
      if (x - d < 0 || pct(rng) >= 70) continue;
      const int v = pct(rng) < 20 ? std::min(c.d - 1, std::max(0, d + pct(rng) % 5 - 2)) : d;
      m.dr.at(x - d, y) = uint8_t(v);
    }
    for (int x = 0; x < c.w; ++x) {
      const int dv = m.dl.at(x, y);
      const int o = (dv == 0 || dv == c.d - 1) ? 0 : off(rng);
      m.value.at(x, y) = uint16_t(c.wide ? kSubpixelScale * dv + o : dv);
    }
  }
  return m;
}

class PostBench {
 public:
  PostBench(const Case& c, const Maps& m) : c_(c), m_(m), rng_(c.seed) {
    W_ = c.w;
    H_ = c.h;
    stride_ = uint32_t((W_ + 3) / 4 * 4 + 8);
    ostride_ = uint32_t(((c.wide ? 2 : 1) * W_ + 3) / 4 * 4 + 4);
    const uint32_t plane = (std::max(stride_, ostride_) * uint32_t(H_) + 4095) / 4096 * 4096;
    dl_ = 4096;
    dr_ = dl_ + plane;
    out_ = dr_ + plane;
    mask_ = out_ + plane;
    mem_.assign(mask_ + plane + 4096, 0xa5);
    for (int y = 0; y < H_; ++y)
      for (int x = 0; x < W_; ++x) {
        mem_[dr_ + y * stride_ + x] = m.dr.at(x, y);
        if (c.wide) {
          const int v = m.value.at(x, y), d = m.dl.at(x, y);
          const int packed = d | ((v - kSubpixelScale * d + kSubpixelOffsetMax) << kDispBits);
          mem_[dl_ + y * ostride_ + 2 * x] = uint8_t(packed);
          mem_[dl_ + y * ostride_ + 2 * x + 1] = uint8_t(packed >> 8);
        } else {
          mem_[dl_ + y * ostride_ + x] = m.dl.at(x, y);
        }
      }
    before_ = mem_;
  }

  // Runs the frame; returns the cycles from start to done, -1 on timeout.
  long run() {
    auto& t = *top_;
    t.rst_ni = 0;
    t.clk_i = 0;
    t.start_i = 0;
    t.mem_gnt_i = 0;
    t.mem_rvalid_i = 0;
    t.eval();
    tick();
    t.rst_ni = 1;
    t.base_dl_i = dl_;
    t.base_dr_i = dr_;
    t.base_out_i = out_;
    t.base_mask_i = mask_;
    t.stride_i = stride_;
    t.out_stride_i = ostride_;
    t.width_i = uint32_t(W_);
    t.height_i = uint32_t(H_);
    t.tol_i = uint32_t(c_.tol);
    t.wide_i = c_.wide;
    t.start_i = 1;
    tick();
    t.start_i = 0;
    for (long n = 1; n < 200L * W_ * H_ + 10000; ++n) {
      tick();
      if (t.done_o) return n;
    }
    return -1;
  }

  // Compares with the reference; returns the first differences, empty if none.
  std::string check(long& compared) const {
    const Plane valid = lr_check(m_.dl, m_.dr, c_.tol);
    const Plane16 want = median3x3(fill_invalid(m_.value, valid));
    std::ostringstream err;
    int n = 0;
    auto report = [&](const std::string& s) {
      if (n++ < 8) err << "  " << s << "\n";
    };
    for (int y = 0; y < H_; ++y)
      for (int x = 0; x < W_; ++x) {
        const uint8_t* p = &mem_[out_ + y * ostride_ + (c_.wide ? 2 * x : x)];
        const int got = c_.wide ? p[0] | p[1] << 8 : p[0];
        if (got != want.at(x, y))
          report("output (" + std::to_string(x) + "," + std::to_string(y) + "): RTL " +
                 std::to_string(got) + ", reference " + std::to_string(want.at(x, y)));
        const int mk = mem_[mask_ + y * stride_ + x];
        if (mk != valid.at(x, y))
          report("mask (" + std::to_string(x) + "," + std::to_string(y) + "): RTL " +
                 std::to_string(mk) + ", reference " + std::to_string(valid.at(x, y)));
        compared += 2;
      }
    // Nothing else written: every byte outside the output and mask pixels unchanged.
    for (size_t a = 0; a < mem_.size(); ++a) {
      const bool in_out = a >= out_ && a < out_ + uint32_t(H_) * ostride_ &&
                          (a - out_) % ostride_ < uint32_t((c_.wide ? 2 : 1) * W_);
      const bool in_mask = a >= mask_ && a < mask_ + uint32_t(H_) * stride_ &&
                           (a - mask_) % stride_ < uint32_t(W_);
      if (!in_out && !in_mask && mem_[a] != before_[a]) report("byte 0x" + std::to_string(a) + " written");
    }
    if (bad_access_) report("access outside the memory or misaligned");
    return err.str();
  }

 private:
  void tick() {
    auto& t = *top_;
    // Read data of the oldest read whose time has come.
    t.mem_rvalid_i = 0;
    if (!pending_.empty() && pending_.front().first <= cycle_) {
      t.mem_rvalid_i = 1;
      t.mem_rdata_i = pending_.front().second;
      pending_.pop_front();
    }
    t.clk_i = 0;
    t.eval();
    t.mem_gnt_i = 0;
    if (t.mem_req_o && std::bernoulli_distribution(c_.gnt_prob)(rng_)) {
      t.mem_gnt_i = 1;
      const uint32_t a = t.mem_addr_o;
      if (a % 4 != 0 || a + 4 > mem_.size()) {
        bad_access_ = true;
      } else if (t.mem_we_o) {
        for (int b = 0; b < 4; ++b)
          if ((t.mem_be_o >> b) & 1) mem_[a + b] = uint8_t(t.mem_wdata_o >> (8 * b));
      } else {
        uint32_t v = 0;
        for (int b = 0; b < 4; ++b) v |= uint32_t(mem_[a + b]) << (8 * b);
        pending_.emplace_back(cycle_ + 1 + c_.latency, v);
      }
    }
    t.eval();
    t.clk_i = 1;
    t.eval();
    ++cycle_;
  }

  Case c_;
  const Maps& m_;
  std::mt19937 rng_;
  int W_ = 0, H_ = 0;
  uint32_t stride_ = 0, ostride_ = 0, dl_ = 0, dr_ = 0, out_ = 0, mask_ = 0;
  std::vector<uint8_t> mem_, before_;
  std::deque<std::pair<long, uint32_t>> pending_;
  long cycle_ = 0;
  bool bad_access_ = false;
  std::unique_ptr<VerilatedContext> ctx_ = std::make_unique<VerilatedContext>();
  std::unique_ptr<Vmcadsw_post> top_ = std::make_unique<Vmcadsw_post>(ctx_.get());
};

void run_case(const Case& c) {
  std::mt19937 rng(c.seed);
  const Maps m = random_maps(c, rng);
  PostBench b(c, m);
  const long cycles = b.run();
  ASSERT_GE(cycles, 0) << "no done";
  long compared = 0;
  const std::string err = b.check(compared);
  EXPECT_TRUE(err.empty()) << err;
  const Plane valid = lr_check(m.dl, m.dr, c.tol);
  long nvalid = 0;
  for (uint8_t v : valid.px) nvalid += v != 0;
  std::printf("%dx%d D=%d T=%d %s: %ld cycles (%.2f a pixel), %ld of %d pixels valid\n", c.w, c.h,
              c.d, c.tol, c.wide ? "sub-pixel" : "8-bit", cycles, double(cycles) / (c.w * c.h),
              nvalid, c.w * c.h);
  // Both outcomes of the check occur, or the case tests little.
  if (c.w * c.h >= 64) {
    EXPECT_GT(nvalid, 0);
    EXPECT_LT(nvalid, long(c.w) * c.h);
  }
}

TEST(Post, EightBitMapsMatchReference) {
  uint32_t seed = 1;
  for (const auto& [w, h] : {std::pair{64, 12}, {37, 9}, {5, 7}, {1, 1}, {2, 3}, {63, 2}})
    for (int tol : {0, 1, 5}) {
      Case c;
      c.w = w;
      c.h = h;
      c.d = 16;
      c.tol = tol;
      c.seed = seed++;
      SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + " T=" + std::to_string(tol));
      run_case(c);
    }
}

TEST(Post, SubpixelMapsMatchReference) {
  uint32_t seed = 100;
  for (const auto& [w, h] : {std::pair{64, 10}, {41, 7}, {3, 5}, {1, 2}}) {
    Case c;
    c.w = w;
    c.h = h;
    c.d = 64;
    c.wide = true;
    c.seed = seed++;
    SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h));
    run_case(c);
  }
}

TEST(Post, RandomMemoryTiming) {
  for (uint32_t seed = 200; seed < 206; ++seed) {
    Case c;
    c.w = 30 + int(seed % 7);
    c.h = 6;
    c.d = 20;
    c.wide = seed % 2;
    c.gnt_prob = 0.5;
    c.latency = int(seed % 4);
    c.seed = seed;
    SCOPED_TRACE("seed " + std::to_string(seed));
    run_case(c);
  }
}

}  // namespace
}  // namespace mcadsw

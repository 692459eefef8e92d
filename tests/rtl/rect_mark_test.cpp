// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_rect_mark (docs/blocks/rectifier.md 8): random frames (1 .. 150 x 1 .. 100, and
// CIF), validity masks of every kind (all valid, none, random pixels, invalid borders as a
// rectified view has), bytes and halfwords, random bases, strides and values, a memory with
// random grants and latency. Every invalid pixel's bytes must be written once with the value
// and no other byte; every bitmap word read once and no other address.
#include <gtest/gtest.h>

#include <cstdio>
#include <deque>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "Vrect_mark.h"
#include "mcadsw/params.hpp"
#include "mcadsw/rectify.hpp"
#include "rtl_bench.hpp"

namespace mcadsw {
namespace {

uint8_t mem_byte(uint32_t addr) {  // the plane's content before the step: a hash of the address
  uint32_t x = addr * 2654435761u;
  return uint8_t(x ^ (x >> 13));
}

struct Job {
  int w = 0, h = 0;
  Plane valid;
  bool half = false;
  uint16_t value = 0;
  uint32_t vbase = 0, base = 0, stride = 0;
  int latency = 0;
  double grant = 1.0;
};

struct MarkRun {
  std::map<uint32_t, uint8_t> written;  // byte address -> value
  std::map<uint32_t, int> times;        // byte address -> writes
  std::multiset<uint32_t> reads;        // word addresses read
  long cycles = 0;
  bool done = false, busy_after = false, stray = false;
};

MarkRun run(Vrect_mark& t, const Job& j, std::mt19937& rng) {
  const std::vector<uint32_t> bitmap = validity_bitmap(j.valid);
  t.width_i = uint32_t(j.w);
  t.height_i = uint32_t(j.h);
  t.valid_base_i = j.vbase;
  t.base_i = j.base;
  t.stride_i = j.stride;
  t.half_i = j.half;
  t.value_i = j.value;
  t.start_i = 1;
  MarkRun r;
  std::deque<std::pair<long, uint32_t>> inflight;  // (cycle it answers, address)
  long cyc = 0;
  for (; cyc < 400000 && !r.done; ++cyc) {
    t.mem_gnt_i = t.mem_req_o && std::bernoulli_distribution(j.grant)(rng);
    const bool rv = !inflight.empty() && inflight.front().first <= cyc;
    uint32_t data = 0xdeadbeef;
    if (rv) {
      const uint32_t i = (inflight.front().second - j.vbase) / 4;
      if (inflight.front().second >= j.vbase && i < bitmap.size()) data = bitmap[i];
      else r.stray = true;
    }
    t.mem_rvalid_i = rv;
    t.mem_rdata_i = data;
    t.clk_i = 0;
    t.eval();
    if (t.mem_req_o && t.mem_gnt_i) {
      const uint32_t a = t.mem_addr_o;
      if (a % 4) r.stray = true;
      if (t.mem_we_o) {
        if (t.mem_len_o != 0 || t.mem_be_o == 0) r.stray = true;
        for (uint32_t b = 0; b < 4; ++b)
          if ((t.mem_be_o >> b) & 1) {
            r.written[a + b] = uint8_t(t.mem_wdata_o >> (8 * b));
            ++r.times[a + b];
          }
      } else {
        const uint32_t n = t.mem_len_o + 1u;
        if ((a & 4095u) + 4 * n > 4096u) r.stray = true;
        for (uint32_t i = 0; i < n; ++i) {
          r.reads.insert(a + 4 * i);
          inflight.push_back({cyc + 1 + j.latency + long(i), a + 4 * i});
        }
      }
    }
    if (rv) inflight.pop_front();
    t.clk_i = 1;
    t.eval();
    t.start_i = 0;
    r.done = t.done_o;
  }
  r.cycles = cyc;
  t.mem_rvalid_i = 0;
  t.mem_gnt_i = 0;
  sim::tick(t);
  r.busy_after = t.busy_o || t.mem_req_o || !inflight.empty();
  return r;
}

// "" or the first difference from the mark step's definition.
std::string check(const Job& j, const MarkRun& r) {
  std::ostringstream e;
  e << j.w << "x" << j.h << (j.half ? " halfwords" : " bytes") << " base " << j.base << " stride " << j.stride
    << " bitmap " << j.vbase << ": ";
  if (!r.done) return e.str() + "no done";
  if (r.busy_after) return e.str() + "busy, requesting or reads in flight after done";
  if (r.stray) return e.str() + "an unaligned, empty or 4 KiB-crossing request, or a read outside the bitmap";
  const size_t nwords = size_t((j.w + 3) / 4 * ((j.h + 7) / 8));
  for (size_t i = 0; i < nwords; ++i)
    if (r.reads.count(j.vbase + 4u * uint32_t(i)) != 1)
      return e.str() + "bitmap word " + std::to_string(i) + " read " +
             std::to_string(r.reads.count(j.vbase + 4u * uint32_t(i))) + " times";
  if (r.reads.size() != nwords) return e.str() + std::to_string(r.reads.size()) + " words read, " +
                                       std::to_string(nwords) + " in the bitmap";
  const int bpp = j.half ? 2 : 1;
  size_t expected = 0;
  for (int y = 0; y < j.h; ++y)
    for (int x = 0; x < j.w; ++x) {
      if (j.valid.at(x, y)) continue;
      for (int b = 0; b < bpp; ++b) {
        const uint32_t a = j.base + uint32_t(y) * j.stride + uint32_t(bpp * x + b);
        const uint8_t want = uint8_t(j.value >> (8 * b));
        const auto it = r.written.find(a);
        ++expected;
        if (it == r.written.end() || r.times.at(a) != 1 || it->second != want) {
          e << "invalid pixel (" << x << "," << y << ") byte " << b << ": "
            << (it == r.written.end() ? "not written" : "written " + std::to_string(r.times.at(a)) + " times, " +
                                                             std::to_string(int(it->second)))
            << ", want " << int(want);
          return e.str();
        }
      }
    }
  if (r.written.size() != expected) {
    for (const auto& [a, v] : r.written) {
      const uint32_t off = a - j.base, y = off / j.stride, x = (off % j.stride) / uint32_t(bpp);
      if (a < j.base || int(y) >= j.h || int(x) >= j.w || j.valid.at(int(x), int(y)))
        return e.str() + "byte " + std::to_string(a) + " written (" + std::to_string(x) + "," + std::to_string(y) +
               "): not an invalid pixel";
    }
    return e.str() + std::to_string(r.written.size()) + " bytes written, " + std::to_string(expected) + " expected";
  }
  return "";
}

// A validity mask: all valid, none, random pixels, or invalid borders (as a rectified
// view's: strips of random widths on each side, a ragged edge).
Plane random_valid(int w, int h, int kind, std::mt19937& rng) {
  Plane v(w, h);
  std::uniform_int_distribution<int> pct(0, 99);
  const int l = int(rng() % uint32_t(w / 3 + 1)), rgt = int(rng() % uint32_t(w / 3 + 1));
  const int tp = int(rng() % uint32_t(h / 3 + 1)), bt = int(rng() % uint32_t(h / 3 + 1));
  const int p = pct(rng);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      bool ok = true;
      switch (kind) {
        case 1: ok = false; break;
        case 2: ok = pct(rng) >= p; break;
        case 3: ok = x >= l + int(rng() % 2) && x < w - rgt && y >= tp && y < h - bt; break;
        default: break;
      }
      v.at(x, y) = ok ? 1 : 0;
    }
  return v;
}

Job random_job(std::mt19937& rng, int n) {
  Job j;
  const int sizes[][2] = {{1, 1}, {3, 9}, {4, 8}, {5, 7}, {8, 17}};
  if (n < 5) {
    j.w = sizes[n][0];
    j.h = sizes[n][1];
  } else {
    j.w = 1 + int(rng() % 150);
    j.h = 1 + int(rng() % 100);
  }
  j.valid = random_valid(j.w, j.h, n % 4, rng);
  j.half = rng() % 2;
  j.value = uint16_t(rng());
  const uint32_t row = uint32_t(j.w * (j.half ? 2 : 1));
  j.stride = ((row + 3) & ~3u) + 4u * (rng() % 4);
  j.base = 0x100000u + 4u * (rng() % 5000);
  // The bitmap sometimes just below a 4 KiB boundary.
  j.vbase = rng() % 2 ? 0x4000000u - 4u * (rng() % 12) : 0x4000000u + 4u * (rng() % 5000);
  j.latency = n % 3 == 0 ? 0 : int(rng() % 12);
  j.grant = n % 3 == 0 ? 1.0 : 0.5 + 0.5 * std::uniform_real_distribution<double>(0, 1)(rng);
  return j;
}

struct RandomInitialValues {
  RandomInitialValues() { sim::random_initial_values(6); }
};

class RectMark : public ::testing::Test, private RandomInitialValues {  // before the model
 protected:
  void SetUp() override {
    t.start_i = 0;
    t.mem_gnt_i = 0;
    t.mem_rvalid_i = 0;
    t.rst_ni = 0;
    sim::tick(t);
    t.rst_ni = 1;
    sim::tick(t);
  }
  Vrect_mark t;
};

TEST_F(RectMark, InvalidPixelsGetTheValueAndNothingElseIsWritten) {
  std::mt19937 rng(3210);
  for (int n = 0; n < 300; ++n) {
    const Job j = random_job(rng, n);
    const MarkRun r = run(t, j, rng);
    ASSERT_EQ(check(j, r), "") << "job " << n;
  }
}

// The disparity plane of a sub-pixel frame: the invalid code of mark_rect_invalid.
TEST_F(RectMark, MatchesTheReferenceOnASubpixelMap) {
  std::mt19937 rng(77);
  for (int n = 0; n < 20; ++n) {
    Job j = random_job(rng, 5 + 4 * n + 2);  // kind 3: invalid borders
    j.half = true;
    j.value = uint16_t(kRectInvalidDisp16);
    j.stride = ((uint32_t(2 * j.w) + 3) & ~3u);
    const MarkRun r = run(t, j, rng);
    ASSERT_EQ(check(j, r), "") << "job " << n;
    Plane16 disp(j.w, j.h), got(j.w, j.h);
    for (int y = 0; y < j.h; ++y)
      for (int x = 0; x < j.w; ++x) {
        const uint32_t a = j.base + uint32_t(y) * j.stride + uint32_t(2 * x);
        disp.at(x, y) = uint16_t(mem_byte(a) | mem_byte(a + 1) << 8);
        const auto lo = r.written.find(a), hi = r.written.find(a + 1);
        got.at(x, y) = uint16_t((lo != r.written.end() ? lo->second : mem_byte(a)) |
                                (hi != r.written.end() ? hi->second : mem_byte(a + 1)) << 8);
      }
    mark_rect_invalid(disp, j.valid);
    ASSERT_EQ(got.px, disp.px) << "job " << n;
  }
}

// Cycles on a CIF frame, zero latency: all valid (a cycle a bitmap word, plus the reads)
// and with invalid borders as camera C leaves them.
TEST_F(RectMark, CifCycles) {
  std::mt19937 rng(5);
  for (const int kind : {0, 3}) {
    Job j;
    j.w = 352;
    j.h = 288;
    j.valid = random_valid(j.w, j.h, kind, rng);
    j.value = 255;
    j.stride = 352;
    j.base = 0x100000u;
    j.vbase = 0x4000000u;
    const MarkRun r = run(t, j, rng);
    ASSERT_EQ(check(j, r), "");
    long bad = 0;
    for (const uint8_t v : j.valid.px) bad += v == 0;
    std::printf("rect_mark: CIF, %ld invalid pixels: %ld cycles for %d bitmap words, %zu bytes written\n", bad,
                r.cycles, 88 * 36, r.written.size());
  }
}

}  // namespace
}  // namespace mcadsw

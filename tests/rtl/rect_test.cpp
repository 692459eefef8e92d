// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_rect, the rectifier pass (docs/blocks/rectifier.md 7), on whole frames against
// mcadsw::rectify: random frame and raw sizes, S = 8, 16, 32, random smooth meshes per
// view (some reaching outside the raw view), random plane sets, raster and column-tiled
// layouts, a memory with random grants and latency. Every rectified pixel and validity
// bit must equal the reference's, nothing else may be written; a mesh with a node out of
// range or a tile beyond the buffer must end the pass with its error and no write.
#include <gtest/gtest.h>

#include <cstdio>
#include <deque>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Vrect.h"
#include "mcadsw/params.hpp"
#include "mcadsw/rectify.hpp"
#include "rect_bench.hpp"
#include "rtl_bench.hpp"
#include "mcadsw/image_io.hpp"
#include "test_util.hpp"

namespace mcadsw {
namespace {

constexpr uint32_t kMemSize = 1u << 23;
constexpr uint32_t kRawBase = 0x010000, kOutBase = 0x200000, kMeshBase = 0x500000, kValidBase = 0x600000;
constexpr uint32_t kPlaneSpan = 0x40000;

struct Layout {
  bool tiled;
  uint32_t raw_stride, stride;
  uint32_t addr(uint32_t base, uint32_t st, int x, int y) const {
    return tiled ? base + uint32_t(x / 4) * st + 4u * uint32_t(y) + uint32_t(x % 4) : base + uint32_t(y) * st + uint32_t(x);
  }
};

struct Frame {
  int w, h, rw, rh, s;
  int planes;  // bit p: LY LU LV RY RU RV
  Layout lay;
  Mesh mesh[2];
  YuvImage raw[2];
};

struct PassRun {
  int err = -1;
  long cycles = 0, reads = 0, writes = 0;
  std::vector<uint8_t> mem;
  std::vector<uint8_t> written;  // per byte: times written
};

void put_word(std::vector<uint8_t>& mem, uint32_t a, uint32_t v) {
  for (int b = 0; b < 4; ++b) mem[a + uint32_t(b)] = uint8_t(v >> (8 * b));
}

PassRun run_frame(Vrect& t, const Frame& f, std::mt19937& rng, double grant, int latency) {
  PassRun r;
  r.mem.assign(kMemSize, 0);
  for (auto& b : r.mem) b = uint8_t(rng());
  r.written.assign(kMemSize, 0);
  for (int v = 0; v < 2; ++v) {
    const Plane* pl[3] = {&f.raw[v].y, &f.raw[v].u, &f.raw[v].v};
    for (int c = 0; c < 3; ++c)
      for (int y = 0; y < f.rh; ++y)
        for (int x = 0; x < f.rw; ++x)
          r.mem[f.lay.addr(kRawBase + uint32_t(3 * v + c) * kPlaneSpan, f.lay.raw_stride, x, y)] = pl[c]->at(x, y);
    const Mesh& m = f.mesh[v];
    for (size_t k = 0; k < m.u.size(); ++k) {
      put_word(r.mem, kMeshBase + uint32_t(v) * 0x40000 + uint32_t(8 * k), uint32_t(m.u[k]));
      put_word(r.mem, kMeshBase + uint32_t(v) * 0x40000 + uint32_t(8 * k + 4), uint32_t(m.v[k]));
    }
  }
  t.step_log2_i = uint32_t(f.s);
  t.width_i = uint32_t(f.w);
  t.height_i = uint32_t(f.h);
  t.raw_w_i = uint32_t(f.rw);
  t.raw_h_i = uint32_t(f.rh);
  t.tiled_i = f.lay.tiled;
  t.raw_stride_i = f.lay.raw_stride;
  t.stride_i = f.lay.stride;
  for (int p = 0; p < 6; ++p) {
    t.raw_base_i[size_t(p)] = kRawBase + uint32_t(p) * kPlaneSpan;
    t.base_i[size_t(p)] = kOutBase + uint32_t(p) * kPlaneSpan;
  }
  t.planes_i = uint32_t(f.planes);
  t.mesh_base_i = uint64_t(kMeshBase) | uint64_t(kMeshBase + 0x40000) << 32;
  t.valid_base_i = uint64_t(kValidBase) | uint64_t(kValidBase + 0x40000) << 32;
  t.start_i = 1;
  std::deque<std::pair<long, uint32_t>> inflight;
  long cyc = 0;
  for (; cyc < 4000000; ++cyc) {
    t.mem_gnt_i = t.mem_req_o && std::bernoulli_distribution(grant)(rng);
    const bool rv = !inflight.empty() && inflight.front().first <= cyc;
    t.mem_rvalid_i = rv;
    uint32_t rd = 0;
    if (rv)
      for (int b = 0; b < 4; ++b) rd |= uint32_t(r.mem[inflight.front().second + uint32_t(b)]) << (8 * b);
    t.mem_rdata_i = rd;
    t.clk_i = 0;
    t.eval();
    if (t.mem_req_o && t.mem_gnt_i) {
      const uint32_t a = t.mem_addr_o;
      EXPECT_EQ(a % 4, 0u);
      if (t.mem_we_o) {
        for (int b = 0; b < 4; ++b)
          if ((t.mem_be_o >> b) & 1) {
            r.mem[a + uint32_t(b)] = uint8_t(t.mem_wdata_o >> (8 * b));
            ++r.written[a + uint32_t(b)];
          }
        ++r.writes;
      } else {
        const uint32_t n = t.mem_len_o + 1u;
        EXPECT_LE((a & 4095u) + 4 * n, 4096u) << "a read burst across 4 KiB";
        for (uint32_t i = 0; i < n; ++i) inflight.push_back({cyc + 1 + latency + long(i), a + 4 * i});
        r.reads += n;
      }
    }
    if (rv) inflight.pop_front();
    t.clk_i = 1;
    t.eval();
    t.start_i = 0;
    if (t.done_o) {
      r.err = int(t.err_o);
      break;
    }
  }
  r.cycles = cyc;
  if (r.err < 0)
    std::printf("no done: %dx%d from %dx%d S %d planes %x %s; at the end req %d we %d addr %x, %zu reads in flight, "
                "%ld reads %ld writes\n",
                f.w, f.h, f.rw, f.rh, 1 << f.s, f.planes, f.lay.tiled ? "tiled" : "raster", int(t.mem_req_o),
                int(t.mem_we_o), t.mem_addr_o, inflight.size(), r.reads, r.writes);
  EXPECT_TRUE(inflight.empty()) << "reads in flight at the end";
  t.mem_rvalid_i = 0;
  t.mem_gnt_i = 0;
  for (int i = 0; i < 3; ++i) sim::tick(t);
  EXPECT_FALSE(t.busy_o);
  return r;
}

// "" or the first difference between the run's memory and the reference.
std::string compare(const Frame& f, const PassRun& r) {
  long expected_bytes = 0;
  for (int v = 0; v < 2; ++v) {
    if (!((f.planes >> (3 * v)) & 7)) continue;
    const Rectified ref = rectify(f.raw[v], f.mesh[v]);
    const Plane* pl[3] = {&ref.image.y, &ref.image.u, &ref.image.v};
    for (int c = 0; c < 3; ++c) {
      if (!((f.planes >> (3 * v + c)) & 1)) continue;
      for (int y = 0; y < f.h; ++y)
        for (int x = 0; x < f.w; ++x) {
          const uint32_t a = f.lay.addr(kOutBase + uint32_t(3 * v + c) * kPlaneSpan, f.lay.stride, x, y);
          ++expected_bytes;
          if (r.written[a] != 1 || r.mem[a] != pl[c]->at(x, y)) {
            const auto [pu, pv] = mesh_position(f.mesh[v], x, y);
            std::ostringstream e;
            e << "plane " << 3 * v + c << " pixel (" << x << "," << y << ") position (" << pu << "," << pv
              << ")/32: written " << int(r.written[a]) << " times, RTL " << int(r.mem[a]) << ", reference "
              << int(pl[c]->at(x, y)) << (ref.valid.at(x, y) ? " valid" : " invalid");
            return e.str();
          }
        }
    }
    // Validity bitmap (validity_bitmap: word (x / 4) ceil(H / 8) + y / 8, bit 4 (y % 8) + x % 4).
    const int vh = (f.h + 7) / 8;
    const std::vector<uint32_t> bitmap = validity_bitmap(ref.valid);
    for (int k = 0; 4 * k < f.w; ++k)
      for (int g = 0; g < vh; ++g) {
        const uint32_t a = kValidBase + uint32_t(v) * 0x40000 + 4u * uint32_t(k * vh + g);
        uint32_t got = 0;
        for (int b = 0; b < 4; ++b) {
          if (r.written[a + uint32_t(b)] != 1) return "validity word " + std::to_string(k) + "," + std::to_string(g) +
                                                      " written " + std::to_string(r.written[a + uint32_t(b)]) + " times";
          got |= uint32_t(r.mem[a + uint32_t(b)]) << (8 * b);
        }
        expected_bytes += 4;
        const uint32_t want = bitmap[size_t(k * vh + g)];
        if (got != want) {
          std::ostringstream e;
          e << "view " << v << " validity word (" << k << "," << g << "): " << std::hex << got << ", reference " << want;
          return e.str();
        }
      }
  }
  long total = 0;
  for (const uint8_t n : r.written) total += n;
  if (total != expected_bytes)
    return std::to_string(total) + " bytes written, " + std::to_string(expected_bytes) + " expected";
  return "";
}

Frame random_frame(std::mt19937& rng, int n) {
  Frame f;
  f.s = 3 + n % 3;
  f.w = 1 + int(rng() % 150);
  f.h = 1 + int(rng() % 90);
  f.rw = 8 + int(rng() % 160);
  f.rh = 8 + int(rng() % 110);
  const int sets[] = {0x0f, 0x3f, 0x3b, 0x07, 0x38, 0x09, 0x01};
  f.planes = sets[n % 7];
  f.lay.tiled = n % 2;
  f.lay.raw_stride = f.lay.tiled ? 4u * uint32_t(f.rh + int(rng() % 5)) : uint32_t((f.rw + 3) & ~3) + 4u * (rng() % 3);
  f.lay.stride = f.lay.tiled ? 4u * uint32_t(f.h + int(rng() % 5)) : uint32_t((f.w + 3) & ~3) + 4u * (rng() % 3);
  for (int v = 0; v < 2; ++v) {
    f.mesh[v] = sim::random_mesh(f.w, f.h, f.s, f.rw, f.rh, rng, 0.9);
    f.raw[v] = test::random_yuv(f.rw, f.rh, rng);
  }
  return f;
}

Vrect& dut() {
  static Vrect* t = [] {
    sim::random_initial_values(5);
    auto* v = new Vrect;
    v->start_i = 0;
    v->mem_gnt_i = 0;
    v->mem_rvalid_i = 0;
    v->rst_ni = 0;
    sim::tick(*v);
    v->rst_ni = 1;
    return v;
  }();
  return *t;
}

TEST(Rect, FramesMatchTheReference) {
  std::mt19937 rng(3207);
  long pixels = 0, cycles_free = 0, pixels_free = 0, reads = 0, written = 0;
  int ran = 0;
  for (int n = 0; n < 40; ++n) {
    Frame f = random_frame(rng, n);
    bool fits = true;
    for (int v = 0; v < 2; ++v) try {
        check_rect_footprints(f.mesh[v], f.rw, f.rh);
      } catch (const std::invalid_argument&) {
        fits = false;
      }
    if (!fits) continue;  // the error cases below
    const bool free = n % 3 == 0;
    const PassRun r = run_frame(dut(), f, rng, free ? 1.0 : 0.6, free ? 0 : int(rng() % 9));
    ASSERT_EQ(r.err, 0) << "frame " << n;
    const std::string e = compare(f, r);
    ASSERT_EQ(e, "") << "frame " << n << ": " << f.w << "x" << f.h << " from " << f.rw << "x" << f.rh << ", S "
                     << (1 << f.s) << ", planes " << f.planes << (f.lay.tiled ? ", tiled" : ", raster");
    long px = 0;
    for (int p = 0; p < 6; ++p) px += ((f.planes >> p) & 1) * long(f.w) * f.h;
    pixels += px;
    if (free) {
      cycles_free += r.cycles;
      pixels_free += px;
    }
    reads += r.reads;
    written += px;
    ++ran;
  }
  std::printf("%d frames, %ld rectified pixels; zero latency: %.3f cycles a pixel; %.2f bytes read a byte written\n",
              ran, pixels, double(cycles_free) / double(pixels_free), 4.0 * double(reads) / double(written));
  EXPECT_GE(ran, 30);
}

// A bundled camera (B, the strong one, on the Teddy CIF crop) at S = 16, the raw mode's
// planes (LY LU LV RY), zero latency, every request granted: bit-exact, and the cycles
// and the reads a byte written, printed (docs/blocks/rectifier.md 7). Column-tiled, as the
// DDR-like bar's input. Then at S = 32 (raster), whose tiles fit since their box is over
// their own edges (docs/algorithm.md 13.8): every tap of every pixel in the loaded rectangle.
TEST(Rect, BundledCameraCif) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/raw/B/cif/teddy/";
  const StereoRectification cal = read_calibration(dir + "calib.yml");
  Frame f;
  f.w = f.rw = cal.size.width;
  f.h = f.rh = cal.size.height;
  f.planes = 0x0f;
  std::mt19937 rng(5);
  const std::pair<int, bool> runs[] = {{4, false}, {4, true}, {5, false}};  // (log2 S, tiled)
  for (const auto& [step, tiled] : runs) {
    f.s = step;
    f.lay.tiled = tiled;
    f.lay.raw_stride = f.lay.stride = tiled ? 4u * uint32_t(f.h) : uint32_t(f.w);
    const auto meshes = meshes_from_rectification(cal, f.w, f.h, f.s);
    f.mesh[0] = meshes.first;
    f.mesh[1] = meshes.second;
    f.raw[0] = load_yuv(dir + "left.png");
    f.raw[1] = load_yuv(dir + "right.png");
    const PassRun r = run_frame(dut(), f, rng, 1.0, 0);
    ASSERT_EQ(r.err, 0);
    ASSERT_EQ(compare(f, r), "");
    const long px = 4L * f.w * f.h;
    std::printf("camera B, CIF, S = %d, LY LU LV RY, %s, zero latency: %ld cycles (%.3f a pixel), %.2f bytes read "
                "a byte written\n",
                1 << step, tiled ? "column-tiled" : "raster", r.cycles, double(r.cycles) / double(px),
                4.0 * double(r.reads) / double(px));
  }
}

TEST(Rect, BadMeshesEndThePassWithoutWriting) {
  std::mt19937 rng(3210);
  for (int n = 0; n < 6; ++n) {
    Frame f = random_frame(rng, n);
    f.mesh[0] = sim::random_mesh(f.w, f.h, f.s, f.rw, f.rh, rng, 0.2);
    f.mesh[1] = f.mesh[0];
    f.planes = 0x3f;
    int want;
    const int v = n % 2;  // the bad view
    if (n < 3) {           // a node out of range, in the last tile's nodes
      f.mesh[v].u[f.mesh[v].u.size() - 1] = kMeshCoordLimit;
      want = 1;
    } else {               // a steep mesh: a source rectangle beyond the buffer
      f.w = 100;
      f.h = 40;
      f.rw = f.rh = 200;
      f.lay.raw_stride = f.lay.tiled ? 4u * 200 : 200;
      f.lay.stride = f.lay.tiled ? 4u * 40 : 100;
      f.mesh[v] = make_mesh(f.w, f.h, f.s);
      f.mesh[1 - v] = sim::random_mesh(f.w, f.h, f.s, f.rw, f.rh, rng, 0.2);
      for (size_t k = 0; k < f.mesh[v].u.size(); ++k) {
        f.mesh[v].u[k] = int32_t(k % size_t(f.mesh[v].nx)) * f.mesh[v].step() * 32 * 3;
        f.mesh[v].v[k] = int32_t(k / size_t(f.mesh[v].nx)) * f.mesh[v].step() * 32;
      }
      f.raw[0] = test::random_yuv(f.rw, f.rh, rng);
      f.raw[1] = test::random_yuv(f.rw, f.rh, rng);
      EXPECT_THROW(check_rect_footprints(f.mesh[v], f.rw, f.rh), std::invalid_argument);
      want = 2;
    }
    const PassRun r = run_frame(dut(), f, rng, 0.7, 3);
    EXPECT_EQ(r.err, want) << "case " << n;
    EXPECT_EQ(r.writes, 0) << "case " << n;
  }
}

}  // namespace
}  // namespace mcadsw

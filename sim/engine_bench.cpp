// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "engine_bench.hpp"

#include <verilated.h>
#if VM_TRACE_FST
#include <verilated_fst_c.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

// The model (sim/bench_dut.hpp; CMake links the build's implementation) and
// the driver a user's firmware uses, over the model's register bus.
#include "bench_dut.hpp"
#include "mcadsw/driver.hpp"
#include "mcadsw/regs.hpp"
#if VM_COVERAGE
#include <unistd.h>
#include <verilated_cov.h>

#include <atomic>
#endif

namespace mcadsw::sim {
namespace {


// Memory layout of a frame (docs/memory_map.md): six input planes (left Y, U,
// V, right Y, U, V) of stride bytes per row (default: the width rounded up to
// 4) and the output plane of out_stride bytes per row (default: its row, 1 or
// 2 bytes a pixel, rounded up to 4), each starting on a 4 KiB boundary after a
// 4 KiB guard, from EngineOptions::origin (EngineOptions::packed: each plane
// at the first multiple of 4 after the previous one's stride x height bytes).
// The right view's U and V are always in memory; only the right and LR modes
// may read them. The LR mode adds, after the output plane, the scratch planes
// dL (output stride) and dR (input stride) and the mask plane (input stride).
// Tiled (EngineOptions::tiled), the six input planes are column-tiled, tile
// bytes a column of 4 pixels (default 4 x height); dR and the mask keep the
// raster stride. Sizes are computed in 64 bits: a layout that does not fit
// below 2^32 is refused.
// Rectification (EngineOptions::rect): the six planes above are the rectified
// planes (the engine writes those the mode reads, then reads them); after the
// planes above follow the six raw planes (raw width x height, raster with the
// raw stride, or column-tiled when the input planes are), the left and right
// meshes' memory images (8 nx ny bytes each) and the left and right validity
// bitmaps (4 ceil(W / 4) ceil(H / 8) bytes each), in the same scheme (4 KiB
// boundaries or packed, the whole order reversed with reversed_planes).
struct Layout {
  uint32_t stride, out_stride, ly, lu, lv, ry, ru, rv, out, dl = 0, dr = 0, mask = 0, tile = 0;
  uint64_t origin, plane, out_plane, in_plane, total;  // sizes: stride x height etc.
  int width, height, out_bpp, lr_t;
  bool right, lr;
  // Rectification: off, or the raw views' size and planes, meshes and bitmaps.
  bool rect = false;
  int rect_step = 0, raw_width = 0, raw_height = 0, mesh_nx = 0, mesh_ny = 0;
  int rect_planes = 0;  // bit p: plane p (LY LU LV RY RU RV) rectified: the planes the mode reads
  uint32_t raw_stride = 0, raw_tile = 0;  // raw_tile: raw_stride when column-tiled, else 0
  std::array<uint32_t, 6> raw{};
  std::array<uint32_t, 2> mesh{}, valid{};
  uint64_t raw_plane = 0, mesh_bytes = 0, valid_bytes = 0;
  // in_w x in_h: the images run_engine takes (with rectification the raw views;
  // the frame is then the meshes' rectified size).
  Layout(int in_w, int in_h, uint64_t origin_at, const EngineOptions& opt)
      : origin(origin_at), width(opt.rect ? opt.rect->left.out_width : in_w),
        height(opt.rect ? opt.rect->left.out_height : in_h), out_bpp(opt.subpixel ? 2 : 1),
        lr_t(opt.lr_tolerance), right(opt.right), lr(opt.lr) {
    const int w = width, h = height;
    if (opt.rect) rect_geometry(in_w, in_h, opt);
    stride = opt.stride ? opt.stride : uint32_t((w + 3) / 4 * 4);
    if (stride < uint32_t(w) || stride % 4 != 0)
      throw std::invalid_argument("stride " + std::to_string(stride) +
                                  " must be a multiple of 4 and at least the width " + std::to_string(w));
    const uint32_t row = uint32_t(w * out_bpp);
    out_stride = opt.out_stride ? opt.out_stride : (row + 3) / 4 * 4;
    if (out_stride < row || out_stride % 4 != 0)
      throw std::invalid_argument("output stride " + std::to_string(out_stride) +
                                  " must be a multiple of 4 and at least the output row of " +
                                  std::to_string(row) + " bytes");
    if (opt.origin % 4096 != 0)
      throw std::invalid_argument("origin " + std::to_string(opt.origin) + " must be a multiple of 4096");
    const uint64_t align = opt.packed ? 4 : 4096;
    const auto up = [align](uint64_t n) { return (n + align - 1) / align * align; };
    plane = up(uint64_t(stride) * uint64_t(h));
    out_plane = up(uint64_t(out_stride) * uint64_t(h));
    in_plane = plane;
    if (opt.tiled) {
      tile = opt.tile_stride ? opt.tile_stride : 4 * uint32_t(h);
      if (tile < 4 * uint32_t(h) || tile % 4 != 0)
        throw std::invalid_argument("tile stride " + std::to_string(tile) +
                                    " must be a multiple of 4 and at least 4 x the height " +
                                    std::to_string(h));
      in_plane = up(uint64_t(tile) * uint64_t((w + 3) / 4));
    }
    if (rect) {
      raw_stride = opt.rect->raw_stride ? opt.rect->raw_stride
                                        : opt.tiled ? 4 * uint32_t(raw_height) : uint32_t((raw_width + 3) / 4 * 4);
      const uint32_t least = opt.tiled ? 4 * uint32_t(raw_height) : uint32_t(raw_width);
      if (raw_stride < least || raw_stride % 4 != 0)
        throw std::invalid_argument("raw stride " + std::to_string(raw_stride) + " must be a multiple of 4 and at least " +
                                    (opt.tiled ? "4 x the raw height " : "the raw width ") + std::to_string(least / (opt.tiled ? 4 : 1)));
      raw_tile = opt.tiled ? raw_stride : 0;
      raw_plane = up(uint64_t(raw_stride) * uint64_t(opt.tiled ? (raw_width + 3) / 4 : raw_height));
      mesh_bytes = up(8 * uint64_t(mesh_nx) * uint64_t(mesh_ny));
      valid_bytes = up(4 * uint64_t((w + 3) / 4) * uint64_t((h + 7) / 8));
    }
    // The planes in this order from the origin, or (reversed_planes) the other
    // way round: the written planes below the ones read.
    std::vector<std::pair<uint32_t*, uint64_t>> order{{&ly, in_plane}, {&lu, in_plane}, {&lv, in_plane},
                                                       {&ry, in_plane}, {&ru, in_plane}, {&rv, in_plane},
                                                       {&out, out_plane + (lr ? align : 0u)}};
    if (lr) order.insert(order.end(), {{&dl, out_plane}, {&dr, plane}, {&mask, plane}});
    if (rect) {
      for (uint32_t& b : raw) order.emplace_back(&b, raw_plane);
      for (uint32_t& b : mesh) order.emplace_back(&b, mesh_bytes);
      for (uint32_t& b : valid) order.emplace_back(&b, valid_bytes);
    }
    if (opt.reversed_planes) std::reverse(order.begin(), order.end());
    uint64_t at = origin + 4096;
    for (const auto& [base, size] : order) {
      *base = uint32_t(at);
      at += size;
    }
    total = at + 4096;
    if (total > (uint64_t(1) << 32))
      throw std::invalid_argument("the frame's planes (" + std::to_string(total - origin) +
                                  " bytes from the origin " + std::to_string(origin) +
                                  ") do not fit in the 32-bit address space");
  }
  // The meshes and raw views of a rectified frame: checked, and their geometry.
  void rect_geometry(int raw_w, int raw_h, const EngineOptions& opt) {
    const Mesh& ml = opt.rect->left;
    const Mesh& mr = opt.rect->right;
    check_mesh(ml);
    check_mesh(mr);
    if (mr.step_log2 != ml.step_log2 || mr.out_width != ml.out_width || mr.out_height != ml.out_height)
      throw std::invalid_argument("the two meshes must have one step and one rectified size (left: step " +
                                  std::to_string(ml.step()) + ", " + std::to_string(ml.out_width) + "x" +
                                  std::to_string(ml.out_height) + "; right: step " + std::to_string(mr.step()) +
                                  ", " + std::to_string(mr.out_width) + "x" + std::to_string(mr.out_height) + ")");
    if (width < 1 || width > kMaxWidth || height < 1 || height > kMaxHeight)
      throw std::invalid_argument("rectified frame " + std::to_string(width) + "x" + std::to_string(height) +
                                  " out of range 1.." + std::to_string(kMaxWidth) + " x 1.." +
                                  std::to_string(kMaxHeight));
    if (raw_w < 1 || raw_w > kMaxWidth || raw_h < 1 || raw_h > kMaxHeight)
      throw std::invalid_argument("raw views " + std::to_string(raw_w) + "x" + std::to_string(raw_h) +
                                  " out of range 1.." + std::to_string(kMaxWidth) + " x 1.." +
                                  std::to_string(kMaxHeight));
    rect = true;
    rect_step = ml.step_log2;
    raw_width = raw_w;
    raw_height = raw_h;
    mesh_nx = ml.nx;
    mesh_ny = ml.ny;
    rect_planes = lr ? 0x3f : right ? 0x39 : 0x0f;  // docs/algorithm.md 13.4
  }
  // Byte address of pixel (x, y) of an input (or rectified) plane (plane_addr: any plane).
  uint64_t in_addr(uint32_t base, int x, int y) const { return plane_addr(base, stride, tile, x, y); }
  static uint64_t plane_addr(uint32_t base, uint32_t stride, uint32_t tile, int x, int y) {
    const uint64_t ux = uint64_t(x), uy = uint64_t(y);
    return uint64_t(base) + (tile ? ux / 4 * tile + 4 * uy + ux % 4 : uy * stride + ux);
  }
  // The input (rectified) plane p: LY LU LV RY RU RV.
  uint32_t in_base(int p) const {
    const uint32_t b[6] = {ly, lu, lv, ry, ru, rv};
    return b[p];
  }
  RawConfig raw_config(int disparities) const {
    RawConfig c{ly, lu, lv, ry, out, stride, out_stride, width, height, disparities};
    c.mode = (out_bpp == 2 ? 1 : 0) | (lr ? 2 : 0) | (right ? 4 : 0);
    c.base_ru = ru;
    c.base_rv = rv;
    c.base_dl = dl;
    c.base_dr = dr;
    c.base_mask = mask;
    c.lr_t = lr_t;
    c.tile_stride = tile;
    if (rect) {
      c.rect = true;
      c.rect_step = rect_step;
      c.raw_width = raw_width;
      c.raw_height = raw_height;
      c.raw_stride = raw_stride;
      c.raw_base = raw;
      c.mesh_base = mesh;
      c.valid_base = valid;
      c.mesh_nx = mesh_nx;
      c.mesh_ny = mesh_ny;
    }
    return c;
  }
  // What the frame may touch: reads in the pixels of the planes its mode
  // reads, writes in the output plane's pixels (LR: and the scratch and mask
  // planes' pixels, the scratch planes read back).
  // Rectification (rect_regions): the raw planes and meshes read, the rectified
  // planes and bitmaps written, then read.
  // With rectification in the LR mode (right_valid: the right view's validity), dL and
  // the output are written twice at invalid left pixels, dR at invalid right pixels.
  MemoryModel::Regions regions(const Plane* base_valid = nullptr, const Plane* right_valid = nullptr) const {
    std::vector<uint32_t> in{ly, lu, lv, ry};
    if (right) in = {ry, ru, rv, ly};
    if (lr) {
      MemoryModel::Regions r{{ly, lu, lv, ry, ru, rv}, dl, stride, width, height, out_stride, out_bpp, true,
                             {{dr, stride, 1, true}, {out, out_stride, out_bpp, false}, {mask, stride, 1, false}},
                             tile};
      if (rect) {
        rect_regions(r, base_valid);  // dL (r.out): out_rewrite
        if (base_valid) r.more_outs[1].rewrite = r.out_rewrite;
        if (right_valid) {
          r.more_outs[0].rewrite.assign(right_valid->px.size(), 0);
          for (size_t i = 0; i < right_valid->px.size(); ++i) r.more_outs[0].rewrite[i] = right_valid->px[i] == 0;
        }
      }
      return r;
    }
    MemoryModel::Regions r{in, out, stride, width, height, out_stride, out_bpp, false, {}, tile};
    if (rect) rect_regions(r, base_valid);
    return r;
  }
  // The planes the mode reads are now the rectified ones (written first); the
  // output pixels of invalid base pixels (base_valid 0) written twice (the mark step).
  void rect_regions(MemoryModel::Regions& r, const Plane* base_valid) const {
    static const char* const kPlane[6] = {"LY", "LU", "LV", "RY", "RU", "RV"};
    static const char* const kView[2] = {"L", "R"};
    r.inputs.clear();
    for (int p = 0; p < 6; ++p)
      if (rect_planes >> p & 1)
        r.areas.push_back({std::string("raw plane ") + kPlane[p], raw[size_t(p)], raw_width, raw_height,
                           raw_tile ? 0 : raw_stride, raw_tile, false, true, false});
    const int nodes = 8 * mesh_nx * mesh_ny;
    const int bitmap = 4 * ((width + 3) / 4) * ((height + 7) / 8);
    for (int v = 0; v < 2; ++v)
      r.areas.push_back({std::string("mesh ") + kView[v], mesh[size_t(v)], nodes, 1, uint32_t(nodes), 0, false, true,
                         false});
    for (int p = 0; p < 6; ++p)
      if (rect_planes >> p & 1)
        r.areas.push_back({std::string("rectified plane ") + kPlane[p], in_base(p), width, height,
                           tile ? 0 : stride, tile, true, true, true});
    for (int v = 0; v < 2; ++v)
      r.areas.push_back({std::string("validity bitmap ") + kView[v], valid[size_t(v)], bitmap, 1, uint32_t(bitmap), 0,
                         true, true, true});
    if (base_valid) {
      r.out_rewrite.assign(size_t(width) * size_t(height), 0);
      for (size_t i = 0; i < r.out_rewrite.size(); ++i) r.out_rewrite[i] = base_valid->px[i] == 0;
    }
  }
};

// The reference's rectification of a frame's raw views (EngineOptions::rect):
// each view through its mesh (mcadsw::rectify), and its validity bitmap as the
// engine writes it (mcadsw::validity_bitmap).
struct RectRef {
  Rectified view[2];
  std::vector<uint32_t> bitmap[2];
  const Plane& base_valid(bool right) const { return view[right ? 1 : 0].valid; }
};
std::optional<RectRef> rect_reference(const YuvImage& left, const YuvImage& right, const EngineOptions& opt) {
  if (!opt.rect) return std::nullopt;
  if (right.width() != left.width() || right.height() != left.height())
    throw std::invalid_argument("the raw views must have one size (left " + std::to_string(left.width()) + "x" +
                                std::to_string(left.height()) + ", right " + std::to_string(right.width()) + "x" +
                                std::to_string(right.height()) + ")");
  RectRef r;
  r.view[0] = rectify(left, opt.rect->left);
  r.view[1] = rectify(right, opt.rect->right);
  for (int v = 0; v < 2; ++v) r.bitmap[v] = validity_bitmap(r.view[v].valid);
  return r;
}

// An input plane, raster (stride bytes a row) or column-tiled (tile != 0).
void put_plane(MemoryModel& m, uint32_t base, uint32_t stride, uint32_t tile, const Plane& p) {
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const uint32_t ux = uint32_t(x), uy = uint32_t(y);
      m.byte(uint64_t(base) + (tile ? uint64_t(ux / 4) * tile + 4 * uy + ux % 4 : uint64_t(uy) * stride + ux)) =
          p.at(x, y);
    }
}
// The pixels of a w x h plane, raster or column-tiled, set to v.
void fill_plane(MemoryModel& m, uint32_t base, uint32_t stride, uint32_t tile, int w, int h, uint8_t v) {
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.byte(Layout::plane_addr(base, stride, tile, x, y)) = v;
}

class Engine {
 public:
  Engine(MemoryModel& mem, const EngineOptions& opt) : mem_(mem) {
    // Waves in real time: one cycle is kClockPeriodPs; the model is verilated
    // with --timescale 1ns/1ps (sim/CMakeLists.txt), so trace times are in ps.
    ctx_->traceEverOn(!opt.waves.empty());
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
    firmware_ = opt.firmware;
    if (!opt.waves.empty()) {
#if VM_TRACE_FST
      trace_ = std::make_unique<VerilatedFstC>();
      dut_->trace(*trace_);
      trace_->open(opt.waves.c_str());
#else
      throw std::runtime_error("this model was built without FST tracing: no waves");
#endif
    }
    dut_->eval();
    reset();
  }
  // Asynchronous reset for 4 cycles, with the memory system.
  void reset() {
    dut_->set_reset(true);
    dut_->eval();
    mem_.reset();
    dut_->reset_memory();
    for (int i = 0; i < 4; ++i) cycle();
    dut_->set_reset(false);
  }
  ~Engine() {
#if VM_TRACE_FST
    if (trace_) trace_->close();
#endif
    dut_->final();
#if VM_COVERAGE
    // `make coverage` (scripts/coverage.sh): one coverage file per engine instance.
    if (const char* dir = std::getenv("MCADSW_COVERAGE_DIR")) {
      static std::atomic<int> serial{0};
      const std::string path = std::string(dir) + "/" + std::to_string(getpid()) + "_" +
                               std::to_string(serial++) + ".dat";
      ctx_->coveragep()->write(path.c_str());
    }
#endif
  }

  BenchDut& dut() { return *dut_; }
  driver::Engine& driver() { return *driver_; }
  Firmware* firmware() { return firmware_; }

  // One clock cycle; `at_sample` runs once the cycle's outputs have settled.
  void cycle(const std::function<void()>& at_sample = {}) {
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

// The harness's configuration as the driver's (docs/registers.md).
driver::FrameConfig frame_config(const RawConfig& c, const WeightTable& table) {
  driver::FrameConfig f;
  f.base_ly = c.base_ly;
  f.base_lu = c.base_lu;
  f.base_lv = c.base_lv;
  f.base_ry = c.base_ry;
  f.base_ru = c.base_ru;
  f.base_rv = c.base_rv;
  f.base_out = c.base_out;
  f.base_dl = c.base_dl;
  f.base_dr = c.base_dr;
  f.base_mask = c.base_mask;
  f.stride = c.stride;
  f.out_stride = c.out_stride;
  f.tile_stride = c.tile_stride;
  f.width = c.width;
  f.height = c.height;
  f.disparities = c.disparities;
  f.subpixel = c.mode >> regs::kModeSubpixelBit & 1;
  f.lr = c.mode >> regs::kModeLrBit & 1;
  f.right = c.mode >> regs::kModeRightBit & 1;
  f.lr_tolerance = c.lr_t;
  f.rect = c.rect;
  f.rect_step_log2 = c.rect_step;
  f.raw_width = c.raw_width;
  f.raw_height = c.raw_height;
  f.raw_stride = c.raw_stride;
  f.raw_base = c.raw_base;
  f.mesh_base = c.mesh_base;
  f.mesh_nx = c.mesh_nx;
  f.mesh_ny = c.mesh_ny;
  f.valid_base = c.valid_base;
  const WeightThresholds thr = weight_thresholds(table);
  std::copy(thr.begin(), thr.end(), f.thresholds.begin());
  return f;
}

// The configuration through the driver (or EngineOptions::firmware), both
// interrupts on; the frame starts with start().
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

// Status and counters, read as a driver reads them.
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
void run_frame(Engine& e, EngineResult& r, long limit, bool progress, const StartAgain& again = {}) {
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

// Generous: four times the memory-bound estimate of 8000 cycles per block; with
// rectification, 16 cycles a rectified pixel of each of up to 6 planes more (about
// 1.05 at zero latency, docs/blocks/rectifier.md 7), the mark step included.
long frame_limit(int W, int H, const EngineOptions& opt) {
  const long blocks = long((W + kBlock - 1) / kBlock) * ((H + kBlock - 1) / kBlock);
  const long rect = opt.rect ? 16L * 6 * W * H + 100000 : 0;
  return opt.max_cycles > 0 ? opt.max_cycles : (opt.lr ? 3 : 1) * (40000 * blocks + 100000) + rect;
}

// Writes a frame's planes at its layout and fills the pixels of its disparity
// plane with 0xff ("never written"; LR: dL and dR too, the mask with 0x77).
void fill_pixels(MemoryModel& mem, uint32_t base, uint32_t stride, uint32_t row, int height, uint8_t v) {
  for (int y = 0; y < height; ++y)
    for (uint32_t i = 0; i < row; ++i) mem.byte(uint64_t(base) + uint64_t(y) * stride + i) = v;
}
// With rectification the views go to the raw planes, the meshes' memory images
// (docs/algorithm.md 13.1: node by node, row by row, u then v, 32-bit little
// endian) to theirs, and the pixels of the rectified planes and the bitmaps
// hold 0xa5 until the engine writes them.
void put_word(MemoryModel& mem, uint64_t a, uint32_t v) {
  for (int b = 0; b < 4; ++b) mem.byte(a + uint64_t(b)) = uint8_t(v >> (8 * b));
}
void load_rect(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right,
               const Rectification& rect) {
  const Plane* raw[6] = {&left.y, &left.u, &left.v, &right.y, &right.u, &right.v};
  for (int p = 0; p < 6; ++p) {
    put_plane(mem, lay.raw[size_t(p)], lay.raw_stride, lay.raw_tile, *raw[p]);
    fill_plane(mem, lay.in_base(p), lay.stride, lay.tile, lay.width, lay.height, 0xa5);
  }
  for (int v = 0; v < 2; ++v) {
    const Mesh& m = v ? rect.right : rect.left;
    for (size_t k = 0; k < m.u.size(); ++k) {
      put_word(mem, uint64_t(lay.mesh[size_t(v)]) + 8 * k, uint32_t(m.u[k]));
      put_word(mem, uint64_t(lay.mesh[size_t(v)]) + 8 * k + 4, uint32_t(m.v[k]));
    }
    const uint64_t words = uint64_t((lay.width + 3) / 4) * uint64_t((lay.height + 7) / 8);
    for (uint64_t k = 0; k < words; ++k) put_word(mem, uint64_t(lay.valid[size_t(v)]) + 4 * k, 0xa5a5a5a5u);
  }
}
void load_frame(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right,
                const EngineOptions& opt) {
  if (lay.rect) {
    load_rect(mem, lay, left, right, *opt.rect);
  } else {
    put_plane(mem, lay.ly, lay.stride, lay.tile, left.y);
    put_plane(mem, lay.lu, lay.stride, lay.tile, left.u);
    put_plane(mem, lay.lv, lay.stride, lay.tile, left.v);
    put_plane(mem, lay.ry, lay.stride, lay.tile, right.y);
    put_plane(mem, lay.ru, lay.stride, lay.tile, right.u);
    put_plane(mem, lay.rv, lay.stride, lay.tile, right.v);
  }
  const uint32_t w = uint32_t(lay.width), orow = w * uint32_t(lay.out_bpp);
  fill_pixels(mem, lay.out, lay.out_stride, orow, lay.height, 0xff);
  if (lay.lr) {
    fill_pixels(mem, lay.dl, lay.out_stride, orow, lay.height, 0xff);
    fill_pixels(mem, lay.dr, lay.stride, w, lay.height, 0xff);
    fill_pixels(mem, lay.mask, lay.stride, w, lay.height, 0x77);
  }
}

// Byte x of row y of a plane.
uint8_t& at(MemoryModel& mem, uint32_t base, uint32_t stride, int x, int y) {
  return mem.byte(uint64_t(base) + uint64_t(y) * stride + uint64_t(x));
}

// Pixel (x, y) of the output plane: a byte, or in sub-pixel mode a
// little-endian halfword.
int out_pixel(MemoryModel& mem, const Layout& lay, int x, int y) {
  const int ox = x * lay.out_bpp;
  return at(mem, lay.out, lay.out_stride, ox, y) |
         (lay.out_bpp == 2 ? at(mem, lay.out, lay.out_stride, ox + 1, y) << 8 : 0);
}

// Rectification: the rectified planes the mode reads and both views' validity
// bitmaps against the reference's (mcadsw::rectify, mcadsw::validity_bitmap),
// every pixel and every bit of an in-frame pixel, each byte written once.
void score_rect(MemoryModel& mem, const Layout& lay, const RectRef& rr, const EngineOptions& opt,
                EngineResult& r, std::ostringstream& rep) {
  static const char* const kPlane[6] = {"LY", "LU", "LV", "RY", "RU", "RV"};
  static const char* const kView[2] = {"L", "R"};
  long reported = 0;
  const auto bad = [&](const std::string& line) {
    ++r.mismatches;
    if (r.rect_mismatches++ == 0 || reported < opt.max_reported) {
      rep << "  " << line << "\n";
      ++reported;
    }
  };
  const int W = lay.width, H = lay.height;
  for (int p = 0; p < 6; ++p) {
    if (!(lay.rect_planes >> p & 1)) continue;
    const Rectified& ref = rr.view[p / 3];
    const Plane& want = p % 3 == 0 ? ref.image.y : p % 3 == 1 ? ref.image.u : ref.image.v;
    const Mesh& m = p < 3 ? opt.rect->left : opt.rect->right;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const uint64_t a = lay.in_addr(lay.in_base(p), x, y);
        const int got = mem.byte(a), n = mem.times_written(uint32_t(a));
        if (got == want.at(x, y) && n == 1) continue;
        const auto [pu, pv] = mesh_position(m, x, y);
        std::ostringstream e;
        e << "rectified plane " << kPlane[p] << " mismatch at (" << x << "," << y << "): RTL " << got;
        if (n != 1) e << " (written " << n << " times)";
        e << ", reference " << int(want.at(x, y)) << " (" << (ref.valid.at(x, y) ? "valid" : "invalid")
          << ", source (" << pu << "," << pv << ")/32)";
        bad(e.str());
      }
  }
  const int vh = (H + 7) / 8;
  for (int v = 0; v < 2; ++v) {
    if (!(lay.rect_planes >> (3 * v) & 7)) continue;
    for (int k = 0; 4 * k < W; ++k)
      for (int g = 0; g < vh; ++g) {
        const uint64_t a = uint64_t(lay.valid[size_t(v)]) + 4 * uint64_t(k * vh + g);
        uint32_t got = 0, in_frame = 0;
        int n = 1;
        for (int b = 0; b < 4; ++b) {
          got |= uint32_t(mem.byte(a + uint64_t(b))) << (8 * b);
          const int nb = mem.times_written(uint32_t(a) + uint32_t(b));
          if (nb != 1) n = nb;
        }
        for (int row = 0; row < 8; ++row)
          for (int c = 0; c < 4; ++c)
            if (4 * k + c < W && 8 * g + row < H) in_frame |= 1u << (4 * row + c);
        const uint32_t want = rr.bitmap[v][size_t(k) * size_t(vh) + size_t(g)];
        const uint32_t diff = (got ^ want) & in_frame;
        if (n != 1) {
          bad("validity bitmap " + std::string(kView[v]) + " word (" + std::to_string(k) + "," + std::to_string(g) +
              ") (pixels x " + std::to_string(4 * k) + "+, y " + std::to_string(8 * g) + "+) written " +
              std::to_string(n) + " times");
          if (!diff) continue;
        }
        for (int bit = 0; bit < 32; ++bit)
          if (diff >> bit & 1) {
            const int x = 4 * k + bit % 4, y = 8 * g + bit / 4;
            bad("validity bitmap " + std::string(kView[v]) + " mismatch at (" + std::to_string(x) + "," +
                std::to_string(y) + "): RTL " + std::to_string(got >> bit & 1) + ", reference " +
                std::to_string(want >> bit & 1) + " (word " + std::to_string(k) + "," + std::to_string(g) + ")");
          }
      }
  }
  if (r.rect_mismatches)
    rep << "  " << r.rect_mismatches << " rectified pixels or validity bits differ (or were not written once)\n";
}

// LR mode: the output plane and the mask against depth_map() (docs/algorithm.md
// 12.2-12.5), and the two scratch planes against the left and right maps
// (dL's integer d in sub-pixel mode), every pixel. With rectification the
// reference takes both views' validity (docs/algorithm.md 13.4), and the scratch
// planes hold the mark step's marks at invalid pixels (docs/blocks/rectifier.md 10):
// the flag in dL at an invalid left pixel, 255 in dR at an invalid right one.
void score_lr(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right,
              const Config& cfg, const EngineOptions& opt, EngineResult& r, const RectRef* rr,
              std::ostringstream& rep) {
  const int W = left.width(), H = left.height();
  DepthOptions dopt;
  dopt.lr = true;
  dopt.subpixel = opt.subpixel;
  dopt.tolerance = opt.lr_tolerance;
  if (rr) {
    dopt.left_valid = rr->view[0].valid;
    dopt.right_valid = rr->view[1].valid;
  }
  const DepthResult ref = depth_map(left, right, cfg, dopt);
  r.disparity = Plane(W, H);
  if (opt.subpixel) r.disparity16 = Plane16(W, H);
  r.mask = Plane(W, H);
  const auto bad = [&](const char* what, int x, int y, int got, int want) {
    if (r.mismatches++ >= opt.max_reported) return;
    rep << "  " << what << " mismatch at (" << x << "," << y << "): RTL " << got << ", reference "
        << want << " (dL " << int(ref.raw.at(x, y)) << ", dR(x - dL) "
        << (x >= ref.raw.at(x, y) ? std::to_string(ref.right.at(x - ref.raw.at(x, y), y)) : "-")
        << ", valid " << int(ref.valid.at(x, y) != 0) << ")\n";
  };
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int got = out_pixel(mem, lay, x, y);
      const int want = opt.subpixel ? ref.disp16.at(x, y)
                       : rr && ref.disp16.at(x, y) == kRectInvalidDisp16 ? kRectInvalidDisp8
                                                                           : ref.disp16.at(x, y) / kSubpixelScale;
      if (opt.subpixel) {
        r.disparity16.at(x, y) = uint16_t(got);
        r.disparity.at(x, y) = uint8_t(std::min(got / kSubpixelScale, 255));
      } else {
        r.disparity.at(x, y) = uint8_t(got);
      }
      if (got != want) bad(opt.subpixel ? "output 16d+o" : "output d", x, y, got, want);
      else if (rr && mem.times_written(uint32_t(lay.out) + uint32_t(y) * lay.out_stride +
                                       uint32_t(x * lay.out_bpp)) == 0)
        bad("output never written,", x, y, got, want);
      const int mk = at(mem, lay.mask, lay.stride, x, y);
      r.mask.at(x, y) = uint8_t(mk);
      if (mk != ref.valid.at(x, y)) bad("mask", x, y, mk, ref.valid.at(x, y));
      // With rectification the mark step flags dL at invalid left pixels (a byte 0x80,
      // a scratch halfword 0x8000) and writes 255 into dR at invalid right pixels
      // (docs/algorithm.md 13.4), before the post stage reads them.
      const int dl_full = opt.subpixel ? at(mem, lay.dl, lay.out_stride, 2 * x, y) |
                                             at(mem, lay.dl, lay.out_stride, 2 * x + 1, y) << 8
                                       : at(mem, lay.dl, lay.out_stride, x, y);
      const bool l_invalid = rr && !rr->view[0].valid.at(x, y);
      if (l_invalid) {
        const int flag = opt.subpixel ? kRectFlagDisp16 : kRectFlagDisp8;
        if (dl_full != flag) bad("scratch dL (flagged: invalid left pixel)", x, y, dl_full, flag);
      } else {
        const int dl = dl_full & (opt.subpixel ? (1 << kDispBits) - 1 : 0xff);
        if (dl != ref.raw.at(x, y)) bad("scratch dL", x, y, dl, ref.raw.at(x, y));
      }
      const int dr = at(mem, lay.dr, lay.stride, x, y);
      const int dr_want = rr && !rr->view[1].valid.at(x, y) ? kRectInvalidDisp8 : ref.right.at(x, y);
      if (dr != dr_want) bad("scratch dR", x, y, dr, dr_want);
    }
}

// Scoreboard: every pixel of the plane against the reference, both ways (a
// pixel the engine never wrote still holds 0xff or 0xffff, never a legal value).
// The reference runs the pass as the engine does: the left view as base, or,
// in the right mode, the mirrored pair with the views swapped (docs/algorithm.md
// 12.1), whose column W - 1 - x is output column x.
// With rectification (rr): `left` and `right` are the reference's rectified
// views; the rectified planes and bitmaps are compared first (score_rect), and
// every invalid base pixel (the left view's validity, the right view's in the
// right mode) expects the invalid code (mcadsw::mark_rect_invalid: 0xFFFF, 255
// in 8-bit output); 255 being a legal value then, "never written" comes from the
// memory model's count of writes.
void score(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right,
           const Config& cfg, const EngineOptions& opt, EngineResult& r, const RectRef* rr = nullptr) {
  std::ostringstream rep;
  if (rr) {
    score_rect(mem, lay, *rr, opt, r, rep);
    r.rect_valid = rr->base_valid(opt.right);
  }
  if (opt.lr) {
    score_lr(mem, lay, left, right, cfg, opt, r, rr, rep);
    r.bus = mem.violations();
    rep << r.bus.describe();
    r.report += rep.str();
    return;
  }
  const int W = left.width(), H = left.height();
  Config ref_cfg = cfg;
  Intermediates keep;
  const Plane ref = opt.right ? disparity_map(mirror(right), mirror(left), ref_cfg, &keep)
                              : disparity_map(left, right, ref_cfg, &keep);
  Plane16 ref16 = opt.subpixel ? subpixel_from_costs(keep, ref, cfg.disparities) : Plane16();
  const Plane* invalid = rr ? &rr->base_valid(opt.right) : nullptr;  // output columns, 0: invalid
  if (rr && opt.subpixel) {
    // 16-bit: the reference's own marking, on the pass's columns (mirrored in the right mode).
    mark_rect_invalid(ref16, opt.right ? mirror(*invalid) : *invalid);
  }
  r.disparity = Plane(W, H);
  if (opt.subpixel) r.disparity16 = Plane16(W, H);
  const auto cost = [&](int d, size_t i) -> std::string {
    return d >= 0 && d < cfg.disparities ? std::to_string(keep.final_cost[d][i]) : "-";
  };
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int xp = opt.right ? W - 1 - x : x;  // the pass's column
      const int got = out_pixel(mem, lay, x, y);
      const bool marked = invalid && invalid->at(x, y) == 0;
      const int want = opt.subpixel ? ref16.at(xp, y) : marked ? kRectInvalidDisp8 : ref.at(xp, y);
      if (opt.subpixel) {
        r.disparity16.at(x, y) = uint16_t(got);
        r.disparity.at(x, y) = uint8_t(std::min(got / kSubpixelScale, 255));
      } else {
        r.disparity.at(x, y) = uint8_t(got);
      }
      // Rectification: the code is a legal value; a pixel must have been written.
      const bool never =
          rr ? mem.times_written(uint32_t(lay.out) + uint32_t(y) * lay.out_stride + uint32_t(x * lay.out_bpp)) == 0
             : got == (opt.subpixel ? 0xffff : 0xff);
      if (got == want && !(rr && never)) continue;
      if (r.mismatches++ >= opt.max_reported) continue;
      const size_t i = size_t(y) * W + xp;
      const int dg = opt.subpixel ? (got + kSubpixelScale / 2) / kSubpixelScale : got;
      const int dw = ref.at(xp, y);
      rep << "  mismatch at (" << x << "," << y << "): RTL " << (opt.subpixel ? "16d+o=" : "d=") << got;
      if (never) rep << " (never written)";
      else if (dg < cfg.disparities) rep << " (cost " << keep.final_cost[dg][i] << ")";
      else rep << " (out of range)";
      rep << ", reference " << (opt.subpixel ? "16d+o=" : "d=") << want;
      if (marked) rep << " (invalid base pixel after rectification; the pass's d=" << dw << ")\n";
      else
        rep << " (d=" << dw << ", costs E(d-1) " << cost(dw - 1, i) << ", E(d) " << cost(dw, i) << ", E(d+1) "
            << cost(dw + 1, i) << ")\n";
    }
  r.bus = mem.violations();
  rep << r.bus.describe();
  r.report += rep.str();
}

// Records the driver's register writes (reads answer the last value written,
// CTRL without its pulse bits), for the Verilog bench to replay.
class RecordingBus : public driver::RegisterBus {
 public:
  uint32_t read(uint32_t offset) override {
    const auto it = last_.find(offset);
    const uint32_t v = it == last_.end() ? 0 : it->second;
    return offset == regs::kCtrl ? v & ~(1u << regs::kCtrlStartLsb | 1u << regs::kCtrlAbortLsb) : v;
  }
  void write(uint32_t offset, uint32_t value) override {
    last_[offset] = value;
    writes_.emplace_back(offset, value);
  }
  const std::vector<std::pair<uint32_t, uint32_t>>& writes() const { return writes_; }

 private:
  std::map<uint32_t, uint32_t> last_;
  std::vector<std::pair<uint32_t, uint32_t>> writes_;
};

// Files for tests/icarus/run.sh: mem.hex ($readmemh, one 32-bit word a line,
// byte 0 in bits 7:0), regs.txt (the register writes the driver makes to
// configure and start the frame, "offset value" in hex, which the Verilog bench
// replays onto the engine's configuration ports), config.txt (plusargs: the
// memory's size), and after the run verilator_out.hex (the disparity plane's
// words, then in the LR mode the mask plane's), verilator_regions.txt (where those
// words are: "base bytes" in hex and decimal, a line a plane, in the order of
// verilator_out.hex; tests/cocotb reads it) and verilator_counters.txt.
void dump_before(const std::string& dir, MemoryModel& mem, const RawConfig& c, const WeightTable& table) {
  // The Verilog bench's memory starts at address 0 (tests/icarus/tb_mcadsw_engine.sv).
  if (mem.lo() != 0) throw std::invalid_argument("--dump needs the frame at origin 0");
  std::ofstream m(dir + "/mem.hex");
  for (uint64_t a = 0; a + 4 <= mem.hi(); a += 4) {
    uint32_t w = 0;
    for (int b = 0; b < 4; ++b) w |= uint32_t(mem.byte(a + b)) << (8 * b);
    char buf[16];
    std::snprintf(buf, sizeof buf, "%08x\n", w);
    m << buf;
  }
  RecordingBus bus;
  driver::Engine drv(bus);
  drv.configure(frame_config(c, table));
  drv.enable_interrupts(true, true);
  drv.start();
  std::ofstream r(dir + "/regs.txt");
  for (const auto& [offset, value] : bus.writes()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%02x %08x\n", offset, value);
    r << buf;
  }
  std::ofstream f(dir + "/config.txt");
  f << "+WORDS=" << mem.hi() / 4 << "\n";
  if (!m || !r || !f) throw std::runtime_error("cannot write the dump files in " + dir);
}

void dump_after(const std::string& dir, MemoryModel& mem, const Layout& lay, const EngineResult& r) {
  std::ofstream m(dir + "/verilator_out.hex");
  const auto words = [&](uint64_t base, uint64_t bytes) {
    for (uint64_t a = base; a < base + bytes; a += 4) {
      uint32_t w = 0;
      for (int b = 0; b < 4; ++b) w |= uint32_t(mem.byte(a + b)) << (8 * b);
      char buf[16];
      std::snprintf(buf, sizeof buf, "%08x\n", w);
      m << buf;
    }
  };
  std::ofstream g(dir + "/verilator_regions.txt");
  const auto plane = [&](uint64_t base, uint64_t bytes) {
    words(base, bytes);
    char buf[48];
    std::snprintf(buf, sizeof buf, "%08llx %llu\n", static_cast<unsigned long long>(base),
                  static_cast<unsigned long long>(bytes));
    g << buf;
  };
  plane(lay.out, uint64_t(lay.out_stride) * uint32_t(lay.height));
  if (lay.lr) plane(lay.mask, uint64_t(lay.stride) * uint32_t(lay.height));  // and the mask plane
  std::ofstream c(dir + "/verilator_counters.txt");
  c << "cycles " << r.cycles << " words_read " << r.words_read << " words_written "
    << r.words_written << "\n";
  if (!m || !g || !c) throw std::runtime_error("cannot write the dump files in " + dir);
}

}  // namespace

uint64_t frame_bytes(int w, int h, const EngineOptions& opt) {
  const Layout lay(w, h, opt.origin, opt);
  return lay.total - lay.origin;
}

EngineResult run_engine(const YuvImage& left, const YuvImage& right, const Config& cfg,
                        const EngineOptions& opt) {
  const Layout lay(left.width(), left.height(), opt.origin, opt);
  const int W = lay.width, H = lay.height;  // with rectification: the meshes' frame
  const std::optional<RectRef> rr = rect_reference(left, right, opt);
  MemoryModel mem(lay.origin, lay.total, opt.latency);
  load_frame(mem, lay, left, right, opt);
  const Plane* base_valid = rr ? &rr->base_valid(opt.right) : nullptr;
  mem.set_regions(lay.regions(base_valid, rr ? &rr->view[1].valid : nullptr));

  EngineResult r;
  r.width = W;
  r.height = H;
  r.disparities = cfg.disparities;
  const RawConfig raw = lay.raw_config(cfg.disparities);
  if (!opt.dump_dir.empty()) dump_before(opt.dump_dir, mem, raw, cfg.table);
  {
    Engine e(mem, opt);
    program(e, raw, cfg.table);
    run_frame(e, r, frame_limit(W, H, opt), opt.progress);
  }
  if (!opt.dump_dir.empty()) dump_after(opt.dump_dir, mem, lay, r);
  if (rr) score(mem, lay, rr->view[0].image, rr->view[1].image, cfg, opt, r, &*rr);
  else score(mem, lay, left, right, cfg, opt, r);
  return r;
}

std::vector<EngineResult> run_frames(const std::vector<Frame>& frames, const EngineOptions& opt,
                                     FaultSpec fault) {
  std::vector<Layout> lays;
  std::vector<std::optional<RectRef>> rrs;
  uint64_t at = opt.origin;
  for (const Frame& f : frames) {
    lays.emplace_back(f.left.width(), f.left.height(), at, opt);
    rrs.push_back(rect_reference(f.left, f.right, opt));
    at = lays.back().total;
  }
  MemoryModel mem(opt.origin, at, opt.latency);
  for (size_t k = 0; k < frames.size(); ++k) load_frame(mem, lays[k], frames[k].left, frames[k].right, opt);

  std::vector<EngineResult> results(frames.size());
  Engine e(mem, opt);
  for (size_t k = 0; k < frames.size(); ++k) {
    const Frame& f = frames[k];
    const Layout& lay = lays[k];
    const std::optional<RectRef>& rr = rrs[k];
    const Plane* base_valid = rr ? &rr->base_valid(opt.right) : nullptr;
    const int W = lay.width, H = lay.height;
    EngineResult& r = results[k];
    r.width = W;
    r.height = H;
    r.disparities = f.cfg.disparities;
    // Only this frame's planes may be touched while it runs.
    mem.set_regions(lay.regions(base_valid, rr ? &rr->view[1].valid : nullptr));
    program(e, lay.raw_config(f.cfg.disparities), f.cfg.table);
    if (k == 0 && fault.kind == Fault::kResetMidFrame) {
      EngineResult aborted;
      run_frame(e, aborted, fault.at_cycle, false);
      if (!aborted.timed_out) throw std::runtime_error("frame 0 finished before the reset was due");
      e.reset();
      // The aborted frame's writes are not this frame's: checks start again.
      mem.set_regions(lay.regions(base_valid, rr ? &rr->view[1].valid : nullptr));
      program(e, lay.raw_config(f.cfg.disparities), f.cfg.table);
    }
    StartAgain again;
    if (fault.kind == Fault::kStartWhileBusy) again = {fault.at_cycle, fault.other, &f.cfg.table};
    if (fault.kind == Fault::kAbort && k == 0) again = {fault.at_cycle, {}, nullptr, true};
    run_frame(e, r, frame_limit(W, H, opt), opt.progress, again);
    if (rr) score(mem, lay, rr->view[0].image, rr->view[1].image, f.cfg, opt, r, &*rr);
    else score(mem, lay, f.left, f.right, f.cfg, opt, r);
  }
  return results;
}

MemoryModel::Violations with_registers(const std::function<void(RegisterPort&)>& script,
                                       const EngineOptions& opt) {
  MemoryModel mem(1 << 20, opt.latency);
  mem.set_regions({});
  {
    Engine e(mem, opt);
    RegisterPort port = e.dut().raw_registers([&e](long n) {
      for (long i = 0; i < n; ++i) e.cycle();
    });
    script(port);
  }
  return mem.violations();
}

EngineResult run_raw(const RawConfig& raw, const EngineOptions& opt, long cycles,
                     const std::vector<std::pair<uint32_t, std::vector<uint8_t>>>& readable) {
  MemoryModel mem(1 << 20, opt.latency);
  MemoryModel::Regions regions;  // a rejected configuration must touch nothing
  for (const auto& [base, bytes] : readable) {
    for (size_t i = 0; i < bytes.size(); ++i) mem.byte(uint64_t(base) + i) = bytes[i];
    MemoryModel::Area a;
    a.name = "readable range";
    a.base = base;
    a.width = int(bytes.size());
    a.height = 1;
    a.stride = uint32_t(bytes.size());
    regions.areas.push_back(a);
  }
  mem.set_regions(regions);
  EngineResult r;
  {
    Engine e(mem, opt);
    program(e, raw, make_weight_table(kDefaultGamma));
    run_frame(e, r, cycles, false);
    // A register read takes a few cycles (AXI4-Lite) or none (engine core): idle
    // cycles of 1, 0 and 2 in between make the gaps of different parity, so a
    // status that alternates from cycle to cycle is seen.
    const uint32_t first = e.dut().registers().read(regs::kStatus);
    for (const int idle : {1, 0, 2}) {
      for (int i = 0; i < idle; ++i) e.cycle();
      r.status_changes += e.dut().registers().read(regs::kStatus) != first;
    }
  }
  r.bus = mem.violations();
  return r;
}

}  // namespace mcadsw::sim

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
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

// The model (sim/bench_dut.hpp; CMake links the build's implementation) and
// the driver a user's firmware uses, over the model's register bus.
#include "bench_dut.hpp"
#include "mcadsw/driver.hpp"
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
struct Layout {
  uint32_t stride, out_stride, ly, lu, lv, ry, ru, rv, out, dl = 0, dr = 0, mask = 0, tile = 0;
  uint64_t origin, plane, out_plane, in_plane, total;  // sizes: stride x height etc.
  int width, height, out_bpp, lr_t;
  bool right, lr;
  Layout(int w, int h, uint64_t origin_at, const EngineOptions& opt)
      : origin(origin_at), width(w), height(h), out_bpp(opt.subpixel ? 2 : 1), lr_t(opt.lr_tolerance),
        right(opt.right), lr(opt.lr) {
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
    // The planes in this order from the origin, or (reversed_planes) the other
    // way round: the written planes below the ones read.
    std::vector<std::pair<uint32_t*, uint64_t>> order{{&ly, in_plane}, {&lu, in_plane}, {&lv, in_plane},
                                                       {&ry, in_plane}, {&ru, in_plane}, {&rv, in_plane},
                                                       {&out, out_plane + (lr ? align : 0u)}};
    if (lr) order.insert(order.end(), {{&dl, out_plane}, {&dr, plane}, {&mask, plane}});
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
  RawConfig raw(int disparities) const {
    RawConfig c{ly, lu, lv, ry, out, stride, out_stride, width, height, disparities};
    c.mode = (out_bpp == 2 ? 1 : 0) | (lr ? 2 : 0) | (right ? 4 : 0);
    c.base_ru = ru;
    c.base_rv = rv;
    c.base_dl = dl;
    c.base_dr = dr;
    c.base_mask = mask;
    c.lr_t = lr_t;
    c.tile_stride = tile;
    return c;
  }
  // What the frame may touch: reads in the pixels of the planes its mode
  // reads, writes in the output plane's pixels (LR: and the scratch and mask
  // planes' pixels, the scratch planes read back).
  MemoryModel::Regions regions() const {
    std::vector<uint32_t> in{ly, lu, lv, ry};
    if (right) in = {ry, ru, rv, ly};
    if (lr) {
      return {{ly, lu, lv, ry, ru, rv}, dl, stride, width, height, out_stride, out_bpp, true,
              {{dr, stride, 1, true}, {out, out_stride, out_bpp, false}, {mask, stride, 1, false}},
              tile};
    }
    return {in, out, stride, width, height, out_stride, out_bpp, false, {}, tile};
  }
};

// An input plane, raster (stride bytes a row) or column-tiled (tile != 0).
void put_plane(MemoryModel& m, uint32_t base, uint32_t stride, uint32_t tile, const Plane& p) {
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const uint32_t ux = uint32_t(x), uy = uint32_t(y);
      m.byte(uint64_t(base) + (tile ? uint64_t(ux / 4) * tile + 4 * uy + ux % 4 : uint64_t(uy) * stride + ux)) =
          p.at(x, y);
    }
}

class Engine {
 public:
  Engine(MemoryModel& mem, const EngineOptions& opt) : mem_(mem) {
    // Waves in real time: one cycle is kClockPeriodPs; the model is verilated
    // with --timescale 1ns/1ps (sim/CMakeLists.txt), so trace times are in ps.
    ctx_->traceEverOn(!opt.waves.empty());
    // `make mutate` (scripts/mutate.sh): a model built with every mutant of the
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
  f.subpixel = c.mode & 1;
  f.lr = c.mode >> 1 & 1;
  f.right = c.mode >> 2 & 1;
  f.lr_tolerance = c.lr_t;
  const WeightThresholds thr = weight_thresholds(table);
  std::copy(thr.begin(), thr.end(), f.thresholds.begin());
  return f;
}

// The configuration through the driver, both interrupts on; the frame starts
// with start().
void program(Engine& e, const RawConfig& c, const WeightTable& table) {
  e.driver().configure(frame_config(c, table));
  e.driver().enable_interrupts(true, true);
}

void start(Engine& e) { e.driver().start(); }

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
  r.read_bursts -= before.read_bursts;
  r.write_bursts -= before.write_bursts;
}

// Generous: four times the memory-bound estimate of 8000 cycles per block.
long frame_limit(int W, int H, const EngineOptions& opt) {
  const long blocks = long((W + kBlock - 1) / kBlock) * ((H + kBlock - 1) / kBlock);
  return opt.max_cycles > 0 ? opt.max_cycles : (opt.lr ? 3 : 1) * (40000 * blocks + 100000);
}

// Writes a frame's planes at its layout and fills the pixels of its disparity
// plane with 0xff ("never written"; LR: dL and dR too, the mask with 0x77).
void fill_pixels(MemoryModel& mem, uint32_t base, uint32_t stride, uint32_t row, int height, uint8_t v) {
  for (int y = 0; y < height; ++y)
    for (uint32_t i = 0; i < row; ++i) mem.byte(uint64_t(base) + uint64_t(y) * stride + i) = v;
}
void load_frame(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right) {
  put_plane(mem, lay.ly, lay.stride, lay.tile, left.y);
  put_plane(mem, lay.lu, lay.stride, lay.tile, left.u);
  put_plane(mem, lay.lv, lay.stride, lay.tile, left.v);
  put_plane(mem, lay.ry, lay.stride, lay.tile, right.y);
  put_plane(mem, lay.ru, lay.stride, lay.tile, right.u);
  put_plane(mem, lay.rv, lay.stride, lay.tile, right.v);
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

// LR mode: the output plane and the mask against depth_map() (docs/algorithm.md
// 12.2-12.5), and the two scratch planes against the left and right maps
// (dL's integer d in sub-pixel mode), every pixel.
void score_lr(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right,
              const Config& cfg, const EngineOptions& opt, EngineResult& r) {
  const int W = left.width(), H = left.height();
  DepthOptions dopt;
  dopt.lr = true;
  dopt.subpixel = opt.subpixel;
  dopt.tolerance = opt.lr_tolerance;
  const DepthResult ref = depth_map(left, right, cfg, dopt);
  r.disparity = Plane(W, H);
  if (opt.subpixel) r.disparity16 = Plane16(W, H);
  r.mask = Plane(W, H);
  std::ostringstream rep;
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
      const int want = opt.subpixel ? ref.disp16.at(x, y) : ref.disp16.at(x, y) / kSubpixelScale;
      if (opt.subpixel) {
        r.disparity16.at(x, y) = uint16_t(got);
        r.disparity.at(x, y) = uint8_t(std::min(got / kSubpixelScale, 255));
      } else {
        r.disparity.at(x, y) = uint8_t(got);
      }
      if (got != want) bad(opt.subpixel ? "output 16d+o" : "output d", x, y, got, want);
      const int mk = at(mem, lay.mask, lay.stride, x, y);
      r.mask.at(x, y) = uint8_t(mk);
      if (mk != ref.valid.at(x, y)) bad("mask", x, y, mk, ref.valid.at(x, y));
      const int dl = at(mem, lay.dl, lay.out_stride, x * lay.out_bpp, y) &
                     (opt.subpixel ? (1 << kDispBits) - 1 : 0xff);
      if (dl != ref.raw.at(x, y)) bad("scratch dL", x, y, dl, ref.raw.at(x, y));
      const int dr = at(mem, lay.dr, lay.stride, x, y);
      if (dr != ref.right.at(x, y)) bad("scratch dR", x, y, dr, ref.right.at(x, y));
    }
  r.bus = mem.violations();
  rep << r.bus.describe();
  r.report += rep.str();
}

// Scoreboard: every pixel of the plane against the reference, both ways (a
// pixel the engine never wrote still holds 0xff or 0xffff, never a legal value).
// The reference runs the pass as the engine does: the left view as base, or,
// in the right mode, the mirrored pair with the views swapped (docs/algorithm.md
// 12.1), whose column W - 1 - x is output column x.
void score(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right,
           const Config& cfg, const EngineOptions& opt, EngineResult& r) {
  if (opt.lr) {
    score_lr(mem, lay, left, right, cfg, opt, r);
    return;
  }
  const int W = left.width(), H = left.height();
  Config ref_cfg = cfg;
  Intermediates keep;
  const Plane ref = opt.right ? disparity_map(mirror(right), mirror(left), ref_cfg, &keep)
                              : disparity_map(left, right, ref_cfg, &keep);
  const Plane16 ref16 = opt.subpixel ? subpixel_from_costs(keep, ref, cfg.disparities) : Plane16();
  r.disparity = Plane(W, H);
  if (opt.subpixel) r.disparity16 = Plane16(W, H);
  std::ostringstream rep;
  const auto cost = [&](int d, size_t i) -> std::string {
    return d >= 0 && d < cfg.disparities ? std::to_string(keep.final_cost[d][i]) : "-";
  };
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int xp = opt.right ? W - 1 - x : x;  // the pass's column
      const int got = out_pixel(mem, lay, x, y);
      const int want = opt.subpixel ? ref16.at(xp, y) : ref.at(xp, y);
      if (opt.subpixel) {
        r.disparity16.at(x, y) = uint16_t(got);
        r.disparity.at(x, y) = uint8_t(std::min(got / kSubpixelScale, 255));
      } else {
        r.disparity.at(x, y) = uint8_t(got);
      }
      if (got == want) continue;
      if (r.mismatches++ >= opt.max_reported) continue;
      const size_t i = size_t(y) * W + xp;
      const int dg = opt.subpixel ? (got + kSubpixelScale / 2) / kSubpixelScale : got;
      const int dw = ref.at(xp, y);
      rep << "  mismatch at (" << x << "," << y << "): RTL " << (opt.subpixel ? "16d+o=" : "d=") << got;
      if (got == (opt.subpixel ? 0xffff : 0xff)) rep << " (never written)";
      else if (dg < cfg.disparities) rep << " (cost " << keep.final_cost[dg][i] << ")";
      else rep << " (out of range)";
      rep << ", reference " << (opt.subpixel ? "16d+o=" : "d=") << want << " (d=" << dw
          << ", costs E(d-1) " << cost(dw - 1, i) << ", E(d) " << cost(dw, i) << ", E(d+1) "
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
// words) and verilator_counters.txt.
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
  words(lay.out, uint64_t(lay.out_stride) * uint32_t(lay.height));
  if (lay.lr) words(lay.mask, uint64_t(lay.stride) * uint32_t(lay.height));  // and the mask plane
  std::ofstream c(dir + "/verilator_counters.txt");
  c << "cycles " << r.cycles << " words_read " << r.words_read << " words_written "
    << r.words_written << "\n";
  if (!m || !c) throw std::runtime_error("cannot write the dump files in " + dir);
}

}  // namespace

uint64_t frame_bytes(int w, int h, const EngineOptions& opt) {
  const Layout lay(w, h, opt.origin, opt);
  return lay.total - lay.origin;
}

EngineResult run_engine(const YuvImage& left, const YuvImage& right, const Config& cfg,
                        const EngineOptions& opt) {
  const int W = left.width(), H = left.height();
  const Layout lay(W, H, opt.origin, opt);
  MemoryModel mem(lay.origin, lay.total, opt.latency);
  load_frame(mem, lay, left, right);
  mem.set_regions(lay.regions());

  EngineResult r;
  r.width = W;
  r.height = H;
  r.disparities = cfg.disparities;
  const RawConfig raw = lay.raw(cfg.disparities);
  if (!opt.dump_dir.empty()) dump_before(opt.dump_dir, mem, raw, cfg.table);
  {
    Engine e(mem, opt);
    program(e, raw, cfg.table);
    run_frame(e, r, frame_limit(W, H, opt), opt.progress);
  }
  if (!opt.dump_dir.empty()) dump_after(opt.dump_dir, mem, lay, r);
  score(mem, lay, left, right, cfg, opt, r);
  return r;
}

std::vector<EngineResult> run_frames(const std::vector<Frame>& frames, const EngineOptions& opt,
                                     FaultSpec fault) {
  std::vector<Layout> lays;
  uint64_t at = opt.origin;
  for (const Frame& f : frames) {
    lays.emplace_back(f.left.width(), f.left.height(), at, opt);
    at = lays.back().total;
  }
  MemoryModel mem(opt.origin, at, opt.latency);
  for (size_t k = 0; k < frames.size(); ++k) load_frame(mem, lays[k], frames[k].left, frames[k].right);

  std::vector<EngineResult> results(frames.size());
  Engine e(mem, opt);
  for (size_t k = 0; k < frames.size(); ++k) {
    const Frame& f = frames[k];
    const Layout& lay = lays[k];
    const int W = f.left.width(), H = f.left.height();
    EngineResult& r = results[k];
    r.width = W;
    r.height = H;
    r.disparities = f.cfg.disparities;
    // Only this frame's planes may be touched while it runs.
    mem.set_regions(lay.regions());
    program(e, lay.raw(f.cfg.disparities), f.cfg.table);
    if (k == 0 && fault.kind == Fault::kResetMidFrame) {
      EngineResult aborted;
      run_frame(e, aborted, fault.at_cycle, false);
      if (!aborted.timed_out) throw std::runtime_error("frame 0 finished before the reset was due");
      e.reset();
      // The aborted frame's writes are not this frame's: checks start again.
      mem.set_regions(lay.regions());
      program(e, lay.raw(f.cfg.disparities), f.cfg.table);
    }
    StartAgain again;
    if (fault.kind == Fault::kStartWhileBusy) again = {fault.at_cycle, fault.other, &f.cfg.table};
    if (fault.kind == Fault::kAbort && k == 0) again = {fault.at_cycle, {}, nullptr, true};
    run_frame(e, r, frame_limit(W, H, opt), opt.progress, again);
    score(mem, lay, f.left, f.right, f.cfg, opt, r);
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

EngineResult run_raw(const RawConfig& raw, const EngineOptions& opt, long cycles) {
  MemoryModel mem(1 << 20, opt.latency);
  mem.set_regions({});  // a rejected configuration must touch nothing
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

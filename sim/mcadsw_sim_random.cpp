// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_sim_random: random differential regression of the Verilated engine
// against the reference (`make sim-random N=<cases> SEED=<s>`).
//   mcadsw_sim_random [--cases N] [--seed S] [--case K] [--data DIR]
// Case k of seed S is a function of (S, k) only: a random stereo pair (noise,
// flat, stripes, gradients, shifted copies, crops of the bundled Middlebury
// pairs), a random size (smaller than the window, not a multiple of 18, up to
// the maximum width), a random D in 1..DMAX, a random legal weight table and
// random memory latency and grant stalls, and a random stride (a quarter of
// the cases the width rounded up to 4, the others up to 4 KiB more). One case in
// eight is first interrupted: a read or a write burst answered
// SLVERR or DECERR, or CTRL.ABORT at a random cycle; that frame must end with
// code 13, 14 or 15 (an abort due after the frame's end changes nothing), and the
// same case run again on the same engine, without a reset, must be exact.
// Each case lies somewhere in the 32-bit address space (place(): origin, packed
// planes, strides padded by up to 2^30 bytes).
// One case in four is rectified by the engine first (register map 1.2; none in a build
// without the rectifier, MCADSW_RECT=OFF):
// its images are then raw views of 0.6 .. 1.6 times the frame each way (at least
// 8 x 4), made as above, and two random smooth meshes at S = 8, 16 or 32 (some
// reaching outside the raw views: invalid pixels; in a third of them the right
// view's mesh is the left's) rectify them to the frame; the raw planes' stride is
// padded like the others. That draw and the meshes come from a generator of their
// own, so a seed's other cases are those of earlier versions; every mode, layout,
// latency and interruption above combines with it.
// Every pixel is compared; a failing case prints the one command that reruns it
// alone.
// Exit status: 0 all cases bit-exact, 1 a mismatch or harness error, 2 usage.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "engine_bench.hpp"
#include "mcadsw/parse.hpp"
#include "mcadsw/image_io.hpp"
#include "mcadsw/rectify.hpp"
#include "mcadsw/regs.hpp"
#include "random_mesh.hpp"

namespace {

using namespace mcadsw;

const char* kUsage =
    "usage: mcadsw_sim_random [--cases N] [--seed S] [--case K] [--data DIR] [--fail-fast]\n"
    "  --fail-fast  stop at the first failing case (the mutation run's kill suite)\n";

enum class Interrupt { kNone, kRead, kWrite, kAbort };

struct Case {
  std::string pattern;
  YuvImage left, right;  // rectified (opt.frame.rect): the raw views
  Config cfg;
  sim::EngineOptions opt;
  Interrupt interrupt = Interrupt::kNone;
  long abort_at = 0;  // kAbort: cycles after the start
  // The frame: the images' size, or the meshes' rectified size.
  int width() const { return opt.frame.rect ? opt.frame.rect->left.out_width : left.width(); }
  int height() const { return opt.frame.rect ? opt.frame.rect->left.out_height : left.height(); }
};

Plane pattern_plane(const std::string& kind, int w, int h, std::mt19937& rng) {
  Plane p(w, h);
  std::uniform_int_distribution<int> byte(0, 255);
  const int base = byte(rng), amp = byte(rng);
  const int period = std::uniform_int_distribution<int>(2, 24)(rng);
  const bool vertical = rng() % 2;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      int v = base;
      if (kind == "noise") v = byte(rng);
      else if (kind == "stripes") v = (((vertical ? x : y) / period) % 2) ? base : amp;
      else if (kind == "gradient") v = (base + (x * amp) / std::max(1, w) + (y * 37) / std::max(1, h)) & 255;
      p.at(x, y) = uint8_t(v);
    }
  return p;
}

// The right view: the left one shifted by a disparity, with a little noise,
// or an unrelated image.
YuvImage right_view(const YuvImage& l, std::mt19937& rng) {
  const int shift = std::uniform_int_distribution<int>(0, 70)(rng);
  const int noise = std::uniform_int_distribution<int>(0, 6)(rng);
  YuvImage r = l;
  for (Plane* p : {&r.y, &r.u, &r.v}) {
    const Plane& src = p == &r.y ? l.y : p == &r.u ? l.u : l.v;
    for (int y = 0; y < p->height; ++y)
      for (int x = 0; x < p->width; ++x) {
        const int v = src.clamped(x + shift, y) + std::uniform_int_distribution<int>(-noise, noise)(rng);
        p->at(x, y) = uint8_t(std::clamp(v, 0, 255));
      }
  }
  return r;
}

// Where the frame lies in the 32-bit space (every address bit),
// drawn from a generator of its own so the draws of make_case stay those of
// earlier versions: in one case out of three the strides (input, output, tile)
// get padding of up to 2^30 bytes, halved until the frame fits; the planes
// are packed at 4-byte alignment in every other case; the origin is 0 in a
// third of the cases, the highest that fits in a third, anywhere in the rest.
// An interrupted case runs two frames, one after the other in memory.
// Rectified, the raw planes' stride is padded too (drawn after the others, so
// only rectified cases' later draws move).
void place(Case& c, uint32_t seed, int k) {
  std::seed_seq seq{seed, uint32_t(k), 0x706c6163u};
  std::mt19937 rng(seq);
  const int w = c.width(), h = c.height();                      // the frame
  const int iw = c.left.width(), ih = c.left.height();          // the images (rectified: raw)
  const uint32_t raw_row = c.opt.frame.tiled ? 4 * uint32_t(ih) : uint32_t(iw);  // least raw stride
  const uint64_t frames = c.interrupt == Interrupt::kNone ? 1 : 2;
  if (rng() % 3 == 0) {
    const auto pad = [&rng](uint32_t& stride, uint32_t row) {
      const int bits = std::uniform_int_distribution<int>(8, 30)(rng);
      stride = (row + 3) / 4 * 4 + 4 * uint32_t(std::uniform_int_distribution<uint64_t>(0, (1ull << (bits - 2)) - 1)(rng));
    };
    const uint32_t row = uint32_t(w * (c.opt.frame.subpixel ? 2 : 1));
    pad(c.opt.frame.stride, uint32_t(w));
    pad(c.opt.frame.out_stride, row);
    if (c.opt.frame.tiled) pad(c.opt.frame.tile_stride, 4 * uint32_t(h));
    if (c.opt.frame.rect) pad(c.opt.frame.rect->raw_stride, raw_row);
    const auto fits = [&] {
      try {
        return frames * sim::frame_bytes(iw, ih, c.opt) <= (uint64_t(1) << 32);
      } catch (const std::invalid_argument&) {
        return false;
      }
    };
    // Halve the padding of the largest stride until the frame fits.
    while (!fits()) {
      uint32_t* s = &c.opt.frame.stride;
      uint32_t min = (uint32_t(w) + 3) / 4 * 4;
      if (c.opt.frame.out_stride > *s) s = &c.opt.frame.out_stride, min = (row + 3) / 4 * 4;
      if (c.opt.frame.tiled && c.opt.frame.tile_stride > *s) s = &c.opt.frame.tile_stride, min = 4 * uint32_t(h);
      if (c.opt.frame.rect && c.opt.frame.rect->raw_stride > *s) s = &c.opt.frame.rect->raw_stride, min = (raw_row + 3) / 4 * 4;
      if (*s - min < 8) throw std::logic_error("place: case " + std::to_string(k) + " does not fit below 2^32");
      *s = min + (*s - min) / 8 * 4;
    }
  }
  c.opt.frame.packed = rng() % 2;
  const uint64_t room = (uint64_t(1) << 32) - frames * sim::frame_bytes(iw, ih, c.opt);
  const int where = int(rng() % 3);
  c.opt.frame.origin = where == 0 ? 0u
                 : where == 1 ? uint32_t(room / 4096 * 4096)
                              : uint32_t(std::uniform_int_distribution<uint64_t>(0, room / 4096)(rng) * 4096);
}

Case make_case(uint32_t seed, int k, const std::vector<std::pair<YuvImage, YuvImage>>& real) {
  std::seed_seq seq{seed, uint32_t(k), 0x6d636164u};
  std::mt19937 rng(seq);
  // Rectification in one case out of four, from a generator of its own (the
  // draws of rng stay those of earlier versions in the other cases).
  std::seed_seq rect_seq{seed, uint32_t(k), 0x72656374u};
  std::mt19937 rect_rng(rect_seq);
  const bool rect = rect_rng() % 4 == 0 && kRect;  // none in a build without the rectifier
  Case c;
  // Size: mostly small, some smaller than the 31x31 window, a few wide strips
  // up to the maximum width (kept short so a case stays fast).
  int w, h;
  const int kind = std::uniform_int_distribution<int>(0, 9)(rng);
  if (kind == 0) {
    w = std::uniform_int_distribution<int>(1, 30)(rng);
    h = std::uniform_int_distribution<int>(1, 30)(rng);
  } else if (kind == 1) {
    w = std::uniform_int_distribution<int>(200, kMaxWidth)(rng);
    h = std::uniform_int_distribution<int>(1, 12)(rng);
  } else {
    w = std::uniform_int_distribution<int>(8, 110)(rng);
    h = std::uniform_int_distribution<int>(8, 60)(rng);
  }
  // Rectified: the images are the raw views, iw x ih, 0.6 .. 1.6 times the frame
  // (w x h, the meshes' size) each way, at least 8 x 4.
  int iw = w, ih = h;
  if (rect) {
    std::uniform_real_distribution<double> ratio(0.6, 1.6);
    iw = std::clamp(int(std::lround(w * ratio(rect_rng))), 8, kMaxWidth);
    ih = std::clamp(int(std::lround(h * ratio(rect_rng))), 4, kMaxHeight);
  }
  static const char* kPatterns[] = {"noise", "flat", "stripes", "gradient", "real"};
  c.pattern = kPatterns[std::uniform_int_distribution<int>(0, real.empty() ? 3 : 4)(rng)];
  if (c.pattern == "real") {
    const auto& pair = real[rng() % real.size()];
    const int x0 = std::uniform_int_distribution<int>(0, std::max(0, pair.first.width() - iw))(rng);
    const int y0 = std::uniform_int_distribution<int>(0, std::max(0, pair.first.height() - ih))(rng);
    c.left = crop(pair.first, x0, y0, iw, ih);
    c.right = crop(pair.second, x0, y0, iw, ih);
  } else {
    c.left = YuvImage{pattern_plane(c.pattern, iw, ih, rng), pattern_plane(c.pattern, iw, ih, rng),
                      pattern_plane(c.pattern, iw, ih, rng)};
    if (rng() % 4 == 0) {
      c.right = YuvImage{pattern_plane("noise", iw, ih, rng), pattern_plane("noise", iw, ih, rng),
                         pattern_plane("noise", iw, ih, rng)};
    } else {
      c.right = right_view(c.left, rng);
    }
  }
  c.cfg.disparities = std::uniform_int_distribution<int>(1, kDmax)(rng);
  // A random legal table: non-increasing, values from the 8 legal weights.
  if (rng() % 3 == 0) {
    c.cfg.table = make_weight_table(std::uniform_real_distribution<double>(2.0, 200.0)(rng));
  } else {
    int code = std::uniform_int_distribution<int>(0, 7)(rng);
    for (auto& v : c.cfg.table) {
      if (code > 0 && rng() % 40 == 0) code -= 1 + int(rng() % code);
      v = uint8_t(weight_from_code(code));
    }
  }
  c.opt.memory.latency.random = rng() % 2;
  c.opt.memory.latency.seed = rng();
  c.opt.memory.latency.max_random = std::uniform_int_distribution<int>(1, 12)(rng);
  c.opt.memory.latency.gnt_prob = std::uniform_real_distribution<double>(0.3, 1.0)(rng);
  if (!c.opt.memory.latency.random) c.opt.memory.latency.fixed = std::uniform_int_distribution<int>(0, 4)(rng);
  // Rows far apart in memory: padding of up to 4 KiB after each row.
  if (rng() % 4 != 0)
    c.opt.frame.stride = uint32_t((w + 3) / 4 * 4 + 4 * std::uniform_int_distribution<int>(1, 1024)(rng));
  // Output mode (drawn last, so the draws above stay those of earlier versions):
  // sub-pixel in one case out of three, half of them with an output stride of
  // their own beyond the 2-byte row.
  if (rng() % 3 == 0) {
    c.opt.frame.subpixel = true;
    if (rng() % 2)
      c.opt.frame.out_stride =
          uint32_t((2 * w + 3) / 4 * 4 + 4 * std::uniform_int_distribution<int>(1, 512)(rng));
  }
  // The right view as base in one case out of three.
  c.opt.frame.right = rng() % 3 == 0;
  // The LR mode (left map, right map, post stage) in one of the other cases out
  // of three (up to the post stage's width), the tolerance T mostly small,
  // sometimes up to its maximum.
  if (!c.opt.frame.right && rng() % 3 == 0 && w <= kPostMaxWidth) {
    c.opt.frame.lr = true;
    c.opt.frame.lr_tolerance = rng() % 4 == 0 ? int(rng() % (kLrToleranceMax + 1)) : int(rng() % 4);
  }
  // Column-tiled input planes in one case out of three (read bursts), half of
  // them with a padded tile stride (4 KiB boundaries at other rows).
  if (rng() % 3 == 0) {
    c.opt.frame.tiled = true;
    if (rng() % 2) c.opt.frame.tile_stride = uint32_t(4 * h + 4 * std::uniform_int_distribution<int>(1, 300)(rng));
  }
  // An interruption in one case out of eight (drawn last). The burst numbers
  // stay inside the first frame: it reads more than a word a pixel (tiled: more
  // than a burst in 8 pixels) and writes at least a burst a block row (rectified:
  // more of both, the rectify pass's before).
  if (rng() % 8 == 0) {
    const int kind = int(rng() % 3);
    const int resp = 2 + int(rng() % 2);
    if (kind == 0) {
      c.interrupt = Interrupt::kRead;
      const long read_bursts = std::max(1L, long(w) * h / (c.opt.frame.tiled ? 8 : 1));
      c.opt.memory.axi_fault = {std::uniform_int_distribution<long>(1, read_bursts)(rng), 0, resp};
    } else if (kind == 1) {
      c.interrupt = Interrupt::kWrite;
      const long block_rows = long(h) * ((w + kBlock - 1) / kBlock);
      c.opt.memory.axi_fault = {0, std::uniform_int_distribution<long>(1, block_rows)(rng), resp};
    } else {
      c.interrupt = Interrupt::kAbort;
      c.abort_at = std::uniform_int_distribution<long>(1, 20000)(rng);
    }
  }
  // The meshes (rect_rng): S = 8, 16 or 32; the right view's the left's in a
  // third of the cases (the pair's own disparity), else one of its own. The raw
  // planes' stride: default (raw width rounded up to 4, tiled 4 x the raw height)
  // in a quarter of the cases, else up to 4 KiB (tiled: 1200 bytes) more.
  if (rect) {
    const int s = 3 + int(rect_rng() % 3);
    sim::Rectification r;
    r.left = sim::random_fitting_mesh(w, h, s, iw, ih, rect_rng);
    r.right = rect_rng() % 3 == 0 ? r.left : sim::random_fitting_mesh(w, h, s, iw, ih, rect_rng);
    if (rect_rng() % 4 != 0)
      r.raw_stride = c.opt.frame.tiled ? uint32_t(4 * ih + 4 * std::uniform_int_distribution<int>(1, 300)(rect_rng))
                                 : uint32_t((iw + 3) / 4 * 4 + 4 * std::uniform_int_distribution<int>(1, 1024)(rect_rng));
    c.opt.frame.rect = std::move(r);
  }
  place(c, seed, k);
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  // A failing RTL assertion prints on stdout and aborts: keep stdout line-buffered
  // so its message is not lost in a pipe's buffer.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  int cases = 200, only = -1;
  uint32_t seed = 1;
  bool fail_fast = false;
  std::string data = MCADSW_DATA_DIR;
  try {
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto val = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
        return argv[++i];
      };
      if (a == "--cases") cases = int(mcadsw::parse_long(val(), "cases"));
      else if (a == "--seed") seed = uint32_t(mcadsw::parse_long(val(), "seed"));
      else if (a == "--case") only = int(mcadsw::parse_long(val(), "case"));
      else if (a == "--data") data = val();
      else if (a == "--fail-fast") fail_fast = true;
      else if (a == "-h" || a == "--help") {
        std::cout << kUsage;
        return 0;
      } else throw std::invalid_argument("unknown option " + a);
    }
    if (cases < 1) throw std::invalid_argument("--cases must be at least 1");
    if (only < -1) throw std::invalid_argument("--case must be 0 or more");
  } catch (const std::exception& e) {
    std::cerr << "mcadsw_sim_random: " << e.what() << "\n" << kUsage;
    return 2;
  }

  std::vector<std::pair<YuvImage, YuvImage>> real;
  try {
    for (const char* pair : {"tsukuba", "venus", "teddy", "cones"}) {
      const std::string dir = data + "/middlebury/" + pair + "/";
      real.emplace_back(load_yuv(dir + "left.png"), load_yuv(dir + "right.png"));
    }
  } catch (const std::exception& e) {
    std::cerr << "mcadsw_sim_random: " << e.what() << " (crops of real pairs need --data DIR)\n";
    return 2;
  }

  const int first = only >= 0 ? only : 0, last = only >= 0 ? only : cases - 1;
  long failures = 0, run = 0, cycles = 0;
  for (int k = first; k <= last; ++k) {
    Case c;
    std::string err;
    try {
      c = make_case(seed, k, real);
    } catch (const std::exception& e) {
      err = std::string("making the case: ") + e.what();
    }
    sim::EngineResult r;
    std::string ended;  // the interrupted frame's fault, if any
    try {
      if (!err.empty()) {
        // the case could not be made: reported below
      } else if (c.interrupt == Interrupt::kNone) {
        r = sim::run_engine(c.left, c.right, c.cfg, c.opt);
      } else {
        const sim::Frame f{c.left, c.right, c.cfg};
        const sim::FaultSpec abort{c.interrupt == Interrupt::kAbort ? sim::Fault::kAbort : sim::Fault::kNone,
                                   c.abort_at};
        const auto res = sim::run_frames({f, f}, c.opt, abort);
        const sim::EngineResult& first = res[0];
        const int code = c.interrupt == Interrupt::kRead    ? regs::kErrReadResponse
                         : c.interrupt == Interrupt::kWrite ? regs::kErrWriteResponse
                                                            : regs::kErrAborted;
        const bool late_abort = c.interrupt == Interrupt::kAbort && !first.error && first.clean();
        if (first.timed_out) ended = "the interrupted frame did not end";
        else if (!late_abort && (!first.error || first.error_code != code))
          ended = "the interrupted frame ended with code " + std::to_string(first.error_code) +
                  ", expected " + std::to_string(code);
        else if (first.bus.protocol + first.bus.bad_reads + first.bus.bad_writes + first.bus.double_writes +
                 first.bus.early_reads)
          ended = "the interrupted frame broke a bus rule:\n" + first.bus.describe();
        r = res[1];
      }
    } catch (const std::exception& e) {
      err = e.what();
    }
    ++run;
    cycles += r.cycles;
    const bool ok = err.empty() && ended.empty() && r.clean();
    static const char* kInterrupt[] = {"", "  after a read error", "  after a write error",
                                       "  after an abort"};
    // Rectified: the step, the raw views' size and the raw planes' stride.
    std::string rect;
    if (c.opt.frame.rect) {
      const uint32_t rs = c.opt.frame.rect->raw_stride ? c.opt.frame.rect->raw_stride
                          : c.opt.frame.tiled ? 4u * unsigned(c.left.height())
                                        : unsigned((c.left.width() + 3) / 4 * 4);
      rect = " rect S=" + std::to_string(c.opt.frame.rect->left.step()) + " raw " + std::to_string(c.left.width()) + "x" +
             std::to_string(c.left.height()) + " (stride " + std::to_string(rs) + ")";
    }
    std::printf("case %4d  %-8s %4dx%-3d D=%-2d %s %s stride %5u%s at 0x%08x%s%s  %s latency  %8ld cycles  %s%s\n", k,
                c.pattern.c_str(), c.width(), c.height(), c.cfg.disparities,
                c.opt.frame.subpixel ? "sub" : "raw", c.opt.frame.right ? "R " : c.opt.frame.lr ? "LR" : "L ",
                c.opt.frame.stride ? c.opt.frame.stride : unsigned((c.width() + 3) / 4 * 4),
                c.opt.frame.tiled ? (" tile " + std::to_string(c.opt.frame.tile_stride ? c.opt.frame.tile_stride
                                                                         : 4u * unsigned(c.height())))
                                  .c_str()
                            : "",
                unsigned(c.opt.frame.origin), c.opt.frame.packed ? " packed" : "", rect.c_str(),
                c.opt.memory.latency.random ? "random" : ("fixed " + std::to_string(c.opt.memory.latency.fixed)).c_str(),
                r.cycles, ok ? "BIT-EXACT" : "FAILED", kInterrupt[int(c.interrupt)]);
    if (!ok) {
      ++failures;
      if (!err.empty()) std::printf("  harness error: %s\n", err.c_str());
      if (!ended.empty()) std::printf("  %s\n", ended.c_str());
      if (r.timed_out) std::printf("  the engine did not finish\n");
      if (r.error) std::printf("  configuration rejected, code %d\n", r.error_code);
      std::printf("  %ld mismatches%s, %ld memory-port violations\n%s", r.mismatches,
                  c.opt.frame.rect ? (" (" + std::to_string(r.rect_mismatches) + " in the rectified planes and bitmaps)").c_str()
                             : "",
                  r.bus.total(), r.report.c_str());
      std::printf("  reproduce: %s --seed %u --case %d\n", argv[0], seed, k);
    }
    std::fflush(stdout);
    if (failures && fail_fast) break;
  }
  std::printf("sim-random: %ld case(s), seed %u, %ld cycles, %ld mismatching case(s)\n", run, seed,
              cycles, failures);
  return failures ? 1 : 0;
}

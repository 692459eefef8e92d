// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Whole-engine test bench: driver (loads the planes into the memory model and
// programs the engine), clock loop with a cycle limit and progress output,
// and scoreboard (every disparity against the reference, both ways).
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "axi_memory.hpp"
#include "memory_model.hpp"
#include "mcadsw/rectify.hpp"
#include "mcadsw/ref.hpp"

namespace mcadsw::driver {
class RegisterBus;
struct FrameConfig;
}  // namespace mcadsw::driver

namespace mcadsw::sim {

// Firmware other than the C++ driver (the C header's test, tests/c/): run_engine and
// run_frames configure and start each frame through it, on the register bus the
// driver uses, and hand it the bus once the frame is over (after the bench has read
// status and counters itself, with the driver).
class Firmware {
 public:
  virtual ~Firmware() = default;
  // Every configuration register, the mode and both interrupt enables.
  virtual void configure(driver::RegisterBus& bus, const driver::FrameConfig& frame) = 0;
  virtual void start(driver::RegisterBus& bus) = 0;
  virtual void frame_over(driver::RegisterBus& bus) = 0;
};

// Clock period the waves are written with: 95 MHz, the paper's clock and
// constraints/mcadsw.sdc's `period` (a test checks they agree).
constexpr uint64_t kClockPeriodPs = 10526;

// Rectification by the engine (register map 1.2; docs/blocks/rectifier.md,
// docs/algorithm.md 13): the images given to run_engine / run_frames are then the
// raw views (Wr x Hr, 1 .. 2048 each, the two of one size), and the frame is the
// meshes' out_width x out_height.
struct Rectification {
  Mesh left, right;           // the views' meshes: one step, one rectified size (the frame)
  // Bytes a row of the raw planes (raster), or from one 4-pixel column to the next
  // (FrameOptions::tiled); 0: the raw width rounded up to 4, or 4 x the raw height.
  uint32_t raw_stride = 0;
};

// Where the frame lies in memory and the mode it runs in.
struct FrameOptions {
  uint32_t stride = 0;           // bytes per row of the input planes; 0: width rounded up to 4
  // Input planes column-tiled (docs/memory_map.md): pixel (x, y) at
  // base + (x / 4) tile + 4 y + x % 4, so a strip's rows are read in bursts.
  bool tiled = false;
  uint32_t tile_stride = 0;      // tiled: bytes per 4-pixel column; 0: 4 x height
  uint32_t out_stride = 0;       // bytes per row of the output plane; 0: its row rounded up to 4
  // The planes in memory in the reverse order: output (LR: and the scratch and
  // mask planes) below the input planes, right view's below the left view's.
  bool reversed_planes = false;
  // Where the frame's memory starts (a multiple of 4 KiB): the planes follow a
  // 4 KiB guard from here, so a frame can lie anywhere in the 32-bit space.
  uint32_t origin = 0;
  // The planes back to back, each at the first multiple of 4 after the previous
  // one's stride x height bytes, instead of on 4 KiB boundaries.
  bool packed = false;
  bool subpixel = false;         // mode bit 0: 16-bit output pixels, 16 d + offset
  bool right = false;            // mode bit 2: the right view as base (docs/algorithm.md 12.1)
  bool lr = false;               // mode bit 1: left-right check, fill, median (docs/algorithm.md 12.2-12.5)
  int lr_tolerance = kLrToleranceDefault;  // T
  // The engine rectifies the raw views first (RECT_CTRL.ENABLE): besides the planes
  // above, which it then writes (the rectified planes) and reads, memory holds the
  // raw planes (raster, or column-tiled with `tiled`), both meshes' memory images
  // and the two validity bitmaps the engine writes. The expected output: each view
  // through mcadsw::rectify, the usual reference on the rectified pair, then the
  // invalid code at every invalid base pixel (mcadsw::mark_rect_invalid); the
  // rectified planes the mode reads and the bitmaps are compared too.
  std::optional<Rectification> rect;
};

// The memory system's timing and the faults it answers with.
struct MemoryTiming {
  MemoryModel::Latency latency;  // memory latency and back-pressure (sim/axi_memory.hpp)
  AxiMemory::Fault axi_fault;    // a read or write burst answered SLVERR / DECERR
  long axi_write_latency = 0;    // further cycles before each write response (and its landing)
  int axi_ar_interval = 1;       // an AR accepted at most every this many cycles
};

// How a run is bounded, programmed and observed.
struct RunControl {
  long max_cycles = 0;           // 0: derived from the frame size
  bool progress = false;         // a line every few million cycles on stderr
  std::string waves;             // FST file, empty: no waves
  // The engine core's ports, every cycle, to this file (the CORE build only:
  // `make power`'s activity, sim/activity/netlist_activity.cpp); empty: none.
  std::string record_ports;
  int max_reported = 10;         // mismatches printed
  // Directory for the second simulator (tests/icarus): the memory image and
  // configuration before the run, the disparity plane and counters after it.
  std::string dump_dir;
  Firmware* firmware = nullptr;  // programs the frames instead of the C++ driver; not owned
};

struct EngineOptions {
  FrameOptions frame;
  MemoryTiming memory;
  RunControl run;
};

struct EngineResult {
  int width = 0, height = 0, disparities = 0;
  long cycles = 0;               // engine's cycle counter
  long words_read = 0, words_written = 0, stall_cycles = 0;
  long read_bursts = 0, write_bursts = 0;  // AXI4 bursts the memory model served in the frame
  long mismatches = 0;           // pixels differing from the reference (incl. never written)
  // Rectification: of `mismatches`, the rectified planes' pixels and validity
  // bitmaps' bits that differ (or were not written once); 0 without it.
  long rect_mismatches = 0;
  Plane rect_valid;              // rectification: the base view's validity (nonzero valid); otherwise empty
  MemoryModel::Violations bus;   // port and address checks of the memory model
  bool timed_out = false;
  bool error = false;            // engine rejected the configuration
  int error_code = 0;
  bool done = false;             // STATUS.DONE after the frame (a rejected start sets it too)
  // run_raw: of three further STATUS reads (one, none and two idle cycles after
  // the previous one), how many differed from the first read (a status must hold).
  int status_changes = 0;
  double sim_seconds = 0;
  std::string report;            // first mismatches, human-readable
  Plane disparity;               // what the engine wrote (sub-pixel mode: value / 16)
  Plane16 disparity16;           // sub-pixel mode: what the engine wrote; otherwise empty
  Plane mask;                    // LR mode: the validity mask the engine wrote; otherwise empty
  // Finished, accepted, every pixel equal to the reference, every check of the
  // memory model passed.
  bool clean() const { return !timed_out && !error && mismatches == 0 && bus.total() == 0; }
};

// Bytes of memory a frame of w x h pixels takes with these options (its planes,
// padding and guards, from FrameOptions::origin); throws std::invalid_argument
// for an illegal stride or a layout that does not fit in the 32-bit space. With
// FrameOptions::rect, w x h is the raw views' size (the images run_engine takes).
uint64_t frame_bytes(int w, int h, const EngineOptions& opt);

// Runs one frame. Throws std::runtime_error for harness failures (memory
// access out of range, model errors).
EngineResult run_engine(const YuvImage& left, const YuvImage& right, const Config& cfg,
                        const EngineOptions& opt);

// Several frames through one engine instance, in the same memory, without a
// reset between them (back to back), each scored like run_engine. A fault
// can be injected into every frame at `at_cycle` cycles after its start:
//   kResetMidFrame   reset (engine and memory system) in the middle of frame 0,
//                    which is then started again from the beginning;
//   kStartWhileBusy  start_i pulsed again while the frame runs, with the
//                    configuration `other` on the configuration ports (must be
//                    ignored: the frame, its status and counters unchanged);
//   kAbort           CTRL.ABORT written in frame 0 (at_cycle 0: just before its
//                    start, while idle, which must be ignored).
// MemoryTiming::axi_fault answers a read or write burst with an error (counted
// over the whole run, so a small burst number falls in frame 0).
struct Frame {
  YuvImage left, right;
  Config cfg;
};
// A configuration as the engine's ports take it.
struct RawConfig {
  uint32_t base_ly, base_lu, base_lv, base_ry, base_out, stride, out_stride;
  int width, height, disparities;
  int mode = 0;  // bit 0 sub-pixel, bit 1 LR, bit 2 right view as base
  uint32_t base_ru = 0, base_rv = 0;
  uint32_t base_dl = 0, base_dr = 0, base_mask = 0;  // LR mode's scratch and mask planes
  uint32_t tile_stride = 0;  // input planes column-tiled: bytes per 4-pixel column; 0: raster
  int lr_t = kLrToleranceDefault;
  // Rectification (register map 1.2): RECT_CTRL, RAW_*, MESH_*, VALID_*; all 0: off.
  bool rect = false;
  int rect_step = 0;  // STEP_LOG2
  int raw_width = 0, raw_height = 0;
  uint32_t raw_stride = 0;
  std::array<uint32_t, 6> raw_base{};  // LY LU LV RY RU RV
  std::array<uint32_t, 2> mesh_base{}, valid_base{};  // left, right
  int mesh_nx = 0, mesh_ny = 0;
};
enum class Fault { kNone, kResetMidFrame, kStartWhileBusy, kAbort };
struct FaultSpec {
  Fault kind = Fault::kNone;
  long at_cycle = 0;
  RawConfig other{};  // kStartWhileBusy: programmed just before the second start
};
std::vector<EngineResult> run_frames(const std::vector<Frame>& frames, const EngineOptions& opt,
                                     FaultSpec fault = {});

// Runs one frame with a raw configuration and reports the engine's status,
// without comparing (fault tests: rejected configurations); any write is
// counted in bus.bad_writes. STATUS is read again three times (status_changes).
// `readable`: byte ranges (base, bytes) loaded into memory first, which the frame
// may read (a rectifier's meshes: its check phase reads them, then may end the
// frame with code 22 or 23); nothing may be written anywhere.
EngineResult run_raw(const RawConfig& raw, const EngineOptions& opt, long cycles,
                     const std::vector<std::pair<uint32_t, std::vector<uint8_t>>>& readable = {});

// The SoC's AXI4-Lite register port (mcadsw_top, engine idle after reset),
// for register-level tests: write and read return or report the response (0
// OKAY, 2 SLVERR), cycles runs the clock.
struct RegisterPort {
  std::function<int(uint32_t offset, uint32_t data)> write;
  // A write of the bytes whose WSTRB bit is set (bit k: byte k).
  std::function<int(uint32_t offset, uint32_t data, uint32_t strb)> write_strobed;
  std::function<uint32_t(uint32_t offset, int* resp)> read;
  std::function<void(long n)> cycles;
  // Writes back to back, the next AW and W offered before the previous B (BREADY
  // low for the first `hold_b` cycles); the BRESPs in order.
  std::function<std::vector<int>(const std::vector<std::pair<uint32_t, uint32_t>>& writes, long hold_b)>
      write_pipelined;
};
// Runs `script` on a fresh SoC whose AXI4 port faces 1 MiB of memory that
// nothing may touch: the result counts any access (bad_reads, bad_writes).
// Not available in the gate-level model (no register block): throws.
MemoryModel::Violations with_registers(const std::function<void(RegisterPort&)>& script,
                                       const EngineOptions& opt = {});

// Whether this model was verilated with FST tracing (EngineOptions::run.waves). The
// regression's models are not (a traced model keeps every traced signal a variable and
// runs slower); build/bin/mcadsw_sim_waves is mcadsw_sim on the traced model.
bool model_writes_waves();

}  // namespace mcadsw::sim

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Driver of the MCADSW engine (rtl/mcadsw_top.sv) for firmware, the simulation
// harness and the tests alike: configure a frame from a plain struct, start it,
// wait for it (poll STATUS, or take the interrupt and read it), read the status
// and counters, decode error codes. The register map is sw_ref/include/mcadsw/regs.hpp
// (docs/registers.md); the meaning of each value docs/memory_map.md.
//
// A platform gives register access through two functions, RegisterBus::read and
// ::write, of 32-bit registers at byte offsets from the block's base: the Verilator
// harness over its AXI4-Lite bus functional model, a Linux program over an mmap of
// /dev/uioN or /dev/mem (driver/examples/mcadsw_uio.cpp), a bare-metal one over a
// volatile pointer. Header-only, C++17, no allocation, no exceptions of its own.
#pragma once

#include <array>
#include <cstdint>

#include "mcadsw/params.hpp"
#include "mcadsw/regs.hpp"

namespace mcadsw::driver {

class RegisterBus {
 public:
  virtual ~RegisterBus() = default;
  virtual uint32_t read(uint32_t offset) = 0;
  virtual void write(uint32_t offset, uint32_t value) = 0;
};

// One frame. Addresses are byte addresses in the engine's AXI4 master space, each a
// multiple of 4; strides in bytes (docs/memory_map.md gives the layouts).
struct FrameConfig {
  uint32_t base_ly = 0, base_lu = 0, base_lv = 0;  // left view Y, U, V planes
  uint32_t base_ry = 0, base_ru = 0, base_rv = 0;  // right view (U, V: right view as base, LR)
  uint32_t base_out = 0;                           // disparity plane
  uint32_t base_dl = 0, base_dr = 0, base_mask = 0;  // LR mode: scratch maps, validity mask
  uint32_t stride = 0;        // input planes (raster), dR and the mask
  uint32_t out_stride = 0;    // disparity plane and dL
  uint32_t tile_stride = 0;   // input planes column-tiled: bytes per 4-pixel column; 0: raster
  int width = 0, height = 0;
  int disparities = 0;        // D, 1 .. the build's DMAX (HWCONFIG.DMAX)
  bool subpixel = false;      // 16-bit output, 16 d + offset
  bool lr = false;            // left-right check, fill, median; writes the mask
  bool right = false;         // the right view as base (not with lr)
  int lr_tolerance = kLrToleranceDefault;  // T, 0 .. 63
  // The weight table as its thresholds (docs/algorithm.md; mcadsw::weight_thresholds()).
  std::array<uint32_t, kWeightThresholds> thresholds{};
  // Rectification (register map 1.2; docs/architecture.md 3.10, docs/algorithm.md 13):
  // with `rect` the engine first resamples the raw planes through the meshes into the
  // planes above (base_ly ..., in their layout: raster with `stride`, or column-tiled
  // with `tile_stride`) and writes one validity bitmap a view; the matching passes then
  // read those planes, and the output of a base pixel outside its raw view is the
  // invalid code (255, 0xFFFF sub-pixel). configure() writes these registers always:
  // a frame without rectification writes RECT_CTRL = 0 (with the defaults below).
  bool rect = false;
  int rect_step_log2 = 0;     // RECT_CTRL.STEP_LOG2: 3, 4 or 5 (mesh step S = 8, 16, 32)
  int raw_width = 0, raw_height = 0;  // the raw views, 1 .. 2048 (the frame: width x height)
  uint32_t raw_stride = 0;    // raw planes' bytes a row; column-tiled (tile_stride != 0):
                              // bytes from one 4-pixel column to the next
  std::array<uint32_t, 6> raw_base{};    // raw planes LY LU LV RY RU RV (the planes the mode reads)
  std::array<uint32_t, 2> mesh_base{};   // left, right: nx x ny nodes, u then v, 8 bytes a node
  int mesh_nx = 0, mesh_ny = 0;          // ((width - 1) >> s) + 2, ((height - 1) >> s) + 2
  std::array<uint32_t, 2> valid_base{};  // left, right validity bitmaps (written by the engine)
};

struct Identity {
  uint32_t id = 0;
  int version_major = 0, version_minor = 0;
  int dmax = 0, par = 0;      // build parameters
  bool rect = false;          // the rectifier is built in (HWCONFIG.NORECT 0; map 1.3)
  // The block answers with the ID and a register map version this driver knows.
  bool compatible() const {
    return id == regs::kIdValue && version_major == int(regs::kVersionMajor) &&
           version_minor >= int(regs::kVersionMinor);
  }
};

struct Status {
  bool busy = false;
  bool done = false;          // a frame finished or was rejected since start()
  bool error = false;         // ... rejected, or ended by a bus error or an abort
  int error_code = 0;         // regs::kErrors; error_text() below
};

struct Counters {
  uint32_t cycles = 0, words_read = 0, words_written = 0, stalls = 0;
};

// The text of an error code, for messages.
inline const char* error_text(int code) { return regs::error_text(code); }

class Engine {
 public:
  explicit Engine(RegisterBus& bus) : bus_(bus) {}

  Identity identify() {
    Identity i;
    i.id = bus_.read(regs::kId);
    const uint32_t v = bus_.read(regs::kVersion);
    i.version_major = int(field(v, regs::kVersionMajorLsb, 8));
    i.version_minor = int(field(v, regs::kVersionMinorLsb, 8));
    const uint32_t hw = bus_.read(regs::kHwConfig);
    i.dmax = int(field(hw, regs::kHwConfigDmaxLsb, 8));
    i.par = int(field(hw, regs::kHwConfigParLsb, 4));
    i.rect = field(hw, regs::kHwConfigNoRectLsb, 1) == 0;
    return i;
  }

  // Writes every configuration register and the mode; the frame starts with start().
  void configure(const FrameConfig& c) {
    bus_.write(regs::kBaseLy, c.base_ly);
    bus_.write(regs::kBaseLu, c.base_lu);
    bus_.write(regs::kBaseLv, c.base_lv);
    bus_.write(regs::kBaseRy, c.base_ry);
    bus_.write(regs::kBaseRu, c.base_ru);
    bus_.write(regs::kBaseRv, c.base_rv);
    bus_.write(regs::kBaseOut, c.base_out);
    bus_.write(regs::kBaseDl, c.base_dl);
    bus_.write(regs::kBaseDr, c.base_dr);
    bus_.write(regs::kBaseMask, c.base_mask);
    bus_.write(regs::kStride, c.stride);
    bus_.write(regs::kOutStride, c.out_stride);
    bus_.write(regs::kTileStride, c.tile_stride);
    bus_.write(regs::kSize, put(uint32_t(c.width), regs::kSizeWidthLsb, regs::kSizeBits) |
                                put(uint32_t(c.height), regs::kSizeHeightLsb, regs::kSizeBits));
    bus_.write(regs::kDisp, put(uint32_t(c.disparities), 0, regs::kDispBitsReg));
    bus_.write(regs::kLrT, put(uint32_t(c.lr_tolerance), 0, regs::kLrTBits));
    for (int i = 0; i < kWeightThresholds; ++i)
      bus_.write(regs::kThr0 + 4 * uint32_t(i), put(c.thresholds[size_t(i)], 0, regs::kThrBits));
    bus_.write(regs::kRectCtrl, put(uint32_t(c.rect), regs::kRectEnableLsb, 1) |
                                    put(uint32_t(c.rect_step_log2), regs::kRectStepLsb, regs::kRectStepWidth));
    bus_.write(regs::kRawSize, put(uint32_t(c.raw_width), regs::kSizeWidthLsb, regs::kSizeBits) |
                                   put(uint32_t(c.raw_height), regs::kSizeHeightLsb, regs::kSizeBits));
    bus_.write(regs::kRawStride, c.raw_stride);
    for (size_t p = 0; p < c.raw_base.size(); ++p) bus_.write(regs::kRawLy + 4 * uint32_t(p), c.raw_base[p]);
    bus_.write(regs::kMeshL, c.mesh_base[0]);
    bus_.write(regs::kMeshR, c.mesh_base[1]);
    bus_.write(regs::kMeshNodes, put(uint32_t(c.mesh_nx), regs::kMeshNxLsb, regs::kSizeBits) |
                                     put(uint32_t(c.mesh_ny), regs::kMeshNyLsb, regs::kSizeBits));
    bus_.write(regs::kValidL, c.valid_base[0]);
    bus_.write(regs::kValidR, c.valid_base[1]);
    const uint32_t mode = uint32_t(c.subpixel) | uint32_t(c.lr) << 1 | uint32_t(c.right) << 2;
    bus_.write(regs::kCtrl, mode << regs::kCtrlModeLsb);
  }

  // IRQ_ENABLE: the interrupt on STATUS.DONE and / or STATUS.ERROR.
  void enable_interrupts(bool done, bool error) {
    bus_.write(regs::kIrqEnable, uint32_t(done) << regs::kIrqDoneLsb | uint32_t(error) << regs::kIrqErrorLsb);
  }

  // Clears the sticky DONE and ERROR (and so the interrupt), then CTRL.START with
  // the mode CTRL holds (read-modify-write: the pulse bits read 0). Ignored by
  // the engine while it is busy.
  void start() {
    clear();
    pulse(regs::kCtrlStartLsb);
  }

  // CTRL.ABORT: a running frame ends (error code kErrAborted) once the bus is quiet.
  void abort() { pulse(regs::kCtrlAbortLsb); }

  // Write 1 to clear STATUS.DONE and STATUS.ERROR: acknowledges the interrupt.
  void clear() {
    bus_.write(regs::kStatus, 1u << regs::kStatusDoneLsb | 1u << regs::kStatusErrorLsb);
  }

  Status status() {
    const uint32_t s = bus_.read(regs::kStatus);
    Status st;
    st.busy = field(s, regs::kStatusBusyLsb, 1);
    st.done = field(s, regs::kStatusDoneLsb, 1);
    st.error = field(s, regs::kStatusErrorLsb, 1);
    st.error_code = int(field(s, regs::kStatusCodeLsb, regs::kStatusCodeWidth));
    return st;
  }

  // IRQ_STATUS: the pending interrupt causes (an interrupt handler's first read).
  bool interrupt_pending() { return bus_.read(regs::kIrqStatus) != 0; }

  // Polls STATUS until DONE, at most max_polls reads (calling idle() between two,
  // if given: a sleep, or a simulation's clock); returns the last status read.
  template <typename Idle>
  Status wait(long max_polls, Idle idle) {
    Status st = status();
    for (long n = 1; !st.done && n < max_polls; ++n) {
      idle();
      st = status();
    }
    return st;
  }
  Status wait(long max_polls) {
    return wait(max_polls, [] {});
  }

  Counters counters() {
    Counters c;
    c.cycles = bus_.read(regs::kCycles);
    c.words_read = bus_.read(regs::kWordsRead);
    c.words_written = bus_.read(regs::kWordsWritten);
    c.stalls = bus_.read(regs::kStalls);
    return c;
  }

 private:
  static uint32_t field(uint32_t v, int lsb, int width) {
    return v >> lsb & (width >= 32 ? ~0u : (1u << width) - 1);
  }
  static uint32_t put(uint32_t v, int lsb, int width) { return field(v, 0, width) << lsb; }
  void pulse(int lsb) { bus_.write(regs::kCtrl, bus_.read(regs::kCtrl) | 1u << lsb); }

  RegisterBus& bus_;
};

}  // namespace mcadsw::driver

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Driver of the MCADSW engine (rtl/mcadsw_top.sv) for firmware, the simulation
// harness and the tests alike: configure a frame from a plain struct, start it,
// wait for it (poll STATUS, or take the interrupt and read it), read the status
// and counters, decode error codes. Built on the C header mcadsw/mcadsw_regs.h, the
// register map C firmware uses too (generated from sw_ref/include/mcadsw/regs.hpp,
// docs/registers.md); the meaning of each value docs/memory_map.md.
//
// A platform gives register access through two functions, RegisterBus::read and
// ::write, of 32-bit registers at byte offsets from the block's base: the Verilator
// harness over its AXI4-Lite bus functional model, a Linux program over an mmap of
// /dev/uioN or /dev/mem (driver/examples/mcadsw_uio.cpp), a bare-metal one over a
// volatile pointer. Header-only, C++17, no allocation, no exceptions of its own; it
// needs only this directory (driver/include).
#pragma once

#include <array>
#include <cstdint>

#include "mcadsw/mcadsw_regs.h"

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
  int lr_tolerance = MCADSW_LR_T_DEFAULT;  // T, 0 .. MCADSW_LR_T_MAX
  // The weight table as its thresholds (docs/algorithm.md; mcadsw::weight_thresholds()).
  std::array<uint32_t, MCADSW_WEIGHT_THRESHOLDS> thresholds{};
  // Rectification (register map 1.2; docs/blocks/rectifier.md, docs/algorithm.md 13):
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
  std::array<uint32_t, MCADSW_RAW_PLANES> raw_base{};    // raw planes LY LU LV RY RU RV (the planes the mode reads)
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
    return id == MCADSW_ID_MAGIC && version_major == int(MCADSW_MAP_VERSION_MAJOR) &&
           version_minor >= int(MCADSW_MAP_VERSION_MINOR);
  }
};

struct Status {
  bool busy = false;
  bool done = false;          // a frame finished or was rejected since start()
  bool error = false;         // ... rejected, or ended by a bus error or an abort
  int error_code = 0;         // enum mcadsw_error; error_text() below
};

struct Counters {
  uint32_t cycles = 0, words_read = 0, words_written = 0, stalls = 0;
};

// The text of an error code, for messages.
inline const char* error_text(int code) { return mcadsw_error_text(uint32_t(code)); }

class Engine {
 public:
  explicit Engine(RegisterBus& bus) : bus_(bus) {}

  Identity identify() {
    Identity i;
    i.id = bus_.read(MCADSW_REG_ID);
    const uint32_t v = bus_.read(MCADSW_REG_VERSION);
    i.version_major = int(MCADSW_GET(v, VERSION_MAJOR));
    i.version_minor = int(MCADSW_GET(v, VERSION_MINOR));
    const uint32_t hw = bus_.read(MCADSW_REG_HWCONFIG);
    i.dmax = int(MCADSW_GET(hw, HWCONFIG_DMAX));
    i.par = int(MCADSW_GET(hw, HWCONFIG_PAR));
    i.rect = MCADSW_GET(hw, HWCONFIG_NORECT) == 0;
    return i;
  }

  // Writes every configuration register and the mode; the frame starts with start().
  void configure(const FrameConfig& c) {
    bus_.write(MCADSW_REG_BASE_LY, c.base_ly);
    bus_.write(MCADSW_REG_BASE_LU, c.base_lu);
    bus_.write(MCADSW_REG_BASE_LV, c.base_lv);
    bus_.write(MCADSW_REG_BASE_RY, c.base_ry);
    bus_.write(MCADSW_REG_BASE_RU, c.base_ru);
    bus_.write(MCADSW_REG_BASE_RV, c.base_rv);
    bus_.write(MCADSW_REG_BASE_OUT, c.base_out);
    bus_.write(MCADSW_REG_BASE_DL, c.base_dl);
    bus_.write(MCADSW_REG_BASE_DR, c.base_dr);
    bus_.write(MCADSW_REG_BASE_MASK, c.base_mask);
    bus_.write(MCADSW_REG_STRIDE, c.stride);
    bus_.write(MCADSW_REG_OUT_STRIDE, c.out_stride);
    bus_.write(MCADSW_REG_TILE_STRIDE, c.tile_stride);
    bus_.write(MCADSW_REG_SIZE,
               MCADSW_PUT(uint32_t(c.width), SIZE_WIDTH) | MCADSW_PUT(uint32_t(c.height), SIZE_HEIGHT));
    bus_.write(MCADSW_REG_DISP, MCADSW_PUT(uint32_t(c.disparities), DISP_D));
    bus_.write(MCADSW_REG_LR_T, MCADSW_PUT(uint32_t(c.lr_tolerance), LR_T_T));
    for (int i = 0; i < MCADSW_WEIGHT_THRESHOLDS; ++i)
      bus_.write(MCADSW_REG_THR0 + 4 * uint32_t(i), mcadsw_put(c.thresholds[size_t(i)], 0, MCADSW_THR_BITS));
    bus_.write(MCADSW_REG_RECT_CTRL,
               MCADSW_PUT(uint32_t(c.rect), RECT_CTRL_ENABLE) |
                   MCADSW_PUT(uint32_t(c.rect_step_log2), RECT_CTRL_STEP_LOG2));
    bus_.write(MCADSW_REG_RAW_SIZE,
               MCADSW_PUT(uint32_t(c.raw_width), RAW_SIZE_WIDTH) | MCADSW_PUT(uint32_t(c.raw_height), RAW_SIZE_HEIGHT));
    bus_.write(MCADSW_REG_RAW_STRIDE, c.raw_stride);
    for (size_t p = 0; p < c.raw_base.size(); ++p) bus_.write(MCADSW_REG_RAW_LY + 4 * uint32_t(p), c.raw_base[p]);
    bus_.write(MCADSW_REG_MESH_L, c.mesh_base[0]);
    bus_.write(MCADSW_REG_MESH_R, c.mesh_base[1]);
    bus_.write(MCADSW_REG_MESH_NODES,
               MCADSW_PUT(uint32_t(c.mesh_nx), MESH_NODES_NX) | MCADSW_PUT(uint32_t(c.mesh_ny), MESH_NODES_NY));
    bus_.write(MCADSW_REG_VALID_L, c.valid_base[0]);
    bus_.write(MCADSW_REG_VALID_R, c.valid_base[1]);
    const uint32_t mode = uint32_t(c.subpixel) << MCADSW_MODE_SUBPIXEL_BIT | uint32_t(c.lr) << MCADSW_MODE_LR_BIT |
                          uint32_t(c.right) << MCADSW_MODE_RIGHT_BIT;
    bus_.write(MCADSW_REG_CTRL, MCADSW_PUT(mode, CTRL_MODE));
  }

  // IRQ_ENABLE: the interrupt on STATUS.DONE and / or STATUS.ERROR.
  void enable_interrupts(bool done, bool error) {
    bus_.write(MCADSW_REG_IRQ_ENABLE,
               MCADSW_PUT(uint32_t(done), IRQ_ENABLE_DONE) | MCADSW_PUT(uint32_t(error), IRQ_ENABLE_ERROR));
  }

  // Clears the sticky DONE and ERROR (and so the interrupt), then CTRL.START with
  // the mode CTRL holds (read-modify-write: the pulse bits read 0). Ignored by
  // the engine while it is busy.
  void start() {
    clear();
    pulse(MCADSW_CTRL_START_MASK);
  }

  // CTRL.ABORT: a running frame ends (MCADSW_ERR_ABORTED) once the bus is quiet.
  void abort() { pulse(MCADSW_CTRL_ABORT_MASK); }

  // Write 1 to clear STATUS.DONE and STATUS.ERROR: acknowledges the interrupt.
  void clear() {
    bus_.write(MCADSW_REG_STATUS, MCADSW_STATUS_DONE_MASK | MCADSW_STATUS_ERROR_MASK);
  }

  Status status() {
    const uint32_t s = bus_.read(MCADSW_REG_STATUS);
    Status st;
    st.busy = MCADSW_GET(s, STATUS_BUSY);
    st.done = MCADSW_GET(s, STATUS_DONE);
    st.error = MCADSW_GET(s, STATUS_ERROR);
    st.error_code = int(MCADSW_GET(s, STATUS_ERROR_CODE));
    return st;
  }

  // IRQ_STATUS: the pending interrupt causes (an interrupt handler's first read).
  bool interrupt_pending() { return bus_.read(MCADSW_REG_IRQ_STATUS) != 0; }

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
    c.cycles = bus_.read(MCADSW_REG_CYCLES);
    c.words_read = bus_.read(MCADSW_REG_WORDS_READ);
    c.words_written = bus_.read(MCADSW_REG_WORDS_WRITTEN);
    c.stalls = bus_.read(MCADSW_REG_STALLS);
    return c;
  }

 private:
  // CTRL with a pulse bit (START or ABORT) set: read-modify-write, the pulse bits read 0.
  void pulse(uint32_t bit) { bus_.write(MCADSW_REG_CTRL, bus_.read(MCADSW_REG_CTRL) | bit); }

  RegisterBus& bus_;
};

}  // namespace mcadsw::driver

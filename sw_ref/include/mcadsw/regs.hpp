// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Register map of the engine's AXI4-Lite slave: the single source of
// truth. rtl/mcadsw_pkg.sv (offsets, field positions and error codes for the
// RTL) and docs/registers.md are generated from this file by
// build/bin/gen_rtl_pkg (`make rtl-pkg`); tests fail when either is stale. A
// driver includes this header for the offsets and fields.
//
// 32-bit registers at word-aligned byte offsets. Reads of an unmapped offset
// return 0 with SLVERR, writes to one are dropped with SLVERR; writes to
// read-only registers are dropped with OKAY. WSTRB is honoured byte by byte.
#pragma once

#include <cstdint>

#include "mcadsw/params.hpp"  // kColorDistBits

namespace mcadsw::regs {

enum class Access { kRO, kRW, kW1C, kWO };  // kWO: write-only pulse, reads 0

struct Reg {
  const char* name;
  uint32_t offset;
  Access access;
  const char* doc;
};

struct Field {
  const char* reg;
  const char* name;
  int lsb;
  int width;
  Access access;
  const char* doc;
};

// ---- Offsets ---------------------------------------------------------------------------
inline constexpr uint32_t kId = 0x00;
inline constexpr uint32_t kVersion = 0x04;
inline constexpr uint32_t kHwConfig = 0x08;
inline constexpr uint32_t kCtrl = 0x10;
inline constexpr uint32_t kStatus = 0x14;
inline constexpr uint32_t kIrqEnable = 0x18;
inline constexpr uint32_t kIrqStatus = 0x1C;
inline constexpr uint32_t kBaseLy = 0x20;
inline constexpr uint32_t kBaseLu = 0x24;
inline constexpr uint32_t kBaseLv = 0x28;
inline constexpr uint32_t kBaseRy = 0x2C;
inline constexpr uint32_t kBaseRu = 0x30;
inline constexpr uint32_t kBaseRv = 0x34;
inline constexpr uint32_t kBaseOut = 0x38;
inline constexpr uint32_t kBaseDl = 0x3C;
inline constexpr uint32_t kBaseDr = 0x40;
inline constexpr uint32_t kBaseMask = 0x44;
inline constexpr uint32_t kStride = 0x48;
inline constexpr uint32_t kOutStride = 0x4C;
inline constexpr uint32_t kSize = 0x50;
inline constexpr uint32_t kDisp = 0x54;
inline constexpr uint32_t kLrT = 0x58;
inline constexpr uint32_t kTileStride = 0x5C;
inline constexpr uint32_t kThr0 = 0x60;  // THR0 .. THR6 at kThr0 + 4 i
inline constexpr uint32_t kCycles = 0x80;
inline constexpr uint32_t kWordsRead = 0x84;
inline constexpr uint32_t kWordsWritten = 0x88;
inline constexpr uint32_t kStalls = 0x8C;
// Rectification (register map 1.2, docs/blocks/rectifier.md 2, docs/algorithm.md 13)
inline constexpr uint32_t kRectCtrl = 0x90;
inline constexpr uint32_t kRawSize = 0x94;
inline constexpr uint32_t kRawStride = 0x98;
inline constexpr uint32_t kRawLy = 0x9C;  // RAW_LY .. RAW_RV at kRawLy + 4 p
inline constexpr uint32_t kMeshL = 0xB4;
inline constexpr uint32_t kMeshR = 0xB8;
inline constexpr uint32_t kMeshNodes = 0xBC;
inline constexpr uint32_t kValidL = 0xC0;
inline constexpr uint32_t kValidR = 0xC4;
inline constexpr uint32_t kSpan = 0x100;  // address bits decoded: offsets 0 .. kSpan - 4

// ---- Constants read from ID and VERSION ---------------------------------------------------
inline constexpr uint32_t kIdValue = 0x4D434144;  // "MCAD"
inline constexpr uint32_t kVersionMajor = 1;
inline constexpr uint32_t kVersionMinor = 3;  // 1: TILE_STRIDE; 2: rectification; 3: HWCONFIG.NORECT

// ---- Fields (lsb, width) ---------------------------------------------------------------
inline constexpr int kVersionMinorLsb = 0, kVersionMajorLsb = 8;
inline constexpr int kHwConfigDmaxLsb = 0, kHwConfigParLsb = 8, kHwConfigNoRectLsb = 12;
inline constexpr int kCtrlStartLsb = 0;
inline constexpr int kCtrlAbortLsb = 1;
inline constexpr int kCtrlModeLsb = 8, kCtrlModeWidth = 3;
// CTRL.MODE's bits (docs/memory_map.md); LR and right view as base not together (code 8).
inline constexpr int kModeSubpixelBit = 0, kModeLrBit = 1, kModeRightBit = 2;
inline constexpr int kStatusBusyLsb = 0;
inline constexpr int kStatusDoneLsb = 1;
inline constexpr int kStatusErrorLsb = 2;
inline constexpr int kStatusCodeLsb = 4, kStatusCodeWidth = 8;
inline constexpr int kIrqDoneLsb = 0;
inline constexpr int kIrqErrorLsb = 1;
inline constexpr int kSizeWidthLsb = 0, kSizeHeightLsb = 16, kSizeBits = 12;
inline constexpr int kDispBitsReg = 8;  // D, whatever DMAX (<= 128); D > DMAX is error code 3
inline constexpr int kLrTBits = 8;
inline constexpr int kRectEnableLsb = 0;
inline constexpr int kRectStepLsb = 4, kRectStepWidth = 3;
inline constexpr int kMeshNxLsb = 0, kMeshNyLsb = 16;  // 12 bits each (kSizeBits), as SIZE
inline constexpr int kThrBits = kColorDistBits;

// ---- Error codes (STATUS.ERROR_CODE) ---------------------------------------------------------
// The single source of the codes: gen_rtl_pkg makes them the RTL package's enum
// (mcadsw_pkg::err_e, ErrWidth ...) and the table in docs/registers.md; a driver
// decodes STATUS.ERROR_CODE with error_text(). 1..12: a start rejected by the
// engine's configuration check (rtl/mcadsw_cfg_check.sv), checked in this order,
// nothing read or written; 13..15: a frame ended early by mcadsw_top.
struct Error {
  int code;
  const char* name;  // the enum constant's name after "Err" (UpperCamelCase)
  const char* doc;
};
inline constexpr int kErrCodeBits = 5;  // the codes the RTL carries (STATUS.ERROR_CODE: 8 bits)
inline constexpr int kErrReadResponse = 13;   // an AXI4 read answered SLVERR or DECERR
inline constexpr int kErrWriteResponse = 14;  // an AXI4 write answered SLVERR or DECERR
inline constexpr int kErrAborted = 15;        // CTRL.ABORT written while busy
inline constexpr Error kErrors[] = {
    {0, "None", "accepted, and the frame finished"},
    {1, "Width", "width 0 or above 2048"},
    {2, "Height", "height 0 or above 2048"},
    {3, "Disp", "D = 0 or above DMAX (64 by default; a build parameter up to 128)"},
    {4, "Stride",
     "input stride below the width, or not a multiple of 4 (raster input planes, or the LR "
     "mode); tile stride (when not 0) below 4 x height, or not a multiple of 4"},
    {5, "Align", "a base address not a multiple of 4 (the planes the mode reads and writes)"},
    {6, "Overlap",
     "a plane the mode writes overlaps a plane it reads or another plane it writes (the "
     "disparity plane and, in the LR mode, dL: out_stride x height bytes; input planes, dR and "
     "the mask: stride x height bytes)"},
    {7, "OutStride",
     "output stride below the output row (width bytes; 2 x width in sub-pixel mode), or not a "
     "multiple of 4"},
    {8, "Mode", "mode bits 1 (LR) and 2 (right view as base) both set"},
    {9, "Beyond",
     "a plane the mode reads or writes reaches beyond the 32-bit address space (base + stride x "
     "height > 2^32)"},
    {10, "LrTolerance", "LR mode: T above 63"},
    {11, "LrWidth", "LR mode: width above 1024 (the post stage's row buffers)"},
    {12, "LrColour",
     "LR mode: the right U or V plane not configured: its base equals the other's or that of "
     "the left Y, U, V or right Y plane (registers left at their reset value or copied)"},
    {kErrReadResponse, "ReadResponse", "the frame ended: an AXI4 read was answered SLVERR or DECERR"},
    {kErrWriteResponse, "WriteResponse",
     "the frame ended: an AXI4 write burst was answered SLVERR or DECERR"},
    {kErrAborted, "Aborted", "the frame ended: CTRL.ABORT was written while busy"},
    // 16..21: RECT_CTRL.ENABLE set, checked after 1..12 (rtl/rect/mcadsw_rect_check.sv),
    // nothing read or written; 22, 23: found by the rectify pass's check phase (nodes
    // read), nothing written.
    {16, "RectStep", "rectification: RECT_CTRL.STEP_LOG2 not 3, 4 or 5 (S = 8, 16, 32)"},
    {17, "RawSize",
     "rectification: raw width or height 0 or above 2048; RAW_STRIDE below the raw width "
     "(raster) or 4 x the raw height (column-tiled), or not a multiple of 4"},
    {18, "MeshSize",
     "rectification: MESH_NODES not ((W - 1) >> s) + 2 by ((H - 1) >> s) + 2 for the frame's W x H"},
    {19, "RectAlign", "rectification: a raw plane, mesh or validity bitmap base not a multiple of 4"},
    {20, "RectOverlap",
     "rectification: a raw plane or mesh overlaps a plane the frame writes (rectified planes, "
     "bitmaps, outputs), or a bitmap overlaps another plane the frame reads or writes"},
    {21, "RectBeyond", "rectification: a raw plane, mesh or bitmap reaches beyond the 32-bit address space"},
    {22, "MeshRange", "rectification: a mesh node beyond -4096 .. 4096 pixels; nothing written"},
    {23, "RectFootprint",
     "rectification: a tile's source rectangle beyond the 64 x 32 tile buffer (docs/algorithm.md "
     "13.8); nothing written"},
    // 24: checked with 1..12, after them (rtl/mcadsw_cfg_check.sv); nothing read or written.
    {24, "NoRect", "RECT_CTRL.ENABLE set in a build without the rectifier (HWCONFIG.NORECT 1)"},
};

// The text of an error code (STATUS.ERROR_CODE), for messages.
constexpr const char* error_text(int code) {
  for (const Error& e : kErrors)
    if (e.code == code) return e.doc;
  return "unknown error code";
}

// Codes 0 .. n - 1 each once, in order, in kErrCodeBits, which STATUS.ERROR_CODE holds.
constexpr bool errors_valid() {
  const int n = int(sizeof(kErrors) / sizeof(kErrors[0]));
  for (int i = 0; i < n; ++i)
    if (kErrors[i].code != i) return false;
  return n <= (1 << kErrCodeBits) && n > (1 << (kErrCodeBits - 1)) && kErrCodeBits <= kStatusCodeWidth;
}
inline constexpr int kErrCount = int(sizeof(kErrors) / sizeof(kErrors[0]));
static_assert(errors_valid(), "error codes must be 0 .. n - 1, each once, in order, in kErrCodeBits");

inline constexpr Reg kRegs[] = {
    {"ID", kId, Access::kRO, "identification, \"MCAD\""},
    {"VERSION", kVersion, Access::kRO, "register map version"},
    {"HWCONFIG", kHwConfig, Access::kRO, "build parameters"},
    {"CTRL", kCtrl, Access::kRW, "start, abort and output mode"},
    {"STATUS", kStatus, Access::kRW, "busy, sticky done and error (write 1 to clear), error code"},
    {"IRQ_ENABLE", kIrqEnable, Access::kRW, "interrupt enables"},
    {"IRQ_STATUS", kIrqStatus, Access::kRO, "pending interrupts: STATUS sticky bits and IRQ_ENABLE"},
    {"BASE_LY", kBaseLy, Access::kRW, "byte address of the left Y plane"},
    {"BASE_LU", kBaseLu, Access::kRW, "left U plane"},
    {"BASE_LV", kBaseLv, Access::kRW, "left V plane"},
    {"BASE_RY", kBaseRy, Access::kRW, "right Y plane"},
    {"BASE_RU", kBaseRu, Access::kRW, "right U plane (right view as base, or LR)"},
    {"BASE_RV", kBaseRv, Access::kRW, "right V plane (idem)"},
    {"BASE_OUT", kBaseOut, Access::kRW, "disparity plane"},
    {"BASE_DL", kBaseDl, Access::kRW, "LR: scratch plane of the left map"},
    {"BASE_DR", kBaseDr, Access::kRW, "LR: scratch plane of the right map"},
    {"BASE_MASK", kBaseMask, Access::kRW, "LR: validity mask plane"},
    {"STRIDE", kStride, Access::kRW, "bytes per row of the input planes"},
    {"OUT_STRIDE", kOutStride, Access::kRW, "bytes per row of the disparity plane"},
    {"SIZE", kSize, Access::kRW, "image width and height"},
    {"DISP", kDisp, Access::kRW, "D, the disparities searched"},
    {"LR_T", kLrT, Access::kRW, "LR: check tolerance T"},
    {"TILE_STRIDE", kTileStride, Access::kRW,
     "input planes column-tiled: bytes from one 4-pixel column to the next; 0: raster"},
    {"THR0", kThr0 + 0, Access::kRW, "weight table threshold 0"},
    {"THR1", kThr0 + 4, Access::kRW, "threshold 1"},
    {"THR2", kThr0 + 8, Access::kRW, "threshold 2"},
    {"THR3", kThr0 + 12, Access::kRW, "threshold 3"},
    {"THR4", kThr0 + 16, Access::kRW, "threshold 4"},
    {"THR5", kThr0 + 20, Access::kRW, "threshold 5"},
    {"THR6", kThr0 + 24, Access::kRW, "threshold 6"},
    {"CYCLES", kCycles, Access::kRO, "cycles of the last frame"},
    {"WORDS_READ", kWordsRead, Access::kRO, "memory words read in the last frame"},
    {"WORDS_WRITTEN", kWordsWritten, Access::kRO, "memory words written in the last frame"},
    {"STALLS", kStalls, Access::kRO, "cycles with a memory request not granted"},
    {"RECT_CTRL", kRectCtrl, Access::kRW, "rectification: enable and mesh step"},
    {"RAW_SIZE", kRawSize, Access::kRW, "rectification: raw views' width and height"},
    {"RAW_STRIDE", kRawStride, Access::kRW,
     "rectification: bytes a row of the raw planes; with TILE_STRIDE not 0, bytes from one 4-pixel column to the next"},
    {"RAW_LY", kRawLy + 0, Access::kRW, "rectification: raw left Y plane"},
    {"RAW_LU", kRawLy + 4, Access::kRW, "rectification: raw left U plane"},
    {"RAW_LV", kRawLy + 8, Access::kRW, "rectification: raw left V plane"},
    {"RAW_RY", kRawLy + 12, Access::kRW, "rectification: raw right Y plane"},
    {"RAW_RU", kRawLy + 16, Access::kRW, "rectification: raw right U plane (right view as base)"},
    {"RAW_RV", kRawLy + 20, Access::kRW, "rectification: raw right V plane (idem)"},
    {"MESH_L", kMeshL, Access::kRW, "rectification: the left view's mesh (docs/algorithm.md 13.1)"},
    {"MESH_R", kMeshR, Access::kRW, "rectification: the right view's mesh"},
    {"MESH_NODES", kMeshNodes, Access::kRW, "rectification: mesh nodes a row and a column"},
    {"VALID_L", kValidL, Access::kRW, "rectification: the left view's validity bitmap (written)"},
    {"VALID_R", kValidR, Access::kRW, "rectification: the right view's validity bitmap (written)"},
};

inline constexpr Field kFields[] = {
    {"ID", "VALUE", 0, 32, Access::kRO, "0x4D434144"},
    {"VERSION", "MINOR", kVersionMinorLsb, 8, Access::kRO, "minor version"},
    {"VERSION", "MAJOR", kVersionMajorLsb, 8, Access::kRO, "major version"},
    {"HWCONFIG", "DMAX", kHwConfigDmaxLsb, 8, Access::kRO, "largest D of this build"},
    {"HWCONFIG", "PAR", kHwConfigParLsb, 4, Access::kRO, "disparities a step of this build"},
    {"HWCONFIG", "NORECT", kHwConfigNoRectLsb, 1, Access::kRO,
     "1: this build has no rectifier (RECT_CTRL.ENABLE is rejected with code 24)"},
    {"CTRL", "START", kCtrlStartLsb, 1, Access::kWO,
     "write 1: start a frame with the registers as they are after this write; ignored while "
     "busy; reads 0"},
    {"CTRL", "ABORT", kCtrlAbortLsb, 1, Access::kWO,
     "write 1: end the running frame; the memory transactions in flight are completed, "
     "then DONE and ERROR with code 15; ignored while idle; reads 0"},
    {"CTRL", "MODE", kCtrlModeLsb, kCtrlModeWidth, Access::kRW,
     "bit 0 sub-pixel, bit 1 LR, bit 2 right view as base (docs/memory_map.md)"},
    {"STATUS", "BUSY", kStatusBusyLsb, 1, Access::kRO, "a frame is running"},
    {"STATUS", "DONE", kStatusDoneLsb, 1, Access::kW1C,
     "a frame finished or was rejected since the bit was cleared"},
    {"STATUS", "ERROR", kStatusErrorLsb, 1, Access::kW1C,
     "a start was rejected, or a frame ended by a bus error or an abort, since the bit was "
     "cleared"},
    {"STATUS", "ERROR_CODE", kStatusCodeLsb, kStatusCodeWidth, Access::kRO,
     "error code of the last frame (0: accepted and finished; docs/memory_map.md)"},
    {"IRQ_ENABLE", "DONE", kIrqDoneLsb, 1, Access::kRW, "interrupt on STATUS.DONE"},
    {"IRQ_ENABLE", "ERROR", kIrqErrorLsb, 1, Access::kRW, "interrupt on STATUS.ERROR"},
    {"IRQ_STATUS", "DONE", kIrqDoneLsb, 1, Access::kRO, "STATUS.DONE and IRQ_ENABLE.DONE"},
    {"IRQ_STATUS", "ERROR", kIrqErrorLsb, 1, Access::kRO, "STATUS.ERROR and IRQ_ENABLE.ERROR"},
    {"SIZE", "WIDTH", kSizeWidthLsb, kSizeBits, Access::kRW, "width in pixels"},
    {"SIZE", "HEIGHT", kSizeHeightLsb, kSizeBits, Access::kRW, "height in pixels"},
    {"DISP", "D", 0, kDispBitsReg, Access::kRW, "1 .. DMAX"},
    {"LR_T", "T", 0, kLrTBits, Access::kRW, "0 .. 63"},
    {"RECT_CTRL", "ENABLE", kRectEnableLsb, 1, Access::kRW,
     "rectify the raw planes before matching (docs/blocks/rectifier.md)"},
    {"RECT_CTRL", "STEP_LOG2", kRectStepLsb, kRectStepWidth, Access::kRW, "mesh step S = 2^STEP_LOG2: 3, 4 or 5"},
    {"RAW_SIZE", "WIDTH", kSizeWidthLsb, kSizeBits, Access::kRW, "raw width in pixels"},
    {"RAW_SIZE", "HEIGHT", kSizeHeightLsb, kSizeBits, Access::kRW, "raw height in pixels"},
    {"MESH_NODES", "NX", kMeshNxLsb, kSizeBits, Access::kRW, "nodes a row: ((W - 1) >> STEP_LOG2) + 2"},
    {"MESH_NODES", "NY", kMeshNyLsb, kSizeBits, Access::kRW, "nodes a column: ((H - 1) >> STEP_LOG2) + 2"},
};

// ---- The engine's configuration bundle ------------------------------------------------------
// What the register block hands the engine core (mcadsw_regs's cfg_o, mcadsw_engine's cfg_i)
// as one vector: the fields below in this order from bit 0, each width bits wide. gen_rtl_pkg
// makes them the package's CFG_<NAME> (the field's lowest bit) and CFG_<NAME>_W, and
// CFG_BITS (Icarus 11 takes no packed struct of a package at a port: docs/tool_notes.md 1); a
// harness driving the engine core sets them with cfg_lsb(). A new configuration register is
// a row here, its storage in mcadsw_regs, and its use in the block that reads it.
enum class Cfg {
  kBaseLy, kBaseLu, kBaseLv, kBaseRy, kBaseRu, kBaseRv, kBaseOut, kBaseDl, kBaseDr, kBaseMask,
  kStride, kOutStride, kTileStride, kMode, kLrT, kWidth, kHeight, kDisp, kThr,
  kRectEn, kRectStep, kRawWidth, kRawHeight, kRawStride, kRaw, kMesh, kMeshNx, kMeshNy, kValid,
  kCount
};
struct CfgField {
  Cfg id;
  const char* name;  // the package's CFG_<name>
  int width;
  const char* doc;   // the register field it holds
};
inline constexpr CfgField kCfgFields[] = {
    {Cfg::kBaseLy, "BASE_LY", 32, "BASE_LY"},
    {Cfg::kBaseLu, "BASE_LU", 32, "BASE_LU"},
    {Cfg::kBaseLv, "BASE_LV", 32, "BASE_LV"},
    {Cfg::kBaseRy, "BASE_RY", 32, "BASE_RY"},
    {Cfg::kBaseRu, "BASE_RU", 32, "BASE_RU"},
    {Cfg::kBaseRv, "BASE_RV", 32, "BASE_RV"},
    {Cfg::kBaseOut, "BASE_OUT", 32, "BASE_OUT"},
    {Cfg::kBaseDl, "BASE_DL", 32, "BASE_DL"},
    {Cfg::kBaseDr, "BASE_DR", 32, "BASE_DR"},
    {Cfg::kBaseMask, "BASE_MASK", 32, "BASE_MASK"},
    {Cfg::kStride, "STRIDE", 32, "STRIDE"},
    {Cfg::kOutStride, "OUT_STRIDE", 32, "OUT_STRIDE"},
    {Cfg::kTileStride, "TILE_STRIDE", 32, "TILE_STRIDE (0: raster input planes)"},
    {Cfg::kMode, "MODE", kCtrlModeWidth, "CTRL.MODE: bit 0 sub-pixel, bit 1 LR, bit 2 right view as base"},
    {Cfg::kLrT, "LR_T", kLrTBits, "LR_T.T"},
    {Cfg::kWidth, "WIDTH", kSizeBits, "SIZE.WIDTH"},
    {Cfg::kHeight, "HEIGHT", kSizeBits, "SIZE.HEIGHT"},
    {Cfg::kDisp, "DISP", kDispBitsReg, "DISP.D; 0 (error code 3) when above DMAX"},
    {Cfg::kThr, "THR", kWeightThresholds * kThrBits, "THR0 .. THR6, THR i at bit kThrBits x i"},
    {Cfg::kRectEn, "RECT_EN", 1, "RECT_CTRL.ENABLE"},
    {Cfg::kRectStep, "RECT_STEP", kRectStepWidth, "RECT_CTRL.STEP_LOG2"},
    {Cfg::kRawWidth, "RAW_WIDTH", kSizeBits, "RAW_SIZE.WIDTH"},
    {Cfg::kRawHeight, "RAW_HEIGHT", kSizeBits, "RAW_SIZE.HEIGHT"},
    {Cfg::kRawStride, "RAW_STRIDE", 32, "RAW_STRIDE"},
    {Cfg::kRaw, "RAW", 6 * 32, "RAW_LY .. RAW_RV, plane p at bit 32 p"},
    {Cfg::kMesh, "MESH", 2 * 32, "MESH_L (bit 0), MESH_R (bit 32)"},
    {Cfg::kMeshNx, "MESH_NX", kSizeBits, "MESH_NODES.NX"},
    {Cfg::kMeshNy, "MESH_NY", kSizeBits, "MESH_NODES.NY"},
    {Cfg::kValid, "VALID_MAP", 2 * 32, "VALID_L (bit 0), VALID_R (bit 32)"},
};
inline constexpr int kCfgCount = int(sizeof(kCfgFields) / sizeof(kCfgFields[0]));
static_assert(kCfgCount == int(Cfg::kCount), "one kCfgFields row for each Cfg");

// The lowest bit of field F in the bundle; kCfgBits its width.
constexpr int cfg_lsb(Cfg f) {
  int lsb = 0;
  for (int i = 0; i < int(f); ++i) lsb += kCfgFields[i].width;
  return lsb;
}
constexpr int cfg_width(Cfg f) { return kCfgFields[int(f)].width; }
inline constexpr int kCfgBits = cfg_lsb(Cfg::kCount);

// The rows in Cfg's order.
constexpr bool cfg_valid() {
  for (int i = 0; i < kCfgCount; ++i)
    if (int(kCfgFields[i].id) != i || kCfgFields[i].width <= 0) return false;
  return true;
}
static_assert(cfg_valid(), "kCfgFields rows in Cfg's order, each at least a bit wide");

// Every offset word-aligned, inside the decoded span, and unique.
constexpr bool offsets_valid() {
  const int n = int(sizeof(kRegs) / sizeof(kRegs[0]));
  for (int i = 0; i < n; ++i) {
    if (kRegs[i].offset % 4 != 0 || kRegs[i].offset >= kSpan) return false;
    for (int j = i + 1; j < n; ++j)
      if (kRegs[i].offset == kRegs[j].offset) return false;
  }
  return true;
}
static_assert(offsets_valid(), "register offsets must be aligned, in the span and unique");

}  // namespace mcadsw::regs

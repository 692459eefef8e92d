// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The frame as the bench lays it out in the memory model, loads it and reads the
// engine's output back (sim/engine_bench.cpp's run_engine and run_frames).
#pragma once

#include <array>
#include <cstdint>

#include "engine_bench.hpp"
#include "memory_model.hpp"
#include "mcadsw/driver.hpp"
#include "mcadsw/ref.hpp"

namespace mcadsw::sim::bench {

// Memory layout of a frame (docs/memory_map.md): six input planes (left Y, U,
// V, right Y, U, V) of stride bytes per row (default: the width rounded up to
// 4) and the output plane of out_stride bytes per row (default: its row, 1 or
// 2 bytes a pixel, rounded up to 4), each starting on a 4 KiB boundary after a
// 4 KiB guard, from FrameOptions::origin (FrameOptions::packed: each plane
// at the first multiple of 4 after the previous one's stride x height bytes).
// The right view's U and V are always in memory; only the right and LR modes
// may read them. The LR mode adds, after the output plane, the scratch planes
// dL (output stride) and dR (input stride) and the mask plane (input stride).
// Tiled (FrameOptions::tiled), the six input planes are column-tiled, tile
// bytes a column of 4 pixels (default 4 x height); dR and the mask keep the
// raster stride. Sizes are computed in 64 bits: a layout that does not fit
// below 2^32 is refused.
// Rectification (FrameOptions::rect): the six planes above are the rectified
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
  Layout(int in_w, int in_h, uint64_t origin_at, const EngineOptions& opt);
  // The meshes and raw views of a rectified frame: checked, and their geometry.
  void rect_geometry(int raw_w, int raw_h, const EngineOptions& opt);
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
  RawConfig raw_config(int disparities) const;
  // What the frame may touch: reads in the pixels of the planes its mode
  // reads, writes in the output plane's pixels (LR: and the scratch and mask
  // planes' pixels, the scratch planes read back).
  // Rectification (rect_regions): the raw planes and meshes read, the rectified
  // planes and bitmaps written, then read.
  // With rectification in the LR mode (right_valid: the right view's validity), dL and
  // the output are written twice at invalid left pixels, dR at invalid right pixels.
  MemoryModel::Regions regions(const Plane* base_valid = nullptr, const Plane* right_valid = nullptr) const;
  // The planes the mode reads are now the rectified ones (written first); the
  // output pixels of invalid base pixels (base_valid 0) written twice (the mark step).
  void rect_regions(MemoryModel::Regions& r, const Plane* base_valid) const;
};

// An input plane, raster (stride bytes a row) or column-tiled (tile != 0).
void put_plane(MemoryModel& m, uint32_t base, uint32_t stride, uint32_t tile, const Plane& p);
// The pixels of a w x h plane, raster or column-tiled, set to v.
void fill_plane(MemoryModel& m, uint32_t base, uint32_t stride, uint32_t tile, int w, int h, uint8_t v);

// Writes a frame's planes at its layout (with rectification the raw views, the meshes'
// memory images, and 0xa5 in the pixels of the rectified planes and bitmaps) and fills the
// pixels of its disparity plane with 0xff ("never written"; LR: dL and dR too, the mask
// with 0x77).
void load_frame(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right,
                const EngineOptions& opt);

// Byte x of row y of a plane.
uint8_t& at(MemoryModel& mem, uint32_t base, uint32_t stride, int x, int y);
// Pixel (x, y) of the output plane: a byte, or in sub-pixel mode a
// little-endian halfword.
int out_pixel(MemoryModel& mem, const Layout& lay, int x, int y);

// The harness's configuration as the driver's (docs/registers.md).
driver::FrameConfig frame_config(const RawConfig& c, const WeightTable& table);

}  // namespace mcadsw::sim::bench

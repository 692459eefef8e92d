// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "frame_layout.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "mcadsw/regs.hpp"

namespace mcadsw::sim::bench {

Layout::Layout(int in_w, int in_h, uint64_t origin_at, const EngineOptions& opt)
    : origin(origin_at), width(opt.frame.rect ? opt.frame.rect->left.out_width : in_w),
      height(opt.frame.rect ? opt.frame.rect->left.out_height : in_h), out_bpp(opt.frame.subpixel ? 2 : 1),
      lr_t(opt.frame.lr_tolerance), right(opt.frame.right), lr(opt.frame.lr) {
  const int w = width, h = height;
  if (opt.frame.rect) rect_geometry(in_w, in_h, opt);
  stride = opt.frame.stride ? opt.frame.stride : uint32_t((w + 3) / 4 * 4);
  if (stride < uint32_t(w) || stride % 4 != 0)
    throw std::invalid_argument("stride " + std::to_string(stride) +
                                " must be a multiple of 4 and at least the width " + std::to_string(w));
  const uint32_t row = uint32_t(w * out_bpp);
  out_stride = opt.frame.out_stride ? opt.frame.out_stride : (row + 3) / 4 * 4;
  if (out_stride < row || out_stride % 4 != 0)
    throw std::invalid_argument("output stride " + std::to_string(out_stride) +
                                " must be a multiple of 4 and at least the output row of " +
                                std::to_string(row) + " bytes");
  if (opt.frame.origin % 4096 != 0)
    throw std::invalid_argument("origin " + std::to_string(opt.frame.origin) + " must be a multiple of 4096");
  const uint64_t align = opt.frame.packed ? 4 : 4096;
  const auto up = [align](uint64_t n) { return (n + align - 1) / align * align; };
  plane = up(uint64_t(stride) * uint64_t(h));
  out_plane = up(uint64_t(out_stride) * uint64_t(h));
  in_plane = plane;
  if (opt.frame.tiled) {
    tile = opt.frame.tile_stride ? opt.frame.tile_stride : 4 * uint32_t(h);
    if (tile < 4 * uint32_t(h) || tile % 4 != 0)
      throw std::invalid_argument("tile stride " + std::to_string(tile) +
                                  " must be a multiple of 4 and at least 4 x the height " +
                                  std::to_string(h));
    in_plane = up(uint64_t(tile) * uint64_t((w + 3) / 4));
  }
  if (rect) {
    raw_stride = opt.frame.rect->raw_stride ? opt.frame.rect->raw_stride
                                      : opt.frame.tiled ? 4 * uint32_t(raw_height) : uint32_t((raw_width + 3) / 4 * 4);
    const uint32_t least = opt.frame.tiled ? 4 * uint32_t(raw_height) : uint32_t(raw_width);
    if (raw_stride < least || raw_stride % 4 != 0)
      throw std::invalid_argument("raw stride " + std::to_string(raw_stride) + " must be a multiple of 4 and at least " +
                                  (opt.frame.tiled ? "4 x the raw height " : "the raw width ") + std::to_string(least / (opt.frame.tiled ? 4 : 1)));
    raw_tile = opt.frame.tiled ? raw_stride : 0;
    raw_plane = up(uint64_t(raw_stride) * uint64_t(opt.frame.tiled ? (raw_width + 3) / 4 : raw_height));
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
  if (opt.frame.reversed_planes) std::reverse(order.begin(), order.end());
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

void Layout::rect_geometry(int raw_w, int raw_h, const EngineOptions& opt) {
  const Mesh& ml = opt.frame.rect->left;
  const Mesh& mr = opt.frame.rect->right;
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

RawConfig Layout::raw_config(int disparities) const {
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

MemoryModel::Regions Layout::regions(const Plane* base_valid, const Plane* right_valid) const {
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

void Layout::rect_regions(MemoryModel::Regions& r, const Plane* base_valid) const {
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

void put_plane(MemoryModel& m, uint32_t base, uint32_t stride, uint32_t tile, const Plane& p) {
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) {
      const uint32_t ux = uint32_t(x), uy = uint32_t(y);
      m.byte(uint64_t(base) + (tile ? uint64_t(ux / 4) * tile + 4 * uy + ux % 4 : uint64_t(uy) * stride + ux)) =
          p.at(x, y);
    }
}

void fill_plane(MemoryModel& m, uint32_t base, uint32_t stride, uint32_t tile, int w, int h, uint8_t v) {
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.byte(Layout::plane_addr(base, stride, tile, x, y)) = v;
}

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

namespace {

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

}  // namespace

void load_frame(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right,
                const EngineOptions& opt) {
  if (lay.rect) {
    load_rect(mem, lay, left, right, *opt.frame.rect);
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

uint8_t& at(MemoryModel& mem, uint32_t base, uint32_t stride, int x, int y) {
  return mem.byte(uint64_t(base) + uint64_t(y) * stride + uint64_t(x));
}

int out_pixel(MemoryModel& mem, const Layout& lay, int x, int y) {
  const int ox = x * lay.out_bpp;
  return at(mem, lay.out, lay.out_stride, ox, y) |
         (lay.out_bpp == 2 ? at(mem, lay.out, lay.out_stride, ox + 1, y) << 8 : 0);
}

}  // namespace mcadsw::sim::bench

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The bench's scoreboard: the reference's rectification of a frame and every output
// pixel (and, with rectification, every rectified pixel and validity bit) against it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "engine_bench.hpp"
#include "frame_layout.hpp"
#include "memory_model.hpp"
#include "mcadsw/rectify.hpp"
#include "mcadsw/ref.hpp"

namespace mcadsw::sim::bench {

// The reference's rectification of a frame's raw views (FrameOptions::rect):
// each view through its mesh (mcadsw::rectify), and its validity bitmap as the
// engine writes it (mcadsw::validity_bitmap).
struct RectRef {
  Rectified view[2];
  std::vector<uint32_t> bitmap[2];
  const Plane& base_valid(bool right) const { return view[right ? 1 : 0].valid; }
};
std::optional<RectRef> rect_reference(const YuvImage& left, const YuvImage& right, const EngineOptions& opt);

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
           const Config& cfg, const EngineOptions& opt, EngineResult& r, const RectRef* rr = nullptr);

}  // namespace mcadsw::sim::bench

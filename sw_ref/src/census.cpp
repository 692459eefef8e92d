// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Mini-census transformer (paper Sec. III-B, Fig. 2 and Fig. 10).
#include <algorithm>

#include "mcadsw/ref.hpp"

namespace mcadsw {

int clamp_coord(int v, int size) { return std::clamp(v, 0, size - 1); }

uint8_t Plane::clamped(int x, int y) const {
  return at(clamp_coord(x, width), clamp_coord(y, height));
}

uint8_t census_code(const Plane& luma, int x, int y) {
  const int centre = luma.clamped(x, y);
  uint8_t code = 0;
  for (const Offset& o : kCensusTaps) {
    // Paper: label 0 when the neighbour is larger than the centre, else 1.
    code = uint8_t(code << 1) | uint8_t(luma.clamped(x + o.dx, y + o.dy) <= centre);
  }
  return code;
}

Plane census_transform(const Plane& luma) {
  Plane out(luma.width, luma.height);
  for (int y = 0; y < luma.height; ++y)
    for (int x = 0; x < luma.width; ++x) out.at(x, y) = census_code(luma, x, y);
  return out;
}

// Popcount of a 6-bit value, written so that it vectorises on uint8 lanes.
static inline uint8_t popcount6(uint8_t v) {
  v = uint8_t((v & 0x15) + ((v >> 1) & 0x15));  // three 2-bit sums at bits 0, 2, 4
  return uint8_t((v & 3) + ((v >> 2) & 3) + ((v >> 4) & 3));
}

int census_cost(uint8_t left_code, uint8_t right_code) {
  return popcount6(uint8_t((left_code ^ right_code) & ((1u << kCensusBits) - 1)));
}

void census_cost_slice(const Plane& census_left, const Plane& census_right, int d,
                       std::vector<uint8_t>& cost) {
  const int w = census_left.width, h = census_left.height;
  cost.resize(size_t(w) * h);
  const int split = std::min(d, w);  // x < d reads the clamped right pixel x = 0
  for (int y = 0; y < h; ++y) {
    const uint8_t* l = &census_left.px[size_t(y) * w];
    const uint8_t* r = &census_right.px[size_t(y) * w];
    uint8_t* c = &cost[size_t(y) * w];
    for (int x = 0; x < split; ++x) c[x] = popcount6(uint8_t(l[x] ^ r[0]));
    for (int x = split; x < w; ++x) c[x] = popcount6(uint8_t(l[x] ^ r[x - d]));
  }
}

}  // namespace mcadsw

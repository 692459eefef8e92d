// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Helpers shared by the reference tests.
#pragma once

#include <random>

#include "mcadsw/ref.hpp"

namespace mcadsw::test {

inline Plane random_plane(int w, int h, std::mt19937& rng, int lo = 0, int hi = 255) {
  Plane p(w, h);
  std::uniform_int_distribution<int> dist(lo, hi);
  for (auto& v : p.px) v = uint8_t(dist(rng));
  return p;
}

inline YuvImage random_yuv(int w, int h, std::mt19937& rng) {
  return YuvImage{random_plane(w, h, rng), random_plane(w, h, rng), random_plane(w, h, rng)};
}

inline YuvImage flat_yuv(int w, int h, uint8_t y = 100, uint8_t u = 128, uint8_t v = 128) {
  return YuvImage{Plane(w, h, y), Plane(w, h, u), Plane(w, h, v)};
}

}  // namespace mcadsw::test

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Random smooth meshes for the rectifier's block benches, the engine's
// tests and mcadsw_sim_random.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>

#include "mcadsw/rectify.hpp"

namespace mcadsw::sim {

// A random smooth mesh of a w x h frame at step 2^s for a raw view of raw_w x raw_h:
// an affine map (scale 0.6 .. 0.6 + spread, rotation up to 11 degrees, an offset that
// is sometimes far off the raw view) plus a random jitter per node.
inline Mesh random_mesh(int w, int h, int s, int raw_w, int raw_h, std::mt19937& rng, double spread = 1.1) {
  Mesh m = make_mesh(w, h, s);
  std::uniform_real_distribution<double> u01(0, 1);
  const double scale = 0.6 + spread * u01(rng), ang = (u01(rng) - 0.5) * 0.4;
  const double jit = u01(rng) < 0.3 ? 0.0 : 2.5 * u01(rng);
  const double far = u01(rng) < 0.25 ? 0.5 : 0.1;
  const double ox = (u01(rng) - 0.5) * far * raw_w * 2, oy = (u01(rng) - 0.5) * far * raw_h * 2;
  std::normal_distribution<double> n01(0, 1);
  for (int j = 0; j < m.ny; ++j)
    for (int i = 0; i < m.nx; ++i) {
      const double x = i * m.step() - w / 2.0, y = j * m.step() - h / 2.0;
      const double u = raw_w / 2.0 + ox + scale * (std::cos(ang) * x - std::sin(ang) * y) + jit * n01(rng);
      const double v = raw_h / 2.0 + oy + scale * (std::sin(ang) * x + std::cos(ang) * y) + jit * n01(rng);
      m.u[size_t(j * m.nx + i)] = int32_t(std::lround(u * 32));
      m.v[size_t(j * m.nx + i)] = int32_t(std::lround(v * 32));
    }
  check_mesh(m);
  return m;
}

// A random mesh (random_mesh) whose every tile fits the engine's tile buffer
// (check_rect_footprints): drawn again, with a smaller spread each time, until it does.
inline Mesh random_fitting_mesh(int w, int h, int s, int raw_w, int raw_h, std::mt19937& rng, double spread = 1.1) {
  for (int k = 0;; ++k) {
    Mesh m = random_mesh(w, h, s, raw_w, raw_h, rng, spread * std::pow(0.8, k));
    try {
      check_rect_footprints(m, raw_w, raw_h);
      return m;
    } catch (const std::invalid_argument&) {
      if (k > 40) throw;
    }
  }
}

}  // namespace mcadsw::sim

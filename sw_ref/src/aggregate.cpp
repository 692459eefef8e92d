// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Cost aggregator: two-pass weighted aggregation (paper Sec. III-D, Eqs. 3-4,
// Figs. 12-14). The loops run over x innermost so the compiler vectorises them.
#include <algorithm>

#include "mcadsw/ref.hpp"

namespace mcadsw {

void vertical_aggregate(const std::vector<uint8_t>& cost, const Weights& w,
                        std::vector<uint16_t>& vert_cost) {
  const int W = w.width, H = w.height;
  vert_cost.assign(size_t(W) * H, 0);
  for (int y = 0; y < H; ++y) {
    uint16_t* acc = &vert_cost[size_t(y) * W];
    for (int k = 0; k < kWindow; ++k) {
      const uint8_t* c = &cost[size_t(clamp_coord(y + k - kRadius, H)) * W];
      const uint8_t* wk = &w.vert[(size_t(k) * H + y) * W];
      // Bounded by kVertCostMax < 2^16 (params.hpp), so uint16 cannot overflow.
      for (int x = 0; x < W; ++x) acc[x] = uint16_t(acc[x] + c[x] * wk[x]);
    }
  }
}

void horizontal_aggregate(const std::vector<uint16_t>& vert_cost, const Weights& w,
                          std::vector<uint32_t>& final_cost) {
  const int W = w.width, H = w.height;
  final_cost.assign(size_t(W) * H, 0);
  std::vector<uint32_t> padded(size_t(W) + 2 * kRadius);  // row with clamped borders
  for (int y = 0; y < H; ++y) {
    const uint16_t* ev = &vert_cost[size_t(y) * W];
    for (int i = 0; i < W + 2 * kRadius; ++i) padded[i] = ev[clamp_coord(i - kRadius, W)];
    uint32_t* acc = &final_cost[size_t(y) * W];
    for (int j = 0; j < kWindow; ++j) {
      const uint32_t* p = &padded[j];
      const uint8_t* wj = &w.horz[(size_t(j) * H + y) * W];
      for (int x = 0; x < W; ++x) acc[x] += p[x] * wj[x];
    }
  }
}

}  // namespace mcadsw

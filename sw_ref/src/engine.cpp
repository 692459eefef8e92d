// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Top level of the reference (paper Fig. 1 / Fig. 9): census, weights, then per
// disparity census cost -> vertical -> horizontal aggregation -> WTA.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <thread>

#include "mcadsw/ref.hpp"

namespace mcadsw {

void check_config(const Config& cfg, int width, int height) {
  if (width < 1 || width > kMaxWidth)
    throw std::invalid_argument("width " + std::to_string(width) + " out of range 1.." +
                                std::to_string(kMaxWidth));
  if (height < 1 || height > kMaxHeight)
    throw std::invalid_argument("height " + std::to_string(height) + " out of range 1.." +
                                std::to_string(kMaxHeight));
  if (cfg.disparities < 1 || cfg.disparities > kDmax)
    throw std::invalid_argument("disparity range D = " + std::to_string(cfg.disparities) +
                                " out of range 1.." + std::to_string(kDmax));
  check_weight_table(cfg.table);
}

void check_views(const YuvImage& left, const YuvImage& right) {
  const auto same = [](const Plane& a, const Plane& b) {
    return a.width == b.width && a.height == b.height && a.px.size() == b.px.size();
  };
  if (!same(left.y, left.u) || !same(left.y, left.v) || !same(left.y, right.y))
    throw std::invalid_argument("left and right views must have the same size (" +
                                std::to_string(left.width()) + "x" +
                                std::to_string(left.height()) + " vs " +
                                std::to_string(right.width()) + "x" +
                                std::to_string(right.height()) + ")");
}

Plane disparity_map(const YuvImage& left, const YuvImage& right, const Config& cfg,
                    Intermediates* keep) {
  return keep ? disparity_map_blocks(left, right, cfg, keep) : disparity_map_fast(left, right, cfg);
}

Plane disparity_map_blocks(const YuvImage& left, const YuvImage& right, const Config& cfg,
                           Intermediates* keep) {
  check_views(left, right);
  check_config(cfg, left.width(), left.height());
  const int W = left.width(), H = left.height(), D = cfg.disparities;
  const size_t n = size_t(W) * H;

  const Plane cl = census_transform(left.y);
  const Plane cr = census_transform(right.y);
  const Weights w = generate_weights(left, cfg.table);
  if (keep) {
    keep->census_left = cl;
    keep->census_right = cr;
    keep->weights = w;
    keep->vert_cost.assign(D, {});
    keep->final_cost.assign(D, {});
  }

  // Disparities are dealt round-robin to workers; each keeps its own WTA over
  // an increasing subsequence of d, and the merge below applies the same
  // tie rule, so the result does not depend on the number of workers.
  int workers = cfg.threads > 0 ? cfg.threads : int(std::thread::hardware_concurrency());
  workers = std::clamp(workers, 1, D);
  std::vector<Wta> wta(workers, Wta(n));
  auto work = [&](int t) {
    std::vector<uint8_t> cost;
    std::vector<uint16_t> ev;
    std::vector<uint32_t> e;
    for (int d = t; d < D; d += workers) {
      census_cost_slice(cl, cr, d, cost);
      vertical_aggregate(cost, w, ev);
      horizontal_aggregate(ev, w, e);
      wta[t].update(e, d);
      if (keep) {
        keep->vert_cost[d] = ev;
        keep->final_cost[d] = e;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(work, t);
  work(0);
  for (auto& th : pool) th.join();

  Plane disp(W, H);
  for (size_t i = 0; i < n; ++i) {
    uint32_t best = wta[0].best_cost[i];
    uint8_t best_d = wta[0].best_d[i];
    for (int t = 1; t < workers; ++t) {
      const uint32_t c = wta[t].best_cost[i];
      if (c < best || (c == best && wta[t].best_d[i] < best_d)) {
        best = c;
        best_d = wta[t].best_d[i];
      }
    }
    disp.px[i] = best_d;
  }
  return disp;
}

}  // namespace mcadsw

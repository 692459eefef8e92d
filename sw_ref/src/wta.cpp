// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Winner-takes-all (paper Sec. V-D, right half of Fig. 12).
#include "mcadsw/ref.hpp"

namespace mcadsw {

void Wta::update(const std::vector<uint32_t>& final_cost, int d) {
  for (size_t i = 0; i < final_cost.size(); ++i) {
    // Strictly smaller only: disparities arrive in increasing order, so a tie
    // keeps the smaller d.
    if (final_cost[i] < best_cost[i]) {
      best_cost[i] = final_cost[i];
      best_d[i] = uint8_t(d);
    }
  }
}

}  // namespace mcadsw

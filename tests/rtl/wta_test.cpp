// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_wta (the WTA, paper Fig. 12; P disparities a step) against
// the reference: for every pixel of a row, the winner of mcadsw::Wta (smallest
// cost, ties to the smallest d) and the sub-pixel value of subpixel_value()
// from the costs of d - 1, d and d + 1. Built for P = 1 (the engine's), 2 and 4;
// D not a multiple of P leaves lanes masked in the last step. Costs are drawn
// from small ranges (many ties) and from the full 25-bit range.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "Vwta_p1.h"
#include "Vwta_p2.h"
#include "Vwta_p4.h"
#include "mcadsw/ref.hpp"
#include "vbits.hpp"

namespace mcadsw {
namespace {

using sim::get_bits;
using sim::set_bits;

constexpr int kPixels = kBlock;                      // 18 pixels a row
constexpr int kGroupsPerRow = kBlock / kHorzAggregators;  // 6 groups of 3

// Runs one row of costs[pixel][d] (D disparities) through the model; returns the
// first differences (empty if none) and counts the pixels compared.
template <typename V, int P>
std::string run_row(V& t, const std::vector<std::vector<uint32_t>>& costs, int D, int& compared,
                    int& fractional, std::mt19937& rng) {
  const auto tick = [&t] {
    t.clk_i = 0;
    t.eval();
    t.clk_i = 1;
    t.eval();
  };
  std::vector<int> got_d(kPixels, -1), got_sub(kPixels, -1), got_sub_d(kPixels, -1);
  const auto sample = [&] {
    if (t.valid_o)
      for (int m = 0; m < kHorzAggregators; ++m)
        got_d[t.grp_o * kHorzAggregators + m] = int(get_bits(t.disp_o, m * kDispBits, kDispBits));
    if (t.sub_valid_o)
      for (int m = 0; m < kHorzAggregators; ++m) {
        const int px = t.sub_grp_o * kHorzAggregators + m;
        got_sub[px] = int(get_bits(t.sub_o, m * (kDispBits + 4), kDispBits + 4));
        got_sub_d[px] = int(get_bits(t.sub_d_o, m * kDispBits, kDispBits));
      }
  };
  const int steps = (D + P - 1) / P;
  for (int s = 0; s < steps; ++s)
    for (int g = 0; g < kGroupsPerRow; ++g) {
      // Idle cycles between groups now and then: the state waits.
      while (rng() % 5 == 0) {
        t.valid_i = 0;
        tick();
        sample();
      }
      t.valid_i = 1;
      t.first_i = s == 0;
      t.last_i = s == steps - 1;
      t.d_i = uint32_t(s * P);
      t.grp_i = uint32_t(g);
      uint32_t lanes = 0;
      for (int p = 0; p < P; ++p) {
        const int d = s * P + p;
        if (d < D) lanes |= 1u << p;
        for (int m = 0; m < kHorzAggregators; ++m)
          set_bits(t.fc_i, (p * kHorzAggregators + m) * kFinalCostBits, kFinalCostBits,
                   d < D ? costs[size_t(g * kHorzAggregators + m)][size_t(d)] : rng() % 7);
      }
      t.lanes_i = lanes;
      tick();
      sample();
    }
  t.valid_i = 0;
  for (int i = 0; i < 4; ++i) {
    tick();
    sample();
  }
  // Reference: mcadsw::Wta over the disparities in order, then 12.6.
  Wta wta(kPixels);
  for (int d = 0; d < D; ++d) {
    std::vector<uint32_t> fc(kPixels);
    for (int px = 0; px < kPixels; ++px) fc[size_t(px)] = costs[size_t(px)][size_t(d)];
    wta.update(fc, d);
  }
  std::ostringstream err;
  for (int px = 0; px < kPixels; ++px) {
    const int d = wta.best_d[size_t(px)];
    const auto& c = costs[size_t(px)];
    const auto e = [&](int k) { return (k >= 0 && k < D) ? c[size_t(k)] : 0u; };
    const int sub = subpixel_value(d, D, e(d - 1), e(d), e(d + 1));
    ++compared;
    fractional += sub % kSubpixelScale != 0;
    if (got_d[size_t(px)] != d || got_sub[size_t(px)] != sub || got_sub_d[size_t(px)] != d)
      err << "  P=" << P << " D=" << D << " pixel " << px << ": RTL d " << got_d[size_t(px)] << " sub "
          << got_sub[size_t(px)] << " (d " << got_sub_d[size_t(px)] << "), reference d " << d
          << " sub " << sub << " (E(d-1) " << e(d - 1) << ", E(d) " << e(d) << ", E(d+1) " << e(d + 1)
          << ")\n";
  }
  return err.str();
}

template <typename V, int P>
void run_model() {
  auto ctx = std::make_unique<VerilatedContext>();
  V t(ctx.get());
  t.rst_ni = 0;
  t.clk_i = 0;
  t.valid_i = 0;
  t.eval();
  t.rst_ni = 1;
  t.eval();
  std::mt19937 rng(18 + P);
  int compared = 0, fractional = 0;
  for (const int D : {1, 2, 3, 5, 16, 17, 23, kDmax}) {
    for (const bool small : {true, false}) {
      std::uniform_int_distribution<uint32_t> cost(0, small ? 40u : (1u << kFinalCostBits) - 1);
      std::vector<std::vector<uint32_t>> costs(kPixels, std::vector<uint32_t>(size_t(D)));
      for (auto& row : costs)
        for (auto& c : row) c = cost(rng);
      const std::string err = run_row<V, P>(t, costs, D, compared, fractional, rng);
      EXPECT_TRUE(err.empty()) << err;
    }
  }
  EXPECT_EQ(compared, 8 * 2 * kPixels);
  EXPECT_GT(fractional, kPixels) << "few sub-pixel offsets: the test is weak";
  t.final();
}

TEST(Wta, OneDisparityAStepMatchesReference) { run_model<Vwta_p1, 1>(); }
TEST(Wta, TwoDisparitiesAStepMatchReference) { run_model<Vwta_p2, 2>(); }
TEST(Wta, FourDisparitiesAStepMatchReference) { run_model<Vwta_p4, 4>(); }

}  // namespace
}  // namespace mcadsw

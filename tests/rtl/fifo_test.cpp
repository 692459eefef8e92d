// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_fifo (the post stage's queues) against a std::deque: random pushes of
// one or two entries and pops, kept within what the queue holds (the user's
// side of its contract, which the RTL's assumptions check), at full and empty
// edges; the head and the count are compared every cycle. Both
// parameterisations the post stage uses: 32-bit words, depth 4 (the dL word
// queue) and 49-bit entries, depth 8 (the write queue).
#include <gtest/gtest.h>

#include <cstdint>
#include <deque>
#include <random>

#include "Vfifo_d4.h"
#include "Vfifo_d8.h"
#include "vbits.hpp"

namespace mcadsw {
namespace {

template <typename V>
void run_random(int width, int depth, uint32_t seed, int cycles) {
  V t;
  std::mt19937 rng(seed);
  const uint64_t mask = width >= 64 ? ~0ull : (1ull << width) - 1;
  std::deque<uint64_t> model;
  t.clk_i = 0;
  t.rst_ni = 0;
  t.push_i = t.push2_i = t.pop_i = 0;
  t.eval();
  t.clk_i = 1;
  t.eval();
  t.clk_i = 0;
  t.rst_ni = 1;
  t.eval();
  int full_seen = 0, empty_pops_avoided = 0, double_pushes = 0;
  for (int c = 0; c < cycles; ++c) {
    // Phases that fill and drain, so both edges are reached.
    const bool filling = (c / 64) % 2 == 0;
    const int room = depth - int(model.size());
    const bool pop = !model.empty() && std::uniform_int_distribution<int>(0, 3)(rng) < (filling ? 1 : 3);
    const int free_now = room + (pop ? 1 : 0);
    int pushes = std::uniform_int_distribution<int>(0, filling ? 2 : 1)(rng);
    if (pushes > free_now) pushes = free_now;
    const bool second_only = pushes == 1 && (rng() & 1);
    const uint64_t a = (uint64_t(rng()) << 32 | rng()) & mask, b = (uint64_t(rng()) << 32 | rng()) & mask;
    t.push_i = pushes >= 1 && !second_only;
    t.push2_i = pushes == 2 || second_only;
    sim::set_bits(t.data_i, 0, width, a);
    sim::set_bits(t.data2_i, 0, width, b);
    t.pop_i = pop;
    t.eval();
    ASSERT_EQ(int(t.count_o), int(model.size())) << "cycle " << c;
    if (!model.empty()) {
      ASSERT_EQ(sim::get_bits(t.head_o, 0, width), model.front()) << "head at cycle " << c;
    }
    if (model.empty()) ++empty_pops_avoided;
    if (int(model.size()) == depth) ++full_seen;
    if (pushes == 2) ++double_pushes;
    t.clk_i = 1;
    t.eval();
    t.clk_i = 0;
    t.eval();
    if (pop) model.pop_front();
    if (t.push_i) model.push_back(a);
    if (t.push2_i) model.push_back(b);
  }
  t.final();
  EXPECT_GT(full_seen, 10) << "the queue was never full: the test does not reach the edge";
  EXPECT_GT(empty_pops_avoided, 10) << "the queue was never empty";
  EXPECT_GT(double_pushes, 100);
}

TEST(Fifo, WordQueueDepth4) { run_random<Vfifo_d4>(32, 4, 1, 20000); }
TEST(Fifo, WriteQueueDepth8TwoPushes) { run_random<Vfifo_d8>(49, 8, 2, 20000); }

}  // namespace
}  // namespace mcadsw

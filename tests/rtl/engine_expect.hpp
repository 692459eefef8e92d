// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The whole-engine tests' check of a frame that must be exact (rtl_engine_test,
// rtl_axi_test).
#pragma once

#include <gtest/gtest.h>

#include <cstdio>

#include "engine_bench.hpp"

namespace mcadsw::test {

// Finished, accepted, every pixel equal to the reference, every memory check
// passed; prints the frame's figures.
inline void expect_exact(const sim::EngineResult& r) {
  EXPECT_FALSE(r.timed_out) << "engine did not finish";
  EXPECT_FALSE(r.error) << "frame rejected or ended early, code " << r.error_code;
  EXPECT_EQ(r.mismatches, 0) << r.report;
  EXPECT_EQ(r.bus.total(), 0) << r.bus.describe() << r.report;
  EXPECT_TRUE(r.clean());
  std::printf("%dx%d D=%d: %ld cycles, %ld words read, %ld written, %ld stall cycles\n", r.width,
              r.height, r.disparities, r.cycles, r.words_read, r.words_written, r.stall_cycles);
}

}  // namespace mcadsw::test

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_census (Fig. 10) against census_code(): every position of the census
// buffer, read through the aggregator's read port at every row and column
// offset, equals the reference code of the clamped image coordinate. Left and
// right instances, random input stalls, both banks, borders at all four sides,
// images smaller than the window. The right view is built as the engine builds
// it for P = 1, 2 and 4 disparities a step: 8, 9 and 11 columns a
// read (8 and 16 census sub-banks). On the FPGA target the views have the engine's
// read ports (one left, two right), each a copy of the buffer returning a whole
// column word: every column through every port, the ports at different columns
// in the same cycle.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <sstream>

#include "Vcensus_l.h"
#include "Vcensus_r.h"
#if !MCADSW_FPGA
#include "Vcensus_r11.h"
#include "Vcensus_r9.h"
#endif
#include "mcadsw/ref.hpp"
#include "test_util.hpp"
#include "rtl_bench.hpp"
#include "vbits.hpp"

namespace mcadsw {
namespace {

using sim::get_bits;
using sim::set_bits;

constexpr int kRows = kBlockCols;                     // 48 census rows
constexpr int kColsLeft = kBlockCols;                 // 48
constexpr int kColsRight = kBlockCols + kDmax - 1;    // 111

// Census columns the read port delivers (the model's RL; on the FPGA target its
// read ports).
template <typename V>
constexpr int kReadLanes = kFpga ? 1 : kLanes;
#if MCADSW_FPGA
template <>
constexpr int kReadLanes<Vcensus_r> = 2;
#else
template <>
constexpr int kReadLanes<Vcensus_r9> = kLanes + 1;
template <>
constexpr int kReadLanes<Vcensus_r11> = kLanes + 3;
#endif

// Runs f(Model<V>{}) for the right-view models.
template <typename V>
struct Model {
  using type = V;
};
template <typename F>
void for_right_models(F f) {
  f(Model<Vcensus_r>{});
#if !MCADSW_FPGA
  f(Model<Vcensus_r9>{});
  f(Model<Vcensus_r11>{});
#endif
}

// One block's window of one view: origin in image coordinates.
struct Window {
  int x0, y0;
};

template <typename V>
class CensusBench {
 public:
  explicit CensusBench(int cols) : cols_(cols) {
    top_->clk_i = 0;
    top_->rst_ni = 0;
    top_->cfg_valid_i = 0;
    top_->pix_valid_i = 0;
    top_->rd_en_i = 0;
    top_->ring_free_i = 1;
    top_->cfg_cont_i = 0;
    top_->eval();
    tick();
    tick();
    top_->rst_ni = 1;
  }

  // Fills `bank` from `luma` with random input stalls; returns the cycles used.
  // `cont`: the window continues the previous fill's, 18 columns to the right,
  // and only the strips the input buffer does not hold yet are streamed;
  // otherwise (the first block of a row band) the strips left of the first one
  // the kernel needs are skipped, as the engine does.
  // `expect_done` false: the fill must stop short of done (a band-start block
  // whose ring is not free yet); the kernel then waits, and so does the input
  // once the luma ring is full; finish() streams the rest.
  long fill(const Plane& luma, Window w, int bank, double stall_prob, std::mt19937& rng,
            bool cont = false, bool expect_done = true) {
    auto& t = *top_;
    const int W = luma.width, H = luma.height;
    const int lo_x = std::max(0, -w.x0), hi_x = std::min(cols_ - 1, W - 1 - w.x0);
    const int lo_y = std::max(0, -w.y0), hi_y = std::min(kRows - 1, H - 1 - w.y0);
    {
      const int first = w.x0 - 2;
      t.cfg_ofs_i = ((first % 4) + 4) % 4;
    }
    t.cfg_valid_i = 1;
    t.cfg_bank_i = bank;
    t.cfg_lo_x_i = lo_x;
    t.cfg_hi_x_i = hi_x;
    t.cfg_lo_y_i = lo_y;
    t.cfg_hi_y_i = hi_y;
    const int strips = (cols_ + 4 + 6) / 4;
    // Band start: the first strip is the one holding image column -2 (the
    // leftmost luma the codes of column 0 need).
    const int aligned0 = (w.x0 - 2) - ((((w.x0 - 2) % 4) + 4) % 4);
    const int skip = aligned0 <= -2 ? (-2 - aligned0) / 4 : 0;
    const int first_strip = cont ? sim::first_strip(w.x0 - 2, cont, strips) : skip;
    t.cfg_first_i = first_strip;
    t.cfg_cont_i = cont;
    t.eval();
    EXPECT_TRUE(t.cfg_ready_o);
    tick();
    t.cfg_valid_i = 0;

    // The luma window at clamped coordinates, as the window reader delivers
    // it: strips of 4 columns, rows 0 .. ROWS+3 each, starting at the aligned
    // column at or left of the first input column (offset 0..3).
    const int first = w.x0 - 2, aligned = first - (((first % 4) + 4) % 4);
    std::vector<uint32_t> words;
    for (int s = first_strip; s < strips; ++s)
      for (int u = 0; u < kRows + 4; ++u) {
        uint32_t v = 0;
        for (int b = 0; b < 4; ++b)
          v |= uint32_t(luma.clamped(aligned + 4 * s + b, w.y0 - 2 + u)) << (8 * b);
        words.push_back(v);
      }
    const long limit = expect_done ? 20L * kRows * cols_ + 10000 : 5000;  // never hang
    const sim::StreamResult r = sim::stream_words(t, words, stall_prob, rng, limit);
    EXPECT_EQ(r.done_pulses, expect_done ? 1 : 0) << "done must pulse exactly once, when the ring is free";
    if (expect_done) {
      EXPECT_EQ(r.consumed, words.size()) << "not every input word was consumed";
    } else {
      pending_.assign(words.begin() + long(r.consumed), words.end());
    }
    return r.cycles;
  }

  // Streams the words a fill with expect_done false left; done must follow.
  long finish(std::mt19937& rng) {
    const sim::StreamResult r = sim::stream_words(*top_, pending_, 0.0, rng, 20000);
    EXPECT_EQ(r.consumed, pending_.size()) << "not every input word was consumed";
    EXPECT_EQ(r.done_pulses, 1) << "done must pulse exactly once";
    pending_.clear();
    return r.cycles;
  }

  V& top() { return *top_; }

  // Reads every position of `bank` and compares it with the reference.
  std::string check(const Plane& luma, Window w, int bank, long* compared) {
    if constexpr (kFpga) return check_ports(luma, w, bank, compared);
    auto& t = *top_;
    for (int row = 0; row + kWindow <= kRows; ++row) {
      for (int col = 0; col + kReadLanes<V> <= cols_; ++col) {
        t.rd_en_i = 1;
        t.rd_bank_i = bank;
        t.rd_row_i = row;
        t.rd_col_i = col;
        tick();
        t.rd_en_i = 0;
        for (int l = 0; l < kReadLanes<V>; ++l)
          for (int k = 0; k < kWindow; ++k) {
            const int x = clamp_coord(w.x0 + col + l, luma.width);
            const int y = clamp_coord(w.y0 + row + sim::window_tap(k, row), luma.height);
            const int want = census_code(luma, x, y);
            const int got = int(get_bits(t.rd_data_o, (l * kWindow + k) * kCensusBits, kCensusBits));
            ++*compared;
            if (got != want) {
              std::ostringstream o;
              o << kReadLanes<V> << "-lane read, bank " << bank << " census at window (" << col + l << "," << row + k
                << ") = image (" << x << "," << y << "): RTL " << got << ", reference " << want;
              return o.str();
            }
          }
      }
    }
    return "";
  }

  // FPGA target: in read c, port p reads column (c + 37 p) mod cols, its whole word
  // (every row), which it holds until its next read (checked one idle cycle later).
  std::string check_ports(const Plane& luma, Window w, int bank, long* compared) {
    auto& t = *top_;
    constexpr int kPorts = kReadLanes<V>;
    const int xb = bits_for(cols_ - 1);
    for (int c = 0; c < cols_; ++c) {
      uint32_t cols_word = 0;
      for (int p = 0; p < kPorts; ++p) cols_word |= uint32_t((c + 37 * p) % cols_) << (p * xb);
      t.rd_en_i = (1u << kPorts) - 1;
      t.rd_bank_i = bank;
      t.rd_col_i = cols_word;
      tick();
      t.rd_en_i = 0;
      t.rd_col_i = 0;
      for (int idle = 0; idle < 2; ++idle) {
        for (int p = 0; p < kPorts; ++p) {
          const int col = (c + 37 * p) % cols_;
          for (int row = 0; row < kRows; ++row) {
            const int x = clamp_coord(w.x0 + col, luma.width);
            const int y = clamp_coord(w.y0 + row, luma.height);
            const int want = census_code(luma, x, y);
            const int got = int(get_bits(t.rd_data_o, (p * kRows + row) * kCensusBits, kCensusBits));
            ++*compared;
            if (got != want) {
              std::ostringstream o;
              o << "port " << p << " of " << kPorts << (idle ? ", held a cycle," : "") << ", bank " << bank
                << " census at window (" << col << "," << row << ") = image (" << x << "," << y
                << "): RTL " << got << ", reference " << want;
              return o.str();
            }
          }
        }
        if (idle == 0) tick();
      }
    }
    return "";
  }

 private:
  void tick() { sim::tick(*top_); }
  int cols_;
  std::vector<uint32_t> pending_;
  std::unique_ptr<V> top_ = std::make_unique<V>();
};

template <typename V>
void run_case(int cols, const Plane& luma, Window w, int bank, double stall, uint32_t seed) {
  std::mt19937 rng(seed);
  CensusBench<V> bench(cols);
  const long cycles = bench.fill(luma, w, bank, stall, rng);
  long compared = 0;
  const std::string err = bench.check(luma, w, bank, &compared);
  EXPECT_TRUE(err.empty()) << err;
  std::printf("census %d cols (%d-lane reads), %dx%d image, window (%d,%d), bank %d: filled in "
              "%ld cycles, %ld codes compared\n",
              cols, kReadLanes<V>, luma.width, luma.height, w.x0, w.y0, bank, cycles, compared);
}

// Window origins of a block at (bx, by): left x0 = bx - 15, right x0 = bx - 15 - 63.
Window left_window(int bx, int by) { return {bx - kRadius, by - kRadius}; }
Window right_window(int bx, int by) { return {bx - kRadius - (kDmax - 1), by - kRadius}; }

TEST(Census, LeftInteriorBlock) {
  std::mt19937 rng(1);
  const Plane p = test::random_plane(100, 90, rng);
  run_case<Vcensus_l>(kColsLeft, p, left_window(36, 36), 0, 0.0, 1);
}

TEST(Census, LeftTopLeftCornerWithStalls) {
  std::mt19937 rng(2);
  const Plane p = test::random_plane(60, 50, rng);
  run_case<Vcensus_l>(kColsLeft, p, left_window(0, 0), 1, 0.5, 2);
}

TEST(Census, LeftBottomRightPartialBlock) {
  std::mt19937 rng(3);
  const Plane p = test::random_plane(47, 41, rng);
  run_case<Vcensus_l>(kColsLeft, p, left_window(36, 36), 0, 0.2, 3);
}

TEST(Census, LeftImageSmallerThanTheWindow) {
  std::mt19937 rng(4);
  const Plane p = test::random_plane(7, 5, rng);
  run_case<Vcensus_l>(kColsLeft, p, left_window(0, 0), 1, 0.1, 4);
}

TEST(Census, LeftFlatAndMaximumContrast) {
  run_case<Vcensus_l>(kColsLeft, Plane(50, 50, 77), left_window(18, 18), 0, 0.0, 5);
  Plane c(50, 50);
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 50; ++x) c.at(x, y) = ((x + y) & 1) ? 255 : 0;
  run_case<Vcensus_l>(kColsLeft, c, left_window(18, 18), 1, 0.0, 6);
}

TEST(Census, RightWindowReachesPastTheLeftBorder) {
  std::mt19937 rng(7);
  const Plane p = test::random_plane(130, 70, rng);
  for_right_models([&](auto m) {
    using V = typename decltype(m)::type;
    run_case<V>(kColsRight, p, right_window(18, 18), 0, 0.3, 7);
    run_case<V>(kColsRight, p, right_window(108, 36), 1, 0.0, 8);
  });
}

// The census buffer is a ring (docs/blocks/census.md): a block's new columns
// must not overwrite the previous block's window, which the aggregator still
// reads while the next block is prepared.
template <typename V>
void previous_block_survives(int cols, Window (*window)(int, int), uint32_t seed) {
  std::mt19937 rng(seed);
  const Plane a = test::random_plane(140, 60, rng);
  CensusBench<V> bench(cols);
  long compared = 0;
  for (int bx = 0; bx <= 72; bx += kBlock) {
    const int bank = (bx / kBlock) % 2;
    bench.fill(a, window(bx, 18), bank, 0.0, rng, bx > 0);
    if (bx > 0) {
      const std::string err = bench.check(a, window(bx - kBlock, 18), 1 - bank, &compared);
      ASSERT_TRUE(err.empty()) << "block " << bx - kBlock << " after block " << bx << " was prepared: " << err;
    }
    const std::string err = bench.check(a, window(bx, 18), bank, &compared);
    ASSERT_TRUE(err.empty()) << "block " << bx << ": " << err;
  }
}

TEST(Census, LeftPreviousBlockSurvivesTheNextBlocksColumns) {
  previous_block_survives<Vcensus_l>(kColsLeft, left_window, 9);
}

TEST(Census, RightPreviousBlockSurvivesTheNextBlocksColumns) {
  for_right_models([](auto m) {
    previous_block_survives<typename decltype(m)::type>(kColsRight, right_window, 19);
  });
}

// A block that does not continue its neighbour (the first of a row band)
// writes its window after the neighbour's in the ring: its first RING - COLS
// columns before, the others only after ring_free_i; until then the
// neighbour's codes stay readable. The neighbour is a band start too here
// (both at bx = 0), so the ring positions of two band starts in a row count.
template <typename V>
void band_start_waits(int cols, Window (*window)(int, int), uint32_t seed) {
  std::mt19937 rng(seed);
  const Plane a = test::random_plane(80, 60, rng), b = test::random_plane(80, 60, rng);
  CensusBench<V> bench(cols);
  bench.fill(a, window(0, 0), 0, 0.0, rng);
  bench.fill(a, window(18, 0), 1, 0.0, rng, true);
  for (int by : {18, 36}) {
    const Window prev = by == 18 ? window(18, 0) : window(0, 18);
    const int bank = by == 18 ? 0 : 1;
    const Plane& img = by == 18 ? b : a;
    bench.top().ring_free_i = 0;
    bench.fill(img, window(0, by), bank, 0.0, rng, false, false);
    EXPECT_TRUE(bench.top().busy_o) << "the band-start block did not wait for the ring";
    long compared = 0;
    std::string err = bench.check(by == 18 ? a : b, prev, 1 - bank, &compared);
    EXPECT_TRUE(err.empty()) << "while waiting: " << err;
    bench.top().ring_free_i = 1;
    bench.finish(rng);
    err = bench.check(img, window(0, by), bank, &compared);
    EXPECT_TRUE(err.empty()) << "band start at y " << by << ": " << err;
  }
}

TEST(Census, LeftBandStartWaitsUntilTheRingIsFree) { band_start_waits<Vcensus_l>(kColsLeft, left_window, 12); }

TEST(Census, RightBandStartWaitsUntilTheRingIsFree) {
  for_right_models([](auto m) {
    band_start_waits<typename decltype(m)::type>(kColsRight, right_window, 13);
  });
}

// Partial column reuse: a row band of blocks, each block after the first
// streaming only its new strips (4 or 5) into the circular input buffer; every
// block's census buffer is checked, so a stale or misplaced column fails.
template <typename V>
void run_row_band(int cols, const Plane& luma, int by, Window (*window)(int, int), double stall,
                  uint32_t seed) {
  std::mt19937 rng(seed);
  CensusBench<V> bench(cols);
  int block = 0;
  long compared = 0;
  for (int bx = 0; bx < luma.width; bx += kBlock, ++block) {
    const Window w = window(bx, by);
    const long cycles = bench.fill(luma, w, block % 2, stall, rng, bx > 0);
    const std::string err = bench.check(luma, w, block % 2, &compared);
    ASSERT_TRUE(err.empty()) << "block at (" << bx << "," << by << "): " << err;
    if (bx > 0) {  // the previous block, still aggregated while this one is prepared
      const std::string prev = bench.check(luma, window(bx - kBlock, by), 1 - block % 2, &compared);
      ASSERT_TRUE(prev.empty()) << "block at (" << bx - kBlock << "," << by << ") after the next: " << prev;
    }
    std::printf("census %d cols (%d-lane reads), block (%d,%d)%s: filled in %ld cycles\n", cols,
                kReadLanes<V>, bx, by, bx > 0 ? " reusing columns" : "", cycles);
  }
  std::printf("%ld codes compared\n", compared);
}

TEST(Census, LeftRowBandReusesColumns) {
  std::mt19937 rng(10);
  const Plane p = test::random_plane(131, 40, rng);  // 8 blocks, the last partial
  run_row_band<Vcensus_l>(kColsLeft, p, 18, left_window, 0.2, 10);
}

TEST(Census, RightRowBandReusesColumns) {
  std::mt19937 rng(11);
  const Plane p = test::random_plane(113, 30, rng);
  for_right_models([&](auto m) {
    run_row_band<typename decltype(m)::type>(kColsRight, p, 0, right_window, 0.1, 11);
  });
}

}  // namespace
}  // namespace mcadsw

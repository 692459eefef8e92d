// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_weight_gen (Fig. 11) against generate_weights(): every vertical and
// horizontal weight of every row of a sequence of blocks, read through the
// aggregator's read ports as the cost aggregator does (take a ready row, read
// its 6 vertical words, then its 6 horizontal words, the last releasing the
// slot; the next row's vertical reads overlap the previous row's horizontal
// ones), with the table loaded as weight_thresholds(). Random input stalls,
// random aggregator pace, borders, partial blocks, all-64 / all-0 / random
// tables, row bands with column reuse, band starts that must wait for the
// previous block's last row, a real image. In the FPGA build every case also
// runs on the kernel an entry in 1 and in 3 cycles (KPH, besides the package's
// WEIGHT_KPH: docs/blocks/fpga_target.md).
#include <gtest/gtest.h>

#include <deque>
#include <memory>
#include <random>
#include <sstream>

#include "Vmcadsw_weight_gen.h"
#if MCADSW_FPGA
#include "Vweight_gen_kph1.h"
#include "Vweight_gen_kph3.h"
#endif
#include "mcadsw/image_io.hpp"
#include "mcadsw/ref.hpp"
#include "test_util.hpp"
#include "rtl_bench.hpp"
#include "vbits.hpp"

namespace mcadsw {
namespace {

using sim::get_bits;
using sim::set_bits;

constexpr int kStrips = kBlockCols / 4 + 1;  // strips of a window
constexpr int kWordsPerGroup = 6;            // vertical and horizontal words a row

struct Block {
  int bx, by;
};

struct Sequence {
  std::string name;
  YuvImage img;
  WeightTable table;
  std::vector<Block> blocks;  // in the order the engine prepares them
  double stall = 0.0;         // probability an input word is withheld in a cycle
  double take = 1.0;          // probability the aggregator takes a ready row in a cycle
};

struct Stats {
  long cycles = 0;
  long compared = 0;
  long rows = 0;
  long band_waits = 0;  // cycles a word was offered and refused (the loader waited for the kernel)
};

// Rows of a block the aggregator asks for: those inside the image.
int block_rows(const Sequence& r, const Block& b) { return std::min(kBlock, r.img.height() - b.by); }

template <class Model>
class WeightGenBench {
 public:
  WeightGenBench() {
    auto& t = *top_;
    t.clk_i = 0;
    t.rst_ni = 0;
    t.cfg_valid_i = 0;
    t.pix_valid_i = 0;
    t.row_take_i = 0;
    t.vrd_en_i = 0;
    t.hrd_en_i = 0;
    t.hrd_rel_i = 0;
    t.eval();
    sim::tick(t);
    t.rst_ni = 1;
  }

  // Runs the blocks of `r`; returns "" or the first mismatch.
  std::string run(const Sequence& r, std::mt19937& rng, Stats* st) {
    auto& t = *top_;
    const WeightThresholds thr = weight_thresholds(r.table);
    for (int i = 0; i < kWeightThresholds; ++i)
      set_bits(t.thr_i, i * kColorDistBits, kColorDistBits, thr[i]);
    ref_ = generate_weights(r.img, r.table);
    // Rows the aggregator will take, in order.
    std::deque<std::pair<int, int>> expect;  // (block, row)
    for (size_t k = 0; k < r.blocks.size(); ++k)
      for (int y = 0; y < block_rows(r, r.blocks[k]); ++y) expect.emplace_back(int(k), y);

    size_t next_block = 0;
    std::vector<uint32_t> words;
    size_t consumed = 0;
    bool loading = false;
    struct Active {
      int block, row, slot, v = 0, h = 0;
    };
    std::deque<Active> active;
    const long limit = 200000 + 20000L * long(r.blocks.size());
    for (long cyc = 0; cyc < limit; ++cyc) {
      // Loader side: configure the next block when the loader is free.
      t.cfg_valid_i = 0;
      if (!loading && next_block < r.blocks.size() && t.cfg_ready_o) {
        const Block& b = r.blocks[next_block];
        const bool cont = next_block > 0 && b.by == r.blocks[next_block - 1].by &&
                          b.bx == r.blocks[next_block - 1].bx + kBlock;
        configure(r, b, cont, &words);
        consumed = 0;
        loading = true;
        ++next_block;
      }
      const bool offer = loading && consumed < words.size() && !std::bernoulli_distribution(r.stall)(rng);
      t.pix_valid_i = offer;
      if (offer) t.pix_data_i = words[consumed];
      // Aggregator side: take a ready row when no row still has vertical reads.
      t.row_take_i = 0;
      const bool v_pending = !active.empty() && active.back().v < kWordsPerGroup;
      if (t.row_ready_o && !v_pending && std::bernoulli_distribution(r.take)(rng)) {
        if (expect.empty()) return "a row was ready after the last expected one";
        t.row_take_i = 1;
        active.push_back(Active{expect.front().first, expect.front().second, int(t.rd_slot_o)});
        expect.pop_front();
      }
      // One vertical read (oldest row with vertical words left) and one
      // horizontal read (oldest row whose vertical words are read) a cycle.
      Active* va = nullptr;
      Active* ha = nullptr;
      for (auto& a : active) {
        if (!va && a.v < kWordsPerGroup && !t.row_take_i) va = &a;
        if (!ha && a.v == kWordsPerGroup && a.h < kWordsPerGroup) ha = &a;
      }
      t.vrd_en_i = va != nullptr;
      if (va) {
        t.vrd_slot_i = va->slot;
        t.vrd_grp_i = va->v;
      }
      t.hrd_en_i = ha != nullptr;
      t.hrd_rel_i = ha && ha->h == kWordsPerGroup - 1;
      if (ha) {
        t.hrd_slot_i = ha->slot;
        t.hrd_grp_i = ha->h;
      }
      t.clk_i = 0;
      t.eval();
      // While a window loads, the loader refuses a word only to wait for the kernel.
      if (offer && !t.pix_ready_o) ++st->band_waits;
      if (offer && t.pix_ready_o) ++consumed;
      if (t.done_o) {
        if (!loading || consumed != words.size()) return "done_o before the whole window was taken";
        loading = false;
      }
      t.clk_i = 1;
      t.eval();
      if (va) {
        const std::string e = check_vertical(r, *va, st);
        if (!e.empty()) return e;
        ++va->v;
      }
      if (ha) {
        const std::string e = check_horizontal(r, *ha, st);
        if (!e.empty()) return e;
        if (++ha->h == kWordsPerGroup) {
          ++st->rows;
          active.erase(active.begin() + (ha - &active.front()));
        }
      }
      if (next_block == r.blocks.size() && !loading && expect.empty() && active.empty()) {
        st->cycles = cyc;
        if (t.row_ready_o) return "a row is ready after the last expected one";
        return "";
      }
    }
    std::ostringstream o;
    o << "no progress after " << limit << " cycles: " << expect.size() << " rows not taken, "
      << r.blocks.size() - next_block << " blocks not configured";
    return o.str();
  }

 private:
  void configure(const Sequence& r, const Block& b, bool cont, std::vector<uint32_t>* words) {
    auto& t = *top_;
    const int x0 = b.bx - kRadius, y0 = b.by - kRadius;
    const int aligned = x0 - ((x0 % 4) + 4) % 4;  // the window reader starts on a word boundary
    // A continuing block receives the strips its neighbour's window lacks; the
    // first of a row band skips the strips wholly left of the image.
    const int first = cont ? sim::first_strip(x0, true, kStrips) : (aligned < 0 ? -aligned / 4 : 0);
    t.cfg_ofs_i = x0 - aligned;
    t.cfg_first_i = first;
    t.cfg_lo_i = x0 < 0 ? -x0 : 0;
    t.cfg_rows_i = block_rows(r, b);
    t.cfg_valid_i = 1;
    // Strip by strip, Y, U, V of each, rows 0..47, at clamped coordinates.
    words->clear();
    for (int s = first; s < kStrips; ++s)
      for (const Plane* p : {&r.img.y, &r.img.u, &r.img.v})
        for (int y = 0; y < kBlockCols; ++y) {
          uint32_t v = 0;
          for (int k = 0; k < 4; ++k)
            v |= uint32_t(p->clamped(aligned + 4 * s + k, y0 + y)) << (8 * k);
          words->push_back(v);
        }
  }

  template <typename A>
  std::string check_vertical(const Sequence& r, const A& a, Stats* st) {
    const Block& b = r.blocks[size_t(a.block)];
    const int y = b.by + a.row;
    for (int l = 0; l < kLanes; ++l) {
      const int x = clamp_coord(b.bx - kRadius + a.v * kLanes + l, r.img.width());
      // Lane tap t is window tap k (the FPGA target's folded order, sim::window_tap).
      for (int t = 0; t < kWindow; ++t) {
        const int k = sim::window_tap(t, a.row);
        const int want = weight_code(ref_.v(k, x, y));
        const int got = int(get_bits(top_->wv_o, (l * kWindow + t) * kWeightCodeBits, kWeightCodeBits));
        ++st->compared;
        if (got != want) {
          std::ostringstream o;
          o << "vertical weight code, block (" << b.bx << "," << b.by << ") column x=" << x
            << " centre y=" << y << " lane tap " << t << " (window tap k=" << k - kRadius
            << "): RTL " << got << ", reference " << want;
          return o.str();
        }
      }
    }
    return "";
  }

  template <typename A>
  std::string check_horizontal(const Sequence& r, const A& a, Stats* st) {
    const Block& b = r.blocks[size_t(a.block)];
    const int y = b.by + a.row;
    for (int m = 0; m < kHorzAggregators; ++m) {
      const int x = b.bx + a.h * kHorzAggregators + m;
      if (x >= r.img.width()) continue;
      for (int j = 0; j < kWindow; ++j) {
        const int want = weight_code(ref_.h(j, x, y));
        const int got = int(get_bits(top_->wh_o, (m * kWindow + j) * kWeightCodeBits, kWeightCodeBits));
        ++st->compared;
        if (got != want) {
          std::ostringstream o;
          o << "horizontal weight code at (" << x << "," << y << ") tap j=" << j - kRadius
            << ": RTL " << got << ", reference " << want;
          return o.str();
        }
      }
    }
    return "";
  }

  std::unique_ptr<Model> top_ = std::make_unique<Model>();
  Weights ref_;
};

template <class Model>
Stats run_model(const Sequence& r, const char* model, uint32_t seed) {
  std::mt19937 rng(seed);
  WeightGenBench<Model> bench;
  Stats st;
  const std::string err = bench.run(r, rng, &st);
  EXPECT_TRUE(err.empty()) << r.name << " (" << model << "): " << err;
  std::printf("[%s%s] %dx%d, %zu blocks: %ld cycles, %ld rows, %ld weights compared\n",
              r.name.c_str(), model, r.img.width(), r.img.height(), r.blocks.size(), st.cycles,
              st.rows, st.compared);
  return st;
}

// The package's model; in the FPGA build also the kernel in 1 and 3 cycles an entry.
std::vector<Stats> run(const Sequence& r, uint32_t seed = 77) {
  std::vector<Stats> st{run_model<Vmcadsw_weight_gen>(r, "", seed)};
#if MCADSW_FPGA
  st.push_back(run_model<Vweight_gen_kph1>(r, ", KPH 1", seed));
  st.push_back(run_model<Vweight_gen_kph3>(r, ", KPH 3", seed));
#endif
  return st;
}

YuvImage smooth_image(int w, int h, uint32_t seed) {
  std::mt19937 rng(seed);
  // Smooth colours so that distances spread over the whole table.
  YuvImage img = test::random_yuv(w, h, rng);
  for (Plane* p : {&img.y, &img.u, &img.v})
    for (auto& v : p->px) v = uint8_t(100 + v / 8);
  return img;
}

Sequence single(const std::string& name, int w, int h, int bx, int by, uint32_t seed) {
  return Sequence{name, smooth_image(w, h, seed), make_weight_table(kDefaultGamma), {{bx, by}}};
}

// Every block of the image in raster order, as the scheduler prepares them.
std::vector<Block> all_blocks(int w, int h) {
  std::vector<Block> b;
  for (int by = 0; by < h; by += kBlock)
    for (int bx = 0; bx < w; bx += kBlock) b.push_back({bx, by});
  return b;
}

TEST(WeightGen, InteriorBlockDefaultTable) { run(single("interior", 90, 80, 36, 18, 1)); }

TEST(WeightGen, TopLeftCornerWithStallsAndSlowAggregator) {
  Sequence r = single("corner", 50, 50, 0, 0, 2);
  r.stall = 0.4;
  r.take = 0.05;
  run(r);
}

TEST(WeightGen, PartialBlockAtRightAndBottomEdges) { run(single("partial", 47, 41, 36, 36, 3)); }

TEST(WeightGen, ImageSmallerThanTheWindow) { run(single("small", 9, 6, 0, 0, 4)); }

TEST(WeightGen, AllWeights64AndAllZero) {
  Sequence r = single("all-64", 60, 60, 18, 18, 5);
  r.table = WeightTable(kWeightTableSize, 64);
  run(r);
  r.name = "all-0";
  r.table = WeightTable(kWeightTableSize, 0);
  run(r);
}

TEST(WeightGen, RandomLegalTables) {
  std::mt19937 rng(6);
  for (int trial = 0; trial < 4; ++trial) {
    Sequence r = single("random-table", 60, 50, 18, 18, 10 + trial);
    int code = 7;
    for (auto& w : r.table) {
      if (code > 0 && rng() % 12 == 0) code -= 1 + int(rng() % code);
      w = uint8_t(weight_from_code(code));
    }
    run(r);
  }
}

TEST(WeightGen, MaximumContrast) {
  YuvImage img = test::flat_yuv(50, 50);
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 50; ++x)
      img.y.at(x, y) = img.u.at(x, y) = img.v.at(x, y) = ((x + y) & 1) ? 255 : 0;
  run(Sequence{"contrast", img, make_weight_table(300.0), {{18, 18}}});
}

// Partial column reuse and band starts: every block of an image whose width
// and height are not multiples of 18, each continuing block streaming only its
// new strips into the input ring; random input stalls and aggregator pace.
TEST(WeightGen, WholeImageReusesColumns) {
  Sequence r{"whole-image", smooth_image(97, 59, 12), make_weight_table(kDefaultGamma), all_blocks(97, 59)};
  r.stall = 0.2;
  r.take = 0.3;
  run(r);
}

// A band start's window overwrites the previous block's ring strips beyond the
// first free ones: with a slow aggregator the loader must wait for the kernel
// to finish that block (and does, or the previous block's last rows fail).
TEST(WeightGen, BandStartWaitsForThePreviousBlock) {
  Sequence r{"band-start", smooth_image(40, 40, 13), make_weight_table(kDefaultGamma), all_blocks(40, 40)};
  r.take = 0.01;
  for (const Stats& st : run(r))
    EXPECT_GT(st.band_waits, 0) << "the loader never waited: the case does not test the wait";
}

TEST(WeightGen, RealImageTeddyCif) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/cif/teddy/";
  run(Sequence{"teddy", load_yuv(dir + "left.png"), make_weight_table(kDefaultGamma),
          {{144, 108}, {162, 108}, {180, 108}, {0, 126}, {18, 126}}});
}

}  // namespace
}  // namespace mcadsw

// mcadsw_weight_gen (Fig. 11) against generate_weights(): every vertical and
// horizontal weight of a block, read through the aggregator's read ports, with
// the table loaded as weight_thresholds(). Random input stalls, both banks,
// borders, partial blocks, all-64 / all-0 / random tables, a real image.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <sstream>

#include "Vmcadsw_weight_gen.h"
#include "mcadsw/image_io.hpp"
#include "mcadsw/ref.hpp"
#include "test_util.hpp"
#include "rtl_bench.hpp"
#include "vbits.hpp"

namespace mcadsw {
namespace {

using sim::get_bits;
using sim::set_bits;

struct Case {
  std::string name;
  YuvImage img;
  WeightTable table;
  int bx, by;
  int bank = 0;
  double stall = 0.0;
  bool cont = false;  // continues the previous fill's block, 18 columns to the left
};

class WeightGenBench {
 public:
  WeightGenBench() {
    auto& t = *top_;
    t.clk_i = 0;
    t.rst_ni = 0;
    t.cfg_valid_i = 0;
    t.pix_valid_i = 0;
    t.vrd_en_i = 0;
    t.hrd_en_i = 0;
    t.eval();
    tick();
    t.rst_ni = 1;
  }

  long fill(const Case& c, std::mt19937& rng) {
    auto& t = *top_;
    const WeightThresholds thr = weight_thresholds(c.table);
    for (int i = 0; i < kWeightThresholds; ++i)
      set_bits(t.thr_i, i * kColorDistBits, kColorDistBits, thr[i]);
    const int x0 = c.bx - kRadius, y0 = c.by - kRadius;
    const int aligned = x0 - ((x0 % 4) + 4) % 4;  // window reader starts on a word boundary
    t.cfg_ofs_i = x0 - aligned;
    const int strips = kBlockCols / 4 + 1;
    const int first = sim::first_strip(x0, c.cont, strips);
    t.cfg_first_i = first;
    t.cfg_valid_i = 1;
    t.cfg_bank_i = c.bank;
    t.eval();
    EXPECT_TRUE(t.cfg_ready_o);
    tick();
    t.cfg_valid_i = 0;
    // Plane by plane, 4-column strips from the aligned column, rows 0..47,
    // at clamped coordinates; strips before `first` are already in the buffer.
    std::vector<uint32_t> words;
    for (const Plane* p : {&c.img.y, &c.img.u, &c.img.v})
      for (int s = first; s < strips; ++s)
        for (int y = 0; y < kBlockCols; ++y) {
          uint32_t v = 0;
          for (int b = 0; b < 4; ++b)
            v |= uint32_t(p->clamped(aligned + 4 * s + b, y0 + y)) << (8 * b);
          words.push_back(v);
        }
    const sim::StreamResult r = sim::stream_words(t, words, c.stall, rng, 100000);  // limit: never hang
    EXPECT_EQ(r.consumed, words.size()) << "not every input word was consumed";
    EXPECT_EQ(r.done_pulses, 1) << "done must pulse exactly once";
    return r.cycles;
  }

  std::string check(const Case& c, long* compared) {
    auto& t = *top_;
    const Weights ref = generate_weights(c.img, c.table);
    const int W = c.img.width(), H = c.img.height();
    for (int r = 0; r < kBlock; ++r) {
      const int y = c.by + r;
      if (y >= H) break;  // partial block: rows outside the image are never used
      for (int g = 0; g < kGroups; ++g) {
        t.vrd_en_i = 1;
        t.vrd_bank_i = c.bank;
        t.vrd_row_i = r;
        t.vrd_col_i = g * kLanes;
        t.hrd_en_i = 1;
        t.hrd_bank_i = c.bank;
        t.hrd_row_i = r;
        t.hrd_col_i = g * kHorzAggregators;
        tick();
        t.vrd_en_i = t.hrd_en_i = 0;
        for (int l = 0; l < kLanes; ++l) {
          const int x = clamp_coord(c.bx - kRadius + g * kLanes + l, W);
          for (int k = 0; k < kWindow; ++k) {
            const int want = weight_code(ref.v(k, x, y));
            const int got = int(get_bits(t.wv_o, (l * kWindow + k) * kWeightCodeBits, kWeightCodeBits));
            ++*compared;
            if (got != want) {
              std::ostringstream o;
              o << "vertical weight code, column x=" << x << " centre y=" << y << " tap k=" << k - kRadius
                << ": RTL " << got << ", reference " << want;
              return o.str();
            }
          }
        }
        for (int m = 0; m < kHorzAggregators; ++m) {
          const int x = c.bx + g * kHorzAggregators + m;
          if (x >= W) continue;
          for (int j = 0; j < kWindow; ++j) {
            const int want = weight_code(ref.h(j, x, y));
            const int got =
                int(get_bits(t.wh_o, (m * kWindow + j) * kWeightCodeBits, kWeightCodeBits));
            ++*compared;
            if (got != want) {
              std::ostringstream o;
              o << "horizontal weight code at (" << x << "," << y << ") tap j=" << j - kRadius
                << ": RTL " << got << ", reference " << want;
              return o.str();
            }
          }
        }
      }
    }
    return "";
  }

 private:
  void tick() { sim::tick(*top_); }
  std::unique_ptr<Vmcadsw_weight_gen> top_ = std::make_unique<Vmcadsw_weight_gen>();
};

void run(const Case& c) {
  std::mt19937 rng(77);
  WeightGenBench bench;
  const long cycles = bench.fill(c, rng);
  long compared = 0;
  const std::string err = bench.check(c, &compared);
  EXPECT_TRUE(err.empty()) << c.name << ": " << err;
  std::printf("[%s] %dx%d block (%d,%d): %ld cycles from configuration to done, %ld weights "
              "compared\n",
              c.name.c_str(), c.img.width(), c.img.height(), c.bx, c.by, cycles, compared);
}

Case random_case(const std::string& name, int w, int h, int bx, int by, uint32_t seed) {
  std::mt19937 rng(seed);
  // Smooth colours so that distances spread over the whole table.
  YuvImage img = test::random_yuv(w, h, rng);
  for (Plane* p : {&img.y, &img.u, &img.v})
    for (auto& v : p->px) v = uint8_t(100 + v / 8);
  return Case{name, img, make_weight_table(kDefaultGamma), bx, by};
}

TEST(WeightGen, InteriorBlockDefaultTable) { run(random_case("interior", 90, 80, 36, 18, 1)); }

TEST(WeightGen, TopLeftCornerWithStallsInBankOne) {
  Case c = random_case("corner", 50, 50, 0, 0, 2);
  c.bank = 1;
  c.stall = 0.4;
  run(c);
}

TEST(WeightGen, PartialBlockAtRightAndBottomEdges) { run(random_case("partial", 47, 41, 36, 36, 3)); }

TEST(WeightGen, ImageSmallerThanTheWindow) { run(random_case("small", 9, 6, 0, 0, 4)); }

TEST(WeightGen, AllWeights64AndAllZero) {
  Case c = random_case("all-64", 60, 60, 18, 18, 5);
  c.table = WeightTable(kWeightTableSize, 64);
  run(c);
  c.name = "all-0";
  c.table = WeightTable(kWeightTableSize, 0);
  run(c);
}

TEST(WeightGen, RandomLegalTables) {
  std::mt19937 rng(6);
  for (int trial = 0; trial < 4; ++trial) {
    Case c = random_case("random-table", 60, 50, 18, 18, 10 + trial);
    int code = 7;
    for (auto& w : c.table) {
      if (code > 0 && rng() % 12 == 0) code -= 1 + int(rng() % code);
      w = uint8_t(weight_from_code(code));
    }
    run(c);
  }
}

TEST(WeightGen, MaximumContrast) {
  YuvImage img = test::flat_yuv(50, 50);
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 50; ++x)
      img.y.at(x, y) = img.u.at(x, y) = img.v.at(x, y) = ((x + y) & 1) ? 255 : 0;
  run(Case{"contrast", img, make_weight_table(300.0), 18, 18});
}

// Partial column reuse: a row band of blocks, each after the first streaming
// only its new strips into the circular input buffers; every block checked.
TEST(WeightGen, RowBandReusesColumns) {
  Case c = random_case("row-band", 97, 40, 0, 18, 12);
  c.stall = 0.2;
  std::mt19937 rng(12);
  WeightGenBench bench;
  long compared = 0;
  for (c.bx = 0; c.bx < c.img.width(); c.bx += kBlock) {
    c.cont = c.bx > 0;
    const long cycles = bench.fill(c, rng);
    const std::string err = bench.check(c, &compared);
    ASSERT_TRUE(err.empty()) << "block at (" << c.bx << "," << c.by << "): " << err;
    std::printf("[row-band] block (%d,%d)%s: %ld cycles\n", c.bx, c.by,
                c.cont ? " reusing columns" : "", cycles);
    c.bank ^= 1;
  }
  std::printf("%ld weights compared\n", compared);
}

TEST(WeightGen, RealImageTeddyCif) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/cif/teddy/";
  run(Case{"teddy", load_yuv(dir + "left.png"), make_weight_table(kDefaultGamma), 162, 108});
}

}  // namespace
}  // namespace mcadsw

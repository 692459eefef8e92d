// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_cost_agg (Figs. 12-14) against the reference: every vertical cost
// (vertical_aggregate), every final cost (horizontal_aggregate) and every
// disparity (Wta) of a block, and every sub-pixel value (subpixel_from_costs,
// docs/algorithm.md 12.6), with the census and weight buffers modelled from the
// reference's intermediates. The first mismatch is reported with its
// coordinates, disparity and both values. Every scenario runs the block built
// for P = 1 (the paper's), 2 and 4 disparities a step: the right
// census input then holds LANES + P - 1 lanes, and D not a multiple of P leaves
// lanes masked in the last step.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <random>
#include <sstream>
#include <vector>

#include "Vcost_agg_p1.h"
#if !MCADSW_FPGA
#include "Vcost_agg_p2.h"
#include "Vcost_agg_p4.h"
#endif
#include "mcadsw/image_io.hpp"
#include "mcadsw/ref.hpp"
#include "rtl_bench.hpp"
#include "test_util.hpp"
#include "vbits.hpp"

namespace mcadsw {
namespace {

using sim::get_bits;
using sim::set_bits;

struct Scenario {
  std::string name;
  YuvImage left, right;
  Config cfg;
  int bx = 0, by = 0;        // block origin (multiple of kBlock)
  double job_gap_prob = 0;   // probability that no job is offered in a cycle
};

// The census reads of a cycle (mcadsw_cost_agg's lrd_*, rrd_*).
struct CensusReads {
  bool l_en;
  int l_col;
  int r_en;
  uint32_t r_col;
};

struct Result {
  long cycles = 0;           // first job accepted .. last disparity out
  long ev_checked = 0, fc_checked = 0, disp_checked = 0, sub_checked = 0, sub_fractional = 0;
  std::string first_error;
};

template <typename V, int P>
class CostAggBench {
 public:
  explicit CostAggBench(const Scenario& s) : s_(s), rng_(1234) {
    Config cfg = s.cfg;
    cfg.threads = 1;
    disp_ = disparity_map(s.left, s.right, cfg, &ref_);
    sub_ = subpixel_from_costs(ref_, disp_, cfg.disparities);
    W_ = s.left.width();
    H_ = s.left.height();
  }

  Result run() {
    Result res;
    auto& t = *top_;
    t.rst_ni = 0;
    t.clk_i = 0;
    t.job_valid_i = 0;
    t.eval();
    for (int i = 0; i < 3; ++i) tick();
    t.rst_ni = 1;

    const int D = s_.cfg.disparities;
    const int rows = std::min(kBlock, H_ - s_.by);
    const int cols = std::min(kBlock, W_ - s_.bx);
    std::vector<int> seen(kBlock * kBlock, 0), seen_sub(kBlock * kBlock, 0);
    int next_row = 0;
    long first_accept = -1, last_out = -1;
    const long steps = (D + P - 1) / P;
    const long limit = long(rows) * (6L * steps + 64) + 1000;  // never hang
    const int ev_cols = std::min(kBlockCols, W_ - (s_.bx - kRadius));
    const long ev_expected = long(rows) * D * ev_cols;

    for (long cycle = 0; cycle < limit; ++cycle) {
      // Job offer: valid stays up until accepted and never depends on ready.
      if (!t.job_valid_i && next_row < rows &&
          std::bernoulli_distribution(1.0 - s_.job_gap_prob)(rng_)) {
        t.job_valid_i = 1;
        t.job_row_i = next_row;
        t.job_disp_i = D;
        // Last Ev column inside the image (block column of image x = W-1).
        t.job_last_col_i = std::min(kBlockCols - 1, W_ - 1 - (s_.bx - kRadius));
      }
      t.clk_i = 0;
      t.eval();

      // Sample this cycle's outputs.
      const bool vrd = t.vrd_en_o, hrd = t.hrd_en_o;
      const int vrow = t.vrd_row_o, vgrp = t.vrd_grp_o, vd = t.vrd_d_o;
      const int hrow = t.hrd_row_o, hgrp = t.hrd_grp_o;
      const CensusReads creads{bool(t.lrd_en_o), int(t.lrd_col_o), int(t.rrd_en_o), uint32_t(t.rrd_col_o)};
      const bool accepted = t.job_valid_i && t.job_ready_o;
      if (accepted) {
        if (first_accept < 0) first_accept = cycle;
        ++next_row;
      }
      if (t.mon_ev_valid_o) check_ev(res);
      if (t.mon_fc_valid_o) check_fc(res);
      if (t.disp_valid_o) {
        check_disp(res, seen, cols);
        last_out = cycle;
      }
      if (t.sub_valid_o) check_sub(res, seen_sub, cols);
      if (!res.first_error.empty()) return res;

      t.clk_i = 1;
      t.eval();
      if (accepted) t.job_valid_i = 0;
      // Synchronous buffers: data for the sampled address, the next cycle.
      drive_vertical(vrd, vrow, vgrp, vd);
      if (kFpga) drive_census_ports(creads);
      drive_horizontal(hrd, hrow, hgrp);

      if (next_row == rows && !t.sub_busy_o && !t.job_valid_i) break;
    }
    res.cycles = last_out - first_accept + 1;
    for (int r = 0; r < rows; ++r)
      for (int x = 0; x < cols; ++x) {
        if (seen[r * kBlock + x] != 1 && res.first_error.empty())
          res.first_error = "pixel (" + std::to_string(s_.bx + x) + "," + std::to_string(s_.by + r) +
                            ") produced " + std::to_string(seen[r * kBlock + x]) + " times";
        if (seen_sub[r * kBlock + x] != 1 && res.first_error.empty())
          res.first_error = "sub-pixel value of (" + std::to_string(s_.bx + x) + "," +
                            std::to_string(s_.by + r) + ") produced " +
                            std::to_string(seen_sub[r * kBlock + x]) + " times";
      }
    if (res.first_error.empty() && res.ev_checked != ev_expected)
      res.first_error = "saw " + std::to_string(res.ev_checked) + " vertical costs, expected " +
                        std::to_string(ev_expected);
    return res;
  }

 private:
  int cx(int x) const { return clamp_coord(x, W_); }
  int cy(int y) const { return clamp_coord(y, H_); }
  // Image column of Ev column `col` (0..47) of the block row.
  int ev_col(int col) const { return cx(s_.bx - kRadius + col); }

  void tick() {
    top_->clk_i = 0;
    top_->eval();
    top_->clk_i = 1;
    top_->eval();
  }

  // The FPGA target's census ports (mcadsw_cost_agg): a read returns the whole
  // column word of the block's window (its 48 rows, row i at i CB), held until the
  // port's next read. Left column c is image column bx - R + c; right column c is
  // image column bx - R - (DMAX - 1) + c. Port p of the right view at p RXB.
  void drive_census_ports(const CensusReads& c) {
    auto& t = *top_;
    constexpr int kRxb = bits_for(kBlockCols + kDmax - 2);
    const int y0 = s_.by - kRadius;
    if (c.l_en) {
      const int x = cx(s_.bx - kRadius + c.l_col);
      for (int i = 0; i < kBlockCols; ++i)
        set_bits(t.cen_l_i, i * kCensusBits, kCensusBits, ref_.census_left.at(x, cy(y0 + i)));
    }
    for (int p = 0; p < 2; ++p) {
      if (!((c.r_en >> p) & 1)) continue;
      const int col = int((c.r_col >> (p * kRxb)) & ((1u << kRxb) - 1));
      const int x = cx(s_.bx - kRadius - (kDmax - 1) + col);
      for (int i = 0; i < kBlockCols; ++i)
        set_bits(t.cen_r_i, (p * kBlockCols + i) * kCensusBits, kCensusBits,
                 ref_.census_right.at(x, cy(y0 + i)));
    }
  }

  // d is the step's first disparity. Right lane j (0 .. LANES + P - 2) is the
  // image column of left lane j - (P - 1), minus d: disparity d + p of left lane l
  // is right lane l + P - 1 - p. On the FPGA target only the weights: the census
  // reads are the ports above.
  void drive_vertical(bool en, int row, int grp, int d) {
    auto& t = *top_;
    if constexpr (!kFpga) drive_lanes(en, row, grp, d);
    for (int l = 0; l < kLanes; ++l) {
      const int x = s_.bx - kRadius + grp * kLanes + l;
      for (int tp = 0; tp < kWindow; ++tp) {
        const int i = l * kWindow + tp;
        const int k = sim::window_tap(tp, row);
        set_bits(t.wv_i, i * kWeightCodeBits, kWeightCodeBits,
                 en ? weight_code(ref_.weights.v(k, cx(x), cy(s_.by + row))) : (rng_() & 7));
      }
    }
  }

  // The ASIC target's census lanes.
  void drive_lanes(bool en, int row, int grp, int d) {
    auto& t = *top_;
    // Lane tap tp is window row sim::window_tap(tp, row): tp itself on the ASIC target,
    // the census buffer's folded order on the FPGA target.
    const auto tap_y = [&](int tp) { return s_.by + row - kRadius + sim::window_tap(tp, row); };
    for (int j = 0; j < kLanes + P - 1; ++j) {
      const int x = s_.bx - kRadius + grp * kLanes + j - (P - 1);
      for (int tp = 0; tp < kWindow; ++tp) {
        const int i = j * kWindow + tp;
        const int y = tap_y(tp);
        // Garbage on every read port when not reading: it must not matter.
        set_bits(t.cen_r_i, i * kCensusBits, kCensusBits,
                 en ? ref_.census_right.at(cx(x - d), cy(y)) : (rng_() & 63));
      }
    }
    for (int l = 0; l < kLanes; ++l) {
      const int x = s_.bx - kRadius + grp * kLanes + l;
      for (int tp = 0; tp < kWindow; ++tp) {
        const int i = l * kWindow + tp;
        const int y = tap_y(tp);
        set_bits(t.cen_l_i, i * kCensusBits, kCensusBits,
                 en ? ref_.census_left.at(cx(x), cy(y)) : (rng_() & 63));
      }
    }
  }

  void drive_horizontal(bool en, int row, int grp) {
    auto& t = *top_;
    for (int m = 0; m < kHorzAggregators; ++m) {
      const int x = cx(s_.bx + grp * kHorzAggregators + m);
      for (int j = 0; j < kWindow; ++j) {
        const int i = m * kWindow + j;
        set_bits(t.wh_i, i * kWeightCodeBits, kWeightCodeBits,
                 en ? weight_code(ref_.weights.h(j, x, cy(s_.by + row))) : (rng_() & 7));
      }
    }
  }

  void fail(Result& res, const std::string& what) {
    if (res.first_error.empty()) res.first_error = what;
  }

  // Copy p of the monitor holds disparity d + p; copies at d + p >= D are masked
  // lanes (garbage, not compared).
  void check_ev(Result& res) {
    auto& t = *top_;
    const int row = t.mon_ev_row_o, d0 = t.mon_ev_d_o, grp = t.mon_ev_grp_o;
    if (d0 % P != 0) fail(res, "vertical costs of a step starting at d=" + std::to_string(d0));
    const int y = s_.by + row;
    for (int p = 0; p < P && d0 + p < s_.cfg.disparities; ++p) {
      const int d = d0 + p;
      for (int l = 0; l < kLanes; ++l) {
        const int col = grp * kLanes + l;
        // Columns beyond the right border are not used: the ping-pong buffer
        // replaces them by the border column (rtl/mcadsw_pingpong.sv).
        if (s_.bx - kRadius + col >= W_) continue;
        const int x = ev_col(col);
        const uint64_t got = get_bits(t.mon_ev_o, (p * kLanes + l) * kVertCostBits, kVertCostBits);
        const uint64_t want = ref_.vert_cost[d][size_t(y) * W_ + x];
        ++res.ev_checked;
        if (got != want) {
          std::ostringstream o;
          o << "vertical cost Ev at column x=" << x << " (block col " << grp * kLanes + l
            << "), y=" << y << ", d=" << d << ": RTL " << got << ", reference " << want;
          fail(res, o.str());
        }
      }
    }
  }

  void check_fc(Result& res) {
    auto& t = *top_;
    const int row = t.mon_fc_row_o, d0 = t.mon_fc_d_o, grp = t.mon_fc_grp_o;
    const int y = s_.by + row;
    for (int p = 0; p < P && d0 + p < s_.cfg.disparities; ++p) {
      const int d = d0 + p;
      for (int m = 0; m < kHorzAggregators; ++m) {
        const int x = s_.bx + grp * kHorzAggregators + m;
        if (x >= W_) continue;  // partial block: outside the image
        const uint64_t got =
            get_bits(t.mon_fc_o, (p * kHorzAggregators + m) * kFinalCostBits, kFinalCostBits);
        const uint64_t want = ref_.final_cost[d][size_t(y) * W_ + x];
        ++res.fc_checked;
        if (got != want) {
          std::ostringstream o;
          o << "final cost at (" << x << "," << y << "), d=" << d << ": RTL " << got
            << ", reference " << want;
          fail(res, o.str());
        }
      }
    }
  }

  void check_disp(Result& res, std::vector<int>& seen, int cols) {
    auto& t = *top_;
    const int row = t.disp_row_o, grp = t.disp_grp_o;
    const int y = s_.by + row;
    for (int m = 0; m < kHorzAggregators; ++m) {
      const int xb = grp * kHorzAggregators + m;
      if (xb >= cols) continue;
      const int x = s_.bx + xb;
      ++seen[row * kBlock + xb];
      const int got = int(get_bits(t.disp_o, m * kDispBits, kDispBits));
      const int want = disp_.at(x, y);
      ++res.disp_checked;
      if (got != want) {
        std::ostringstream o;
        o << "disparity at (" << x << "," << y << "): RTL " << got;
        if (got < s_.cfg.disparities)
          o << " (cost " << ref_.final_cost[got][size_t(y) * W_ + x] << ")";
        else
          o << " (at or above D = " << s_.cfg.disparities << ")";
        o << ", reference " << want << " (cost " << ref_.final_cost[want][size_t(y) * W_ + x]
          << ")";
        fail(res, o.str());
      }
    }
  }

  void check_sub(Result& res, std::vector<int>& seen, int cols) {
    auto& t = *top_;
    const int row = t.sub_row_o, grp = t.sub_grp_o;
    const int y = s_.by + row;
    constexpr int kSubBits = kDispBits + 4;
    for (int m = 0; m < kHorzAggregators; ++m) {
      const int xb = grp * kHorzAggregators + m;
      if (xb >= cols) continue;
      const int x = s_.bx + xb;
      ++seen[row * kBlock + xb];
      const int got = int(get_bits(t.sub_o, m * kSubBits, kSubBits));
      const int want = sub_.at(x, y);
      ++res.sub_checked;
      // The integer winner travels with the value (the LR mode's scratch format).
      const int got_d = int(get_bits(t.sub_d_o, m * kDispBits, kDispBits));
      if (got_d != disp_.at(x, y)) {
        std::ostringstream o;
        o << "sub_d at (" << x << "," << y << "): RTL " << got_d << ", reference " << disp_.at(x, y);
        fail(res, o.str());
      }
      res.sub_fractional += want % kSubpixelScale != 0;
      if (got != want) {
        const int d = disp_.at(x, y);
        const auto cost = [&](int e) {
          return (e >= 0 && e < s_.cfg.disparities) ? long(ref_.final_cost[e][size_t(y) * W_ + x]) : -1L;
        };
        std::ostringstream o;
        o << "sub-pixel value at (" << x << "," << y << "), d=" << d << ": RTL " << got << ", reference "
          << want << " (E(d-1) " << cost(d - 1) << ", E(d) " << cost(d) << ", E(d+1) " << cost(d + 1) << ")";
        fail(res, o.str());
      }
    }
  }

  const Scenario& s_;
  std::mt19937 rng_;
  std::unique_ptr<V> top_ = std::make_unique<V>();
  Intermediates ref_;
  Plane disp_;
  Plane16 sub_;
  int W_ = 0, H_ = 0;
};

template <typename V, int P>
Result run_p(const Scenario& s) {
  CostAggBench<V, P> bench(s);
  Result r = bench.run();
  std::printf("[%s P=%d] %dx%d block (%d,%d) D=%d: %ld cycles, %ld Ev / %ld final costs / %ld "
              "disparities / %ld sub-pixel values (%ld with an offset) checked\n",
              s.name.c_str(), P, s.left.width(), s.left.height(), s.bx, s.by, s.cfg.disparities,
              r.cycles, r.ev_checked, r.fc_checked, r.disp_checked, r.sub_checked, r.sub_fractional);
  if (!r.first_error.empty()) r.first_error = "P=" + std::to_string(P) + ": " + r.first_error;
  return r;
}

// The scenario at P = 1, 2 and 4 (results in the order of kPs); the FPGA target
// takes one disparity a step.
#if MCADSW_FPGA
constexpr std::array<int, 1> kPs = {1};
std::vector<Result> run_scenario(const Scenario& s) { return {run_p<Vcost_agg_p1, 1>(s)}; }
#else
constexpr std::array<int, 3> kPs = {1, 2, 4};
std::vector<Result> run_scenario(const Scenario& s) {
  return {run_p<Vcost_agg_p1, 1>(s), run_p<Vcost_agg_p2, 2>(s), run_p<Vcost_agg_p4, 4>(s)};
}
#endif

Scenario random_scenario(const std::string& name, int w, int h, int d, int bx, int by,
                         uint32_t seed) {
  std::mt19937 rng(seed);
  Scenario s{name, test::random_yuv(w, h, rng), test::random_yuv(w, h, rng), Config{}, bx, by};
  s.cfg.disparities = d;
  s.cfg.table = make_weight_table(200.0);  // most weights non-zero, all shifts used
  return s;
}

Scenario real_scenario(const std::string& name, int d, int bx, int by) {
  const std::string dir = std::string(MCADSW_DATA_DIR) + "/cif/teddy/";
  Scenario s{name, load_yuv(dir + "left.png"), load_yuv(dir + "right.png"), Config{}, bx, by};
  s.cfg.disparities = d;
  return s;
}

#define EXPECT_CLEAN(results)                                          \
  for (const Result& r_ : (results)) EXPECT_TRUE(r_.first_error.empty()) << r_.first_error

TEST(CostAgg, InteriorBlockRandomImage) {
  const auto rs = run_scenario(random_scenario("interior", 72, 60, 20, 36, 18, 1));
  EXPECT_CLEAN(rs);
  for (const Result& r : rs) EXPECT_EQ(r.disp_checked, 18 * 18);
}

TEST(CostAgg, TopLeftCornerClampsEverythingAtDmax) {
  EXPECT_CLEAN(run_scenario(random_scenario("corner", 40, 40, kDmax, 0, 0, 2)));
}

TEST(CostAgg, PartialBlockAtRightAndBottomEdges) {
  const auto rs = run_scenario(random_scenario("partial", 47, 41, 9, 36, 36, 3));
  EXPECT_CLEAN(rs);
  for (const Result& r : rs) EXPECT_EQ(r.disp_checked, 11 * 5);
}

TEST(CostAgg, SingleDisparity) {
  EXPECT_CLEAN(run_scenario(random_scenario("D=1", 40, 30, 1, 18, 0, 4)));
}

// D = 2, 3, 5, 6, 7: every remainder of D by 2 and 4 (masked lanes in the last step).
TEST(CostAgg, DisparityCountsNotAMultipleOfP) {
  for (int d : {2, 3, 5, 6, 7})
    EXPECT_CLEAN(run_scenario(random_scenario("D=" + std::to_string(d), 44, 40, d, 18, 18, 10 + d)));
}

TEST(CostAgg, RealImageTeddyCifAtDmax) {
  const auto rs = run_scenario(real_scenario("teddy", kDmax, 180, 126));
  EXPECT_CLEAN(rs);
  for (size_t i = 0; i < kPs.size(); ++i) {
    const Result& r = rs[i];
    const int par = kPs[i];
    EXPECT_GT(r.sub_fractional, r.sub_checked / 2) << "most pixels of a real block get an offset";
    // Back-to-back jobs: 6 cycles per step (P disparities) per row plus the pipeline fill;
    // on the FPGA target the horizontal side is a row behind the vertical one (the
    // transposition buffer): one row more, the reader's 2 cycles, and the block's first
    // 8 census columns read before its first step (9 cycles).
    const long per_row = 6L * (kDmax / par);
    const long per_block = 18 * per_row + (kFpga ? per_row + 2 + kLanes + 1 : 0);
    std::printf("P=%d: cycles per 18-pixel row at D=%d: %.1f (paper, P = 1: 7 + 6*64 = 391)\n",
                par, kDmax, double(r.cycles) / 18);
    EXPECT_LE(r.cycles, per_block + 16) << "P=" << par;
  }
}

TEST(CostAgg, FlatImagesTieEverywhereToZero) {
  Scenario s{"flat", test::flat_yuv(40, 40), test::flat_yuv(40, 40, 90), Config{}, 18, 18};
  s.cfg.disparities = 12;
  EXPECT_CLEAN(run_scenario(s));
}

TEST(CostAgg, MaximumContrastAllWeights64) {
  YuvImage l = test::flat_yuv(50, 40), r = test::flat_yuv(50, 40);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 50; ++x) {
      l.y.at(x, y) = ((x / 3 + y / 2) & 1) ? 255 : 0;
      r.y.at(x, y) = ((x / 2 + y / 3) & 1) ? 255 : 0;
    }
  Scenario s{"contrast", l, r, Config{}, 18, 18};
  s.cfg.disparities = 24;
  s.cfg.table = WeightTable(kWeightTableSize, 64);  // every weight 64: the widest sums
  EXPECT_CLEAN(run_scenario(s));
}

TEST(CostAgg, AllWeightsZero) {
  Scenario s = random_scenario("zero-weights", 40, 40, 10, 18, 18, 5);
  s.cfg.table = WeightTable(kWeightTableSize, 0);
  EXPECT_CLEAN(run_scenario(s));
}

TEST(CostAgg, JobBackPressureWithRandomGaps) {
  Scenario s = random_scenario("gaps", 60, 50, 7, 18, 18, 6);
  s.job_gap_prob = 0.7;
  EXPECT_CLEAN(run_scenario(s));
}

}  // namespace
}  // namespace mcadsw

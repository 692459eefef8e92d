// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Bit-exact reference model of the MCADSW disparity estimator.
//
// Each function mirrors one block of the paper's architecture (Fig. 9) and is
// specified in docs/algorithm.md. Everything here is integer-only; the RTL
// unit tests compare against these functions bit for bit.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mcadsw/params.hpp"

namespace mcadsw {

// An 8-bit image plane, row-major, no padding.
struct Plane {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> px;

  Plane() = default;
  Plane(int w, int h, uint8_t fill = 0) : width(w), height(h), px(size_t(w) * h, fill) {}
  uint8_t at(int x, int y) const { return px[size_t(y) * width + x]; }
  uint8_t& at(int x, int y) { return px[size_t(y) * width + x]; }
  // The border rule of docs/algorithm.md: coordinates outside the image are
  // clamped to the nearest edge pixel.
  uint8_t clamped(int x, int y) const;
};

// A 16-bit plane: sub-pixel disparities, value = 16 d + offset (docs/algorithm.md 12.6).
struct Plane16 {
  int width = 0;
  int height = 0;
  std::vector<uint16_t> px;

  Plane16() = default;
  Plane16(int w, int h, uint16_t fill = 0) : width(w), height(h), px(size_t(w) * h, fill) {}
  uint16_t at(int x, int y) const { return px[size_t(y) * width + x]; }
  uint16_t& at(int x, int y) { return px[size_t(y) * width + x]; }
};

// YUV 4:4:4 planes of one view, as the engine reads them from external memory.
struct YuvImage {
  Plane y, u, v;
  int width() const { return y.width; }
  int height() const { return y.height; }
};

int clamp_coord(int v, int size);

// ---- Mini-census transformer (Fig. 10) ---------------------------------------
uint8_t census_code(const Plane& luma, int x, int y);
Plane census_transform(const Plane& luma);
// Hamming distance of two 6-bit codes (Eq. 1).
int census_cost(uint8_t left_code, uint8_t right_code);

// ---- Weight generator (Fig. 11) ------------------------------------------------
using WeightTable = std::vector<uint8_t>;  // kWeightTableSize entries, each 0 or 2^n <= 64
// 64*exp(-dC/gamma) truncated to its most significant set bit (Fig. 5).
WeightTable make_weight_table(double gamma);
// Throws std::invalid_argument unless the table has kWeightTableSize entries,
// each 0 or a power of two <= 64, non-increasing in dC (as every table from
// make_weight_table is), so the engine can hold it as thresholds.
void check_weight_table(const WeightTable& table);
// The table as the engine holds it: threshold[i] is the smallest dC whose weight
// code is <= 6 - i (kWeightTableSize when there is none). Lossless for legal tables.
using WeightThresholds = std::array<uint16_t, kWeightThresholds>;
WeightThresholds weight_thresholds(const WeightTable& table);
WeightTable weight_table_from_thresholds(const WeightThresholds& thresholds);
// Manhattan colour distance |dY|+|dU|+|dV| of two pixels of one view.
int color_distance(const YuvImage& img, int x0, int y0, int x1, int y1);

// Vertical and horizontal weights of every pixel, left (base) view only.
//   vert[k][y][x] = table[dC((x, clamp(y+k-R)), (x, y))]   column centre (x, y)
//   horz[j][y][x] = table[dC((clamp(x+j-R), y), (x, y))]   window centre (x, y)
// for k, j in 0..kWindow-1 (offset = index - kRadius).
struct Weights {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> vert;  // kWindow planes of width*height
  std::vector<uint8_t> horz;  // kWindow planes of width*height
  uint8_t v(int k, int x, int y) const { return vert[(size_t(k) * height + y) * width + x]; }
  uint8_t h(int j, int x, int y) const { return horz[(size_t(j) * height + y) * width + x]; }
};
Weights generate_weights(const YuvImage& left, const WeightTable& table);

// ---- Cost aggregator and WTA (Figs. 12-14) --------------------------------------
// Census cost slice for one disparity: cost[y][x] = H(cl(x,y), cr(clamp(x-d), y)).
void census_cost_slice(const Plane& census_left, const Plane& census_right, int d,
                       std::vector<uint8_t>& cost);
// Ev(x,y) = sum_k cost(x, clamp(y+k-R)) * vert[k][y][x]   (Eq. 3)
void vertical_aggregate(const std::vector<uint8_t>& cost, const Weights& w,
                        std::vector<uint16_t>& vert_cost);
// E(x,y) = sum_j Ev(clamp(x+j-R), y) * horz[j][y][x]       (Eq. 4)
void horizontal_aggregate(const std::vector<uint16_t>& vert_cost, const Weights& w,
                          std::vector<uint32_t>& final_cost);

// Winner-takes-all over disparities presented in increasing order; a strictly
// smaller cost replaces the best, so ties keep the smallest d.
struct Wta {
  std::vector<uint32_t> best_cost;
  std::vector<uint8_t> best_d;
  explicit Wta(size_t pixels) : best_cost(pixels, UINT32_MAX), best_d(pixels, 0) {}
  void update(const std::vector<uint32_t>& final_cost, int d);
};

// ---- Top level -------------------------------------------------------------------
struct Config {
  int disparities = 16;  // D: disparities 0..D-1 are searched, 1 <= D <= kDmax
  WeightTable table = make_weight_table(kDefaultGamma);
  int threads = 0;  // software only: worker threads, 0 = one per core; never changes the result
};
// Throws std::invalid_argument with a message naming the offending value.
void check_config(const Config& cfg, int width, int height);
// Throws std::invalid_argument unless Y, U, V of the left view and Y of the right
// view all have the same size.
void check_views(const YuvImage& left, const YuvImage& right);

// Optional intermediate results, for block-level tests and debugging.
struct Intermediates {
  Plane census_left, census_right;
  Weights weights;
  std::vector<std::vector<uint16_t>> vert_cost;   // [d][y*W+x]
  std::vector<std::vector<uint32_t>> final_cost;  // [d][y*W+x]
};

// The whole engine: 8-bit disparity map of the left view. Only Y of the right
// view is used. If `keep` is non-null it receives every intermediate result
// (block-by-block path); otherwise the whole-frame fast path runs. Both give the
// same map bit for bit.
Plane disparity_map(const YuvImage& left, const YuvImage& right, const Config& cfg,
                    Intermediates* keep = nullptr);
// Block by block, as the functions above chain (the oracle of the fast path).
Plane disparity_map_blocks(const YuvImage& left, const YuvImage& right, const Config& cfg,
                           Intermediates* keep = nullptr);
// Whole frame at once, all disparities of a pixel together (sw_ref/src/fast.cpp,
// docs/algorithm.md section 11). `portable` selects the plain C++ kernel even
// where the SIMD one is compiled in, so tests can check both.
// `subpixel`, when given, receives the sub-pixel map of section 12.6.
Plane disparity_map_fast(const YuvImage& left, const YuvImage& right, const Config& cfg,
                         bool portable = false, Plane16* subpixel = nullptr);

// ---- Post-processing beyond the paper (docs/algorithm.md section 12) ----------------
// Horizontal mirror: column x becomes column W - 1 - x.
Plane mirror(const Plane& p);
Plane16 mirror(const Plane16& p);
YuvImage mirror(const YuvImage& v);
// Right view as the base (12.1): mirror(raw(mirror(right), mirror(left))). Throws
// std::invalid_argument unless the right view's Y, U and V have the left view's size.
Plane disparity_map_right(const YuvImage& left, const YuvImage& right, const Config& cfg);
void check_views_lr(const YuvImage& left, const YuvImage& right);
// 12.6: 16 d + offset from E(d-1), E(d), E(d+1) of the winner d of D disparities
// (the costs of absent neighbours are ignored).
int subpixel_value(int d, int disparities, uint32_t cost_minus, uint32_t cost_best,
                   uint32_t cost_plus);
// 12.6 from the block path's final costs (keep->final_cost[d][y*W+x]) and its map.
Plane16 subpixel_from_costs(const Intermediates& keep, const Plane& disp, int disparities);
// 12.2: 255 where the left pixel passes the check with tolerance T, else 0. With the
// rectification's validity of the views (13.4; nonzero = valid, nullptr = all valid),
// the left pixel and the right pixel it matches must be valid too. Throws
// std::invalid_argument for T outside 0..kLrToleranceMax or planes of different sizes.
Plane lr_check(const Plane& disp_left, const Plane& disp_right, int tolerance, const Plane* left_valid = nullptr,
               const Plane* right_valid = nullptr);
// 13.4: the invalid code (kRectInvalidDisp16) wherever `valid` is 0.
void mark_rect_invalid(Plane16& disp, const Plane& valid);
void check_lr_tolerance(int tolerance);
// 12.3: invalid pixels (valid == 0) take the smaller of the nearest valid values left
// and right in their row; 0 when the row has none.
Plane16 fill_invalid(const Plane16& disp, const Plane& valid);
// 12.4: 3x3 median, edges replicated.
Plane16 median3x3(const Plane16& in);

// The engine's outputs in every mode: raw (the paper), LR (12.2-12.5), sub-pixel (12.6).
struct DepthOptions {
  bool lr = false;
  bool subpixel = false;
  int tolerance = kLrToleranceDefault;
  // Validity after rectification (13.4), nonzero = valid; empty = every pixel valid.
  Plane left_valid, right_valid;
};
struct DepthResult {
  Plane16 disp16;  // 16 x disparity (+ offset with subpixel), after LR processing if lr;
                   // kRectInvalidDisp16 where left_valid is 0
  Plane valid;     // lr: 255 valid, 0 filled (before the median); otherwise empty
  Plane raw;       // the raw left map (section 6), before any invalid code
  Plane right;     // lr: the right-reference map (12.1); otherwise empty
  Plane disp8() const;  // disp16 / 16; kRectInvalidDisp8 for the invalid code
};
DepthResult depth_map(const YuvImage& left, const YuvImage& right, const Config& cfg,
                      const DepthOptions& opt);

}  // namespace mcadsw

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Weight generator (paper Sec. III-C, Fig. 5 and Fig. 11).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "mcadsw/ref.hpp"

namespace mcadsw {

WeightTable make_weight_table(double gamma) {
  if (!(gamma > 0.0) || !std::isfinite(gamma))
    throw std::invalid_argument("gamma must be a positive number, got " + std::to_string(gamma));
  // 64*exp(-dC/gamma) = 2^(6 - s) with s = dC/(gamma ln 2); its most significant
  // set bit is 2^(6 - ceil(s)). For dC > 0 and integer-ish gamma, s is never an
  // exact integer, so ceil() is not sensitive to rounding.
  WeightTable t(kWeightTableSize);
  const double step = gamma * std::log(2.0);
  for (int dc = 0; dc < kWeightTableSize; ++dc) {
    const double n = std::ceil(dc / step);
    t[dc] = n > kWeightShiftMax ? 0 : uint8_t(kWeightMax >> int(n));
  }
  return t;
}

void check_weight_table(const WeightTable& table) {
  if (table.size() != size_t(kWeightTableSize))
    throw std::invalid_argument("weight table must have " + std::to_string(kWeightTableSize) +
                                " entries, has " + std::to_string(table.size()));
  for (size_t i = 0; i < table.size(); ++i) {
    const unsigned w = table[i];
    if (w > unsigned(kWeightMax) || (w & (w - 1)) != 0)
      throw std::invalid_argument("weight table entry " + std::to_string(i) + " = " +
                                  std::to_string(w) + " is not 0 or a power of two <= 64");
    if (i > 0 && w > table[i - 1])
      throw std::invalid_argument("weight table entry " + std::to_string(i) + " = " +
                                  std::to_string(w) + " is larger than entry " +
                                  std::to_string(i - 1) + "; the table must be non-increasing");
  }
}

WeightThresholds weight_thresholds(const WeightTable& table) {
  check_weight_table(table);
  WeightThresholds t;
  for (int i = 0; i < kWeightThresholds; ++i) {
    const int code = kWeightThresholds - 1 - i;  // 6 .. 0
    int dc = 0;
    while (dc < kWeightTableSize && weight_code(table[dc]) > code) ++dc;
    t[i] = uint16_t(dc);
  }
  return t;
}

WeightTable weight_table_from_thresholds(const WeightThresholds& thresholds) {
  WeightTable table(kWeightTableSize);
  for (int dc = 0; dc < kWeightTableSize; ++dc) {
    int code = kWeightThresholds;
    for (uint16_t t : thresholds) code -= dc >= t;
    table[dc] = uint8_t(weight_from_code(code));
  }
  return table;
}

int color_distance(const YuvImage& img, int x0, int y0, int x1, int y1) {
  return std::abs(int(img.y.clamped(x0, y0)) - int(img.y.clamped(x1, y1))) +
         std::abs(int(img.u.clamped(x0, y0)) - int(img.u.clamped(x1, y1))) +
         std::abs(int(img.v.clamped(x0, y0)) - int(img.v.clamped(x1, y1)));
}

Weights generate_weights(const YuvImage& left, const WeightTable& table) {
  Weights w;
  w.width = left.width();
  w.height = left.height();
  const int W = w.width, H = w.height;
  const size_t plane = size_t(W) * H;
  w.vert.resize(kWindow * plane);
  w.horz.resize(kWindow * plane);
  const Plane* yuv[3] = {&left.y, &left.u, &left.v};
  std::vector<int> dist(W);
  std::vector<uint8_t> padded[3];  // one row with clamped borders, for the horizontal taps
  for (auto& p : padded) p.resize(size_t(W) + 2 * kRadius);
  for (int y = 0; y < H; ++y) {
    // Vertical: pixel (x, y+off) against its column centre (x, y).
    for (int k = 0; k < kWindow; ++k) {
      const size_t yy = size_t(clamp_coord(y + k - kRadius, H));
      std::fill(dist.begin(), dist.end(), 0);
      for (const Plane* c : yuv) {
        const uint8_t* a = &c->px[yy * W];
        const uint8_t* b = &c->px[size_t(y) * W];
        for (int x = 0; x < W; ++x) dist[x] += std::abs(int(a[x]) - int(b[x]));
      }
      uint8_t* out = &w.vert[k * plane + size_t(y) * W];
      for (int x = 0; x < W; ++x) out[x] = table[dist[x]];
    }
    // Horizontal: column centre (x+off, y) against the window centre (x, y).
    for (int c = 0; c < 3; ++c)
      for (int i = 0; i < W + 2 * kRadius; ++i)
        padded[c][i] = yuv[c]->px[size_t(y) * W + clamp_coord(i - kRadius, W)];
    for (int j = 0; j < kWindow; ++j) {
      std::fill(dist.begin(), dist.end(), 0);
      for (int c = 0; c < 3; ++c) {
        const uint8_t* a = &padded[c][j];
        const uint8_t* b = &yuv[c]->px[size_t(y) * W];
        for (int x = 0; x < W; ++x) dist[x] += std::abs(int(a[x]) - int(b[x]));
      }
      uint8_t* out = &w.horz[j * plane + size_t(y) * W];
      for (int x = 0; x < W; ++x) out[x] = table[dist[x]];
    }
  }
  return w;
}

}  // namespace mcadsw

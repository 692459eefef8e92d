// Weight generator (paper Sec. III-C, Fig. 5 and Fig. 11).
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
  }
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
  const size_t plane = size_t(w.width) * w.height;
  w.vert.resize(kWindow * plane);
  w.horz.resize(kWindow * plane);
  for (int i = 0; i < kWindow; ++i) {
    const int off = i - kRadius;
    for (int y = 0; y < w.height; ++y) {
      for (int x = 0; x < w.width; ++x) {
        const size_t at = i * plane + size_t(y) * w.width + x;
        // Vertical: pixel (x, y+off) against its column centre (x, y).
        w.vert[at] = table[color_distance(left, x, y + off, x, y)];
        // Horizontal: column centre (x+off, y) against the window centre (x, y).
        w.horz[at] = table[color_distance(left, x + off, y, x, y)];
      }
    }
  }
  return w;
}

}  // namespace mcadsw

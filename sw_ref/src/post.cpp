// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Depth post-processing beyond the paper (docs/algorithm.md section 12): the
// right-reference pass, the left-right check, the fill, the 3x3 median and the
// sub-pixel disparity. Integer-only, as the rest of the reference.
#include <algorithm>
#include <array>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "mcadsw/ref.hpp"

namespace mcadsw {
namespace {

template <typename P>
P mirror_plane(const P& p) {
  P m(p.width, p.height);
  for (int y = 0; y < p.height; ++y)
    for (int x = 0; x < p.width; ++x) m.at(x, y) = p.at(p.width - 1 - x, y);
  return m;
}

}  // namespace

Plane mirror(const Plane& p) { return mirror_plane(p); }
Plane16 mirror(const Plane16& p) { return mirror_plane(p); }
YuvImage mirror(const YuvImage& v) { return YuvImage{mirror(v.y), mirror(v.u), mirror(v.v)}; }

void check_views_lr(const YuvImage& left, const YuvImage& right) {
  check_views(left, right);
  const auto same = [](const Plane& a, const Plane& b) {
    return a.width == b.width && a.height == b.height && a.px.size() == b.px.size();
  };
  if (!same(right.y, right.u) || !same(right.y, right.v))
    throw std::invalid_argument(
        "the left-right check needs Y, U and V of the right view, each the size of the left view");
}

Plane disparity_map_right(const YuvImage& left, const YuvImage& right, const Config& cfg) {
  check_views_lr(left, right);
  return mirror(disparity_map(mirror(right), mirror(left), cfg));
}

int subpixel_value(int d, int disparities, uint32_t cost_minus, uint32_t cost_best,
                   uint32_t cost_plus) {
  if (d <= 0 || d >= disparities - 1) return kSubpixelScale * d;
  const int64_t num = int64_t(cost_minus) - int64_t(cost_plus);
  const int64_t den = int64_t(cost_minus) + int64_t(cost_plus) - 2 * int64_t(cost_best);
  if (den <= 0) return kSubpixelScale * d;
  const int64_t mag = (kSubpixelScale * std::llabs(num) + den) / (2 * den);
  return kSubpixelScale * d + int(num < 0 ? -mag : mag);
}

Plane16 subpixel_from_costs(const Intermediates& keep, const Plane& disp, int disparities) {
  Plane16 out(disp.width, disp.height);
  for (size_t i = 0; i < disp.px.size(); ++i) {
    const int d = disp.px[i];
    const auto cost = [&](int e) { return (e >= 0 && e < disparities) ? keep.final_cost[e][i] : 0u; };
    out.px[i] = uint16_t(subpixel_value(d, disparities, cost(d - 1), cost(d), cost(d + 1)));
  }
  return out;
}

void check_lr_tolerance(int tolerance) {
  if (tolerance < 0 || tolerance > kLrToleranceMax)
    throw std::invalid_argument("LR tolerance T = " + std::to_string(tolerance) +
                                " out of range 0.." + std::to_string(kLrToleranceMax));
}

Plane lr_check(const Plane& disp_left, const Plane& disp_right, int tolerance, const Plane* left_valid,
               const Plane* right_valid) {
  check_lr_tolerance(tolerance);
  const auto same = [&](const auto& p) { return p.width == disp_left.width && p.height == disp_left.height; };
  if (!same(disp_right)) throw std::invalid_argument("left and right disparity maps differ in size");
  if ((left_valid && !same(*left_valid)) || (right_valid && !same(*right_valid)))
    throw std::invalid_argument("a validity mask differs in size from the disparity maps");
  Plane valid(disp_left.width, disp_left.height);
  for (int y = 0; y < disp_left.height; ++y)
    for (int x = 0; x < disp_left.width; ++x) {
      const int d = disp_left.at(x, y);
      const bool ok = x - d >= 0 && (!left_valid || left_valid->at(x, y)) &&
                      (!right_valid || right_valid->at(x - d, y)) &&
                      std::abs(d - int(disp_right.at(x - d, y))) <= tolerance;
      valid.at(x, y) = ok ? 255 : 0;
    }
  return valid;
}

void mark_rect_invalid(Plane16& disp, const Plane& valid) {
  if (valid.width != disp.width || valid.height != disp.height)
    throw std::invalid_argument("the validity mask differs in size from the disparity map");
  for (size_t i = 0; i < disp.px.size(); ++i)
    if (!valid.px[i]) disp.px[i] = uint16_t(kRectInvalidDisp16);
}

Plane16 fill_invalid(const Plane16& disp, const Plane& valid) {
  Plane16 out = disp;
  const int W = disp.width;
  std::vector<int> left(static_cast<size_t>(W)), right(static_cast<size_t>(W));  // nearest valid value, -1 if none
  for (int y = 0; y < disp.height; ++y) {
    int last = -1;
    for (int x = 0; x < W; ++x) {
      left[size_t(x)] = last;
      if (valid.at(x, y)) last = disp.at(x, y);
    }
    last = -1;
    for (int x = W - 1; x >= 0; --x) {
      right[size_t(x)] = last;
      if (valid.at(x, y)) last = disp.at(x, y);
    }
    for (int x = 0; x < W; ++x) {
      if (valid.at(x, y)) continue;
      const int l = left[size_t(x)], r = right[size_t(x)];
      out.at(x, y) = uint16_t(l < 0 ? std::max(r, 0) : r < 0 ? l : std::min(l, r));
    }
  }
  return out;
}

Plane16 median3x3(const Plane16& in) {
  Plane16 out(in.width, in.height);
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      std::array<uint16_t, 9> v{};
      int n = 0;
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i)
          v[size_t(n++)] = in.at(clamp_coord(x + i, in.width), clamp_coord(y + j, in.height));
      std::nth_element(v.begin(), v.begin() + 4, v.end());
      out.at(x, y) = v[4];
    }
  return out;
}

Plane DepthResult::disp8() const {
  Plane p(disp16.width, disp16.height);
  for (size_t i = 0; i < p.px.size(); ++i)
    p.px[i] = disp16.px[i] == kRectInvalidDisp16 ? uint8_t(kRectInvalidDisp8) : uint8_t(disp16.px[i] / kSubpixelScale);
  return p;
}

DepthResult depth_map(const YuvImage& left, const YuvImage& right, const Config& cfg,
                      const DepthOptions& opt) {
  if (opt.lr) {
    check_lr_tolerance(opt.tolerance);
    check_views_lr(left, right);
  }
  DepthResult r;
  Plane16 sub;
  r.raw = disparity_map_fast(left, right, cfg, false, opt.subpixel ? &sub : nullptr);
  if (opt.subpixel) {
    r.disp16 = std::move(sub);
  } else {
    r.disp16 = Plane16(r.raw.width, r.raw.height);
    for (size_t i = 0; i < r.raw.px.size(); ++i) r.disp16.px[i] = uint16_t(kSubpixelScale * r.raw.px[i]);
  }
  const Plane* lv = opt.left_valid.px.empty() ? nullptr : &opt.left_valid;
  const Plane* rv = opt.right_valid.px.empty() ? nullptr : &opt.right_valid;
  if (opt.lr) {
    r.right = disparity_map_right(left, right, cfg);
    r.valid = lr_check(r.raw, r.right, opt.tolerance, lv, rv);
    r.disp16 = median3x3(fill_invalid(r.disp16, r.valid));
  }
  if (lv) mark_rect_invalid(r.disp16, *lv);  // 13.4: after fill and median
  return r;
}

}  // namespace mcadsw

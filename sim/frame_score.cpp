// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

#include "frame_score.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>

namespace mcadsw::sim::bench {

std::optional<RectRef> rect_reference(const YuvImage& left, const YuvImage& right, const EngineOptions& opt) {
  if (!opt.frame.rect) return std::nullopt;
  if (right.width() != left.width() || right.height() != left.height())
    throw std::invalid_argument("the raw views must have one size (left " + std::to_string(left.width()) + "x" +
                                std::to_string(left.height()) + ", right " + std::to_string(right.width()) + "x" +
                                std::to_string(right.height()) + ")");
  RectRef r;
  r.view[0] = rectify(left, opt.frame.rect->left);
  r.view[1] = rectify(right, opt.frame.rect->right);
  for (int v = 0; v < 2; ++v) r.bitmap[v] = validity_bitmap(r.view[v].valid);
  return r;
}

namespace {

// Rectification: the rectified planes the mode reads and both views' validity
// bitmaps against the reference's (mcadsw::rectify, mcadsw::validity_bitmap),
// every pixel and every bit of an in-frame pixel, each byte written once.
void score_rect(MemoryModel& mem, const Layout& lay, const RectRef& rr, const EngineOptions& opt,
                EngineResult& r, std::ostringstream& rep) {
  static const char* const kPlane[6] = {"LY", "LU", "LV", "RY", "RU", "RV"};
  static const char* const kView[2] = {"L", "R"};
  long reported = 0;
  const auto bad = [&](const std::string& line) {
    ++r.mismatches;
    if (r.rect_mismatches++ == 0 || reported < opt.run.max_reported) {
      rep << "  " << line << "\n";
      ++reported;
    }
  };
  const int W = lay.width, H = lay.height;
  for (int p = 0; p < 6; ++p) {
    if (!(lay.rect_planes >> p & 1)) continue;
    const Rectified& ref = rr.view[p / 3];
    const Plane& want = p % 3 == 0 ? ref.image.y : p % 3 == 1 ? ref.image.u : ref.image.v;
    const Mesh& m = p < 3 ? opt.frame.rect->left : opt.frame.rect->right;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x < W; ++x) {
        const uint64_t a = lay.in_addr(lay.in_base(p), x, y);
        const int got = mem.byte(a), n = mem.times_written(uint32_t(a));
        if (got == want.at(x, y) && n == 1) continue;
        const auto [pu, pv] = mesh_position(m, x, y);
        std::ostringstream e;
        e << "rectified plane " << kPlane[p] << " mismatch at (" << x << "," << y << "): RTL " << got;
        if (n != 1) e << " (written " << n << " times)";
        e << ", reference " << int(want.at(x, y)) << " (" << (ref.valid.at(x, y) ? "valid" : "invalid")
          << ", source (" << pu << "," << pv << ")/32)";
        bad(e.str());
      }
  }
  const int vh = (H + 7) / 8;
  for (int v = 0; v < 2; ++v) {
    if (!(lay.rect_planes >> (3 * v) & 7)) continue;
    for (int k = 0; 4 * k < W; ++k)
      for (int g = 0; g < vh; ++g) {
        const uint64_t a = uint64_t(lay.valid[size_t(v)]) + 4 * uint64_t(k * vh + g);
        uint32_t got = 0, in_frame = 0;
        int n = 1;
        for (int b = 0; b < 4; ++b) {
          got |= uint32_t(mem.byte(a + uint64_t(b))) << (8 * b);
          const int nb = mem.times_written(uint32_t(a) + uint32_t(b));
          if (nb != 1) n = nb;
        }
        for (int row = 0; row < 8; ++row)
          for (int c = 0; c < 4; ++c)
            if (4 * k + c < W && 8 * g + row < H) in_frame |= 1u << (4 * row + c);
        const uint32_t want = rr.bitmap[v][size_t(k) * size_t(vh) + size_t(g)];
        const uint32_t diff = (got ^ want) & in_frame;
        if (n != 1) {
          bad("validity bitmap " + std::string(kView[v]) + " word (" + std::to_string(k) + "," + std::to_string(g) +
              ") (pixels x " + std::to_string(4 * k) + "+, y " + std::to_string(8 * g) + "+) written " +
              std::to_string(n) + " times");
          if (!diff) continue;
        }
        for (int bit = 0; bit < 32; ++bit)
          if (diff >> bit & 1) {
            const int x = 4 * k + bit % 4, y = 8 * g + bit / 4;
            bad("validity bitmap " + std::string(kView[v]) + " mismatch at (" + std::to_string(x) + "," +
                std::to_string(y) + "): RTL " + std::to_string(got >> bit & 1) + ", reference " +
                std::to_string(want >> bit & 1) + " (word " + std::to_string(k) + "," + std::to_string(g) + ")");
          }
      }
  }
  if (r.rect_mismatches)
    rep << "  " << r.rect_mismatches << " rectified pixels or validity bits differ (or were not written once)\n";
}

// LR mode: the output plane and the mask against depth_map() (docs/algorithm.md
// 12.2-12.5), and the two scratch planes against the left and right maps
// (dL's integer d in sub-pixel mode), every pixel. With rectification the
// reference takes both views' validity (docs/algorithm.md 13.4), and the scratch
// planes hold the mark step's marks at invalid pixels (docs/blocks/rectifier.md 10):
// the flag in dL at an invalid left pixel, 255 in dR at an invalid right one.
void score_lr(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right,
              const Config& cfg, const EngineOptions& opt, EngineResult& r, const RectRef* rr,
              std::ostringstream& rep) {
  const int W = left.width(), H = left.height();
  DepthOptions dopt;
  dopt.lr = true;
  dopt.subpixel = opt.frame.subpixel;
  dopt.tolerance = opt.frame.lr_tolerance;
  if (rr) {
    dopt.left_valid = rr->view[0].valid;
    dopt.right_valid = rr->view[1].valid;
  }
  const DepthResult ref = depth_map(left, right, cfg, dopt);
  r.disparity = Plane(W, H);
  if (opt.frame.subpixel) r.disparity16 = Plane16(W, H);
  r.mask = Plane(W, H);
  const auto bad = [&](const char* what, int x, int y, int got, int want) {
    if (r.mismatches++ >= opt.run.max_reported) return;
    rep << "  " << what << " mismatch at (" << x << "," << y << "): RTL " << got << ", reference "
        << want << " (dL " << int(ref.raw.at(x, y)) << ", dR(x - dL) "
        << (x >= ref.raw.at(x, y) ? std::to_string(ref.right.at(x - ref.raw.at(x, y), y)) : "-")
        << ", valid " << int(ref.valid.at(x, y) != 0) << ")\n";
  };
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int got = out_pixel(mem, lay, x, y);
      const int want = opt.frame.subpixel ? ref.disp16.at(x, y)
                       : rr && ref.disp16.at(x, y) == kRectInvalidDisp16 ? kRectInvalidDisp8
                                                                           : ref.disp16.at(x, y) / kSubpixelScale;
      if (opt.frame.subpixel) {
        r.disparity16.at(x, y) = uint16_t(got);
        r.disparity.at(x, y) = uint8_t(std::min(got / kSubpixelScale, 255));
      } else {
        r.disparity.at(x, y) = uint8_t(got);
      }
      if (got != want) bad(opt.frame.subpixel ? "output 16d+o" : "output d", x, y, got, want);
      else if (rr && mem.times_written(uint32_t(lay.out) + uint32_t(y) * lay.out_stride +
                                       uint32_t(x * lay.out_bpp)) == 0)
        bad("output never written,", x, y, got, want);
      const int mk = at(mem, lay.mask, lay.stride, x, y);
      r.mask.at(x, y) = uint8_t(mk);
      if (mk != ref.valid.at(x, y)) bad("mask", x, y, mk, ref.valid.at(x, y));
      // With rectification the mark step flags dL at invalid left pixels (a byte 0x80,
      // a scratch halfword 0x8000) and writes 255 into dR at invalid right pixels
      // (docs/algorithm.md 13.4), before the post stage reads them.
      const int dl_full = opt.frame.subpixel ? at(mem, lay.dl, lay.out_stride, 2 * x, y) |
                                             at(mem, lay.dl, lay.out_stride, 2 * x + 1, y) << 8
                                       : at(mem, lay.dl, lay.out_stride, x, y);
      const bool l_invalid = rr && !rr->view[0].valid.at(x, y);
      if (l_invalid) {
        const int flag = opt.frame.subpixel ? kRectFlagDisp16 : kRectFlagDisp8;
        if (dl_full != flag) bad("scratch dL (flagged: invalid left pixel)", x, y, dl_full, flag);
      } else {
        const int dl = dl_full & (opt.frame.subpixel ? (1 << kDispBits) - 1 : 0xff);
        if (dl != ref.raw.at(x, y)) bad("scratch dL", x, y, dl, ref.raw.at(x, y));
      }
      const int dr = at(mem, lay.dr, lay.stride, x, y);
      const int dr_want = rr && !rr->view[1].valid.at(x, y) ? kRectInvalidDisp8 : ref.right.at(x, y);
      if (dr != dr_want) bad("scratch dR", x, y, dr, dr_want);
    }
}

}  // namespace

void score(MemoryModel& mem, const Layout& lay, const YuvImage& left, const YuvImage& right,
           const Config& cfg, const EngineOptions& opt, EngineResult& r, const RectRef* rr) {
  std::ostringstream rep;
  if (rr) {
    score_rect(mem, lay, *rr, opt, r, rep);
    r.rect_valid = rr->base_valid(opt.frame.right);
  }
  if (opt.frame.lr) {
    score_lr(mem, lay, left, right, cfg, opt, r, rr, rep);
    r.bus = mem.violations();
    rep << r.bus.describe();
    r.report += rep.str();
    return;
  }
  const int W = left.width(), H = left.height();
  Config ref_cfg = cfg;
  Intermediates keep;
  const Plane ref = opt.frame.right ? disparity_map(mirror(right), mirror(left), ref_cfg, &keep)
                              : disparity_map(left, right, ref_cfg, &keep);
  Plane16 ref16 = opt.frame.subpixel ? subpixel_from_costs(keep, ref, cfg.disparities) : Plane16();
  const Plane* invalid = rr ? &rr->base_valid(opt.frame.right) : nullptr;  // output columns, 0: invalid
  if (rr && opt.frame.subpixel) {
    // 16-bit: the reference's own marking, on the pass's columns (mirrored in the right mode).
    mark_rect_invalid(ref16, opt.frame.right ? mirror(*invalid) : *invalid);
  }
  r.disparity = Plane(W, H);
  if (opt.frame.subpixel) r.disparity16 = Plane16(W, H);
  const auto cost = [&](int d, size_t i) -> std::string {
    return d >= 0 && d < cfg.disparities ? std::to_string(keep.final_cost[d][i]) : "-";
  };
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const int xp = opt.frame.right ? W - 1 - x : x;  // the pass's column
      const int got = out_pixel(mem, lay, x, y);
      const bool marked = invalid && invalid->at(x, y) == 0;
      const int want = opt.frame.subpixel ? ref16.at(xp, y) : marked ? kRectInvalidDisp8 : ref.at(xp, y);
      if (opt.frame.subpixel) {
        r.disparity16.at(x, y) = uint16_t(got);
        r.disparity.at(x, y) = uint8_t(std::min(got / kSubpixelScale, 255));
      } else {
        r.disparity.at(x, y) = uint8_t(got);
      }
      // Rectification: the code is a legal value; a pixel must have been written.
      const bool never =
          rr ? mem.times_written(uint32_t(lay.out) + uint32_t(y) * lay.out_stride + uint32_t(x * lay.out_bpp)) == 0
             : got == (opt.frame.subpixel ? 0xffff : 0xff);
      if (got == want && !(rr && never)) continue;
      if (r.mismatches++ >= opt.run.max_reported) continue;
      const size_t i = size_t(y) * W + xp;
      const int dg = opt.frame.subpixel ? (got + kSubpixelScale / 2) / kSubpixelScale : got;
      const int dw = ref.at(xp, y);
      rep << "  mismatch at (" << x << "," << y << "): RTL " << (opt.frame.subpixel ? "16d+o=" : "d=") << got;
      if (never) rep << " (never written)";
      else if (dg < cfg.disparities) rep << " (cost " << keep.final_cost[dg][i] << ")";
      else rep << " (out of range)";
      rep << ", reference " << (opt.frame.subpixel ? "16d+o=" : "d=") << want;
      if (marked) rep << " (invalid base pixel after rectification; the pass's d=" << dw << ")\n";
      else
        rep << " (d=" << dw << ", costs E(d-1) " << cost(dw - 1, i) << ", E(d) " << cost(dw, i) << ", E(d+1) "
            << cost(dw + 1, i) << ")\n";
    }
  r.bus = mem.violations();
  rep << r.bus.describe();
  r.report += rep.str();
}

// Records the driver's register writes (reads answer the last value written,

}  // namespace mcadsw::sim::bench

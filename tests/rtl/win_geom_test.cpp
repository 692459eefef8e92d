// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// mcadsw_win_geom (the window geometry of a block) against mcadsw::win_geom: every
// output for every block the scheduler issues, over every width from 1 to 2048
// (the left view as base, and the right view mirrored) and every height, at
// DMAX = 64 (the package's), 128 and 16.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "Vwin_geom_d128.h"
#include "Vwin_geom_d16.h"
#include "Vwin_geom_d64.h"
#include "mcadsw/win_geom.hpp"

namespace mcadsw {
namespace {

constexpr int kCoordBits = 12;  // CW: the RTL's signed coordinates have CW + 1 bits

int sext(uint32_t v, int bits) { return int(v << (32 - bits)) >> (32 - bits); }

// Applies `in`, returns the first differing output ("" if none).
template <typename V>
std::string compare(V& t, const WinGeomIn& in, int dmax) {
  const uint32_t mask = (1u << (kCoordBits + 1)) - 1;
  t.x0_i = uint32_t(in.x0) & mask;
  t.y0_i = uint32_t(in.y0) & mask;
  t.cont_i = in.cont;
  t.xlo_i = in.xlo;
  t.xend_i = in.xend;
  t.height_i = in.height;
  t.eval();
  const WinGeom g = win_geom(in, dmax);
  const int cb = kCoordBits + 1;
  const std::pair<const char*, std::pair<int, int>> outs[] = {
      {"lrd_x0", {sext(t.lrd_x0_o, cb), g.lrd_x0}},   {"lrd_strips", {t.lrd_strips_o, g.lrd_strips}},
      {"rrd_x0", {sext(t.rrd_x0_o, cb), g.rrd_x0}},   {"rrd_strips", {t.rrd_strips_o, g.rrd_strips}},
      {"wrd_x0", {sext(t.wrd_x0_o, cb), g.wrd_x0}},   {"wrd_strips", {t.wrd_strips_o, g.wrd_strips}},
      {"cen_y0", {sext(t.cen_y0_o, cb), g.cen_y0}},   {"cl_lo_x", {t.cl_lo_x_o, g.cl_lo_x}},
      {"cl_hi_x", {t.cl_hi_x_o, g.cl_hi_x}},          {"cl_ofs", {t.cl_ofs_o, g.cl_ofs}},
      {"cl_first", {t.cl_first_o, g.cl_first}},       {"cr_lo_x", {t.cr_lo_x_o, g.cr_lo_x}},
      {"cr_hi_x", {t.cr_hi_x_o, g.cr_hi_x}},          {"cr_ofs", {t.cr_ofs_o, g.cr_ofs}},
      {"cr_first", {t.cr_first_o, g.cr_first}},       {"cen_lo_y", {t.cen_lo_y_o, g.cen_lo_y}},
      {"cen_hi_y", {t.cen_hi_y_o, g.cen_hi_y}},       {"w_ofs", {t.w_ofs_o, g.w_ofs}},
      {"w_first", {t.w_first_o, g.w_first}},          {"w_lo", {t.w_lo_o, g.w_lo}},
  };
  for (const auto& [name, v] : outs)
    if (v.first != v.second) {
      std::ostringstream s;
      s << name << ": RTL " << v.first << ", reference " << v.second << " (x0 " << in.x0 << ", y0 "
        << in.y0 << ", cont " << in.cont << ", xlo " << in.xlo << ", xend " << in.xend
        << ", height " << in.height << ", DMAX " << dmax << ")";
      return s.str();
    }
  return "";
}

// Every block of every pass the scheduler runs: block columns bx = 0, 18, ... below
// xend (x0 = bx - 15, cont = bx > 0) and block rows by = 0, 18, ... below the
// height (y0 = by - 15).
template <typename V>
void sweep(int dmax) {
  V t;
  long compared = 0;
  for (int w = 1; w <= kMaxWidth; ++w)
    for (int mirrored = 0; mirrored < 2; ++mirrored) {
      const int w4 = (w + 3) & ~3;
      WinGeomIn in;
      in.xlo = mirrored ? w4 - w : 0;
      in.xend = mirrored ? w4 : w;
      in.height = 1 + (w * 7) % kMaxHeight;
      in.y0 = -kRadius + kBlock * ((w / 3) % ((in.height + kBlock - 1) / kBlock));
      for (int bx = 0; bx < in.xend; bx += kBlock) {
        in.x0 = bx - kRadius;
        in.cont = bx > 0;
        const std::string err = compare(t, in, dmax);
        ASSERT_EQ(err, "");
        ++compared;
      }
    }
  for (int h = 1; h <= kMaxHeight; ++h) {
    WinGeomIn in;
    in.height = h;
    in.xend = 1 + (h * 13) % kMaxWidth;
    in.x0 = -kRadius;
    for (int by = 0; by < h; by += kBlock) {
      in.y0 = by - kRadius;
      const std::string err = compare(t, in, dmax);
      ASSERT_EQ(err, "");
      ++compared;
    }
  }
  std::printf("DMAX %d: %ld blocks compared\n", dmax, compared);
  EXPECT_GT(compared, 200000);
}

TEST(WinGeom, EveryBlockOfEveryWidthDmax64) { sweep<Vwin_geom_d64>(64); }
TEST(WinGeom, EveryBlockOfEveryWidthDmax128) { sweep<Vwin_geom_d128>(128); }
TEST(WinGeom, EveryBlockOfEveryWidthDmax16) { sweep<Vwin_geom_d16>(16); }

}  // namespace
}  // namespace mcadsw

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Window geometry of a block: the reference of rtl/mcadsw_win_geom.sv
// (docs/blocks/engine.md 4, window geometry), compared output by output with the
// RTL block by tests/rtl/win_geom_test.cpp. Plain integer arithmetic with floor
// division, written from the description, not from the RTL.
#pragma once

#include <algorithm>

#include "mcadsw/params.hpp"

namespace mcadsw {

// The block being prepared, in pass columns (the right view as base runs
// mirrored: the image lies in columns xlo .. xend - 1) and rows.
struct WinGeomIn {
  int x0 = 0;        // weight window origin: block column - kRadius
  int y0 = 0;        // block row - kRadius
  bool cont = false; // the block continues its left neighbour (block column > 0)
  int xlo = 0;       // first image column of the pass (0 .. 3)
  int xend = 0;      // the pass's columns end before xend
  int height = 0;
};

struct WinGeom {
  // Window readers: first column read (a multiple of 4), strips (4 columns) to read
  int lrd_x0, lrd_strips, rrd_x0, rrd_strips, wrd_x0, wrd_strips;
  int cen_y0;  // census windows' first row
  // Census transformers: in-image bounds in window columns / rows, offset of the
  // window's first column in its word, strips the reader skipped
  int cl_lo_x, cl_hi_x, cl_ofs, cl_first;
  int cr_lo_x, cr_hi_x, cr_ofs, cr_first;
  int cen_lo_y, cen_hi_y;
  // Weight generator
  int w_ofs, w_first, w_lo;
};

inline int floor_div4(int v) { return v >= 0 ? v / 4 : -((-v + 3) / 4); }

// dmax: the build's DMAX (the right census window is kBlockCols + dmax - 1 wide).
inline WinGeom win_geom(const WinGeomIn& in, int dmax) {
  const int cols = kBlockCols, rcols = kBlockCols + dmax - 1;
  // Strips of each window: its columns plus the census halo (2 a side) and up to
  // 3 columns of alignment, rounded up; the weight window has no halo.
  const int lstrips = (cols + 4 + 6) / 4, rstrips = (rcols + 4 + 6) / 4, wstrips = cols / 4 + 1;
  const int lx = in.x0 - 2;                 // census left: first luma column
  const int rx = in.x0 - (dmax - 1) - 2;    // census right
  const int wx = in.x0;                     // weights
  // A window's strips: from the aligned word at or left of its first column.
  // The first block of a row band skips the strips wholly left of the first
  // column it needs (xlo - 2 for the census, xlo for the weights); a block that
  // continues its left neighbour reads only the words its window adds (the
  // window moved kBlock columns).
  const auto first = [&](int x, int strips, int need) {
    if (in.cont) return strips - (floor_div4(x) - floor_div4(x - kBlock));
    return std::max(0, floor_div4(need - 4 * floor_div4(x)));
  };
  const int l_first = first(lx, lstrips, in.xlo - 2);
  const int r_first = first(rx, rstrips, in.xlo - 2);
  const int w_first = first(wx, wstrips, in.xlo);
  const auto lo = [&](int x0, int lo_img) { return std::max(0, lo_img - x0); };
  const auto hi = [&](int x0, int end, int n) { return std::min(n - 1, end - 1 - x0); };
  const int rx0 = in.x0 - (dmax - 1);       // right census window origin
  WinGeom g{};
  g.lrd_x0 = 4 * (floor_div4(lx) + l_first);
  g.lrd_strips = lstrips - l_first;
  g.rrd_x0 = 4 * (floor_div4(rx) + r_first);
  g.rrd_strips = rstrips - r_first;
  g.wrd_x0 = 4 * (floor_div4(wx) + w_first);
  g.wrd_strips = wstrips - w_first;
  g.cen_y0 = in.y0 - 2;
  g.cl_lo_x = lo(in.x0, in.xlo);
  g.cl_hi_x = hi(in.x0, in.xend, cols);
  g.cl_ofs = lx - 4 * floor_div4(lx);
  g.cl_first = l_first;
  g.cr_lo_x = lo(rx0, in.xlo);
  g.cr_hi_x = hi(rx0, in.xend, rcols);
  g.cr_ofs = rx - 4 * floor_div4(rx);
  g.cr_first = r_first;
  g.cen_lo_y = lo(in.y0, 0);
  g.cen_hi_y = hi(in.y0, in.height, cols);
  g.w_ofs = wx - 4 * floor_div4(wx);
  g.w_first = w_first;
  g.w_lo = lo(in.x0, in.xlo);
  return g;
}

}  // namespace mcadsw

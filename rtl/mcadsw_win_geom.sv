// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Window geometry of a block (docs/blocks/engine.md 4, window geometry): where the
// three window readers start and how many strips they read, and the in-image
// bounds the census transformers and the weight generator clamp to, from the
// block's window origin the scheduler issues. Combinational; the block test
// (tests/rtl/win_geom_test.cpp) compares every output with mcadsw::win_geom.
//
// Windows, in pass columns (the right view as base runs mirrored: the image lies
// in columns xlo_i .. xend_i - 1) and rows:
//   weights       COLS columns from x0, COLS rows from y0 (31 x 48 window, Sec. V-F)
//   census left   the weight window widened by the census halo: COLS + 4 luma
//                 columns from x0 - 2, COLS + 4 rows from y0 - 2
//   census right  the same COLS + DMAX - 1 columns wide, from x0 - (DMAX - 1) - 2
// A reader starts at the aligned memory word at or left of its window's first
// column (floor to a multiple of 4): a strip (4 columns) is one word a row. The
// first block of a row band skips the strips wholly left of what it needs (image
// column -2 for the census, 0 for the weights; the blocks replicate column 0); a
// block that continues its left neighbour (cont_i, Sec. IV partial column reuse)
// reads only the strips its window adds: the aligned origin moved by 4 or 5 words
// with the block's 18 columns.
`default_nettype none

module mcadsw_win_geom #(
  parameter int CW      = 12,                        // coordinate bits (signed: CW + 1)
  parameter int DMAX    = mcadsw_pkg::DMAX,
  parameter int COLS    = mcadsw_pkg::BLOCK_COLS,    // weight window columns and rows (48)
  parameter int RCOLS   = COLS + DMAX - 1,           // right census window columns
  parameter int LSTRIPS = (COLS + 4 + 6) / 4,        // census left strips (14), as the engine sizes its reader
  parameter int RSTRIPS = (RCOLS + 4 + 6) / 4,       // census right strips (30 at DMAX = 64)
  parameter int WSTRIPS = COLS / 4 + 1,              // weight strips (13)
  parameter int RSB     = $clog2(RSTRIPS + 1),       // census right strip count bits
  parameter int RXB     = $clog2(RCOLS)              // census right column bits
) (
  // The block's window (scheduler) and the pass's image
  input  logic signed [CW:0] x0_i,        // weight window origin, pass column (-15 at a row start)
  input  logic signed [CW:0] y0_i,        // weight window origin, row
  input  logic               cont_i,      // the block continues its left neighbour
  input  logic [1:0]         xlo_i,       // first image column of the pass
  input  logic [CW-1:0]      xend_i,      // the pass's columns end before xend_i
  input  logic [CW-1:0]      height_i,
  // Window readers: first column read, strips to read; the census windows' first row
  output logic signed [CW:0] lrd_x0_o,
  output logic [3:0]         lrd_strips_o,
  output logic signed [CW:0] rrd_x0_o,
  output logic [RSB-1:0]     rrd_strips_o,
  output logic signed [CW:0] wrd_x0_o,
  output logic [3:0]         wrd_strips_o,
  output logic signed [CW:0] cen_y0_o,    // census windows' first row (y0 - 2)
  // Census transformers: in-image bounds (window columns / rows), the first
  // luma column's offset in its word, the strips the reader skipped
  output logic [5:0]         cl_lo_x_o,
  output logic [5:0]         cl_hi_x_o,
  output logic [1:0]         cl_ofs_o,
  output logic [3:0]         cl_first_o,
  output logic [RXB-1:0]     cr_lo_x_o,
  output logic [RXB-1:0]     cr_hi_x_o,
  output logic [1:0]         cr_ofs_o,
  output logic [RSB-1:0]     cr_first_o,
  output logic [5:0]         cen_lo_y_o,
  output logic [5:0]         cen_hi_y_o,
  // Weight generator: offset in the word, strips skipped, first in-image column
  output logic [1:0]         w_ofs_o,
  output logic [3:0]         w_first_o,
  output logic [5:0]         w_lo_o
);

  // In-image bounds of a window starting at x0 (n columns or rows): the image
  // starts at lo and ends before w. Up to RCOLS - 1 (the right census window).
  localparam int BW = $clog2(RCOLS + 1);
  function automatic logic [BW-1:0] lo_bound(input logic signed [CW:0] x0, input logic [1:0] lo);
    logic signed [CW:0] l;
    l = $signed({{(CW - 1){1'b0}}, lo}) - x0;
    lo_bound = (l > 0) ? BW'(l) : '0;
  endfunction
  function automatic logic [BW-1:0] hi_bound(input logic signed [CW:0] x0, input logic [CW-1:0] w,
                                             input int n);
    logic signed [CW+1:0] h;
    h = $signed({2'b00, w}) - 1 - x0;
    hi_bound = (32'(h) > n - 1) ? BW'(n - 1) : BW'(h);
  endfunction
  // Strips a continuing block skips: floor(x / 4) - floor((x - BLOCK) / 4) =
  // ceil((BLOCK - x mod 4) / 4) words are new.
  function automatic logic [5:0] cont_first(input logic [1:0] xin_ofs, input int strips);
    cont_first = 6'(strips - (mcadsw_pkg::BLOCK + 3 - 32'(xin_ofs)) / 4);
  endfunction

  logic signed [CW:0] rx0;                // right census window origin
  assign rx0 = x0_i - (CW + 1)'(DMAX - 1);

  logic signed [CW:0] lx_in, rx_in;       // first luma input column of the census windows
  assign lx_in = x0_i - (CW + 1)'(2);
  assign rx_in = rx0 - (CW + 1)'(2);
  logic signed [CW:0] lx_al, rx_al, wx_al; // aligned window origins
  assign lx_al = {lx_in[CW:2], 2'b00};
  assign rx_al = {rx_in[CW:2], 2'b00};
  assign wx_al = {x0_i[CW:2], 2'b00};

  // The first block of a row band: the census windows skip the strips left of
  // the one holding image column lo - 2, the weight window those left of lo.
  // (Written -x - N'(2): Yosys 0.23 parses a unary minus before a size cast,
  // -(N)'(2), as a cast to the size -(N), i.e. +2; flow/rtl_check.py rejects it.)
  logic signed [CW:0] xlo_s, lx_skip, rx_skip, wx_skip;
  assign xlo_s   = $signed({{(CW - 1){1'b0}}, xlo_i});
  assign lx_skip = xlo_s - lx_al - (CW + 1)'(2);
  assign rx_skip = xlo_s - rx_al - (CW + 1)'(2);
  assign wx_skip = xlo_s - wx_al;
  logic [5:0] l_first, r_first, w_first;
  assign l_first = cont_i ? cont_first(lx_in[1:0], LSTRIPS) :
                   (lx_skip > 0) ? 6'(lx_skip >>> 2) : 6'd0;
  assign r_first = cont_i ? cont_first(rx_in[1:0], RSTRIPS) :
                   (rx_skip > 0) ? 6'(rx_skip >>> 2) : 6'd0;
  assign w_first = cont_i ? cont_first(x0_i[1:0], WSTRIPS) :
                   (wx_skip > 0) ? 6'(wx_skip >>> 2) : 6'd0;

  assign lrd_x0_o     = lx_al + (CW + 1)'(4 * 32'(l_first));
  assign rrd_x0_o     = rx_al + (CW + 1)'(4 * 32'(r_first));
  assign wrd_x0_o     = wx_al + (CW + 1)'(4 * 32'(w_first));
  assign lrd_strips_o = 4'(LSTRIPS - 32'(l_first));
  assign rrd_strips_o = RSB'(RSTRIPS - 32'(r_first));
  assign wrd_strips_o = 4'(WSTRIPS - 32'(w_first));
  assign cen_y0_o     = y0_i - (CW + 1)'(2);

  assign cl_lo_x_o  = 6'(lo_bound(x0_i, xlo_i));
  assign cl_hi_x_o  = 6'(hi_bound(x0_i, xend_i, COLS));
  assign cl_ofs_o   = lx_in[1:0];
  assign cl_first_o = 4'(l_first);
  assign cr_lo_x_o  = RXB'(lo_bound(rx0, xlo_i));
  assign cr_hi_x_o  = RXB'(hi_bound(rx0, xend_i, RCOLS));
  assign cr_ofs_o   = rx_in[1:0];
  assign cr_first_o = RSB'(r_first);
  assign cen_lo_y_o = 6'(lo_bound(y0_i, 2'd0));
  assign cen_hi_y_o = 6'(hi_bound(y0_i, height_i, COLS));
  assign w_ofs_o    = x0_i[1:0];
  assign w_first_o  = 4'(w_first);
  assign w_lo_o     = 6'(lo_bound(x0_i, xlo_i));

endmodule

`default_nettype wire

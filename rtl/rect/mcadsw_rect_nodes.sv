// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Rectifier: the mesh nodes of one output tile and its source rectangle
// (docs/algorithm.md 13.8, docs/blocks/rectifier.md 4).
//
// At start_i the block registers the tile and the frame and names the tile's nodes
// (columns node_i0_o .. + ncols_o - 1, rows node_j0_o .. + nrows_o - 1), which the
// caller reads from memory row by row, each node u then v, and hands in on word_i
// (word_valid_i, in that order). The block keeps them (node_u_o / node_v_o, node (i, j)
// relative to the first at index NODE_COLS j + i, the sampling core's layout), flags a
// word that is not an 18-bit value sign-extended (range_err_o: outside -4096 ..
// 4096 pixels, 13.1), and after the last word computes the source rectangle of 13.8:
// empty_o, or its word-aligned origin (src_x0_o, src_y0_o), its size (src_cols_o x
// src_rows_o) and whether it fits the tile buffer (fits_o). done_o pulses then; the
// outputs hold until the next start.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_rect_nodes #(
  parameter int CW  = 12,
  parameter int NB  = mcadsw_rect_pkg::MESH_NODE_BITS,
  parameter int FB  = mcadsw_rect_pkg::MESH_FRAC_BITS,
  parameter int TW  = mcadsw_rect_pkg::RECT_TILE_W,
  parameter int TH  = mcadsw_rect_pkg::RECT_TILE_H,
  parameter int BW  = mcadsw_rect_pkg::RECT_BUF_W,
  parameter int BH  = mcadsw_rect_pkg::RECT_BUF_H,
  parameter int NODE_COLS = TW / 8 + 1,
  parameter int NODE_ROWS = TH / 8 + 1,
  parameter int NODES = NODE_COLS * NODE_ROWS
) (
  input  logic                 clk_i,
  input  logic                 rst_ni,
  // A tile (registered at start_i)
  input  logic                 start_i,
  input  logic [2:0]           step_log2_i,
  input  logic [CW-1:0]        tile_x0_i,            // a multiple of TW
  input  logic [CW-1:0]        tile_y0_i,            // a multiple of TH
  input  logic [CW-1:0]        width_i,              // the rectified frame, 1 .. 2048
  input  logic [CW-1:0]        height_i,
  input  logic [CW-1:0]        raw_w_i,              // the raw view, 1 .. 2048
  input  logic [CW-1:0]        raw_h_i,
  output logic [CW-1:0]        node_i0_o,            // the tile's first node column and row
  output logic [CW-1:0]        node_j0_o,
  output logic [2:0]           ncols_o,              // 2 .. NODE_COLS
  output logic [1:0]           nrows_o,              // 2 .. NODE_ROWS
  // The nodes' words, row by row, u then v
  input  logic                 word_valid_i,
  input  logic [31:0]          word_i,
  output logic                 busy_o,
  output logic                 done_o,
  // Results (from done_o until the next start)
  output logic [NODES*NB-1:0]  node_u_o,
  output logic [NODES*NB-1:0]  node_v_o,
  output logic                 range_err_o,
  output logic                 empty_o,
  output logic                 fits_o,
  output logic [CW-1:0]        src_x0_o,
  output logic [CW-1:0]        src_y0_o,
  output logic [CW:0]          src_cols_o,           // up to 2048 + 3
  output logic [CW:0]          src_rows_o
);
  // ---- The tile's nodes ---------------------------------------------------------------------
  logic [2:0] s;
  logic [CW-1:0] xl, yl, i0, j0, i1, j1;
  assign s  = step_log2_i;
  // Last column and row of the tile: min(x0 + TW - 1, W - 1)
  assign xl = width_i - tile_x0_i > CW'(TW) ? tile_x0_i + CW'(TW - 1) : width_i - CW'(1);
  assign yl = height_i - tile_y0_i > CW'(TH) ? tile_y0_i + CW'(TH - 1) : height_i - CW'(1);
  assign i0 = tile_x0_i >> s;
  assign j0 = tile_y0_i >> s;
  assign i1 = (xl >> s) + CW'(1);
  assign j1 = (yl >> s) + CW'(1);

  logic [CW-1:0] rw_q, rh_q;
  logic [2:0]    ncols_q;
  logic [1:0]    nrows_q;
  logic [2:0]    ci_q;                              // node column of the next word
  logic [1:0]    cj_q;                              // node row
  logic          v_q;                               // the next word is v
  logic          busy_q, fin_q;
  localparam int XB = NB + 1;                       // the box: 1/64 pixel
  logic signed [XB-1:0] umin_q, umax_q, vmin_q, vmax_q;
  logic          half_q;                            // the step is larger than the tile's height
  logic          lower_q;                           // the tile is a cell row's lower half
  logic          range_q;

  logic signed [NB-1:0] val;
  logic                 word_ok;
  assign val     = word_i[NB-1:0];
  assign word_ok = word_i[31:NB-1] == '0 || word_i[31:NB-1] == '1;
  logic last_word;
  assign last_word = v_q && ci_q == ncols_q - 3'd1 && cj_q == nrows_q - 2'd1;
  // The box (docs/algorithm.md 13.8), in 1/64 pixel: twice each node; at a step larger
  // than the tile's height (the tile is half a cell row) the node of the cell row's near
  // edge twice, and at the other edge the midpoint of the node column's two nodes (their
  // sum: the word's node and the column's row-0 node, stored). A word adds up to two
  // candidates.
  localparam logic signed [XB-1:0] BIG = {1'b0, {(XB - 1){1'b1}}};
  localparam logic signed [XB-1:0] SMALL = {1'b1, {(XB - 1){1'b0}}};
  logic signed [NB-1:0] near0;                      // the word's column's row-0 node
  assign near0 = v_q ? node_v_o[32'(ci_q) * NB +: NB] : node_u_o[32'(ci_q) * NB +: NB];
  logic take_dir, take_mid;
  assign take_dir = !half_q || ((cj_q == 2'd0) != lower_q);
  assign take_mid = half_q && cj_q == 2'd1;
  logic signed [XB-1:0] c_dir, c_mid, lo_a, lo_b, hi_a, hi_b;
  assign c_dir = {val, 1'b0};
  assign c_mid = XB'(near0) + XB'(val);
  assign lo_a = take_dir ? c_dir : BIG;
  assign lo_b = take_mid ? c_mid : BIG;
  assign hi_a = take_dir ? c_dir : SMALL;
  assign hi_b = take_mid ? c_mid : SMALL;
  function automatic logic signed [XB-1:0] smin3(input logic signed [XB-1:0] a, b, c);
    logic signed [XB-1:0] m;
    m = a < b ? a : b;
    smin3 = m < c ? m : c;
  endfunction
  function automatic logic signed [XB-1:0] smax3(input logic signed [XB-1:0] a, b, c);
    logic signed [XB-1:0] m;
    m = a > b ? a : b;
    smax3 = m > c ? m : c;
  endfunction

  // Control (reset)
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      ncols_q <= 3'd2; nrows_q <= 2'd2; ci_q <= '0; cj_q <= '0; v_q <= 1'b0;
      busy_q <= 1'b0; fin_q <= 1'b0; range_q <= 1'b0;
    end else begin
      fin_q <= 1'b0;
      if (start_i && !busy_q) begin
        ncols_q <= 3'(i1 - i0 + CW'(1));
        nrows_q <= 2'(j1 - j0 + CW'(1));
        ci_q <= '0; cj_q <= '0; v_q <= 1'b0; range_q <= 1'b0;
        busy_q <= 1'b1;
      end else if (busy_q && word_valid_i) begin
        range_q <= range_q || !word_ok;
        v_q <= !v_q;
        if (v_q) begin
          if (ci_q == ncols_q - 3'd1) begin
            ci_q <= '0;
            cj_q <= cj_q + 2'd1;
          end else begin
            ci_q <= ci_q + 3'd1;
          end
        end
        if (last_word) begin
          busy_q <= 1'b0;
          fin_q <= 1'b1;
        end
      end
    end
  end
  // Data (no reset: each is written before it is used; a node the tile does not have is
  // never read)
  always_ff @(posedge clk_i) begin
    if (start_i && !busy_q) begin
      rw_q <= raw_w_i; rh_q <= raw_h_i;
      node_i0_o <= i0; node_j0_o <= j0;
      half_q <= 32'(1) << s > TH;
      lower_q <= (32'(tile_y0_i) & ((32'(1) << s) - 1)) != 0;
      umin_q <= BIG; vmin_q <= BIG; umax_q <= SMALL; vmax_q <= SMALL;
    end else if (busy_q && word_valid_i) begin
      if (v_q) begin
        for (int n = 0; n < NODES; n++)   // decoded: no shifter across the store
          if (32'(cj_q) * NODE_COLS + 32'(ci_q) == n) node_v_o[n * NB +: NB] <= val;
        vmin_q <= smin3(vmin_q, lo_a, lo_b);
        vmax_q <= smax3(vmax_q, hi_a, hi_b);
      end else begin
        for (int n = 0; n < NODES; n++)   // decoded: no shifter across the store
          if (32'(cj_q) * NODE_COLS + 32'(ci_q) == n) node_u_o[n * NB +: NB] <= val;
        umin_q <= smin3(umin_q, lo_a, lo_b);
        umax_q <= smax3(umax_q, hi_a, hi_b);
      end
    end
  end

  // ---- The source rectangle (registered a cycle after the last word) ------------------------
  localparam int PB = NB - FB + 1;                   // a pixel coordinate, signed, + 1 of headroom
  logic signed [PB-1:0] uf, ut, vf, vt;               // floor(min), floor(max) + 1, pixels
  logic signed [XB:0]   umax1, vmax1;                 // the largest, 1/64 pixel, + 1
  assign umax1 = (XB + 1)'(umax_q) + (XB + 1)'(1);
  assign vmax1 = (XB + 1)'(vmax_q) + (XB + 1)'(1);
  assign uf = PB'(umin_q >>> (FB + 1));              // floor of the box's 1/32 pixel: >> 1
  assign ut = PB'(umax1 >>> (FB + 1)) + PB'(1);      // ceiling: (x + 1) >> 1
  assign vf = PB'(vmin_q >>> (FB + 1));
  assign vt = PB'(vmax1 >>> (FB + 1)) + PB'(1);
  logic signed [PB:0] rwm1, rhm1, xf, xt, yf, yt;     // one more bit: raw sizes up to 2048
  assign rwm1 = (PB + 1)'({1'b0, rw_q}) - (PB + 1)'(1);
  assign rhm1 = (PB + 1)'({1'b0, rh_q}) - (PB + 1)'(1);
  assign xf = uf < 0 ? '0 : (PB + 1)'(uf);
  assign yf = vf < 0 ? '0 : (PB + 1)'(vf);
  assign xt = (PB + 1)'(ut) > rwm1 ? rwm1 : (PB + 1)'(ut);
  assign yt = (PB + 1)'(vt) > rhm1 ? rhm1 : (PB + 1)'(vt);
  logic empty;
  assign empty = xf > xt || yf > yt;
  logic [CW-1:0] x0;
  assign x0 = CW'(xf) & ~(CW'(3));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      done_o <= 1'b0; range_err_o <= 1'b0; empty_o <= 1'b0; fits_o <= 1'b0;
    end else begin
      done_o <= fin_q;
      if (fin_q) begin
        range_err_o <= range_q;
        empty_o     <= empty;
        fits_o      <= empty || ((CW + 1)'(xt) - (CW + 1)'(x0) < (CW + 1)'(BW) &&
                                 (CW + 1)'(yt) - (CW + 1)'(yf) < (CW + 1)'(BH));
      end
    end
  end
  always_ff @(posedge clk_i) begin                   // data: read with done_o
    if (fin_q) begin
      src_x0_o   <= empty ? '0 : x0;
      src_y0_o   <= empty ? '0 : CW'(yf);
      src_cols_o <= empty ? '0 : (CW + 1)'(xt) - (CW + 1)'(x0) + (CW + 1)'(1);
      src_rows_o <= empty ? '0 : (CW + 1)'(yt) - (CW + 1)'(yf) + (CW + 1)'(1);
    end
  end

  assign busy_o  = busy_q || fin_q;
  assign ncols_o = ncols_q;
  assign nrows_o = nrows_q;

  `MCADSW_ASSUME(start_when_idle, !(start_i && busy_o))
  `MCADSW_ASSERT(node_in_store, !busy_q || (32'(ci_q) < NODE_COLS && 32'(cj_q) < NODE_ROWS))
endmodule

`default_nettype wire

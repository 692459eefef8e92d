// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Rectifier sampling core (docs/algorithm.md 13.2-13.3, docs/blocks/rectifier.md 3):
// one output tile's pixels from the tile's mesh nodes and a loaded tile buffer, a
// pixel a cycle, in strip order (4-column strips, each top to bottom, the pixels of a
// strip row left to right).
//
//   stage 0  the mesh interpolation, incremental and exact: the sum of 13.2 of the
//            pixel (30-bit registers, one add a cycle)
//   stage 1  p = (sum + 2^(2s-1)) >> 2s, in 1/32 pixel
//   stage 2  validity, the taps' bank addresses (the banks read them)
//   stage 3  the bank words -> taps a b c d; h0 = (32-fu) a + fu b, h1 = (32-fu) c + fu d
//   stage 4  out = ((32-fv) h0 + fv h1 + 512) >> 10, or the invalid value
//
// Interpolation (cell offsets ox, oy; nodes n00 n10 n01 n11 of the cell):
//   sum = (S - ox) A + ox B,  A = (S - oy) n00 + oy n01,  B = (S - oy) n10 + oy n11.
// With D = B - A, a strip row's first pixel is sum0 = S A + ox0 D and each next one
// adds D; a row down adds R = S (n01 - n00) + ox0 dD to sum0 and dD = (n11 - n10) -
// (n01 - n00) to D. At a cell's lower edge A = S n01, the next cell's S n00, so sum0
// and D run on and only R and dD change (a setup cycle). The next strip in the same
// cell starts at sum0_top + 4 D_top with R_top + 4 dD_top; a strip in a new cell
// column, and a tile, start with a setup cycle from the cell's nodes. The tile's
// first strip has ox0 = 0 (tiles start at multiples of 32) and oy0 = ty0 mod S, 0 or
// (S = 32) 16.
//
// Tile buffer: RECT_BUF_W x RECT_BUF_H source pixels from (src_x0, src_y0) (src_x0 a
// multiple of 4), four banks b = {row parity, column parity} of the pixel's offset
// (lx, ly) in it, each RECT_BUF_H/2 x RECT_BUF_W/4 words of 16 bits: pixel (lx, ly)
// is bank {ly[0], lx[0]}, word (ly >> 1) * RECT_BUF_W/4 + (lx >> 2), byte lx[1]. The
// four taps of a pixel lie in four different banks. Synchronous read: address and
// read enable in a cycle, data the next (held while the enable is low).
//
// A tile: start_i (taken in a cycle with en_i, while not busy) with the configuration
// (registered), the nodes on node_u_i / node_v_i held until busy_o falls: node (i, j)
// relative to the tile's first node (tile_x0 >> s, tile_y0 >> s) at index
// NODE_COLS j + i. The caller guarantees that
// every valid pixel's taps lie inside the buffer (docs/blocks/rectifier.md 1: the
// source rectangle); a tap right of or below the raw view has weight 0 and may read
// anything. en_i low stalls every stage (the consumer's back pressure).
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_rect_sample #(
  parameter int CW  = 12,                              // coordinates, sizes
  parameter int NB  = mcadsw_rect_pkg::MESH_NODE_BITS,      // a node coordinate, signed
  parameter int TW  = mcadsw_rect_pkg::RECT_TILE_W,
  parameter int TH  = mcadsw_rect_pkg::RECT_TILE_H,
  parameter int BW  = mcadsw_rect_pkg::RECT_BUF_W,
  parameter int BH  = mcadsw_rect_pkg::RECT_BUF_H,
  parameter int NODE_COLS = TW / 8 + 1,                // nodes of a tile at S = 8
  parameter int NODE_ROWS = TH / 8 + 1,
  parameter int NODES = NODE_COLS * NODE_ROWS,
  parameter int BAW = $clog2(BH / 2 * BW / 4)          // bank address bits
) (
  input  logic                  clk_i,
  input  logic                  rst_ni,
  input  logic                  en_i,                  // 0: every stage holds
  // A tile (registered at start_i)
  input  logic                  start_i,
  input  logic [2:0]            step_log2_i,           // s: S = 8, 16, 32
  input  logic [CW-1:0]         tile_y0_i,             // a multiple of TH (the tile's x0, a
                                                       // multiple of TW, does not enter)
  input  logic [5:0]            tile_w_i,              // 1 .. TW (clipped at the frame)
  input  logic [4:0]            tile_h_i,              // 1 .. TH
  input  logic [CW-1:0]         src_x0_i,              // the buffer's origin in the raw view
  input  logic [CW-1:0]         src_y0_i,
  input  logic [CW-1:0]         raw_w_i,               // raw view 1 .. 2048
  input  logic [CW-1:0]         raw_h_i,
  input  logic                  uv_i,                  // U or V plane: invalid pixels 128
  input  logic [NODES*NB-1:0]   node_u_i,              // held while busy
  input  logic [NODES*NB-1:0]   node_v_i,
  output logic                  busy_o,
  // The four banks' read ports, bank b = {row parity, column parity}
  output logic [3:0]            bank_re_o,
  output logic [4*BAW-1:0]      bank_addr_o,
  input  logic [4*16-1:0]       bank_rdata_i,
  // Output stream, strip order
  output logic                  pix_valid_o,
  output logic [7:0]            pix_o,
  output logic                  pix_ok_o,              // 13.3's validity
  output logic [4:0]            pix_x_o,               // position in the tile
  output logic [3:0]            pix_y_o,
  output logic                  pix_last_o             // the tile's last pixel
);
  localparam int SW = 30;                              // sums: |sum| < 2^28
  localparam int PW = SW - 6;                          // positions after >> 2s

  // ---- Tile registers ----------------------------------------------------------------------
  logic [2:0]      s_q;
  logic [5:0]      tw_q;
  logic [4:0]      th_q;
  logic [CW-1:0]   bx0_q, by0_q, rw_q, rh_q;
  logic            uv_q;
  logic            oy0_q;                             // the tile starts mid-cell (S = 32)

  // ---- Stage 0: iteration ------------------------------------------------------------------
  typedef enum logic [1:0] {StIdle, StSetup, StRun} state_e;
  state_e          state_q;
  logic            setup_cross_q;                     // the setup is a cell-row crossing
  logic [2:0]      k_q;                               // strip
  logic [3:0]      r_q;                               // row in the tile
  logic [1:0]      c_q;                               // pixel in the strip row
  logic [2:0]      ci_q;                              // node column of the strip's cell
  logic [1:0]      cj_q;                              // node row of the row's cell
  logic signed [SW-1:0] sum_u_q, sum0_u_q, d_u_q, r_u_q, dd_u_q, sum0t_u_q, dt_u_q, rt_u_q, ddt_u_q;
  logic signed [SW-1:0] sum_v_q, sum0_v_q, d_v_q, r_v_q, dd_v_q, sum0t_v_q, dt_v_q, rt_v_q, ddt_v_q;

  // The cell's nodes
  function automatic logic signed [SW-1:0] node(input logic [NODES*NB-1:0] n, input int i, input int j);
    node = SW'($signed(n[(j * NODE_COLS + i) * NB +: NB]));
  endfunction
  logic signed [SW-1:0] u00, u10, u01, u11, v00, v10, v01, v11;
  always_comb begin
    u00 = '0; u10 = '0; u01 = '0; u11 = '0;
    v00 = '0; v10 = '0; v01 = '0; v11 = '0;
    for (int i = 0; i < NODE_COLS - 1; i++)
      for (int j = 0; j < NODE_ROWS - 1; j++)
        if (32'(ci_q) == i && 32'(cj_q) == j) begin
          u00 = node(node_u_i, i, j);     v00 = node(node_v_i, i, j);
          u10 = node(node_u_i, i + 1, j); v10 = node(node_v_i, i + 1, j);
          u01 = node(node_u_i, i, j + 1); v01 = node(node_v_i, i, j + 1);
          u11 = node(node_u_i, i + 1, j + 1); v11 = node(node_v_i, i + 1, j + 1);
        end
  end

  // A setup from the cell's nodes: the top of a strip at ox0 = 0, or (crossing) the
  // lower cell's R and dD at the strip's ox0 (S = 8: 0 or 4).
  logic signed [SW-1:0] da_u, ddl_u, a_u, dtop_u, rset_u, da_v, ddl_v, a_v, dtop_v, rset_v;
  logic                 ox4;                          // the strip's ox0 is 4 (S = 8)
  assign ox4 = k_q[0] && s_q == 3'd3;
  always_comb begin
    da_u   = u01 - u00;
    ddl_u  = (u11 - u10) - (u01 - u00);
    a_u    = oy0_q ? (u00 + u01) <<< 4 : u00 <<< s_q;
    dtop_u = oy0_q ? ((u10 - u00) + (u11 - u01)) <<< 4 : (u10 - u00) <<< s_q;
    rset_u = (da_u <<< s_q) + (ox4 ? ddl_u <<< 2 : '0);
    da_v   = v01 - v00;
    ddl_v  = (v11 - v10) - (v01 - v00);
    a_v    = oy0_q ? (v00 + v01) <<< 4 : v00 <<< s_q;
    dtop_v = oy0_q ? ((v10 - v00) + (v11 - v01)) <<< 4 : (v10 - v00) <<< s_q;
    rset_v = (da_v <<< s_q) + (ox4 ? ddl_v <<< 2 : '0);
  end

  // Where the iteration goes after this pixel
  logic [5:0] strip_x;                                // 4 k
  logic [2:0] pw_m1;                                  // pixels in this strip row - 1
  logic       row_end, strip_end, tile_end, cross_next, newcol_next;
  logic [5:0] left;
  assign strip_x = {1'b0, k_q, 2'b00};
  assign left    = tw_q - strip_x;                    // >= 1 while running
  assign pw_m1   = left >= 6'd4 ? 3'd3 : 3'(left - 6'd1);
  assign row_end   = {1'b0, c_q} == pw_m1;
  assign strip_end = row_end && {1'b0, r_q} == th_q - 5'd1;
  assign tile_end  = strip_end && strip_x + 6'd4 >= tw_q;
  // The next row enters a new cell row: (oy0 + r + 1) mod S == 0
  logic [5:0] oy_next;
  assign oy_next    = (oy0_q ? 6'd16 : 6'd0) + {2'b0, r_q} + 6'd1;
  assign cross_next = (oy_next & ((6'd1 << s_q) - 6'd1)) == 6'd0;
  // The next strip starts a new cell column: 4 (k + 1) mod S == 0
  logic [5:0] x_next;
  assign x_next      = strip_x + 6'd4;
  assign newcol_next = (x_next & ((6'd1 << s_q) - 6'd1)) == 6'd0;

  logic emit0;                                        // stage 0 presents a pixel
  assign emit0 = state_q == StRun;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      state_q <= StIdle;
      setup_cross_q <= 1'b0;
      k_q <= '0; r_q <= '0; c_q <= '0; ci_q <= '0; cj_q <= '0;
      s_q <= 3'd4; tw_q <= '0; th_q <= '0; bx0_q <= '0; by0_q <= '0; rw_q <= '0; rh_q <= '0;
      uv_q <= 1'b0; oy0_q <= 1'b0;
    end else if (en_i) begin
      case (state_q)
        StIdle: if (start_i) begin
          s_q <= step_log2_i; tw_q <= tile_w_i; th_q <= tile_h_i;
          bx0_q <= src_x0_i; by0_q <= src_y0_i; rw_q <= raw_w_i; rh_q <= raw_h_i; uv_q <= uv_i;
          oy0_q <= step_log2_i == 3'd5 && tile_y0_i[4];
          k_q <= '0; r_q <= '0; c_q <= '0; ci_q <= '0; cj_q <= '0;
          setup_cross_q <= 1'b0;
          state_q <= StSetup;
        end
        StSetup: state_q <= StRun;
        StRun: begin
          if (!row_end) begin
            c_q <= c_q + 2'd1;
          end else if (!strip_end) begin                // next row of the strip
            c_q <= '0;
            r_q <= r_q + 4'd1;
            if (cross_next) begin
              cj_q <= cj_q + 2'd1;
              setup_cross_q <= 1'b1;
              state_q <= StSetup;
            end
          end else if (!tile_end) begin                 // next strip
            c_q <= '0;
            r_q <= '0;
            k_q <= k_q + 3'd1;
            cj_q <= '0;
            if (newcol_next) begin
              ci_q <= ci_q + 3'd1;
              setup_cross_q <= 1'b0;
              state_q <= StSetup;
            end
          end else begin
            state_q <= StIdle;
          end
        end
        default: state_q <= StIdle;
      endcase
    end
  end

  // The interpolation's sums and steps (no reset: a tile's setup writes them before its
  // first pixel)
  always_ff @(posedge clk_i) begin
    if (en_i) begin
      if (state_q == StSetup) begin
        if (setup_cross_q) begin
          r_u_q <= rset_u; dd_u_q <= ddl_u;
          r_v_q <= rset_v; dd_v_q <= ddl_v;
        end else begin
          sum0t_u_q <= a_u <<< s_q; dt_u_q <= dtop_u; rt_u_q <= da_u <<< s_q; ddt_u_q <= ddl_u;
          sum0t_v_q <= a_v <<< s_q; dt_v_q <= dtop_v; rt_v_q <= da_v <<< s_q; ddt_v_q <= ddl_v;
          sum0_u_q <= a_u <<< s_q; sum_u_q <= a_u <<< s_q; d_u_q <= dtop_u; r_u_q <= da_u <<< s_q;
          dd_u_q <= ddl_u;
          sum0_v_q <= a_v <<< s_q; sum_v_q <= a_v <<< s_q; d_v_q <= dtop_v; r_v_q <= da_v <<< s_q;
          dd_v_q <= ddl_v;
        end
      end else if (state_q == StRun) begin
        if (!row_end) begin
          sum_u_q <= sum_u_q + d_u_q;
          sum_v_q <= sum_v_q + d_v_q;
        end else if (!strip_end) begin                  // next row of the strip
          sum0_u_q <= sum0_u_q + r_u_q; sum_u_q <= sum0_u_q + r_u_q; d_u_q <= d_u_q + dd_u_q;
          sum0_v_q <= sum0_v_q + r_v_q; sum_v_q <= sum0_v_q + r_v_q; d_v_q <= d_v_q + dd_v_q;
        end else if (!tile_end && !newcol_next) begin   // next strip in the same cell column
          sum0t_u_q <= sum0t_u_q + (dt_u_q <<< 2); rt_u_q <= rt_u_q + (ddt_u_q <<< 2);
          sum0t_v_q <= sum0t_v_q + (dt_v_q <<< 2); rt_v_q <= rt_v_q + (ddt_v_q <<< 2);
          sum0_u_q <= sum0t_u_q + (dt_u_q <<< 2); sum_u_q <= sum0t_u_q + (dt_u_q <<< 2);
          d_u_q <= dt_u_q; r_u_q <= rt_u_q + (ddt_u_q <<< 2); dd_u_q <= ddt_u_q;
          sum0_v_q <= sum0t_v_q + (dt_v_q <<< 2); sum_v_q <= sum0t_v_q + (dt_v_q <<< 2);
          d_v_q <= dt_v_q; r_v_q <= rt_v_q + (ddt_v_q <<< 2); dd_v_q <= ddt_v_q;
        end
      end
    end
  end

  // ---- Stage 1: the position in 1/32 pixel --------------------------------------------------
  logic                 v1_q, last1_q;
  logic [4:0]           x1_q;
  logic [3:0]           y1_q;
  logic signed [PW-1:0] pu1_q, pv1_q;
  function automatic logic signed [PW-1:0] round_shift(input logic signed [SW-1:0] sum, input logic [2:0] s);
    logic signed [SW-1:0] half;
    half = SW'(1) <<< (2 * s - 1);
    round_shift = PW'((sum + half) >>> (2 * s));       // |p| < 2^17: the upper bits are signs
  endfunction
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      v1_q <= 1'b0; last1_q <= 1'b0; x1_q <= '0; y1_q <= '0; pu1_q <= '0; pv1_q <= '0;
    end else if (en_i) begin
      v1_q <= emit0;
      last1_q <= emit0 && tile_end;
      x1_q <= 5'(strip_x) + 5'(c_q);
      y1_q <= r_q;
      pu1_q <= round_shift(sum_u_q, s_q);
      pv1_q <= round_shift(sum_v_q, s_q);
    end
  end

  // ---- Stage 2: validity and the bank addresses ---------------------------------------------
  // Valid: 0 <= p <= 32 (raw size - 1) in both coordinates (13.3).
  logic                 ok1;
  logic signed [PW-1:0] lim_u, lim_v;
  assign lim_u = PW'({rw_q - CW'(1), 5'b0});
  assign lim_v = PW'({rh_q - CW'(1), 5'b0});
  assign ok1 = pu1_q >= 0 && pu1_q <= lim_u && pv1_q >= 0 && pv1_q <= lim_v;
  // Offsets in the buffer (meaningful when valid), modulo the buffer's size
  localparam int XB = $clog2(BW / 4);                 // word column bits (BW / 4 a power of 2)
  localparam int YB = BAW - XB;                        // bank row bits
  logic [CW-1:0]   ui, vi;
  logic [XB+1:0]   lx, lx1;
  logic [YB:0]     ly, ly1;
  assign ui  = pu1_q[5 +: CW];
  assign vi  = pv1_q[5 +: CW];
  assign lx  = (XB + 2)'(ui - bx0_q);
  assign ly  = (YB + 1)'(vi - by0_q);
  assign lx1 = lx + 1'b1;                              // a tap past the buffer wraps: weight 0
  assign ly1 = ly + 1'b1;
  // Taps a (lx, ly), b (lx+1, ly), c (lx, ly+1), d (lx+1, ly+1): bank {py, px} holds the
  // tap whose row has parity py and whose column has parity px.
  logic [4*BAW-1:0] addr;
  for (genvar b = 0; b < 4; b++) begin : g_bank
    logic [XB+1:0] bx;
    logic [YB:0]   by;
    assign bx = lx[0] == b[0] ? lx : lx1;
    assign by = ly[0] == b[1] ? ly : ly1;
    assign addr[b * BAW +: BAW] = {by[YB:1], bx[XB+1:2]};
    logic unused_bits;
    assign unused_bits = by[0] ^ bx[0] ^ bx[1];
  end
  assign bank_addr_o = addr;
  assign bank_re_o   = {4{en_i && v1_q}};

  logic       v2_q, last2_q, ok2_q;
  logic [4:0] x2_q;
  logic [3:0] y2_q;
  logic [4:0] fu2_q, fv2_q;
  logic       lxo2_q, lyo2_q;                         // tap a's column and row parity
  logic       lxb2_q, lxb12_q;                        // byte of a / c and of b / d in their word
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      v2_q <= 1'b0; last2_q <= 1'b0; ok2_q <= 1'b0; x2_q <= '0; y2_q <= '0; fu2_q <= '0; fv2_q <= '0;
      lxo2_q <= 1'b0; lyo2_q <= 1'b0; lxb2_q <= 1'b0; lxb12_q <= 1'b0;
    end else if (en_i) begin
      v2_q <= v1_q; last2_q <= last1_q; ok2_q <= ok1; x2_q <= x1_q; y2_q <= y1_q;
      fu2_q <= pu1_q[4:0]; fv2_q <= pv1_q[4:0];
      lxo2_q <= lx[0]; lyo2_q <= ly[0]; lxb2_q <= lx[1]; lxb12_q <= lx1[1];
    end
  end

  // ---- Stage 3: taps and the horizontal weights ---------------------------------------------
  function automatic logic [7:0] tap(input logic [4*16-1:0] data, input logic [1:0] bank, input logic b);
    tap = data[bank * 16 + (b ? 8 : 0) +: 8];
  endfunction
  logic [7:0]  ta, tb, tc, td;
  assign ta = tap(bank_rdata_i, {lyo2_q, lxo2_q}, lxb2_q);
  assign tb = tap(bank_rdata_i, {lyo2_q, ~lxo2_q}, lxb12_q);
  assign tc = tap(bank_rdata_i, {~lyo2_q, lxo2_q}, lxb2_q);
  assign td = tap(bank_rdata_i, {~lyo2_q, ~lxo2_q}, lxb12_q);
  logic [5:0]  wu0, wu1;
  assign wu0 = 6'd32 - {1'b0, fu2_q};
  assign wu1 = {1'b0, fu2_q};
  logic        v3_q, last3_q, ok3_q;
  logic [4:0]  x3_q;
  logic [3:0]  y3_q;
  logic [4:0]  fv3_q;
  logic [12:0] h0_q, h1_q;                             // <= 32 x 255
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      v3_q <= 1'b0; last3_q <= 1'b0; ok3_q <= 1'b0; x3_q <= '0; y3_q <= '0; fv3_q <= '0;
      h0_q <= '0; h1_q <= '0;
    end else if (en_i) begin
      v3_q <= v2_q; last3_q <= last2_q; ok3_q <= ok2_q; x3_q <= x2_q; y3_q <= y2_q; fv3_q <= fv2_q;
      h0_q <= 13'(wu0) * 13'(ta) + 13'(wu1) * 13'(tb);
      h1_q <= 13'(wu0) * 13'(tc) + 13'(wu1) * 13'(td);
    end
  end

  // ---- Stage 4: the vertical weights, rounding, the invalid value ---------------------------
  logic [5:0]  wv0, wv1;
  logic [17:0] vsum;                                   // <= 32 x 32 x 255 + 512 < 2^18
  logic [7:0]  out4;
  assign wv0  = 6'd32 - {1'b0, fv3_q};
  assign wv1  = {1'b0, fv3_q};
  assign vsum = 18'(wv0) * 18'(h0_q) + 18'(wv1) * 18'(h1_q) + 18'd512;
  assign out4 = 8'(vsum >> 10);
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      pix_valid_o <= 1'b0; pix_o <= '0; pix_ok_o <= 1'b0; pix_x_o <= '0; pix_y_o <= '0; pix_last_o <= 1'b0;
    end else if (en_i) begin
      pix_valid_o <= v3_q;
      pix_ok_o    <= ok3_q;
      pix_o       <= ok3_q ? out4 : (uv_q ? 8'(mcadsw_rect_pkg::RECT_INVALID_UV) : 8'(mcadsw_rect_pkg::RECT_INVALID_Y));
      pix_x_o     <= x3_q;
      pix_y_o     <= y3_q;
      pix_last_o  <= last3_q;
    end
  end

  logic unused_y0;                                     // the tile's row matters only mod 32
  assign unused_y0 = ^{tile_y0_i[CW-1:5], tile_y0_i[3:0]};

  if (BW / 4 != 1 << XB || BH / 2 != 1 << YB) begin : g_error
    mcadsw_error_rect_buffer_not_a_power_of_two u_error ();
  end

  assign busy_o = state_q != StIdle || v1_q || v2_q || v3_q || pix_valid_o;

  // ---- Assertions ----------------------------------------------------------------------------
  `MCADSW_ASSUME(step_in_range, !(en_i && start_i && state_q == StIdle) ||
                 (step_log2_i >= 3'd3 && step_log2_i <= 3'd5))
  `MCADSW_ASSUME(tile_size, !(en_i && start_i && state_q == StIdle) ||
                 (tile_w_i >= 6'd1 && tile_w_i <= 6'(TW) && tile_h_i >= 5'd1 && tile_h_i <= 5'(TH)))
  `MCADSW_ASSERT(strip_in_tile, state_q != StRun || (strip_x < tw_q && {1'b0, r_q} < th_q))
  `MCADSW_ASSERT(node_in_range, state_q == StIdle || (32'(ci_q) < NODE_COLS - 1 && 32'(cj_q) < NODE_ROWS - 1))

endmodule

`default_nettype wire

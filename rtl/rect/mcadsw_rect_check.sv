// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Rectifier: the check of the rectification's configuration (docs/blocks/rectifier.md 2,
// register map 1.2 codes 16..21; reference mcadsw::rect_check). Sequential, a pair of
// regions a cycle: the engine's own check (mcadsw_cfg_check) is combinational, and the
// rectifier's 20 regions would add about 100 overlap pairs to it.
//
// At start_i: the three sizes the block computes (a raw plane, a mesh, a bitmap) by one
// shift-and-add multiplier, 12 cycles each; then the pairs (one of the rectifier's own 10
// regions, any of the 20), one a cycle (a region with itself: its end against 2^32).
// Then done_o pulses
// with err_o: 0, or the first failing check (1 step, 2 raw size, 3 mesh size, 4 align,
// 5 overlap, 6 beyond). The configuration is held from the start until done_o.
//
// Regions: 0..5 raw plane p (read), 6..7 mesh of view v (read), 8..13 rectified plane p
// (write), 14..15 validity bitmap of view v, 16..19 the frame's output planes (write).
// Overlap counts for read x write, read x bitmap, bitmap x write and bitmap x bitmap.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_rect_check #(
  parameter int AW = 32,
  parameter int CW = 12,
  parameter int SB = AW + CW                  // sizes: exact, no wrap-around
) (
  input  logic            clk_i,
  input  logic            rst_ni,
  input  logic            start_i,
  output logic            busy_o,
  output logic            done_o,             // a pulse, with err_o
  output logic [2:0]      err_o,
  // Configuration (held from start_i until done_o)
  input  logic [2:0]      step_log2_i,
  input  logic [CW-1:0]   width_i,            // the rectified frame, 1 .. 2048
  input  logic [CW-1:0]   height_i,
  input  logic [CW-1:0]   raw_w_i,
  input  logic [CW-1:0]   raw_h_i,
  input  logic [AW-1:0]   raw_stride_i,
  input  logic            tiled_i,
  input  logic [5:0]      planes_i,           // bit p: plane p (LY LU LV RY RU RV) rectified
  input  logic [6*AW-1:0] raw_base_i,         // plane p at bits AW p
  input  logic [6*AW-1:0] rect_base_i,
  input  logic [SB-1:0]   rect_size_i,        // bytes of a rectified plane
  input  logic [2*AW-1:0] mesh_base_i,        // view v at bits AW v
  input  logic [2*AW-1:0] valid_base_i,
  input  logic [CW-1:0]   mesh_nx_i,
  input  logic [CW-1:0]   mesh_ny_i,
  input  logic [4*AW-1:0] out_base_i,         // output plane k at bits AW k
  input  logic [4*SB-1:0] out_size_i,
  input  logic [3:0]      outs_i              // bit k: output plane k written
);

  // Built in only when the package says so (mcadsw_rect_none.sv otherwise).
  if (mcadsw_pkg::RECT == 0) begin : g_no_rect
    mcadsw_error_rect_in_a_build_without_it u_error ();
  end
  localparam int NR = 20;                     // regions
  localparam int RB = 5;                      // region index bits

  // ---- The combinational checks (1 .. 4) --------------------------------------------------
  logic [1:0] views;                          // bit v: view v has a rectified plane
  assign views = {planes_i[5:3] != 3'b0, planes_i[2:0] != 3'b0};
  logic step_bad, raw_bad, mesh_bad, align_bad;
  assign step_bad = step_log2_i < 3'd3 || step_log2_i > 3'd5;
  assign raw_bad  = raw_w_i == '0 || 32'(raw_w_i) > mcadsw_pkg::MAX_WIDTH || raw_h_i == '0 ||
                    32'(raw_h_i) > mcadsw_pkg::MAX_HEIGHT || raw_stride_i[1:0] != 2'b00 ||
                    (tiled_i ? (AW + 2)'(raw_stride_i) < (AW + 2)'({raw_h_i, 2'b00})
                             : raw_stride_i < AW'(raw_w_i));
  assign mesh_bad = mesh_nx_i != ((width_i - CW'(1)) >> step_log2_i) + CW'(2) ||
                    mesh_ny_i != ((height_i - CW'(1)) >> step_log2_i) + CW'(2);
  always_comb begin
    align_bad = 1'b0;
    for (int p = 0; p < 6; p++)
      align_bad = align_bad || (planes_i[p] && raw_base_i[AW * p +: 2] != 2'b00);
    for (int v = 0; v < 2; v++)
      align_bad = align_bad || (views[v] && (mesh_base_i[AW * v +: 2] != 2'b00 ||
                                             valid_base_i[AW * v +: 2] != 2'b00));
  end

  // ---- Sizes: one shift-and-add multiplier ---------------------------------------------------
  typedef enum logic [1:0] { StIdle, StMul, StPairs, StDone } state_e;
  state_e        st_q;
  logic [1:0]    m_q;                         // product: 0 raw plane, 1 mesh, 2 bitmap
  logic [3:0]    k_q;                         // its step
  logic [SB-1:0] a_q, acc_q;                  // multiplicand (shifted left a step), sum
  logic [CW-1:0] b_q;                         // multiplier (shifted right a step)
  logic [SB-1:0] raw_size_q, mesh_size_q, bm_size_q;
  logic [CW-1:0] wq, hq, rq;                  // ceil(W / 4), ceil(H / 8), ceil(Wr / 4)
  assign wq = (width_i + CW'(3)) >> 2;
  assign hq = (height_i + CW'(7)) >> 3;
  assign rq = (raw_w_i + CW'(3)) >> 2;
  logic [SB-1:0] a_of;                        // the operands of product m
  logic [CW-1:0] b_of;
  always_comb begin
    case (m_q)
      2'd0:    begin a_of = SB'(raw_stride_i); b_of = tiled_i ? rq : raw_h_i; end
      2'd1:    begin a_of = SB'({mesh_nx_i, 3'b000}); b_of = mesh_ny_i; end
      default: begin a_of = SB'({wq, 2'b00}); b_of = hq; end
    endcase
  end

  // ---- Pairs ---------------------------------------------------------------------------------
  // Every pair the check needs has one of the rectifier's own regions (a raw plane, a mesh
  // or a bitmap: 10), so a pair is (own region i, any region j): 10 x 20 cycles, each pair
  // of two own regions visited twice. i's region equal to j: its end against 2^32.
  logic [3:0]    i_q;                         // own region: 0..5 raw plane, 6..7 mesh, 8..9 bitmap
  logic [RB-1:0] j_q;                         // region 0 .. NR - 1
  logic [RB-1:0] gi;                          // i's region index
  logic [AW-1:0] ba, bb;                      // bases of i and j
  logic [SB-1:0] sa, sb;                      // sizes
  logic          ea, eb;                      // enabled
  logic          a_bm;                        // i is a bitmap
  logic [1:0]    kb;                          // j's kind: 0 read, 1 write, 2 bitmap
  // The two regions by index: each index compared with constants (a one-hot selection).
  always_comb begin
    gi = '0; ba = '0; sa = '0; ea = 1'b0; a_bm = 1'b0;
    for (int p = 0; p < 6; p++)
      if (i_q == 4'(p)) begin
        gi = RB'(p); ba = raw_base_i[AW * p +: AW]; sa = raw_size_q; ea = planes_i[p];
      end
    for (int v = 0; v < 2; v++) begin
      if (i_q == 4'(6 + v)) begin
        gi = RB'(6 + v); ba = mesh_base_i[AW * v +: AW]; sa = mesh_size_q; ea = views[v];
      end
      if (i_q == 4'(8 + v)) begin
        gi = RB'(14 + v); ba = valid_base_i[AW * v +: AW]; sa = bm_size_q; ea = views[v]; a_bm = 1'b1;
      end
    end
  end
  always_comb begin
    bb = '0; sb = '0; eb = 1'b0; kb = 2'd0;
    for (int p = 0; p < 6; p++) begin
      if (j_q == RB'(p)) begin
        bb = raw_base_i[AW * p +: AW]; sb = raw_size_q; eb = planes_i[p]; kb = 2'd0;
      end
      if (j_q == RB'(8 + p)) begin
        bb = rect_base_i[AW * p +: AW]; sb = rect_size_i; eb = planes_i[p]; kb = 2'd1;
      end
    end
    for (int v = 0; v < 2; v++) begin
      if (j_q == RB'(6 + v)) begin
        bb = mesh_base_i[AW * v +: AW]; sb = mesh_size_q; eb = views[v]; kb = 2'd0;
      end
      if (j_q == RB'(14 + v)) begin
        bb = valid_base_i[AW * v +: AW]; sb = bm_size_q; eb = views[v]; kb = 2'd2;
      end
    end
    for (int k = 0; k < 4; k++)
      if (j_q == RB'(16 + k)) begin
        bb = out_base_i[AW * k +: AW]; sb = out_size_i[SB * k +: SB]; eb = outs_i[k]; kb = 2'd1;
      end
  end
  logic [SB:0] end_a, end_b;                  // exact ends
  assign end_a = (SB + 1)'(ba) + (SB + 1)'(sa);
  assign end_b = (SB + 1)'(bb) + (SB + 1)'(sb);
  logic pair_end, pair_ovl;
  assign pair_end = ea && gi == j_q && end_a > (SB + 1)'(64'd1 << AW);
  assign pair_ovl = ea && eb && gi != j_q && (kb != 2'd0 || a_bm) &&
                    (SB + 1)'(ba) < end_b && (SB + 1)'(bb) < end_a;
  logic fail_ovl_q, fail_end_q;
  logic last_pair;
  assign last_pair = i_q == 4'd9 && j_q == RB'(NR - 1);

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      st_q <= StIdle; m_q <= '0; k_q <= '0; i_q <= '0; j_q <= '0;
      fail_ovl_q <= 1'b0; fail_end_q <= 1'b0; done_o <= 1'b0;
    end else begin
      done_o <= 1'b0;
      case (st_q)
        StIdle: if (start_i) begin
          st_q <= StMul; m_q <= '0; k_q <= '0;
          fail_ovl_q <= 1'b0; fail_end_q <= 1'b0;
        end
        StMul: begin
          if (k_q == 4'(CW)) begin                    // product m done (written below)
            k_q <= '0;
            if (m_q == 2'd2) begin
              st_q <= StPairs; i_q <= '0; j_q <= '0;
            end else m_q <= m_q + 2'd1;
          end else k_q <= k_q + 4'd1;
        end
        StPairs: begin
          if (pair_end) fail_end_q <= 1'b1;
          if (pair_ovl) fail_ovl_q <= 1'b1;
          if (last_pair) st_q <= StDone;
          else if (j_q == RB'(NR - 1)) begin
            i_q <= i_q + 4'd1;
            j_q <= '0;
          end else j_q <= j_q + RB'(1);
        end
        StDone: begin
          st_q <= StIdle;
          done_o <= 1'b1;
        end
        default: st_q <= StIdle;
      endcase
    end
  end

  // Data (no reset: written before they are read)
  always_ff @(posedge clk_i) begin
    if (st_q == StMul) begin
      if (k_q == '0) begin                            // load product m's operands
        a_q   <= a_of;
        b_q   <= b_of;
        acc_q <= '0;
      end
      if (k_q != '0) begin
        if (b_q[0]) acc_q <= acc_q + a_q;
        a_q <= a_q << 1;
        b_q <= b_q >> 1;
      end
      if (k_q == 4'(CW)) begin
        case (m_q)
          2'd0:    raw_size_q  <= b_q[0] ? acc_q + a_q : acc_q;
          2'd1:    mesh_size_q <= b_q[0] ? acc_q + a_q : acc_q;
          default: bm_size_q   <= b_q[0] ? acc_q + a_q : acc_q;
        endcase
      end
    end
  end

  // The first failing check, registered with done_o (in the engine the frame controller
  // branches on it into clock-gate enables: from the configuration through these
  // comparisons it missed half a period).
  logic [2:0] err_c;
  always_comb begin
    err_c = 3'd0;
    if (fail_end_q) err_c = 3'd6;
    if (fail_ovl_q) err_c = 3'd5;
    if (align_bad)  err_c = 3'd4;
    if (mesh_bad)   err_c = 3'd3;
    if (raw_bad)    err_c = 3'd2;
    if (step_bad)   err_c = 3'd1;
  end
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) err_o <= 3'd0;
    else if (st_q == StDone) err_o <= err_c;
  end
  assign busy_o = st_q != StIdle;

  `MCADSW_ASSUME(start_when_idle, !(start_i && busy_o))
endmodule

`default_nettype wire

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Pass configuration of the engine (docs/blocks/engine.md 1): the frame's
// configuration, registered when the frame controller accepts a start and fixed
// for the frame, and the views of it that the engine's blocks read:
//   - the pass's planes and columns (base and match view, output plane, column
//     range, mirroring, output format), registered when a pass is set up;
//   - the planes the rectifier reads and writes, and the frame's written planes
//     for its check;
//   - the mark step's plane, bitmap and value by phase (docs/algorithm.md 13.4).
//
// The pass view. Base view Y, U, V (census and weights) and match view Y: the left
// view and the right, or the other way round with the right view as base (mode bit
// 2, or the LR mode's second pass). The first pass writes the disparity plane, or in
// the LR mode dL (with sub-pixel output in the scratch format: pack_o); the second
// writes dR, one byte a pixel, with the input stride. The pass's columns: the image
// lies in columns xlo .. xend - 1; with the right view as base the pass runs
// mirrored (docs/blocks/engine.md section 6): pass column c is image column
// W4 - 1 - c, W4 the width rounded up to 4, so the image lies in pass columns
// W4 - W .. W4 - 1. Registered at the start from the bundle at the port and, when the
// LR mode's second pass begins (to_second_i), from the registered bundle,
// so that the readers' address and clamp arithmetic starts from flip-flops.
`default_nettype none

module mcadsw_pass_cfg #(
  parameter int AW   = 32,
  parameter int CW   = 12
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  // The configuration bundle (mcadsw_engine's cfg_i; fields at mcadsw_pkg::CFG_*)
  input  logic [mcadsw_pkg::CFG_BITS-1:0] cfg_i,
  // The frame controller's
  input  logic                accept_i,        // register the configuration (a start taken)
  input  logic                to_second_i,     // the LR mode's second pass begins with the next cycle
  input  logic                pass_second_i,   // the LR mode's second pass (or what follows it)
  input  logic [1:0]          mark_phase_i,    // the mark step's phase
  // The configuration registered at the start: the bundle, and its fields for the views below
  output logic [mcadsw_pkg::CFG_BITS-1:0] cfg_q_o,
  // The rectifier's view
  output logic [5:0]          rect_planes_o,   // the planes the mode reads (docs/algorithm.md 13.4)
  output logic                tiled_o,         // TILE_STRIDE not 0
  output logic [AW-1:0]       rect_stride_o,   // the input planes': tiled, bytes a column
  // The frame's written planes (mcadsw_cfg_check's list): the first pass's output
  // (the disparity plane, or dL in the LR mode), dR, the disparity plane, the mask;
  // and those the mode writes
  output logic [4*AW-1:0]     wr_base_o,
  output logic [3:0]          wr_outs_o,
  // The pass view
  output logic [AW-1:0]       pass_by_o, pass_bu_o, pass_bv_o,  // base view Y, U, V
  output logic [AW-1:0]       pass_my_o,       // match view Y
  output logic [AW-1:0]       pass_out_o,      // the pass's output plane
  output logic [AW-1:0]       pass_stride_o,   // its stride (dR: the input stride)
  output logic [CW-1:0]       pass_xend_o,
  output logic [1:0]          pass_xlo_o,
  output logic                pass_right_o,    // the right view as base: mirrored
  output logic                pass_wide_o,     // 16-bit output (sub-pixel)
  output logic                pass_pack_o,     // LR scratch format {offset + 8, d}
  output logic                post_wide_o,     // the LR mode with sub-pixel output
  // The mark step's view by phase: 0 (LR, before the post stage) 255 into dR at the
  // right view's invalid pixels, so that the check fails there (|dL - 255| > T); 1
  // (idem) a flag into dL at the left view's, which the check fails
  // (mcadsw_post_check); 2 (after the pass, or the post stage) the invalid code into
  // the output at the base view's invalid pixels.
  output logic [AW-1:0]       mark_valid_o,
  output logic [AW-1:0]       mark_base_o,
  output logic [AW-1:0]       mark_stride_o,
  output logic                mark_half_o,
  output logic [15:0]         mark_value_o
);

  // ---- The configuration, registered at the start ------------------------------------
  logic [mcadsw_pkg::CFG_BITS-1:0] cfg_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni)       cfg_q <= '0;
    else if (accept_i) cfg_q <= cfg_i;
  end
  assign cfg_q_o = cfg_q;

  // The fields the views read, registered
  logic [AW-1:0] out_q, dl_q, dr_q, stride_q, out_stride_q, tile_q, valid_l_q, valid_r_q;
  logic          sub_q, lr_q, right_q;
  assign out_q        = cfg_q[mcadsw_pkg::CFG_BASE_OUT +: AW];
  assign dl_q         = cfg_q[mcadsw_pkg::CFG_BASE_DL +: AW];
  assign dr_q         = cfg_q[mcadsw_pkg::CFG_BASE_DR +: AW];
  assign stride_q     = cfg_q[mcadsw_pkg::CFG_STRIDE +: AW];
  assign out_stride_q = cfg_q[mcadsw_pkg::CFG_OUT_STRIDE +: AW];
  assign tile_q       = cfg_q[mcadsw_pkg::CFG_TILE_STRIDE +: AW];
  assign {valid_r_q, valid_l_q} = cfg_q[mcadsw_pkg::CFG_VALID_MAP +: 2*AW];
  assign {right_q, lr_q, sub_q} = cfg_q[mcadsw_pkg::CFG_MODE +: 3];

  // ---- The rectifier's and the check's views -------------------------------------------
  assign rect_planes_o   = lr_q ? 6'b111111 : right_q ? 6'b111001 : 6'b001111;
  assign tiled_o         = tile_q != '0;
  assign rect_stride_o   = tiled_o ? tile_q : stride_q;
  assign wr_base_o       = {cfg_q[mcadsw_pkg::CFG_BASE_MASK +: AW], out_q, dr_q, lr_q ? dl_q : out_q};
  assign wr_outs_o       = {lr_q, lr_q, lr_q, 1'b1};
  assign post_wide_o     = lr_q && sub_q;

  // ---- The pass view ---------------------------------------------------------------
  // v_*: at the start from the bundle at the port; when the second pass begins, from the
  // registered bundle.
  // BASE_LY .. BASE_DR are nine neighbouring fields of the bundle, in register order.
  localparam int PL = mcadsw_pkg::CFG_BASE_LY;
  logic [9*AW-1:0] v_planes;
  logic [AW-1:0] v_ly, v_lu, v_lv, v_ry, v_ru, v_rv, v_out, v_dl, v_dr;
  logic [CW-1:0] v_width, v_w4;
  logic [2:0]    v_mode;
  logic          v_right, v_lr, v_sub, v_second;
  assign v_second = !accept_i;
  assign v_planes = accept_i ? cfg_i[PL +: 9*AW] : cfg_q[PL +: 9*AW];
  assign v_width  = accept_i ? cfg_i[mcadsw_pkg::CFG_WIDTH +: CW] : cfg_q[mcadsw_pkg::CFG_WIDTH +: CW];
  assign v_mode   = accept_i ? cfg_i[mcadsw_pkg::CFG_MODE +: 3] : cfg_q[mcadsw_pkg::CFG_MODE +: 3];
  assign {v_dr, v_dl, v_out, v_rv, v_ru, v_ry, v_lv, v_lu, v_ly} = v_planes;
  assign v_right  = v_second || v_mode[2];
  assign v_lr     = v_mode[1];
  assign v_sub    = !v_second && v_mode[0];
  assign v_w4     = (v_width + CW'(3)) & ~(CW'(3));

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      {pass_by_o, pass_bu_o, pass_bv_o, pass_my_o, pass_out_o} <= '0;
      {pass_xend_o, pass_xlo_o, pass_right_o, pass_wide_o, pass_pack_o} <= '0;
    end else if (accept_i || to_second_i) begin
      pass_by_o    <= v_right ? v_ry : v_ly;
      pass_bu_o    <= v_right ? v_ru : v_lu;
      pass_bv_o    <= v_right ? v_rv : v_lv;
      pass_my_o    <= v_right ? v_ly : v_ry;
      pass_out_o   <= v_second ? v_dr : v_lr ? v_dl : v_out;
      pass_xend_o  <= v_right ? v_w4 : v_width;
      pass_xlo_o   <= v_right ? 2'(CW'(0) - v_width) : 2'd0;
      pass_right_o <= v_right;
      pass_wide_o  <= v_sub;
      pass_pack_o  <= v_lr && v_sub;
    end
  end
  assign pass_stride_o = pass_second_i ? stride_q : out_stride_q;

  // ---- The mark step's view -----------------------------------------------------------
  always_comb begin
    case (mark_phase_i)
      2'd0: begin
        mark_valid_o = valid_r_q; mark_base_o = dr_q; mark_stride_o = stride_q; mark_half_o = 1'b0;
        mark_value_o = 16'(mcadsw_rect_pkg::RECT_INVALID_D8);
      end
      2'd1: begin
        mark_valid_o = valid_l_q; mark_base_o = dl_q; mark_stride_o = out_stride_q; mark_half_o = sub_q;
        mark_value_o = sub_q ? 16'(mcadsw_rect_pkg::RECT_FLAG_D16) : 16'(mcadsw_rect_pkg::RECT_FLAG_D8);
      end
      default: begin
        mark_valid_o = right_q ? valid_r_q : valid_l_q; mark_base_o = out_q;
        mark_stride_o = out_stride_q; mark_half_o = sub_q;
        mark_value_o = sub_q ? 16'(mcadsw_rect_pkg::RECT_INVALID_D16) : 16'(mcadsw_rect_pkg::RECT_INVALID_D8);
      end
    endcase
  end

  if (mcadsw_pkg::CFG_BASE_DR != PL + 8*AW || mcadsw_pkg::CFG_BASE_OUT != PL + 6*AW) begin : g_bad_layout
    mcadsw_error_pass_cfg_planes_not_neighbours u_error ();
  end

endmodule

`default_nettype wire

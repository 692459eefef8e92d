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
// W4 - W .. W4 - 1. Registered at the start from the configuration ports and, when
// the LR mode's second pass begins (to_second_i), from the registered configuration,
// so that the readers' address and clamp arithmetic starts from flip-flops.
`default_nettype none

module mcadsw_pass_cfg #(
  parameter int AW   = 32,
  parameter int CW   = 12,
  parameter int NB   = $clog2(mcadsw_pkg::DMAX + 1),
  parameter int NTHR = mcadsw_pkg::WTHRESHOLDS,
  parameter int DCB  = mcadsw_pkg::COLOR_DIST_BITS
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  // The configuration ports (mcadsw_engine's, which documents them)
  input  logic [AW-1:0]       cfg_base_ly_i,
  input  logic [AW-1:0]       cfg_base_lu_i,
  input  logic [AW-1:0]       cfg_base_lv_i,
  input  logic [AW-1:0]       cfg_base_ry_i,
  input  logic [AW-1:0]       cfg_base_ru_i,
  input  logic [AW-1:0]       cfg_base_rv_i,
  input  logic [AW-1:0]       cfg_base_out_i,
  input  logic [AW-1:0]       cfg_base_dl_i,
  input  logic [AW-1:0]       cfg_base_dr_i,
  input  logic [AW-1:0]       cfg_base_mask_i,
  input  logic [AW-1:0]       cfg_stride_i,
  input  logic [AW-1:0]       cfg_out_stride_i,
  input  logic [AW-1:0]       cfg_tile_stride_i,
  input  logic [2:0]          cfg_mode_i,
  input  logic [7:0]          cfg_lr_t_i,
  input  logic [CW-1:0]       cfg_width_i,
  input  logic [CW-1:0]       cfg_height_i,
  input  logic [NB-1:0]       cfg_disp_i,
  input  logic [NTHR*DCB-1:0] cfg_thr_i,
  input  logic                cfg_rect_en_i,
  input  logic [2:0]          cfg_rect_step_i,
  input  logic [CW-1:0]       cfg_raw_width_i,
  input  logic [CW-1:0]       cfg_raw_height_i,
  input  logic [AW-1:0]       cfg_raw_stride_i,
  input  logic [AW-1:0]       cfg_raw_ly_i,
  input  logic [AW-1:0]       cfg_raw_lu_i,
  input  logic [AW-1:0]       cfg_raw_lv_i,
  input  logic [AW-1:0]       cfg_raw_ry_i,
  input  logic [AW-1:0]       cfg_raw_ru_i,
  input  logic [AW-1:0]       cfg_raw_rv_i,
  input  logic [AW-1:0]       cfg_mesh_l_i,
  input  logic [AW-1:0]       cfg_mesh_r_i,
  input  logic [CW-1:0]       cfg_mesh_nx_i,
  input  logic [CW-1:0]       cfg_mesh_ny_i,
  input  logic [AW-1:0]       cfg_valid_l_i,
  input  logic [AW-1:0]       cfg_valid_r_i,
  // The frame controller's
  input  logic                accept_i,        // register the configuration (a start taken)
  input  logic                to_second_i,     // the LR mode's second pass begins with the next cycle
  input  logic                pass_second_i,   // the LR mode's second pass (or what follows it)
  input  logic [1:0]          mark_phase_i,    // the mark step's phase
  // The registered configuration (register map order)
  output logic [AW-1:0]       ly_o, lu_o, lv_o, ry_o, ru_o, rv_o,  // input planes
  output logic [AW-1:0]       out_o, dl_o, dr_o, mask_o,           // written planes
  output logic [AW-1:0]       stride_o,
  output logic [AW-1:0]       out_stride_o,
  output logic [AW-1:0]       tile_o,          // input planes column-tiled: bytes a column; 0: raster
  output logic                sub_o, lr_o, right_o,  // CTRL.MODE bits 0, 1, 2
  output logic [7:0]          lr_t_o,
  output logic [CW-1:0]       width_o,
  output logic [CW-1:0]       height_o,
  output logic [NB-1:0]       disp_o,
  output logic [NTHR*DCB-1:0] thr_o,
  output logic                rect_o,          // RECT_CTRL.ENABLE
  output logic [2:0]          rect_step_o,
  output logic [CW-1:0]       raw_w_o, raw_h_o, mesh_nx_o, mesh_ny_o,
  output logic [AW-1:0]       raw_stride_o,
  // The rectifier's planes, plane p (LY LU LV RY RU RV) at AW p; meshes and bitmaps L, R
  output logic [6*AW-1:0]     raw_base_o,
  output logic [6*AW-1:0]     in_base_o,
  output logic [2*AW-1:0]     mesh_base_o,
  output logic [2*AW-1:0]     valid_base_o,
  output logic [5:0]          rect_planes_o,   // the planes the mode reads (docs/algorithm.md 13.4)
  output logic                tiled_o,         // tile_o != 0
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
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      {ly_o, lu_o, lv_o, ry_o, ru_o, rv_o, out_o, dl_o, dr_o, mask_o} <= '0;
      {stride_o, out_stride_o, tile_o, right_o, lr_o, sub_o, lr_t_o, width_o, height_o} <= '0;
      {disp_o, thr_o, rect_o, rect_step_o, raw_w_o, raw_h_o, mesh_nx_o, mesh_ny_o} <= '0;
      {raw_stride_o, raw_base_o, mesh_base_o, valid_base_o} <= '0;
    end else if (accept_i) begin
      {ly_o, lu_o, lv_o, ry_o, ru_o, rv_o} <= {cfg_base_ly_i, cfg_base_lu_i, cfg_base_lv_i,
                                               cfg_base_ry_i, cfg_base_ru_i, cfg_base_rv_i};
      {out_o, dl_o, dr_o, mask_o} <= {cfg_base_out_i, cfg_base_dl_i, cfg_base_dr_i, cfg_base_mask_i};
      stride_o     <= cfg_stride_i;
      out_stride_o <= cfg_out_stride_i;
      tile_o       <= cfg_tile_stride_i;
      {right_o, lr_o, sub_o} <= cfg_mode_i;
      lr_t_o       <= cfg_lr_t_i;
      width_o      <= cfg_width_i;
      height_o     <= cfg_height_i;
      disp_o       <= cfg_disp_i;
      thr_o        <= cfg_thr_i;
      rect_o       <= cfg_rect_en_i;
      rect_step_o  <= cfg_rect_step_i;
      raw_w_o      <= cfg_raw_width_i;
      raw_h_o      <= cfg_raw_height_i;
      raw_stride_o <= cfg_raw_stride_i;
      raw_base_o   <= {cfg_raw_rv_i, cfg_raw_ru_i, cfg_raw_ry_i, cfg_raw_lv_i, cfg_raw_lu_i, cfg_raw_ly_i};
      mesh_nx_o    <= cfg_mesh_nx_i;
      mesh_ny_o    <= cfg_mesh_ny_i;
      mesh_base_o  <= {cfg_mesh_r_i, cfg_mesh_l_i};
      valid_base_o <= {cfg_valid_r_i, cfg_valid_l_i};
    end
  end

  // ---- The rectifier's and the check's views -------------------------------------------
  assign in_base_o       = {rv_o, ru_o, ry_o, lv_o, lu_o, ly_o};
  assign rect_planes_o   = lr_o ? 6'b111111 : right_o ? 6'b111001 : 6'b001111;
  assign tiled_o         = tile_o != '0;
  assign rect_stride_o   = tiled_o ? tile_o : stride_o;
  assign wr_base_o       = {mask_o, out_o, dr_o, lr_o ? dl_o : out_o};
  assign wr_outs_o       = {lr_o, lr_o, lr_o, 1'b1};
  assign post_wide_o     = lr_o && sub_o;

  // ---- The pass view ---------------------------------------------------------------
  // v_*: at the start from the configuration ports; when the second pass begins, from
  // the registered configuration.
  logic [AW-1:0] v_ly, v_lu, v_lv, v_ry, v_ru, v_rv, v_out, v_dl, v_dr;
  logic [CW-1:0] v_width, v_w4;
  logic          v_right, v_lr, v_sub, v_second;
  assign v_second = !accept_i;
  assign {v_ly, v_lu, v_lv, v_ry, v_ru, v_rv, v_out, v_dl, v_dr, v_width} = accept_i ?
      {cfg_base_ly_i, cfg_base_lu_i, cfg_base_lv_i, cfg_base_ry_i, cfg_base_ru_i, cfg_base_rv_i,
       cfg_base_out_i, cfg_base_dl_i, cfg_base_dr_i, cfg_width_i} :
      {ly_o, lu_o, lv_o, ry_o, ru_o, rv_o, out_o, dl_o, dr_o, width_o};
  assign v_right = accept_i ? cfg_mode_i[2] : 1'b1;
  assign v_lr    = accept_i ? cfg_mode_i[1] : lr_o;
  assign v_sub   = accept_i && cfg_mode_i[0];
  assign v_w4    = (v_width + CW'(3)) & ~(CW'(3));

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
  assign pass_stride_o = pass_second_i ? stride_o : out_stride_o;

  // ---- The mark step's view -----------------------------------------------------------
  logic [AW-1:0] valid_l, valid_r;
  assign {valid_r, valid_l} = valid_base_o;
  always_comb begin
    case (mark_phase_i)
      2'd0: begin
        mark_valid_o = valid_r; mark_base_o = dr_o; mark_stride_o = stride_o;
        mark_half_o  = 1'b0;
        mark_value_o = 16'(mcadsw_rect_pkg::RECT_INVALID_D8);
      end
      2'd1: begin
        mark_valid_o = valid_l; mark_base_o = dl_o; mark_stride_o = out_stride_o;
        mark_half_o  = sub_o;
        mark_value_o = sub_o ? 16'(mcadsw_rect_pkg::RECT_FLAG_D16) : 16'(mcadsw_rect_pkg::RECT_FLAG_D8);
      end
      default: begin
        mark_valid_o = right_o ? valid_r : valid_l; mark_base_o = out_o;
        mark_stride_o = out_stride_o; mark_half_o = sub_o;
        mark_value_o = sub_o ? 16'(mcadsw_rect_pkg::RECT_INVALID_D16) : 16'(mcadsw_rect_pkg::RECT_INVALID_D8);
      end
    endcase
  end

endmodule

`default_nettype wire

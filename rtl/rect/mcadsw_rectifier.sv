// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The rectifier inside the engine (docs/blocks/rectifier.md), wiring only: the check of
// its registers (mcadsw_rect_check), the rectify pass (mcadsw_rect) and the mark step
// (mcadsw_rect_mark, docs/algorithm.md 13.4), each started by the frame controller. The
// fields come from the registered configuration bundle (mcadsw_pkg::CFG_*); the views
// that depend on the pass or the mark phase from mcadsw_pass_cfg; the plane sizes from
// mcadsw_cfg_check. The pass and the mark step each have a memory port, which the
// engine's port owner (mcadsw_port_mux) gives them in their states. A build without
// the rectifier reads rect/mcadsw_rect_none.sv's stand-in of this module instead.
`default_nettype none

module mcadsw_rectifier #(
  parameter int AW = 32,
  parameter int CW = 12,
  parameter int SB = AW + CW                   // plane sizes, exact
) (
  input  logic                            clk_i,
  input  logic                            rst_ni,
  input  logic [mcadsw_pkg::CFG_BITS-1:0] cfg_i,   // registered at the start
  // Views (mcadsw_pass_cfg) and plane sizes (mcadsw_cfg_check)
  input  logic                            tiled_i,
  input  logic [5:0]                      planes_i,
  input  logic [AW-1:0]                   stride_i,
  input  logic [4*AW-1:0]                 out_base_i,
  input  logic [3:0]                      outs_i,
  input  logic [SB-1:0]                   in_size_i,
  input  logic [SB-1:0]                   size_i,
  input  logic [SB-1:0]                   out_size_i,
  input  logic [AW-1:0]                   mark_valid_i,
  input  logic [AW-1:0]                   mark_base_i,
  input  logic [AW-1:0]                   mark_stride_i,
  input  logic                            mark_half_i,
  input  logic [15:0]                     mark_value_i,
  // The frame controller's steps
  input  logic                            chk_start_i,
  output logic                            chk_done_o,
  output logic [2:0]                      chk_err_o,
  input  logic                            rect_start_i,
  output logic                            rect_done_o,
  output logic [1:0]                      rect_err_o,
  input  logic                            mark_start_i,
  output logic                            mark_done_o,
  // The pass's and the mark step's memory ports (read data shared)
  output logic                            rect_req_o,
  input  logic                            rect_gnt_i,
  output logic                            rect_we_o,
  output logic [3:0]                      rect_be_o,
  output logic [AW-1:0]                   rect_addr_o,
  output logic [2:0]                      rect_len_o,
  output logic [31:0]                     rect_wdata_o,
  input  logic                            rect_rvalid_i,
  output logic                            mark_req_o,
  input  logic                            mark_gnt_i,
  output logic                            mark_we_o,
  output logic [3:0]                      mark_be_o,
  output logic [AW-1:0]                   mark_addr_o,
  output logic [2:0]                      mark_len_o,
  output logic [31:0]                     mark_wdata_o,
  input  logic                            mark_rvalid_i,
  input  logic [31:0]                     mem_rdata_i
);

  logic [2:0]      step_log2;
  logic [CW-1:0]   width, height, raw_w, raw_h;
  logic [AW-1:0]   raw_stride;
  logic [6*AW-1:0] raw_base, rect_base;
  logic [2*AW-1:0] mesh_base, valid_base;
  assign step_log2  = cfg_i[mcadsw_pkg::CFG_RECT_STEP +: 3];
  assign width      = cfg_i[mcadsw_pkg::CFG_WIDTH +: CW];
  assign height     = cfg_i[mcadsw_pkg::CFG_HEIGHT +: CW];
  assign raw_w      = cfg_i[mcadsw_pkg::CFG_RAW_WIDTH +: CW];
  assign raw_h      = cfg_i[mcadsw_pkg::CFG_RAW_HEIGHT +: CW];
  assign raw_stride = cfg_i[mcadsw_pkg::CFG_RAW_STRIDE +: AW];
  assign raw_base   = cfg_i[mcadsw_pkg::CFG_RAW +: 6*AW];
  assign rect_base  = cfg_i[mcadsw_pkg::CFG_BASE_LY +: 6*AW];   // the rectified planes: the passes' input
  assign mesh_base  = cfg_i[mcadsw_pkg::CFG_MESH +: 2*AW];
  assign valid_base = cfg_i[mcadsw_pkg::CFG_VALID_MAP +: 2*AW];

  mcadsw_rect_check #(.AW(AW), .CW(CW), .SB(SB)) u_rect_check (
    .clk_i, .rst_ni, .start_i (chk_start_i), .busy_o (), .done_o (chk_done_o),
    .err_o (chk_err_o),
    .step_log2_i (step_log2), .width_i (width), .height_i (height), .raw_w_i (raw_w), .raw_h_i (raw_h),
    .raw_stride_i (raw_stride), .tiled_i, .planes_i, .raw_base_i (raw_base), .rect_base_i (rect_base),
    .rect_size_i (in_size_i), .mesh_base_i (mesh_base), .valid_base_i (valid_base),
    .mesh_nx_i (cfg_i[mcadsw_pkg::CFG_MESH_NX +: CW]), .mesh_ny_i (cfg_i[mcadsw_pkg::CFG_MESH_NY +: CW]),
    .out_base_i, .out_size_i ({size_i, out_size_i, size_i, out_size_i}), .outs_i
  );

  mcadsw_rect #(.CW(CW)) u_rect (
    .clk_i, .rst_ni, .start_i (rect_start_i),
    .step_log2_i (step_log2), .width_i (width), .height_i (height), .raw_w_i (raw_w), .raw_h_i (raw_h),
    .tiled_i, .raw_stride_i (raw_stride), .stride_i, .raw_base_i (raw_base), .base_i (rect_base),
    .planes_i, .mesh_base_i (mesh_base), .valid_base_i (valid_base),
    .busy_o (), .done_o (rect_done_o), .err_o (rect_err_o),
    .mem_req_o (rect_req_o), .mem_gnt_i (rect_gnt_i), .mem_we_o (rect_we_o), .mem_be_o (rect_be_o),
    .mem_addr_o (rect_addr_o), .mem_len_o (rect_len_o), .mem_wdata_o (rect_wdata_o),
    .mem_rvalid_i (rect_rvalid_i), .mem_rdata_i
  );

  mcadsw_rect_mark #(.CW(CW)) u_rect_mark (
    .clk_i, .rst_ni, .start_i (mark_start_i), .width_i (width), .height_i (height),
    .valid_base_i (mark_valid_i), .base_i (mark_base_i), .stride_i (mark_stride_i),
    .half_i (mark_half_i), .value_i (mark_value_i),
    .busy_o (), .done_o (mark_done_o),
    .mem_req_o (mark_req_o), .mem_gnt_i (mark_gnt_i), .mem_we_o (mark_we_o), .mem_be_o (mark_be_o),
    .mem_addr_o (mark_addr_o), .mem_len_o (mark_len_o), .mem_wdata_o (mark_wdata_o),
    .mem_rvalid_i (mark_rvalid_i), .mem_rdata_i
  );

  logic unused;
  assign unused = ^cfg_i;  // cfg_i: other blocks' fields too

endmodule

`default_nettype wire

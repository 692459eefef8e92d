// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The engine without the rectifier (docs/blocks/fpga_target.md): the three rectifier
// modules the engine instantiates, with their ports and nothing inside. A build
// without the rectifier reads this file instead of rtl/rect/'s other modules
// (scripts/rtl_files.sh --no-rect; the package from gen_rtl_pkg --no-rect, RECT = 0),
// and its configuration check rejects RECT_CTRL.ENABLE (error code 24), so the frame
// controller never starts these blocks: their outputs are 0. The instance names are
// the engine's own, as with the rectifier. Each module stops the elaboration when the
// package says the rectifier is built in (and the real modules when it is not).
`default_nettype none

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

  if (mcadsw_pkg::RECT != 0) begin : g_bad_param
    mcadsw_error_rect_stub_with_rect u_error ();
  end
  assign {busy_o, done_o, err_o} = '0;
  logic unused;
  assign unused = ^{clk_i, rst_ni, start_i, step_log2_i, width_i, height_i, raw_w_i, raw_h_i,
                    raw_stride_i, tiled_i, planes_i, raw_base_i, rect_base_i, rect_size_i, mesh_base_i,
                    valid_base_i, mesh_nx_i, mesh_ny_i, out_base_i, out_size_i, outs_i};

endmodule

module mcadsw_rect #(
  parameter int CW  = 12,
  parameter int NB  = mcadsw_rect_pkg::MESH_NODE_BITS,
  parameter int TW  = mcadsw_rect_pkg::RECT_TILE_W,
  parameter int TH  = mcadsw_rect_pkg::RECT_TILE_H,
  parameter int BW  = mcadsw_rect_pkg::RECT_BUF_W,
  parameter int BH  = mcadsw_rect_pkg::RECT_BUF_H,
  parameter int NODES = (TW / 8 + 1) * (TH / 8 + 1),
  parameter int BAW = $clog2(BH / 2 * BW / 4),
  parameter int OUTS = 8                                  // read bursts in flight
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  // Configuration, held while busy
  input  logic               start_i,
  input  logic [2:0]         step_log2_i,
  input  logic [CW-1:0]      width_i,                     // rectified frame
  input  logic [CW-1:0]      height_i,
  input  logic [CW-1:0]      raw_w_i,                     // raw views
  input  logic [CW-1:0]      raw_h_i,
  input  logic               tiled_i,
  input  logic [31:0]        raw_stride_i,
  input  logic [31:0]        stride_i,
  input  logic [6*32-1:0]    raw_base_i,                  // plane p at bits 32p
  input  logic [6*32-1:0]    base_i,
  input  logic [5:0]         planes_i,
  input  logic [2*32-1:0]    mesh_base_i,                 // view v at bits 32v
  input  logic [2*32-1:0]    valid_base_i,
  output logic               busy_o,
  output logic               done_o,                      // pulse: the pass ended (err_o with it)
  output logic [1:0]         err_o,                       // 1: a node out of range; 2: a tile's source too big
  // Memory port (docs/memory_map.md)
  output logic               mem_req_o,
  input  logic               mem_gnt_i,
  output logic               mem_we_o,
  output logic [3:0]         mem_be_o,
  output logic [31:0]        mem_addr_o,
  output logic [2:0]         mem_len_o,
  output logic [31:0]        mem_wdata_o,
  input  logic               mem_rvalid_i,
  input  logic [31:0]        mem_rdata_i
);

  if (mcadsw_pkg::RECT != 0) begin : g_bad_param
    mcadsw_error_rect_stub_with_rect u_error ();
  end
  assign {busy_o, done_o, err_o, mem_req_o, mem_we_o, mem_be_o, mem_addr_o, mem_len_o, mem_wdata_o} = '0;
  logic unused;
  assign unused = ^{clk_i, rst_ni, start_i, step_log2_i, width_i, height_i, raw_w_i, raw_h_i, tiled_i,
                    raw_stride_i, stride_i, raw_base_i, base_i, planes_i, mesh_base_i, valid_base_i,
                    mem_gnt_i, mem_rvalid_i, mem_rdata_i};

endmodule

module mcadsw_rect_mark #(
  parameter int CW = 12,
  parameter int FD = 8                                    // bitmap words queued or in flight
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  input  logic               start_i,
  input  logic [CW-1:0]      width_i,                     // 1 .. 2^CW - 1
  input  logic [CW-1:0]      height_i,
  input  logic [31:0]        valid_base_i,
  input  logic [31:0]        base_i,
  input  logic [31:0]        stride_i,
  input  logic               half_i,
  input  logic [15:0]        value_i,
  output logic               busy_o,
  output logic               done_o,
  // Memory port (docs/memory_map.md): request held until granted, reads answered in order
  output logic               mem_req_o,
  input  logic               mem_gnt_i,
  output logic               mem_we_o,
  output logic [3:0]         mem_be_o,
  output logic [31:0]        mem_addr_o,
  output logic [2:0]         mem_len_o,
  output logic [31:0]        mem_wdata_o,
  input  logic               mem_rvalid_i,
  input  logic [31:0]        mem_rdata_i
);

  if (mcadsw_pkg::RECT != 0) begin : g_bad_param
    mcadsw_error_rect_stub_with_rect u_error ();
  end
  assign {busy_o, done_o, mem_req_o, mem_we_o, mem_be_o, mem_addr_o, mem_len_o, mem_wdata_o} = '0;
  logic unused;
  assign unused = ^{clk_i, rst_ni, start_i, width_i, height_i, valid_base_i, base_i, stride_i, half_i,
                    value_i, mem_gnt_i, mem_rvalid_i, mem_rdata_i};

endmodule

`default_nettype wire

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The engine without the rectifier (docs/blocks/fpga_target.md): the rectifier's module
// (rect/mcadsw_rectifier.sv) with its ports and nothing inside. A build without the
// rectifier reads this file instead of rtl/rect/'s other modules (scripts/rtl_files.sh
// --no-rect; the package from gen_rtl_pkg --no-rect, RECT = 0), and its configuration
// check rejects RECT_CTRL.ENABLE (error code 24), so the frame controller never starts
// the rectifier's steps: its outputs are 0. The instance name is the engine's own, as with
// the rectifier. The stand-in stops the elaboration when the package says the rectifier
// is built in (and the real modules when it is not).
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

  if (mcadsw_pkg::RECT != 0) begin : g_bad_param
    mcadsw_error_rect_stub_with_rect u_error ();
  end
  assign {chk_done_o, chk_err_o, rect_done_o, rect_err_o, mark_done_o} = '0;
  assign {rect_req_o, rect_we_o, rect_be_o, rect_addr_o, rect_len_o, rect_wdata_o} = '0;
  assign {mark_req_o, mark_we_o, mark_be_o, mark_addr_o, mark_len_o, mark_wdata_o} = '0;
  logic unused;
  assign unused = ^{clk_i, rst_ni, cfg_i, tiled_i, planes_i, stride_i, out_base_i, outs_i, in_size_i,
                    size_i, out_size_i, mark_valid_i, mark_base_i, mark_stride_i, mark_half_i,
                    mark_value_i, chk_start_i, rect_start_i, mark_start_i, rect_gnt_i, rect_rvalid_i,
                    mark_gnt_i, mark_rvalid_i, mem_rdata_i};

endmodule

`default_nettype wire

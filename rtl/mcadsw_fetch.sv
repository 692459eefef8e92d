// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// The passes' side of the external memory (paper Fig. 9, memory controller;
// docs/blocks/engine.md 3): the three window readers of the block being prepared
// (left census luma, right census luma, the weight window's Y, U and V) and the
// memory controller that shares the port between them and the depth FIFO's writes.
// Wiring only; each reader streams its window's pixels, strip by strip, to the
// block that owns the buffer (census left, census right, weight generator).
`default_nettype none

module mcadsw_fetch #(
  parameter int AW      = 32,
  parameter int CW      = 12,
  parameter int COLS    = mcadsw_pkg::BLOCK_COLS,    // weight window columns and rows (48)
  parameter int LSTRIPS = (COLS + 4 + 6) / 4,        // census left strips (14)
  parameter int RSTRIPS = 30,                        // census right strips (30 at DMAX = 64)
  parameter int WSTRIPS = COLS / 4 + 1,              // weight strips (13)
  parameter int RSB     = $clog2(RSTRIPS + 1)
) (
  input  logic               clk_i,
  input  logic               rst_ni,
  // The block being prepared (mcadsw_scheduler, mcadsw_win_geom) and the pass
  // (mcadsw_pass_cfg): every reader starts with start_i
  input  logic               start_i,
  input  logic [AW-1:0]      base_y_i,       // the base view's planes Y, U, V
  input  logic [AW-1:0]      base_u_i,
  input  logic [AW-1:0]      base_v_i,
  input  logic [AW-1:0]      base_m_i,       // the matched view's Y
  input  logic [AW-1:0]      stride_i,
  input  logic [AW-1:0]      tile_i,
  input  logic [CW-1:0]      xend_i,
  input  logic [1:0]         xlo_i,
  input  logic               mirror_i,
  input  logic [CW-1:0]      height_i,
  input  logic signed [CW:0] cen_y0_i,       // census windows' first row
  input  logic signed [CW:0] w_y0_i,         // weight window's first row
  input  logic signed [CW:0] lx0_i,
  input  logic [3:0]         lstrips_i,
  input  logic signed [CW:0] rx0_i,
  input  logic [RSB-1:0]     rstrips_i,
  input  logic signed [CW:0] wx0_i,
  input  logic [3:0]         wstrips_i,
  // Pixel streams, four pixels a word
  output logic               lpix_valid_o,
  input  logic               lpix_ready_i,
  output logic [31:0]        lpix_o,
  output logic               rpix_valid_o,
  input  logic               rpix_ready_i,
  output logic [31:0]        rpix_o,
  output logic               wpix_valid_o,
  input  logic               wpix_ready_i,
  output logic [31:0]        wpix_o,
  // The depth FIFO's writes
  input  logic               wr_req_i,
  input  logic [AW-1:0]      wr_addr_i,
  input  logic [3:0]         wr_be_i,
  input  logic [31:0]        wr_wdata_i,
  output logic               wr_gnt_o,
  // The passes' memory port (mcadsw_port_mux)
  output logic               mem_req_o,
  input  logic               mem_gnt_i,
  output logic               mem_we_o,
  output logic [3:0]         mem_be_o,
  output logic [AW-1:0]      mem_addr_o,
  output logic [3:0]         mem_len_o,
  output logic [31:0]        mem_wdata_o,
  input  logic               mem_rvalid_i,
  input  logic [31:0]        mem_rdata_i
);

  localparam int NR = 3;
  logic [NR-1:0]    rd_req, rd_gnt, rd_rvalid, rd_busy_unused;
  logic [NR*AW-1:0] rd_addr;
  logic [NR*4-1:0]  rd_len;
  logic [31:0]      rd_rdata;

  mcadsw_mem_ctrl #(.NR(NR), .AW(AW)) u_mem_ctrl (
    .clk_i, .rst_ni,
    .rd_req_i (rd_req), .rd_addr_i (rd_addr), .rd_len_i (rd_len), .rd_gnt_o (rd_gnt),
    .rd_rvalid_o (rd_rvalid), .rd_rdata_o (rd_rdata),
    .wr_req_i, .wr_addr_i, .wr_be_i, .wr_wdata_i, .wr_gnt_o,
    .mem_req_o, .mem_gnt_i, .mem_we_o, .mem_be_o, .mem_addr_o, .mem_len_o, .mem_wdata_o,
    .mem_rvalid_i, .mem_rdata_i
  );

  mcadsw_win_reader #(.ROWS(COLS + 4), .STRIPS(LSTRIPS), .PLANES(1), .CW(CW), .AW(AW))
  u_rd_census_l (
    .clk_i, .rst_ni,
    .start_i, .base_i (base_y_i), .stride_i, .tile_i, .width_i (xend_i), .lo_i (xlo_i),
    .mirror_i, .height_i, .x0_i (lx0_i), .y0_i (cen_y0_i), .strips_i (lstrips_i),
    .busy_o (rd_busy_unused[0]),
    .req_o (rd_req[0]), .addr_o (rd_addr[0*AW +: AW]), .len_o (rd_len[0*4 +: 4]),
    .gnt_i (rd_gnt[0]), .rvalid_i (rd_rvalid[0]), .rdata_i (rd_rdata),
    .pix_valid_o (lpix_valid_o), .pix_ready_i (lpix_ready_i), .pix_data_o (lpix_o)
  );

  mcadsw_win_reader #(.ROWS(COLS + 4), .STRIPS(RSTRIPS), .PLANES(1), .CW(CW), .AW(AW))
  u_rd_census_r (
    .clk_i, .rst_ni,
    .start_i, .base_i (base_m_i), .stride_i, .tile_i, .width_i (xend_i), .lo_i (xlo_i),
    .mirror_i, .height_i, .x0_i (rx0_i), .y0_i (cen_y0_i), .strips_i (rstrips_i),
    .busy_o (rd_busy_unused[1]),
    .req_o (rd_req[1]), .addr_o (rd_addr[1*AW +: AW]), .len_o (rd_len[1*4 +: 4]),
    .gnt_i (rd_gnt[1]), .rvalid_i (rd_rvalid[1]), .rdata_i (rd_rdata),
    .pix_valid_o (rpix_valid_o), .pix_ready_i (rpix_ready_i), .pix_data_o (rpix_o)
  );

  mcadsw_win_reader #(.ROWS(COLS), .STRIPS(WSTRIPS), .PLANES(3), .CW(CW), .AW(AW))
  u_rd_weight (
    .clk_i, .rst_ni,
    .start_i, .base_i ({base_v_i, base_u_i, base_y_i}), .stride_i, .tile_i, .width_i (xend_i),
    .lo_i (xlo_i), .mirror_i, .height_i, .x0_i (wx0_i), .y0_i (w_y0_i), .strips_i (wstrips_i),
    .busy_o (rd_busy_unused[2]),
    .req_o (rd_req[2]), .addr_o (rd_addr[2*AW +: AW]), .len_o (rd_len[2*4 +: 4]),
    .gnt_i (rd_gnt[2]), .rvalid_i (rd_rvalid[2]), .rdata_i (rd_rdata),
    .pix_valid_o (wpix_valid_o), .pix_ready_i (wpix_ready_i), .pix_data_o (wpix_o)
  );

  logic unused;
  assign unused = ^rd_busy_unused;

endmodule

`default_nettype wire

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Formal environment of the cost aggregator (rtl/mcadsw_cost_agg.sv) for `make
// formal`: the ping-pong buffer's ownership. The properties are in the block
// itself (its `ifdef FORMAL` section: a ghost tag per bank and column group; every
// read of the horizontal side finds all groups of its bank written for its own
// row and disparity). Environment (as the scheduler drives it): jobs of a block
// row 0 .. BLOCK-1, D from 1 to DMAX, the last in-image column inside the
// block's 48 columns; row jobs at any time the block accepts them. The census
// and weight data are free (the datapath does not reach the properties and is
// removed before the proof).
`default_nettype none

module cost_agg_props #(
  localparam int RB  = $clog2(mcadsw_pkg::BLOCK),
  localparam int NB  = $clog2(mcadsw_pkg::DMAX + 1),
  localparam int CLB = $clog2(mcadsw_pkg::GROUPS * mcadsw_pkg::LANES)
) (
  input logic           clk_i,
  input logic           rst_ni,
  input logic           job_valid_i,
  input logic [RB-1:0]  job_row_i,
  input logic [NB-1:0]  job_disp_i,
  input logic [CLB-1:0] job_last_col_i,
  input logic           job_wslot_i
);
  logic job_ready;
  mcadsw_cost_agg dut (
    .clk_i, .rst_ni,
    .job_valid_i, .job_ready_o (job_ready), .job_row_i, .job_disp_i, .job_last_col_i,
    .job_wslot_i,
    .vrd_en_o (), .vrd_row_o (), .vrd_grp_o (), .vrd_d_o (), .vrd_slot_o (),
    .lrd_en_o (), .lrd_col_o (), .rrd_en_o (), .rrd_col_o (),
    .cen_l_i ('0), .cen_r_i ('0), .wv_i ('0),
    .hrd_en_o (), .hrd_row_o (), .hrd_grp_o (), .hrd_slot_o (), .hrd_rel_o (), .wh_i ('0),
    .disp_valid_o (), .disp_row_o (), .disp_grp_o (), .disp_o (), .busy_o (), .vbusy_o (),
    .sub_valid_o (), .sub_row_o (), .sub_grp_o (), .sub_o (), .sub_d_o (), .sub_busy_o ()
  );

  `include "props_reset.svh"

  always_comb begin
    if (job_valid_i) begin
      assume (32'(job_row_i) < mcadsw_pkg::BLOCK);
      assume (job_disp_i >= NB'(1) && 32'(job_disp_i) <= mcadsw_pkg::DMAX);
      assume (32'(job_last_col_i) < mcadsw_pkg::GROUPS * mcadsw_pkg::LANES);
    end
    if (!rst_ni) assume (!job_valid_i);
  end
endmodule

`default_nettype wire

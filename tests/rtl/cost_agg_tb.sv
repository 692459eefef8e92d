// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Bench wrapper of mcadsw_cost_agg for tests/rtl/cost_agg_test.cpp: the block's
// ports, plus its vertical and final costs with their tags read by hierarchical
// reference (bench-only taps stay out of the synthesizable block). Copy p at
// p LANES VB and p HAGG FB holds disparity d + p; lanes >= D are garbage. The
// weight slots of the jobs are the weight generator's: in turn, from slot 0.
`default_nettype none

module cost_agg_tb #(
  parameter int P   = 1,
  parameter int RB  = $clog2(mcadsw_pkg::BLOCK),
  parameter int GB  = $clog2(mcadsw_pkg::GROUPS),
  parameter int DB  = mcadsw_pkg::DISP_BITS,
  parameter int NB  = $clog2(mcadsw_pkg::DMAX + 1),
  parameter int CLB = $clog2(mcadsw_pkg::GROUPS * mcadsw_pkg::LANES),
  parameter int LW  = mcadsw_pkg::LANES * mcadsw_pkg::WINDOW,   // codes / weights of LANES columns
  parameter int HW  = mcadsw_pkg::HAGG * mcadsw_pkg::WINDOW,
  parameter int SLB = $clog2(mcadsw_pkg::WEIGHT_SLOTS),
  // Census reads: the FPGA target's column words (one left, two right ports) or the
  // ASIC target's lanes (mcadsw_cost_agg)
  parameter bit FPGA = mcadsw_pkg::FPGA != 0,
  parameter int CWB = mcadsw_pkg::BLOCK_COLS * mcadsw_pkg::CENSUS_BITS,
  parameter int CRP = FPGA ? 2 : 1,
  parameter int RXB = $clog2(mcadsw_pkg::BLOCK_COLS + mcadsw_pkg::DMAX - 1),
  parameter int CLW = FPGA ? CWB : LW*mcadsw_pkg::CENSUS_BITS,
  parameter int CRW = FPGA ? 2*CWB : (LW + (P - 1) * mcadsw_pkg::WINDOW)*mcadsw_pkg::CENSUS_BITS
) (
  input  logic                           clk_i,
  input  logic                           rst_ni,
  input  logic                           job_valid_i,
  output logic                           job_ready_o,
  input  logic [RB-1:0]                  job_row_i,
  input  logic [NB-1:0]                  job_disp_i,
  input  logic [CLB-1:0]                 job_last_col_i,
  output logic                           vrd_en_o,
  output logic [RB-1:0]                  vrd_row_o,
  output logic [GB-1:0]                  vrd_grp_o,
  output logic [DB-1:0]                  vrd_d_o,
  output logic [SLB-1:0]                 vrd_slot_o,
  input  logic [LW*mcadsw_pkg::WEIGHT_CODE_BITS-1:0] wv_i,
  output logic                           lrd_en_o,
  output logic [CLB-1:0]                 lrd_col_o,
  output logic [CRP-1:0]                 rrd_en_o,
  output logic [CRP*RXB-1:0]             rrd_col_o,
  input  logic [CLW-1:0]                 cen_l_i,
  input  logic [CRW-1:0]                 cen_r_i,
  output logic                           hrd_en_o,
  output logic [RB-1:0]                  hrd_row_o,
  output logic [GB-1:0]                  hrd_grp_o,
  output logic [SLB-1:0]                 hrd_slot_o,
  output logic                           hrd_rel_o,
  input  logic [HW*mcadsw_pkg::WEIGHT_CODE_BITS-1:0] wh_i,
  output logic                           disp_valid_o,
  output logic [RB-1:0]                  disp_row_o,
  output logic [GB-1:0]                  disp_grp_o,
  output logic [mcadsw_pkg::HAGG*DB-1:0] disp_o,
  output logic                           busy_o,
  output logic                           sub_valid_o,
  output logic [RB-1:0]                  sub_row_o,
  output logic [GB-1:0]                  sub_grp_o,
  output logic [mcadsw_pkg::HAGG*(DB+4)-1:0] sub_o,
  output logic [mcadsw_pkg::HAGG*DB-1:0] sub_d_o,
  output logic                           sub_busy_o,
  // Taps
  output logic                           mon_ev_valid_o,
  output logic [RB-1:0]                  mon_ev_row_o,
  output logic [DB-1:0]                  mon_ev_d_o,
  output logic [GB-1:0]                  mon_ev_grp_o,
  output logic [P*mcadsw_pkg::LANES*mcadsw_pkg::VCOST_BITS-1:0] mon_ev_o,
  output logic                           mon_fc_valid_o,
  output logic [RB-1:0]                  mon_fc_row_o,
  output logic [DB-1:0]                  mon_fc_d_o,
  output logic [GB-1:0]                  mon_fc_grp_o,
  output logic [P*mcadsw_pkg::HAGG*mcadsw_pkg::FCOST_BITS-1:0] mon_fc_o
);
  logic [SLB-1:0] job_wslot_i;
  logic           vbusy_unused;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) job_wslot_i <= '0;
    else if (job_valid_i && job_ready_o)
      job_wslot_i <= (job_wslot_i == SLB'(mcadsw_pkg::WEIGHT_SLOTS - 1)) ? '0 : job_wslot_i + SLB'(1);
  end
  mcadsw_cost_agg #(.P(P)) u_dut (.*, .vbusy_o (vbusy_unused));

  assign mon_ev_valid_o = u_dut.ev_valid && u_dut.v2_valid_q;
  assign mon_ev_row_o   = u_dut.v2_row_q;
  assign mon_ev_d_o     = u_dut.v2_d_q;
  assign mon_ev_grp_o   = u_dut.v2_grp_q;
  assign mon_ev_o       = u_dut.ev;
  assign mon_fc_valid_o = u_dut.fc_valid && u_dut.h3_valid_q;
  assign mon_fc_row_o   = u_dut.h3_row_q;
  assign mon_fc_d_o     = u_dut.h3_d_q;
  assign mon_fc_grp_o   = u_dut.h3_grp_q;
  assign mon_fc_o       = u_dut.fc;
endmodule

`default_nettype wire

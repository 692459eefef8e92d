// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Horizontal aggregation (paper Fig. 12 right, Eq. 4): HAGG aggregators, each
// summing WINDOW vertical costs shifted by their one-hot horizontal weights.
// Aggregator m takes costs m .. m + WINDOW - 1 of the 33-cost window from the
// ping-pong buffer (partial column reuse). Result registered: one cycle after
// valid_i, or LAT = 2 on the FPGA target, whose terms are registered before their
// adder tree (the weights' block-RAM read and the multipliers, then the tree).
`default_nettype none

module mcadsw_horz_agg #(
  parameter int HAGG   = mcadsw_pkg::HAGG,
  parameter int WINDOW = mcadsw_pkg::WINDOW,
  parameter int WB     = mcadsw_pkg::WEIGHT_CODE_BITS,
  parameter int VB     = mcadsw_pkg::VCOST_BITS,
  parameter int FB     = mcadsw_pkg::FCOST_BITS,
  parameter bit FPGA   = 1'(mcadsw_pkg::FPGA),          // sums as carry-chain adder trees
  // FPGA target: aggregators 0 .. MULT_AGGS - 1 form their terms as products on the
  // device's multipliers (cost x weight) instead of shifts in LUTs
  parameter int MULT_AGGS = 0
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  input  logic                          valid_i,
  input  logic [(WINDOW+HAGG-1)*VB-1:0] ev_i,   // Ev of columns HAGG*grp + 0 .. 32
  input  logic [HAGG*WINDOW*WB-1:0]     wh_i,   // aggregator m, tap j at m*WINDOW + j
  output logic                          valid_o,
  output logic [HAGG*FB-1:0]            fc_o    // final matching costs
);

  if (WINDOW * ((1 << VB) - 1) * (1 << ((1 << WB) - 2)) >= (1 << FB) * 2) begin : g_bad_param
    mcadsw_error_fcost_width_too_narrow u_error ();
  end

  function automatic logic [FB-1:0] weigh(input logic [VB-1:0] ev, input logic [WB-1:0] e);
    if (e == '0) weigh = '0;
    else weigh = FB'(ev) << (e - WB'(1));
  endfunction
  // The weight of code e (0, or 2^(e-1)), for a product.
  localparam int WVB = (1 << WB) - 1;
  function automatic logic [WVB-1:0] weight_of(input logic [WB-1:0] e);
    weight_of = (e == '0) ? '0 : WVB'(1) << (e - WB'(1));
  endfunction

  localparam int LAT = FPGA ? 2 : 1;   // cycles from valid_i to valid_o
  logic [LAT-1:0] valid_q;             // valid_i, one bit a cycle of the pipeline
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= '0;
    else valid_q <= LAT'({valid_q, valid_i});
  end
  assign valid_o = valid_q[LAT-1];

  if (FPGA) begin : g_fpga_sum
    // FPGA target: each aggregator's WINDOW products (TB bits: a vertical cost
    // shifted by at most 2^WB - 2), registered, then summed by a balanced tree of
    // carry-chain adders (mcadsw_sum_tree); the sum fits FB bits (g_bad_param above).
    localparam int TB = VB + (1 << WB) - 2;
    localparam int SW = TB + $clog2(WINDOW);
    for (genvar m = 0; m < HAGG; m++) begin : g_agg
      logic [WINDOW*TB-1:0] terms, terms_q;
      logic [SW-1:0]        sum;
      for (genvar j = 0; j < WINDOW; j++) begin : g_term
        logic [FB-1:0] t;
        logic [FB-TB-1:0] t_unused;
        if (m < MULT_AGGS) begin : g_mult
          assign t = FB'(ev_i[(m + j)*VB +: VB]) * FB'(weight_of(wh_i[(m*WINDOW + j)*WB +: WB]));
        end else begin : g_shift
          assign t = weigh(ev_i[(m + j)*VB +: VB], wh_i[(m*WINDOW + j)*WB +: WB]);
        end
        assign terms[j*TB +: TB] = t[TB-1:0];
        assign t_unused = t[FB-1:TB];
      end
      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) terms_q <= '0;
        else if (valid_i) terms_q <= terms;
      end
      mcadsw_sum_tree #(.N(WINDOW), .W(TB)) u_sum (.terms_i(terms_q), .sum_o(sum));
      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) fc_o[m*FB +: FB] <= '0;
        else if (valid_q[0]) fc_o[m*FB +: FB] <= FB'(sum);
      end
    end
  end else begin : g_asic_sum
    // The HAGG window sums, computed only when valid (see mcadsw_vert_agg).
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        fc_o <= '0;
      end else if (valid_i) begin
        for (int m = 0; m < HAGG; m++) begin : b_agg
          logic [FB-1:0] sum;
          sum = '0;
          for (int j = 0; j < WINDOW; j++)
            sum = sum + weigh(ev_i[(m + j)*VB +: VB], wh_i[(m*WINDOW + j)*WB +: WB]);
          fc_o[m*FB +: FB] <= sum;
        end
      end
    end
  end

endmodule

`default_nettype wire

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Horizontal aggregation (paper Fig. 12 right, Eq. 4): HAGG aggregators, each
// summing WINDOW vertical costs shifted by their one-hot horizontal weights.
// Aggregator m takes costs m .. m + WINDOW - 1 of the 33-cost window from the
// ping-pong buffer (partial column reuse). Result registered.
`default_nettype none

module mcadsw_horz_agg #(
  parameter int HAGG   = mcadsw_pkg::HAGG,
  parameter int WINDOW = mcadsw_pkg::WINDOW,
  parameter int WB     = mcadsw_pkg::WEIGHT_CODE_BITS,
  parameter int VB     = mcadsw_pkg::VCOST_BITS,
  parameter int FB     = mcadsw_pkg::FCOST_BITS
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

  // The HAGG window sums, computed only when valid (see mcadsw_vert_agg).
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_o <= 1'b0;
      fc_o    <= '0;
    end else begin
      valid_o <= valid_i;
      if (valid_i) begin
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

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// A group's tags delayed by N cycles beside a datapath that takes N cycles more on
// the FPGA target (mcadsw_cost_agg: the vertical and horizontal sums' register
// stages, docs/blocks/fpga_target.md). The top bit of the tags is their valid bit:
// busy_o says a valid group is in one of the N stages.
`default_nettype none

module mcadsw_tag_delay #(
  parameter int W = 1,                 // tag bits, the valid bit on top
  parameter int N = 1                  // cycles
) (
  input  logic         clk_i,
  input  logic         rst_ni,
  input  logic [W-1:0] tags_i,
  output logic [W-1:0] tags_o,         // tags_i of N cycles before
  output logic         busy_o          // a valid tag in one of the stages
);

  if (N < 1 || W < 1) begin : g_bad_param
    mcadsw_error_tag_delay_geometry u_error ();
  end

  logic [N*W-1:0] stage_q;             // stage i at i W
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) stage_q <= '0;
    else stage_q <= (N*W)'({stage_q, tags_i});
  end
  assign tags_o = stage_q[(N-1)*W +: W];

  always_comb begin
    busy_o = 1'b0;
    for (int i = 0; i < N; i++) busy_o = busy_o || stage_q[i*W + W - 1];
  end

endmodule

`default_nettype wire

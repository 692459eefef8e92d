// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Ping-pong buffer of vertical aggregated costs (paper Fig. 12 centre, Fig. 13).
// Two banks of COLS costs: the vertical side fills one bank for disparity d,
// LANES costs a cycle, while the horizontal side reads the other (d - 1).
// The read port delivers the WINDOW + HAGG - 1 = 33 costs starting at HAGG*grp
// (partial column reuse, Fig. 7: aggregator m uses costs m .. m + WINDOW - 1).
// Columns after rd_last_i (beyond the right image border) read as column
// rd_last_i: the support window is clamped at the border (docs/algorithm.md
// section 2). The census of those columns cannot give that value, because the
// right view would be read at clamp(x - d) instead of clamp(x) - d.
`default_nettype none

module mcadsw_pingpong #(
  parameter int COLS   = mcadsw_pkg::BLOCK_COLS,  // Ev columns per block row (48)
  parameter int LANES  = mcadsw_pkg::LANES,       // costs written per cycle
  parameter int HAGG   = mcadsw_pkg::HAGG,        // horizontal aggregators
  parameter int WINDOW = mcadsw_pkg::WINDOW,
  parameter int VB     = mcadsw_pkg::VCOST_BITS,
  parameter int GB     = $clog2(COLS / LANES),    // group index width
  parameter int CB     = $clog2(COLS)             // column index width
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  input  logic                          wr_en_i,
  input  logic                          wr_bank_i,
  input  logic [GB-1:0]                 wr_grp_i,    // columns LANES*grp ..
  input  logic [LANES*VB-1:0]           wr_data_i,
  input  logic                          rd_bank_i,
  input  logic [GB-1:0]                 rd_grp_i,    // columns HAGG*grp ..
  input  logic [CB-1:0]                 rd_last_i,   // last column inside the image
  output logic [(WINDOW+HAGG-1)*VB-1:0] rd_data_o
);

  localparam int RDN = WINDOW + HAGG - 1;

  if (COLS % LANES != 0 || (COLS / LANES - 1) * HAGG + RDN > COLS) begin : g_bad_param
    mcadsw_error_pingpong_geometry u_error ();
  end

  // Both banks in one vector: bank b holds columns b*COLS .. b*COLS + COLS - 1.
  // Writes and reads select among the few legal positions (a group of LANES
  // columns; a window of RDN columns starting at HAGG*grp), so the hardware is
  // small multiplexers rather than bit-granular shifters.
  localparam int WGRPS = 2 * COLS / LANES;         // write positions, both banks
  localparam int RGRPS = COLS / LANES;             // read windows of a bank
  logic [2*COLS*VB-1:0] banks_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      banks_q <= '0;
    end else if (wr_en_i) begin
      for (int p = 0; p < WGRPS; p++)
        if (32'(wr_bank_i)*RGRPS + 32'(wr_grp_i) == p) banks_q[p*LANES*VB +: LANES*VB] <= wr_data_i;
    end
  end

  function automatic logic [COLS*VB-1:0] bank_of(input logic [2*COLS*VB-1:0] b, input logic sel);
    bank_of = sel ? b[COLS*VB +: COLS*VB] : b[0 +: COLS*VB];
  endfunction

  function automatic logic [RDN*VB-1:0] window_of(input logic [COLS*VB-1:0] b, input logic [GB-1:0] grp);
    window_of = '0;
    for (int g = 0; g < RGRPS; g++)
      window_of = window_of | (b[g*HAGG*VB +: RDN*VB] & {(RDN*VB){grp == GB'(g)}});
  endfunction

  function automatic logic [VB-1:0] cost_at(input logic [COLS*VB-1:0] b, input logic [CB-1:0] c);
    cost_at = '0;
    for (int i = 0; i < COLS; i++) cost_at = cost_at | (b[i*VB +: VB] & {VB{c == CB'(i)}});
  endfunction

  logic [COLS*VB-1:0] bank;
  logic [RDN*VB-1:0]  window;
  logic [VB-1:0]      edge_cost;
  assign bank      = bank_of(banks_q, rd_bank_i);
  assign window    = window_of(bank, rd_grp_i);
  assign edge_cost = cost_at(bank, rd_last_i);

  for (genvar i = 0; i < RDN; i++) begin : g_rd
    logic [CB:0] col;
    assign col = (CB + 1)'(32'(rd_grp_i)*HAGG + i);
    assign rd_data_o[i*VB +: VB] = (col > {1'b0, rd_last_i}) ? edge_cost : window[i*VB +: VB];
  end

endmodule

`default_nettype wire

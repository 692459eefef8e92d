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
  logic [2*COLS*VB-1:0] banks_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      banks_q <= '0;
    end else if (wr_en_i) begin
      banks_q[(32'(wr_bank_i)*COLS + 32'(wr_grp_i)*LANES)*VB +: LANES*VB] <= wr_data_i;
    end
  end

  logic [VB-1:0] edge_cost;
  assign edge_cost = banks_q[(32'(rd_bank_i)*COLS + 32'(rd_last_i))*VB +: VB];

  for (genvar i = 0; i < RDN; i++) begin : g_rd
    logic [CB:0] col;
    assign col = (CB + 1)'(32'(rd_grp_i)*HAGG + i);
    assign rd_data_o[i*VB +: VB] =
        (col > {1'b0, rd_last_i}) ? edge_cost
                                  : banks_q[(32'(rd_bank_i)*COLS + 32'(rd_grp_i)*HAGG + i)*VB +: VB];
  end

endmodule

`default_nettype wire

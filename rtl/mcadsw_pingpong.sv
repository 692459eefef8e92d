// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Ping-pong buffer of vertical aggregated costs (paper Fig. 12 centre, Fig. 13).
// Two banks of COLS costs: the vertical side fills one bank for disparity d,
// LANES costs a cycle, while the horizontal side reads the other (d - 1).
// A read delivers, the cycle after rd_en_i (registered), the WINDOW + HAGG - 1 = 33
// costs starting at HAGG*grp (partial column reuse, Fig. 7: aggregator m uses
// costs m .. m + WINDOW - 1).
//
// Border clamp: columns after wr_last_i (beyond the right image border) hold the
// cost of column wr_last_i: the support window is clamped at the border
// (docs/algorithm.md section 2). The census of those columns cannot give that
// value, because the right view would be read at clamp(x - d) instead of
// clamp(x) - d. The clamp is applied as the costs are written: a bank is written
// in group order 0, 1, .. (the vertical side's issue order), so the border
// column's cost is known when the columns after it arrive (in the same group, or
// kept in edge_q from an earlier one). Reads then take columns as stored.
//
// Read: ASIC target, the window is selected from the bank (a 6:1 select of 33
// costs). FPGA target, the window register shifts (docs/blocks/fpga_target.md):
// group 0 loads columns 0 .. 32, each later group shifts by HAGG and appends the
// HAGG columns after the window, so a cost passes a 2:1 select and the 6:1 select
// is only HAGG costs wide. The shift relies on the reads of a bank coming as
// groups 0, 1, .., COLS/LANES - 1 in consecutive cycles (asserted by the producer,
// mcadsw_cost_agg); the registered values are the same as the ASIC target's.
`default_nettype none

module mcadsw_pingpong #(
  parameter int COLS   = mcadsw_pkg::BLOCK_COLS,  // Ev columns per block row (48)
  parameter int LANES  = mcadsw_pkg::LANES,       // costs written per cycle
  parameter int HAGG   = mcadsw_pkg::HAGG,        // horizontal aggregators
  parameter int WINDOW = mcadsw_pkg::WINDOW,
  parameter int VB     = mcadsw_pkg::VCOST_BITS,
  parameter bit FPGA   = 1'(mcadsw_pkg::FPGA),    // shifted window read (above)
  parameter int GB     = $clog2(COLS / LANES),    // group index width
  parameter int CB     = $clog2(COLS)             // column index width
) (
  input  logic                          clk_i,
  input  logic                          rst_ni,
  input  logic                          wr_en_i,
  input  logic                          wr_bank_i,
  input  logic [GB-1:0]                 wr_grp_i,    // columns LANES*grp .., in order
  input  logic [LANES*VB-1:0]           wr_data_i,
  input  logic [CB-1:0]                 wr_last_i,   // last column inside the image
  input  logic                          rd_en_i,
  input  logic                          rd_bank_i,
  input  logic [GB-1:0]                 rd_grp_i,    // columns HAGG*grp ..
  output logic [(WINDOW+HAGG-1)*VB-1:0] rd_data_o    // the cycle after rd_en_i
);

  localparam int RDN = WINDOW + HAGG - 1;

  if (COLS % LANES != 0 || (COLS / LANES - 1) * HAGG + RDN > COLS) begin : g_bad_param
    mcadsw_error_pingpong_geometry u_error ();
  end

  // ---- Write, clamped at the border ----------------------------------------------
  // Lane l holds column LANES*grp + l; the border column's cost is lane wr_last_i
  // of its group (edge_hit), or edge_q for the groups after it.
  logic [LANES*VB-1:0] wdata;
  logic [VB-1:0]       edge_q, edge_new, edge_cost;
  logic                edge_hit;

  always_comb begin
    edge_new = '0;
    edge_hit = 1'b0;
    for (int l = 0; l < LANES; l++)
      if (32'(wr_grp_i)*LANES + l == 32'(wr_last_i)) begin
        edge_hit = 1'b1;
        edge_new = edge_new | wr_data_i[l*VB +: VB];
      end
  end
  assign edge_cost = edge_hit ? edge_new : edge_q;

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) edge_q <= '0;
    else if (wr_en_i && edge_hit) edge_q <= edge_new;
  end

  for (genvar l = 0; l < LANES; l++) begin : g_wlane
    assign wdata[l*VB +: VB] = (32'(wr_grp_i)*LANES + l > 32'(wr_last_i)) ? edge_cost
                                                                         : wr_data_i[l*VB +: VB];
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
        if (wr_bank_i == 1'(p / RGRPS) && wr_grp_i == GB'(p % RGRPS))
          banks_q[p*LANES*VB +: LANES*VB] <= wdata;
    end
  end

  // ---- Read ------------------------------------------------------------------------
  logic [COLS*VB-1:0] bank;
  logic [RDN*VB-1:0]  next;     // the window the read registers
  assign bank = rd_bank_i ? banks_q[COLS*VB +: COLS*VB] : banks_q[0 +: COLS*VB];

  if (FPGA) begin : g_shift_read
    for (genvar i = 0; i < RDN; i++) begin : g_rd
      if (i < RDN - HAGG) begin : g_keep
        // Group 0 loads column i; later groups shift.
        assign next[i*VB +: VB] = (rd_grp_i == '0) ? bank[i*VB +: VB] : rd_data_o[(i + HAGG)*VB +: VB];
      end else begin : g_append
        // Column HAGG*grp + i: one of COLS/LANES, whatever the group.
        logic [VB-1:0] fresh;
        always_comb begin
          fresh = '0;
          for (int g = 0; g < RGRPS; g++)
            fresh = fresh | (bank[(g*HAGG + i)*VB +: VB] & {VB{rd_grp_i == GB'(g)}});
        end
        assign next[i*VB +: VB] = fresh;
      end
    end
  end else begin : g_select_read
    always_comb begin
      next = '0;
      for (int g = 0; g < RGRPS; g++)
        next = next | (bank[g*HAGG*VB +: RDN*VB] & {(RDN*VB){rd_grp_i == GB'(g)}});
    end
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) rd_data_o <= '0;
    else if (rd_en_i) rd_data_o <= next;
  end

endmodule

`default_nettype wire

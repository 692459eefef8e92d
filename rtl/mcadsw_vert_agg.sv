// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Hamming units and vertical aggregation (paper Fig. 12, left of the ping-pong
// buffer; Eq. 3). For each of LANES columns, the census costs of all WINDOW
// pixels of the column are computed in parallel, each is shifted by its one-hot
// vertical weight (weight code e: 0 -> 0, e -> 2^(e-1), docs/algorithm.md) and
// the WINDOW products are summed. One column group per cycle, result registered:
// one cycle after valid_i, or LAT = 3 on the FPGA target, whose inputs (block-RAM
// reads behind the window selects) and products are registered first.
`default_nettype none

module mcadsw_vert_agg #(
  parameter int LANES  = mcadsw_pkg::LANES,             // columns per cycle
  parameter int WINDOW = mcadsw_pkg::WINDOW,            // pixels per column
  parameter int CB     = mcadsw_pkg::CENSUS_BITS,       // census code width
  parameter int WB     = mcadsw_pkg::WEIGHT_CODE_BITS,  // weight code width
  parameter int VB     = mcadsw_pkg::VCOST_BITS,        // vertical cost width
  parameter bit FPGA   = 1'(mcadsw_pkg::FPGA)           // sums as carry-chain adder trees
) (
  input  logic                      clk_i,
  input  logic                      rst_ni,
  // One column group: lane l, tap k at index (l*WINDOW + k)
  input  logic                      valid_i,
  input  logic [LANES*WINDOW*CB-1:0] cen_l_i,  // left census codes
  input  logic [LANES*WINDOW*CB-1:0] cen_r_i,  // right census codes at x - d
  input  logic [LANES*WINDOW*WB-1:0] wv_i,     // vertical weight codes
  // Vertical aggregated costs Ev of the group, LAT cycles later
  output logic                      valid_o,
  output logic [LANES*VB-1:0]       ev_o
);

  localparam int CNTB = $clog2(CB + 1);  // Hamming distance width

  // Illegal parameters stop elaboration (an unknown module is the one check
  // that Verilator, Yosys and Icarus all reject): the largest sum must fit VB.
  if (WINDOW * CB * (1 << ((1 << WB) - 2)) >= (1 << VB)) begin : g_bad_param
    mcadsw_error_vcost_width_too_narrow u_error ();
  end

  // Hamming distance of two census codes (Eq. 1): the ones of their XOR, counted a bit
  // pair at a time (each pair's count is 2 bits and cannot carry into the next pair),
  // then the CBE/2 pair counts added. The same adder of bits as one added at a time, in
  // fewer, wider steps, which a simulator evaluates faster ($countones is miscomputed by
  // Icarus Verilog 11).
  localparam int CBE = CB + (CB % 2);                      // CB rounded up to even
  localparam logic [CBE-1:0] PAIR_LO = {(CBE / 2){2'b01}}; // the low bit of each pair
  function automatic logic [CNTB-1:0] ones(input logic [CB-1:0] x);
    logic [CBE-1:0] xe, pr;
    xe = CBE'(x);
    pr = (xe & PAIR_LO) + ((xe >> 1) & PAIR_LO);
    ones = '0;
    for (int i = 0; i < CBE / 2; i++) ones = ones + CNTB'(pr[2*i +: 2]);
  endfunction

  // Multiplication by a one-hot weight is a shift.
  function automatic logic [VB-1:0] weigh(input logic [CNTB-1:0] cost, input logic [WB-1:0] e);
    if (e == '0) weigh = '0;
    else weigh = VB'(cost) << (e - WB'(1));
  endfunction

  localparam int LAT = FPGA ? 3 : 1;   // cycles from valid_i to valid_o
  logic [LAT-1:0] valid_q;             // valid_i, one bit a cycle of the pipeline
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) valid_q <= '0;
    else valid_q <= LAT'({valid_q, valid_i});
  end
  assign valid_o = valid_q[LAT-1];

  if (FPGA) begin : g_fpga_sum
    // FPGA target, three stages: the inputs registered; the WINDOW products of each
    // lane (TB bits: a cost below 8 shifted by at most 2^WB - 2) registered; their
    // sum by a balanced tree of carry-chain adders, registered. The sum is below
    // 2^VB (g_bad_param above), so VB bits of it are exact.
    localparam int TB = CNTB + (1 << WB) - 2;
    localparam int SW = TB + $clog2(WINDOW);
    logic [LANES*WINDOW*CB-1:0] cen_l_q, cen_r_q;
    logic [LANES*WINDOW*WB-1:0] wv_q;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) {cen_l_q, cen_r_q, wv_q} <= '0;
      else if (valid_i) {cen_l_q, cen_r_q, wv_q} <= {cen_l_i, cen_r_i, wv_i};
    end
    for (genvar ln = 0; ln < LANES; ln++) begin : g_lane
      logic [WINDOW*TB-1:0] terms_q;
      logic [SW-1:0]        sum;
      for (genvar k = 0; k < WINDOW; k++) begin : g_term
        logic [VB-1:0] t;
        logic [VB-TB-1:0] t_unused;
        assign t = weigh(ones(cen_l_q[(ln*WINDOW + k)*CB +: CB] ^ cen_r_q[(ln*WINDOW + k)*CB +: CB]),
                         wv_q[(ln*WINDOW + k)*WB +: WB]);
        always_ff @(posedge clk_i or negedge rst_ni) begin
          if (!rst_ni) terms_q[k*TB +: TB] <= '0;
          else if (valid_q[0]) terms_q[k*TB +: TB] <= t[TB-1:0];
        end
        assign t_unused = t[VB-1:TB];
      end
      mcadsw_sum_tree #(.N(WINDOW), .W(TB)) u_sum (.terms_i(terms_q), .sum_o(sum));
      always_ff @(posedge clk_i or negedge rst_ni) begin
        if (!rst_ni) ev_o[ln*VB +: VB] <= '0;
        else if (valid_q[1]) ev_o[ln*VB +: VB] <= VB'(sum);
      end
    end
  end else begin : g_asic_sum
    // The LANES column sums, computed only when a group is valid, so a simulator
    // skips them in idle cycles; the hardware is the same. The codes are XORed as whole
    // vectors first (one wide operation rather than LANES x WINDOW narrow ones).
    logic [LANES*WINDOW*CB-1:0] diff;
    assign diff = cen_l_i ^ cen_r_i;
    always_ff @(posedge clk_i or negedge rst_ni) begin
      if (!rst_ni) begin
        ev_o <= '0;
      end else if (valid_i) begin
        for (int ln = 0; ln < LANES; ln++) begin : b_lane
          logic [VB-1:0] sum;
          sum = '0;
          for (int k = 0; k < WINDOW; k++)
            sum = sum + weigh(ones(diff[(ln*WINDOW + k)*CB +: CB]), wv_i[(ln*WINDOW + k)*WB +: WB]);
          ev_o[ln*VB +: VB] <= sum;
        end
      end
    end
  end

endmodule

`default_nettype wire

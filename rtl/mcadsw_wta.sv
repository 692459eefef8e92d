// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Winner-takes-all (paper Fig. 12, right): keeps the smallest final cost and
// its disparity for each of the BLOCK pixels of the row being aggregated,
// HAGG pixels a cycle. Disparities arrive in increasing order and only a
// strictly smaller cost replaces the best, so ties keep the smallest d.
// On the last disparity the winners leave, HAGG a cycle (disp_o).
//
// Sub-pixel (docs/algorithm.md 12.6): the WTA also keeps, per pixel, the cost
// of the previous disparity, the cost just before the best (E(d-1)) and the
// first cost after it (E(d+1)). Two more stages after the winners leave turn
// them into 16 d + offset (sub_o, two cycles after disp_o): the first forms
// num = E(d-1) - E(d+1) and den = E(d-1) + E(d+1) - 2 E(d), the second counts
// the k = 1..8 with 16 |num| >= (2k - 1) den, which is the rounded |offset|.
// The offset is 0 when the best is at d = 0 or has no later disparity (d = D-1).
//
// P disparities a step (docs/blocks/cost_agg.md 1): fc_i holds the costs
// of d_i .. d_i + P - 1 (lane p, pixel m at (p HAGG + m) FB); lanes_i masks the
// lanes at or above D. The lanes are taken one after the other, as P single
// steps, so ties still keep the smallest d; P = 1 is the paper's WTA.
`default_nettype none
`include "mcadsw_assert.svh"

module mcadsw_wta #(
  parameter int BLOCK = mcadsw_pkg::BLOCK,
  parameter int HAGG  = mcadsw_pkg::HAGG,
  parameter int FB    = mcadsw_pkg::FCOST_BITS,
  parameter int DB    = mcadsw_pkg::DISP_BITS,
  parameter int SPB   = DB + 4,                  // sub-pixel value: 16 d + offset
  parameter int P     = 1,                       // disparities a step
  parameter int GB    = $clog2(BLOCK / HAGG)
) (
  input  logic                clk_i,
  input  logic                rst_ni,
  input  logic                valid_i,
  input  logic                first_i,    // d == 0: take the cost unconditionally
  input  logic                last_i,     // d == D - 1: emit the winners
  input  logic [DB-1:0]       d_i,        // the step's first disparity
  input  logic [GB-1:0]       grp_i,      // pixels HAGG*grp .. HAGG*grp + HAGG - 1
  input  logic [P*HAGG*FB-1:0] fc_i,
  input  logic [P-1:0]        lanes_i,    // lane p holds a disparity below D
  output logic                valid_o,
  output logic [GB-1:0]       grp_o,
  output logic [HAGG*DB-1:0]  disp_o,
  output logic                sub_valid_o,
  output logic [GB-1:0]       sub_grp_o,
  output logic [HAGG*SPB-1:0] sub_o,
  output logic [HAGG*DB-1:0]  sub_d_o     // the integer winners of sub_o (LR scratch format)
);

  // Per-pixel state of the row, kept as a ring of the GROUPS groups of HAGG
  // pixels: the groups arrive in order 0 .. GROUPS-1 for every disparity (the
  // cost aggregator's horizontal side reads them so), so the state of the
  // arriving group is always at the head, and the updated state goes to the
  // tail. No group-indexed multiplexers or write decoders.
  localparam int GROUPS = BLOCK / HAGG;
  localparam int PS     = 4 * FB + DB + 1;    // best, E(d-1), E(d+1), previous cost, best d, E(d+1) seen
  logic [GROUPS*HAGG*PS-1:0] st_q;           // group g at g*HAGG*PS; the head is group 0
  logic [HAGG*PS-1:0]        head, nxt;
  assign head = st_q[HAGG*PS-1:0];

  logic [HAGG*FB-1:0]  win_cost, win_cm, win_cp;
  logic [HAGG*DB-1:0]  win_d;
  logic [HAGG-1:0]     win_cpok;

  for (genvar m = 0; m < HAGG; m++) begin : g_cmp
    // State p (bits p PS ..): the pixel's before lane p (0: from the ring); P: after the step.
    logic [(P+1)*PS-1:0] st /* verilator split_var */;  // packed: never a memory
    assign st[0 +: PS] = head[m*PS +: PS];
    for (genvar p = 0; p < P; p++) begin : g_lane
      logic [FB-1:0] old_cost, old_prev, old_cm, old_cp, c, cost, cm, cp;
      logic [DB-1:0] old_d, d, dw;
      logic          old_cpok, take, cpok;
      assign {old_cost, old_prev, old_cm, old_cp, old_d, old_cpok} = st[p*PS +: PS];
      assign c    = fc_i[(p*HAGG + m)*FB +: FB];
      assign d    = d_i + DB'(p);
      assign take = (first_i && p == 0) || c < old_cost;
      assign cost = take ? c : old_cost;
      assign dw   = take ? d : old_d;
      // E(d-1) of a new best is the previous disparity's cost; E(d+1) is the first
      // cost after the best.
      assign cm   = take ? old_prev : old_cm;
      assign cp   = (!take && !old_cpok) ? c : old_cp;
      assign cpok = !take;                 // the best has a later cost unless it is new
      // A lane at or above D leaves the state as it is.
      assign st[(p+1)*PS +: PS] = lanes_i[p] ? {cost, c, cm, cp, dw, cpok} : st[p*PS +: PS];
    end
    logic [FB-1:0] prev_unused;
    assign {win_cost[m*FB +: FB], prev_unused, win_cm[m*FB +: FB], win_cp[m*FB +: FB],
            win_d[m*DB +: DB], win_cpok[m]} = st[P*PS +: PS];
    assign nxt[m*PS +: PS] = st[P*PS +: PS];
  end

  // The ring: no reset needed, every field is written at d = 0 before it is used.
  always_ff @(posedge clk_i) begin
    if (valid_i) st_q <= {nxt, st_q[GROUPS*HAGG*PS-1:HAGG*PS]};
  end

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      valid_o <= 1'b0;
      grp_o   <= '0;
      disp_o  <= '0;
    end else begin
      valid_o <= valid_i && last_i;
      if (valid_i) begin
        grp_o  <= grp_i;
        disp_o <= win_d;
      end
    end
  end

  // ---- Sub-pixel ----------------------------------------------------------------------
  // Stage A (with disp_o): the winners' costs. Stage B: num, den. Stage C: value.
  logic               a_valid_q, b_valid_q;
  logic [GB-1:0]      a_grp_q, b_grp_q;
  logic [HAGG*FB-1:0] a_c0_q, a_cm_q, a_cp_q;
  logic [HAGG-1:0]    a_ok_q, b_ok_q, b_neg_q;
  logic [HAGG*DB-1:0] a_d_q, b_d_q;
  logic [HAGG*(FB+1)-1:0] b_num_q;         // |E(d-1) - E(d+1)|
  logic [HAGG*(FB+2)-1:0] b_den_q;         // E(d-1) + E(d+1) - 2 E(d) (>= 0)

  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) begin
      a_valid_q   <= 1'b0;
      b_valid_q   <= 1'b0;
      sub_valid_o <= 1'b0;
      a_grp_q     <= '0;
      b_grp_q     <= '0;
      sub_grp_o   <= '0;
    end else begin
      a_valid_q   <= valid_i && last_i;
      b_valid_q   <= a_valid_q;
      sub_valid_o <= b_valid_q;
      if (valid_i && last_i) a_grp_q <= grp_i;
      if (a_valid_q) b_grp_q <= a_grp_q;
      if (b_valid_q) sub_grp_o <= b_grp_q;
    end
  end

  // (2k - 1) den for k = 1 .. 8 as shifts and at most two adders: no multiplier
  // (synth_ecp5 puts a product by a constant on an 18x18 multiplier: slow, and 42
  // of the ECP5's 156). den < 2^(FB+2), so 15 den fits FB + 6 bits.
  function automatic logic [FB+5:0] odd_times(input logic [FB+5:0] den, input int k);
    case (k)
      1:       odd_times = den;
      2:       odd_times = (den << 1) + den;                 // 3
      3:       odd_times = (den << 2) + den;                 // 5
      4:       odd_times = (den << 3) - den;                 // 7
      5:       odd_times = (den << 3) + den;                 // 9
      6:       odd_times = (den << 3) + (den << 1) + den;    // 11
      7:       odd_times = (den << 3) + (den << 2) + den;    // 13
      default: odd_times = (den << 4) - den;                 // 15
    endcase
  endfunction

  always_ff @(posedge clk_i) begin
    if (valid_i && last_i) begin
      a_c0_q <= win_cost;
      a_cm_q <= win_cm;
      a_cp_q <= win_cp;
      a_d_q  <= win_d;
      // Offset 0 at d = 0 (no E(d-1)) and when no cost followed the best (d = D-1).
      for (int m = 0; m < HAGG; m++) a_ok_q[m] <= win_d[m*DB +: DB] != '0 && win_cpok[m];
    end
    if (a_valid_q) begin
      for (int m = 0; m < HAGG; m++) begin
        logic [FB:0] cm, cp;
        cm = {1'b0, a_cm_q[m*FB +: FB]};
        cp = {1'b0, a_cp_q[m*FB +: FB]};
        b_neg_q[m] <= cm < cp;
        b_num_q[m*(FB+1) +: FB+1] <= (cm < cp) ? cp - cm : cm - cp;
        b_den_q[m*(FB+2) +: FB+2] <= {1'b0, cm} + {1'b0, cp} - {1'b0, a_c0_q[m*FB +: FB], 1'b0};
      end
      b_ok_q <= a_ok_q;
      b_d_q  <= a_d_q;
    end
    if (b_valid_q) begin
      sub_d_o <= b_d_q;
      for (int m = 0; m < HAGG; m++) begin
        logic [FB+5:0] n16, den;
        logic [3:0]    q;
        n16 = {1'b0, b_num_q[m*(FB+1) +: FB+1], 4'b0000};
        den = (FB + 6)'(b_den_q[m*(FB+2) +: FB+2]);
        q = '0;
        // A sum on both targets (a priority select on the FPGA target made the design
        // harder to route: docs/blocks/fpga_target.md, Timing).
        if (mcadsw_pkg::FPGA != 0) begin
          for (int k = 1; k <= 8; k++) q = q + 4'(n16 >= odd_times(den, k));
        end else begin
          for (int k = 1; k <= 8; k++) q = q + 4'(n16 >= odd_times(den, k));
        end
        if (!b_ok_q[m] || den == '0) q = '0;
        sub_o[m*SPB +: SPB] <= b_neg_q[m] ? {b_d_q[m*DB +: DB], 4'b0000} - SPB'(q)
                                          : {b_d_q[m*DB +: DB], 4'b0000} + SPB'(q);
      end
    end
  end

`ifdef MCADSW_CHECKS
  // verilator coverage_off
  // The ring relies on the groups arriving in order, from group 0 after reset.
  logic [GB-1:0] exp_grp_q;
  always_ff @(posedge clk_i or negedge rst_ni) begin
    if (!rst_ni) exp_grp_q <= '0;
    else if (valid_i) exp_grp_q <= (exp_grp_q == GB'(GROUPS - 1)) ? '0 : exp_grp_q + GB'(1);
  end
  // verilator coverage_on
`endif
  `MCADSW_ASSUME(GroupsInOrder, !(valid_i && grp_i != exp_grp_q))

endmodule

`default_nettype wire

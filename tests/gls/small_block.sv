// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// A small block for tests/gls/small_gls.sh: arithmetic like the engine's
// configuration check (a 32 x 11 multiplier, 33-bit compares) and a register
// with asynchronous reset, synthesised by the project's Yosys/abc flow and
// simulated as gates against itself as RTL. The register is not fed by the
// product: that variant hid the Verilator bug the test checks for. Four
// registers with enables: hold_q (33 flip-flops), hold_n_q (3, active-low
// enable) and hold_r_q (4, enabled by a register, so the gate's enable changes
// just after the clock edge: a latch open in the wrong phase lets it through)
// get a clock gate from flow/clock_gate.py (groups of 3 or more in the test),
// pair_q (2) keeps its multiplexer.
module gls_small (
  input  logic        clk_i,
  input  logic        rst_ni,
  input  logic [31:0] a_i,
  input  logic [10:0] b_i,
  input  logic [31:0] c_i,
  output logic [32:0] size_o,
  output logic        overlap_o,
  output logic [32:0] size_q,
  output logic [32:0] hold_q,
  output logic [2:0]  hold_n_q,
  output logic [1:0]  pair_q,
  output logic [3:0]  hold_r_q
);
  logic en_q;
  assign size_o    = 33'(a_i) * 33'(b_i);
  assign overlap_o = ({1'b0, c_i} < {1'b0, a_i} + size_o) && ({1'b0, a_i} < {1'b0, c_i} + size_o);
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) size_q <= '0;
    else size_q <= {32'(b_i) ^ size_q[31:0], overlap_o};
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) hold_q <= '0;
    else if (b_i[0]) hold_q <= {a_i, c_i[0]};
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) hold_n_q <= '0;
    else if (!b_i[1]) hold_n_q <= c_i[3:1];
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) pair_q <= '0;
    else if (b_i[2] && b_i[3]) pair_q <= a_i[1:0];
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) en_q <= 1'b0;
    else en_q <= a_i[5];
  always_ff @(posedge clk_i or negedge rst_ni)
    if (!rst_ni) hold_r_q <= '0;
    else if (en_q) hold_r_q <= c_i[7:4];
endmodule

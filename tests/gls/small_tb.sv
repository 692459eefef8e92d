// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Compares gls_small (RTL) with gls_small_gl (its gate-level netlist) on
// random inputs, cycle by cycle; prints PASS or FAIL and the first difference.
module small_tb;
  logic clk = 0, rst_n = 0;
  logic [31:0] a, c;
  logic [10:0] b;
  logic [32:0] s1, s2, q1, q2;
  logic [32:0] h1, h2;
  logic [2:0] n1, n2;
  logic [1:0] p1, p2;
  logic [3:0] r1, r2;
  logic o1, o2;
  gls_small    u_rtl (.clk_i(clk), .rst_ni(rst_n), .a_i(a), .b_i(b), .c_i(c), .size_o(s1), .overlap_o(o1), .size_q(q1),
                      .hold_q(h1), .hold_n_q(n1), .pair_q(p1), .hold_r_q(r1));
  gls_small_gl u_gl  (.clk_i(clk), .rst_ni(rst_n), .a_i(a), .b_i(b), .c_i(c), .size_o(s2), .overlap_o(o2), .size_q(q2),
                      .hold_q(h2), .hold_n_q(n2), .pair_q(p2), .hold_r_q(r2));
  integer i, bad;
  initial begin
    bad = 0;
    a = 0; b = 0; c = 0;
    #1 rst_n = 1;
    for (i = 0; i < 20000; i++) begin
      a = $urandom; b = 11'($urandom); c = (i % 3 == 0) ? a + a * 32'(b) : $urandom;
      #1 clk = 1;
      #1 clk = 0;
      if (s1 !== s2 || o1 !== o2 || q1 !== q2 || h1 !== h2 || n1 !== n2 || p1 !== p2 || r1 !== r2) begin
        bad++;
        if (bad == 1) $display("FAIL at step %0d: a=%h b=%h c=%h size %h/%h overlap %b/%b reg %h/%h hold %h/%h %h/%h %h/%h %h/%h",
                               i, a, b, c, s1, s2, o1, o2, q1, q2, h1, h2, n1, n2, p1, p2, r1, r2);
      end
    end
    if (bad == 0) $display("PASS: 20000 random steps, netlist equals RTL");
    else $display("FAIL: %0d of 20000 steps differ", bad);
    $finish;
  end
endmodule

// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Clock gate of a block that is idle for long stretches (the rectifier outside its steps, the
// post stage outside the LR mode). ASIC target: the latch-based gate of an integrated
// clock-gate cell (a latch open while the clock is low holds the enable while it is high, so
// the gated clock has no glitch), built from the library's LATCH and AND2 as the synthesis
// flow's own gates are (flow/clock_gate.py). FPGA target: the clock passes (a gate in the LUTs
// would put the clock on general routing). The gated block must not need an edge while en_i
// is 0 (or off_i 1): the frame controller asserts that nothing starts it then. The enable's logic
// is inside the gate, so the gate is one instance (make mutate leaves it out of its draw).
`default_nettype none

module mcadsw_clock_gate (
  input  logic clk_i,
  input  logic en_i,
  input  logic off_i,      // the clock runs while en_i && !off_i
  output logic clk_o
);
`ifdef MCADSW_NO_CLOCK_GATES
  localparam bit PASS = 1'b1;    // make mutate: the gates transparent (flow/mutate.py says why)
`else
  localparam bit PASS = mcadsw_pkg::FPGA != 0;
`endif
  if (PASS) begin : g_pass
    assign clk_o = clk_i;          // en_i, off_i unused (lint_waivers.vlt)
  end else begin : g_gate
    logic en_l;
    always_latch if (!clk_i) en_l = en_i && !off_i;
    assign clk_o = clk_i & en_l;
  end
endmodule

`default_nettype wire

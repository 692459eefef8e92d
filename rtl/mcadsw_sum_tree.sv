// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Balanced adder tree of the FPGA target (mcadsw_pkg::FPGA, docs/blocks/fpga_target.md,
// "Aggregator sums"): the sum of N unsigned terms of W bits as L = ceil(log2 N) levels of
// two-input adders, level l's sums W + l bits wide. Every level's sums are one
// kept net (Yosys `keep`), so synthesis maps each adder to a carry chain (ECP5
// CCU2C, 7-series CARRY4). Without it Yosys's alumacc merges the whole sum into
// one multi-operand $macc, which maccmap builds from full adders in LUTs: twice
// the logic of a carry-chain adder for each bit a level removes. Combinational.
`default_nettype none

module mcadsw_sum_tree #(
  parameter int N  = 31,               // terms
  parameter int W  = 9,                // term width
  parameter int L  = $clog2(N),        // levels
  parameter int SW = W + L             // sum width
) (
  input  logic [N*W-1:0] terms_i,      // term k at k*W
  output logic [SW-1:0]  sum_o
);

  localparam int NT = 1 << L;          // leaves: the terms and zeros

  if (N < 2 || SW != W + L) begin : g_bad_param
    mcadsw_error_sum_tree_geometry u_error ();
  end

  // Offset of level l's first sum in `node`: level m holds NT >> m sums of W + m bits.
  function automatic int level_ofs(input int l);
    level_ofs = 0;
    for (int m = 0; m < l; m++) level_ofs += (NT >> m) * (W + m);
  endfunction

  (* keep *) logic [level_ofs(L + 1)-1:0] node;

  for (genvar k = 0; k < NT; k++) begin : g_leaf
    if (k < N) begin : g_term
      assign node[k*W +: W] = terms_i[k*W +: W];
    end else begin : g_zero
      assign node[k*W +: W] = '0;
    end
  end
  for (genvar l = 1; l <= L; l++) begin : g_level
    localparam int A = level_ofs(l - 1), B = level_ofs(l);
    for (genvar i = 0; i < (NT >> l); i++) begin : g_add
      assign node[B + i*(W + l) +: W + l] = (W + l)'(node[A + 2*i*(W + l - 1) +: W + l - 1]) +
                                            (W + l)'(node[A + (2*i + 1)*(W + l - 1) +: W + l - 1]);
    end
  end
  assign sum_o = node[level_ofs(L) +: SW];

endmodule

`default_nettype wire

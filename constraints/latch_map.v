// SPDX-FileCopyrightText: 2026 The mcadsw authors
// SPDX-License-Identifier: Apache-2.0

// Yosys techmap: the RTL's latches (only the clock gate's, rtl/mcadsw_clock_gate.sv) onto the
// OSU 0.18 um LATCH, which is transparent while its CLK is high (dfflibmap of Yosys 0.23 maps
// flip-flops only). A latch transparent while E is low takes E through an inverter, which ABC
// maps to INVX1 (a gate-level $_NOT_, which ABC reads), as flow/clock_gate.py builds its own
// gates.
(* techmap_celltype = "$_DLATCH_N_" *)
module _mcadsw_dlatch_n_to_latch (input E, input D, output Q);
  wire e_n;
  \$_NOT_ u_inv (.A (E), .Y (e_n));
  LATCH _TECHMAP_REPLACE_ (.CLK (e_n), .D (D), .Q (Q));
endmodule

(* techmap_celltype = "$_DLATCH_P_" *)
module _mcadsw_dlatch_p_to_latch (input E, input D, output Q);
  LATCH _TECHMAP_REPLACE_ (.CLK (E), .D (D), .Q (Q));
endmodule
